// SPDX-License-Identifier: GPL-3.0-or-later
// The scene schema walked field by field: every row of every object goes through the loader,
// the writer, the comparer and the scene edits, and an undo gives the scene back. A field that
// one of them forgets fails here by its key.

#include "edit/scene_edits.h"
#include "format/lesson_reading.h"
#include "format/scene_compare.h"
#include "format/scene_loader.h"
#include "format/scene_schema.h"
#include "format/scene_writer.h"

#include "test_main.h"

#include <QTest>

using namespace rigidlab;
using namespace rigidlab::lessons;
using physics::Vec2;
using schema::Kind;
using schema::Object;
using schema::Value;

namespace {

QString keyOf(std::string_view key)
{
    return QString::fromLatin1(key.data(), qsizetype(key.size()));
}

/// Two bodies (a box and a circle), a spring between them and a pin holding the box to the
/// world: one object of every kind the schema has.
Scene sampleScene()
{
    Scene scene;
    scene.title = QStringLiteral("Sample");
    scene = edit::addBox(scene, Vec2(0.0, 1.0), 1.0, 0.5).scene;
    scene = edit::addCircle(scene, Vec2(3.0, 1.0), 0.5).scene;
    scene = edit::addSpring(scene, 0, Vec2(0.0, 1.0), 1, Vec2(3.0, 1.0), 50.0).scene;
    scene = edit::addPin(scene, 0, physics::kWorld, Vec2(0.0, 1.25)).scene;
    return scene;
}

/// A number inside `range` other than `current`.
double otherNumber(const limits::Range& range, double current)
{
    for (double x : {0.25, 0.5, 2.0, 0.75, range.max, range.min})
        if (range.contains(x) && x != current)
            return x;
    return current;
}

/// A valid value for the field that differs from the one it has, or unset when it can have
/// only one value (a joint's type).
Value otherValue(const Scene& scene, Object object, const schema::Field& f)
{
    const Value now = f.get(scene, 0);
    switch (f.kind) {
    case Kind::Number:
    case Kind::Size:
        return otherNumber(f.range,
                           std::holds_alternative<double>(now) ? std::get<double>(now) : -1.0);
    case Kind::Integer:
        return std::get<int>(now) == 7 ? 8 : 7;
    case Kind::Vec2:
        return Vec2(0.25, -0.5);
    case Kind::Bool:
        return std::holds_alternative<bool>(now) ? !std::get<bool>(now) : true;
    case Kind::Choice:
        for (const QString& name : f.options())
            if (Value(name) != now)
                return name;
        return {};
    case Kind::Text:
        return QStringLiteral("renamed");
    case Kind::LocalText:
        return QStringLiteral("Srážka vozíků");
    case Kind::Colour:
        return QStringLiteral("#123abc");
    case Kind::End:
        // The other end of a spring keeps it attached; a pin's body moves to the circle.
        if (object == Object::Joint && f.key == "a")
            return QStringLiteral("circle1");
        return std::holds_alternative<std::monostate>(now) ? Value(QStringLiteral("circle1"))
                                                           : Value();
    case Kind::Shape:
        break;
    }
    return {};
}

Scene reloaded(const Scene& scene)
{
    const SceneLoadResult r = loadSceneJson(sceneToJson(scene), QStringLiteral("walk.json"));
    if (!r.ok)
        qWarning("%s", qPrintable(r.error));
    return r.scene;
}

} // namespace

class TestSchema : public QObject {
    Q_OBJECT
private slots:
    void everyFieldRoundTrips_data();
    void everyFieldRoundTrips();
    void shapeRoundTrips();
    void everySettingIsRead();
    void keysAreUnique();
    void absentFieldsReadAsTheirDefault();
    void safeFileNames_data();
    void safeFileNames();
    void titleIsWritten();
};

