// SPDX-License-Identifier: GPL-3.0-or-later
// Saving a scene: every shipped scene read, written and read back is the same scene
// in every field, in every language; the written file passes `rigidlab-cli validate`; numbers
// read back bit for bit whatever the locale; a body's colour is read, checked and written.

#include "build_paths.h"
#include "test_main.h"

#include "format/scene_compare.h"
#include "format/scene_loader.h"
#include "format/scene_writer.h"

#include "rigidlab/physics/shape.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using namespace rigidlab;
using lessons::Scene;

namespace {

const QString kCli = rigidlab::test::cliPath();
const QString kScenesDir = rigidlab::test::sourcePath(u"/lessons/scenes");

Scene loadOk(const QString& path, const QString& language)
{
    lessons::SceneLoadOptions options;
    options.language = language;
    const lessons::SceneLoadResult r = lessons::loadSceneFile(path, options);
    if (!r.ok)
        qWarning("%s", qPrintable(r.error));
    return r.scene;
}

lessons::SceneLoadResult loadBytes(const QByteArray& bytes, const QString& language = "en")
{
    lessons::SceneLoadOptions options;
    options.language = language;
    return lessons::loadSceneJson(bytes, QStringLiteral("x.json"), options);
}

QByteArray withBody(const QByteArray& extra)
{
    return R"({"rigidlab": 1, "bodies": [{"id": "ball", "shape": {"type": "circle", "radius": 0.1})" +
           extra + "}]}";
}

} // namespace

class TestSceneWriter : public QObject {
    Q_OBJECT

private slots:
    void shippedScenesRoundTrip_data();
    void shippedScenesRoundTrip();
    void otherLanguagesKept();
    void editedTitleSavedInTheLanguageShown();
    void numbersReadBackBitForBit();
    void colourRead();
    void colourRefused_data();
    void colourRefused();
    void unwritablePathSaysWhy();
};

void TestSceneWriter::shippedScenesRoundTrip_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("language");
    const QStringList files =
        QDir(kScenesDir).entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    QVERIFY(files.size() >= 20);
    for (const QString& file : files)
        for (const char* language : {"en", "cs"})
            QTest::addRow("%s-%s", qPrintable(file), language)
                << QDir(kScenesDir).filePath(file) << QString::fromLatin1(language);
}

void TestSceneWriter::shippedScenesRoundTrip()
{
    QFETCH(QString, path);
    QFETCH(QString, language);
    const Scene original = loadOk(path, language);
    QVERIFY(!original.bodies.empty());

    QTemporaryDir dir;
    const QString saved = dir.filePath(QStringLiteral("saved.json"));
    QCOMPARE(lessons::saveScene(saved, original), QString());
    const Scene reread = loadOk(saved, language);
    const QString difference = lessons::sceneDifference(original, reread);
    QVERIFY2(difference.isEmpty(), qPrintable(difference));
    // Written again, the same bytes: nothing drifts from save to save.
    QCOMPARE(lessons::sceneToJson(reread), lessons::sceneToJson(original));

    // The command line accepts it, with the warnings the shipped file has (sat_non_convex's
    // hull) and no others.
    QProcess cli;
    cli.start(kCli, {QStringLiteral("validate"), saved});
    QVERIFY(cli.waitForFinished(60'000));
    QCOMPARE(cli.exitStatus(), QProcess::NormalExit);
    const QByteArray err = cli.readAllStandardError();
    QVERIFY2(cli.exitCode() == 0, err.constData());
    const lessons::SceneLoadResult asShipped = lessons::loadSceneFile(path);
    QCOMPARE(err.count('\n'), asShipped.warnings.size());
    QVERIFY(cli.readAllStandardOutput().startsWith("ok: "));
}

void TestSceneWriter::otherLanguagesKept()
{
    // Read in English, saved, read in Czech: the Czech texts are still there.
    int translated = 0;
    for (const QString& file :
         QDir(kScenesDir).entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name)) {
        const QString path = QDir(kScenesDir).filePath(file);
        const Scene czech = loadOk(path, QStringLiteral("cs"));
        const Scene english = loadOk(path, QStringLiteral("en"));
        if (!czech.titles.isEmpty())
            ++translated;
        const lessons::SceneLoadResult back = loadBytes(lessons::sceneToJson(english), "cs");
        QVERIFY2(back.ok, qPrintable(back.error));
        QCOMPARE(back.scene.title, czech.title);
        QCOMPARE(back.scene.description, czech.description);
        QCOMPARE(back.scene.titles, czech.titles);
    }
    QVERIFY2(translated > 0, "no shipped scene has its title in two languages: nothing tested");
}

void TestSceneWriter::editedTitleSavedInTheLanguageShown()
{
    const QByteArray file = R"({"rigidlab": 1, "title": {"en": "Drop", "cs": "Pád"},
        "description": {"en": "Balls fall.", "cs": "Míčky padají."}, "bodies": []})";
    lessons::SceneLoadResult czech = loadBytes(file, "cs");
    QVERIFY2(czech.ok, qPrintable(czech.error));
    QCOMPARE(czech.scene.title, QStringLiteral("Pád"));
    czech.scene.title = QStringLiteral("Volný pád");
    const QByteArray saved = lessons::sceneToJson(czech.scene);
    QCOMPARE(loadBytes(saved, "cs").scene.title, QStringLiteral("Volný pád"));
    QCOMPARE(loadBytes(saved, "en").scene.title, QStringLiteral("Drop")); // untouched
    QCOMPARE(loadBytes(saved, "en").scene.description, QStringLiteral("Balls fall."));
    QCOMPARE(loadBytes(saved, "cs").scene.description, QStringLiteral("Míčky padají."));

    // setSceneTitle keeps the scene as it reads back.
    lessons::setSceneTitle(czech.scene, QStringLiteral("Volný pád"));
    QCOMPARE(czech.scene.titles.value(QStringLiteral("cs")), QStringLiteral("Volný pád"));
    QCOMPARE(czech.scene.titles.value(QStringLiteral("en")), QStringLiteral("Drop"));
    QCOMPARE(lessons::sceneDifference(loadBytes(saved, "cs").scene, czech.scene), QString());

    // A plain title stays plain.
    lessons::SceneLoadResult plain = loadBytes(R"({"rigidlab": 1, "title": "Drop", "bodies": []})");
    QVERIFY(plain.ok);
    QVERIFY(plain.scene.titles.isEmpty());
    QVERIFY(lessons::sceneToJson(plain.scene).contains(R"("title": "Drop")"));
}