void TestSchema::everyFieldRoundTrips_data()
{
    QTest::addColumn<int>("object");
    QTest::addColumn<QString>("key");
    for (Object o : {Object::Scene, Object::World, Object::Body, Object::Spring, Object::Joint})
        for (const schema::Field& f : schema::fields(o))
            if (f.kind != Kind::Shape)
                QTest::newRow(qPrintable(schema::placeOf(o, 0) + u'.' + keyOf(f.key)))
                    << int(o) << keyOf(f.key);
}

void TestSchema::everyFieldRoundTrips()
{
    QFETCH(int, object);
    QFETCH(QString, key);
    const Object o = Object(object);
    const schema::Field& f = *schema::findField(o, key.toStdString());
    QVERIFY2(f.get && f.set, "a field without accessors");
    QVERIFY2(f.label && !schema::label(f).isEmpty(), "a field without a label");

    const Scene before = sampleScene();
    QCOMPARE(sceneDifference(before, reloaded(before)), QString());
    const Value value = otherValue(before, o, f);
    if (std::holds_alternative<std::monostate>(value) && f.kind == Kind::Choice) {
        QCOMPARE(f.options().size(), qsizetype(1)); // nothing to change it to
        return;
    }

    // Edit: the edited scene holds the value, and the comparer sees the field change.
    const edit::EditResult edited = edit::setField(before, o, 0, f.key, value);
    QVERIFY2(edited.ok, qPrintable(edited.error));
    QVERIFY2(f.get(edited.scene, 0) == value, qPrintable(schema::text(f.get(edited.scene, 0))));
    const QString difference = sceneDifference(before, edited.scene);
    QVERIFY2(!difference.isEmpty(), "the comparer does not see the field");
    if (f.kind != Kind::Size) // a size shows as its shape's vertices
        QVERIFY2(difference.contains(key), qPrintable(difference));

    // Write and load: the value comes back, and so does every other field.
    const QByteArray json = sceneToJson(edited.scene);
    if (f.kind != Kind::Size && (!f.written || f.written(edited.scene, 0)))
        QVERIFY2(json.contains('"' + key.toUtf8() + "\":"), json.constData());
    const Scene loaded = reloaded(edited.scene);
    QVERIFY2(f.get(loaded, 0) == value, qPrintable(schema::text(f.get(loaded, 0))));
    QCOMPARE(sceneDifference(edited.scene, loaded), QString());

    // Undo: the document keeps the scene before the edit, and the edit did not touch it.
    QCOMPARE(sceneDifference(before, sampleScene()), QString());

    // A value out of range is refused with the field's place.
    if (f.kind == Kind::Number || f.kind == Kind::Size || f.kind == Kind::Integer) {
        const edit::EditResult refused = edit::setField(before, o, 0, f.key, f.range.max * 4 + 1);
        QVERIFY(!refused.ok);
        QVERIFY2(refused.error.contains(key), qPrintable(refused.error));
    }
}

void TestSchema::shapeRoundTrips()
{
    Scene scene = sampleScene();
    scene.bodies[0].shape = physics::makeCircleShape(0.75);
    const QString difference = sceneDifference(sampleScene(), scene);
    QVERIFY2(difference.contains(QStringLiteral("shape")), qPrintable(difference));
    QCOMPARE(sceneDifference(scene, reloaded(scene)), QString());
    // A shape is edited through its sizes, not whole.
    QVERIFY(!edit::setField(scene, Object::Body, 0, "shape", 1.0).ok);
}