void TestSceneWriter::numbersReadBackBitForBit()
{
    // Numbers with no short decimal form, under a locale that writes a decimal comma.
    const QLocale before;
    QLocale::setDefault(QLocale(QLocale::Czech));
    Scene scene;
    scene.title = QStringLiteral("Numbers \"quoted\" \\ and\ttabbed");
    scene.world.dt = 1.0 / 3.0 * 1e-3;
    scene.world.gravity = physics::Vec2(0.1 + 0.2, -9.80665);
    scene.world.sleep = false;
    physics::BodyDef ball;
    ball.name = "ball ⚽";
    ball.shape = physics::makeCircleShape(0.1 + 0.2);
    ball.position = physics::Vec2(1.0 / 7.0, -2.0 / 3.0);
    ball.angle = 3.141592653589793 / 5;
    ball.velocity = physics::Vec2(1e-300, 5e-324); // denormal: still exact
    ball.mass = 0.7;
    ball.restitution = 1.0 / 3.0;
    physics::BodyDef wedge;
    wedge.name = "wedge";
    wedge.type = physics::BodyType::Static;
    wedge.shape = physics::makePolygonShape(
        physics::makePolygon({{0, 0}, {0.4, 0}, {0, 1.0 / 3.0}}).value().polygon);
    wedge.friction = 0.1;
    physics::BodyDef box;
    box.name = "box";
    box.shape = physics::makePolygonShape(physics::makeBox(0.3, 0.1 + 0.2));
    box.collide = false;
    scene.bodies = {ball, wedge, box};
    scene.colours = {QStringLiteral("#d04030"), QString(), QStringLiteral("#00ff7f")};
    scene.springs.push_back({0, physics::Vec2(0.01, 0.02), physics::kWorld,
                             physics::Vec2(1.0 / 3.0, 2), 12.5, 0.1, 0.1 + 0.7});
    scene.joints.push_back({2, physics::Vec2(0.1, 0.1), 1, physics::Vec2(0.1, 0.1)});
    scene.originalVertices.resize(3);

    const QByteArray json = lessons::sceneToJson(scene);
    QLocale::setDefault(before);
    QVERIFY2(!json.contains("0,3"), json.constData());
    QVERIFY2(json.contains(R"("type": "box")"), json.constData()); // a box stays a box
    const lessons::SceneLoadResult back = loadBytes(json);
    QVERIFY2(back.ok, qPrintable(back.error + QLatin1Char('\n') + QString::fromUtf8(json)));
    scene.language = back.scene.language; // the language it was read in
    const QString difference = lessons::sceneDifference(scene, back.scene);
    QVERIFY2(difference.isEmpty(), qPrintable(difference));
}

void TestSceneWriter::colourRead()
{
    const lessons::SceneLoadResult r = loadBytes(withBody(R"(, "colour": "#D04030")"));
    QVERIFY2(r.ok, qPrintable(r.error));
    QCOMPARE(r.scene.colourOf(0), QStringLiteral("#d04030"));
    QCOMPARE(r.scene.colourOf(1), QString()); // no such body: no colour, no crash
    const lessons::SceneLoadResult none = loadBytes(withBody({}));
    QVERIFY(none.ok);
    QCOMPARE(none.scene.colourOf(0), QString());
    QVERIFY(!lessons::sceneToJson(none.scene).contains("colour"));
}

void TestSceneWriter::colourRefused_data()
{
    QTest::addColumn<QByteArray>("value");
    QTest::addColumn<QString>("expected");
    const QString form = QStringLiteral(
        "x.json: bodies[0].colour: must be a colour \"#rrggbb\" (six hexadecimal digits, as "
        "\"#d04030\"), got \"%1\"");
    QTest::newRow("name") << QByteArray(R"("red")") << form.arg(QStringLiteral("red"));
    QTest::newRow("short") << QByteArray(R"("#d04")") << form.arg(QStringLiteral("#d04"));
    QTest::newRow("not-hex") << QByteArray(R"("#gg0000")") << form.arg(QStringLiteral("#gg0000"));
    QTest::newRow("alpha") << QByteArray(R"("#d04030ff")") << form.arg(QStringLiteral("#d04030ff"));
    QTest::newRow("number") << QByteArray("3")
                            << QStringLiteral("x.json: bodies[0].colour: must be a string \"...\", "
                                              "got 3");
}

void TestSceneWriter::colourRefused()
{
    QFETCH(QByteArray, value);
    QFETCH(QString, expected);
    const lessons::SceneLoadResult r = loadBytes(withBody(", \"colour\": " + value));
    QVERIFY(!r.ok);
    QCOMPARE(r.error, expected);
}

void TestSceneWriter::unwritablePathSaysWhy()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("no/such/folder/x.json"));
    const QString error = lessons::saveScene(path, Scene{});
    QVERIFY(!error.isEmpty());
    QVERIFY2(error.contains(path), qPrintable(error));
    QVERIFY(!QFile::exists(path));
}

RIGIDLAB_TEST_GUILESS_MAIN(TestSceneWriter)
#include "test_scene_writer.moc"