void TestSchema::everySettingIsRead()
{
    for (const schema::Field& f : schema::settings()) {
        StepSettings written;
        Value value;
        switch (f.kind) {
        case Kind::Number:
            value = otherNumber(f.range, -1.0);
            break;
        case Kind::Integer:
            value = 7;
            break;
        case Kind::Bool:
            value = false;
            break;
        case Kind::Choice:
            value = f.options().constLast();
            break;
        default:
            QFAIL(qPrintable(keyOf(f.key) + QStringLiteral(": a kind settings do not have")));
        }
        written.set(f.key, value);
        QVERIFY2(written.value(f.key) == value, f.key.data());
        QJsonObject settings;
        settings.insert(keyOf(f.key), std::visit(
                                          [](const auto& v) -> QJsonValue {
                                              using T = std::decay_t<decltype(v)>;
                                              if constexpr (std::is_same_v<T, std::monostate> ||
                                                            std::is_same_v<T, Vec2>)
                                                  return QJsonValue();
                                              else
                                                  return QJsonValue(v);
                                          },
                                          value));
        detail::JsonReader in(QStringLiteral("lesson.json"));
        StepSettings read;
        QVERIFY2(detail::readSettings(in, QJsonObject{{QStringLiteral("settings"), settings}},
                                      QStringLiteral("steps[0]"), read),
                 qPrintable(in.error()));
        QVERIFY2(read.value(f.key) == value, f.key.data());
        QCOMPARE(schema::stepControlNames().size(), schema::settings().size());
    }
}

void TestSchema::keysAreUnique()
{
    for (Object o : {Object::Scene, Object::World, Object::Body, Object::Spring, Object::Joint}) {
        const QStringList keys = schema::keys(o);
        QCOMPARE(QSet<QString>(keys.begin(), keys.end()).size(), keys.size());
    }
    const auto& names = schema::editorPropertyNames();
    QVERIFY(std::find(names.begin(), names.end(), "restitution") != names.end());
    QVERIFY(std::find(names.begin(), names.end(), "title") != names.end());
}

void TestSchema::absentFieldsReadAsTheirDefault()
{
    const SceneLoadResult r = loadSceneJson(
        R"({"rigidlab": 1, "bodies": [{"id": "b", "shape": {"type": "circle", "radius": 1}}]})",
        QStringLiteral("bare.json"));
    QVERIFY2(r.ok, qPrintable(r.error));
    for (Object o : {Object::World, Object::Body}) {
        for (const schema::Field& f : schema::fields(o)) {
            if (f.required || f.kind == Kind::Shape || f.kind == Kind::Size)
                continue;
            QVERIFY2(f.get(r.scene, 0) == schema::defaultValue(f),
                     qPrintable(keyOf(f.key) + u' ' + schema::text(f.get(r.scene, 0))));
        }
    }
}

void TestSchema::safeFileNames_data()
{
    QTest::addColumn<QString>("title");
    QTest::addColumn<QString>("name");
    QTest::newRow("czech") << QStringLiteral("Nová scéna") << QStringLiteral("nova_scena.json");
    QTest::newRow("carts") << QStringLiteral("Srážka vozíků!")
                           << QStringLiteral("srazka_voziku.json");
    QTest::newRow("windows") << QStringLiteral(" a/b:c*?\"<>| d ")
                             << QStringLiteral("a_b_c_d.json");
    QTest::newRow("empty") << QString() << QStringLiteral("scene.json");
    QTest::newRow("only-marks") << QStringLiteral("…") << QStringLiteral("scene.json");
    QTest::newRow("long") << QString(100, u'x') << QString(60, u'x') + QStringLiteral(".json");
}

void TestSchema::safeFileNames()
{
    QFETCH(QString, title);
    QFETCH(QString, name);
    QCOMPARE(schema::safeFileName(title), name);
}

void TestSchema::titleIsWritten()
{
    const edit::EditResult titled =
        edit::setField(sampleScene(), Object::Scene, 0, "title", QStringLiteral("Srážka vozíků"));
    QVERIFY(titled.ok);
    const SceneLoadResult r =
        loadSceneJson(sceneToJson(titled.scene), QStringLiteral("srazka_voziku.json"));
    QVERIFY2(r.ok, qPrintable(r.error));
    QCOMPARE(r.scene.title, QStringLiteral("Srážka vozíků"));
    // No description: none written.
    QVERIFY(!sceneToJson(titled.scene).contains("\"description\""));
}

RIGIDLAB_TEST_GUILESS_MAIN(TestSchema)
#include "test_schema.moc"
