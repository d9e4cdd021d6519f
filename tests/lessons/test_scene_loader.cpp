// SPDX-License-Identifier: GPL-3.0-or-later
// The scene loader: every check, its place and its message; defaults; building a world.

#include "build_paths.h"
#include "test_lessons.h"

#include "format/document.h"
#include "format/sat_report.h"
#include "run/scene_run.h"

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

using namespace rigidlab;
using namespace rigidlab::test;
using physics::Vec2;

void TestLessons::missingFile()
{
    const lessons::SceneLoadResult result =
        lessons::loadSceneFile(QStringLiteral("/nonexistent/dir/x.json"));
    QVERIFY(!result.ok);
    QCOMPARE(result.error,
             QStringLiteral("/nonexistent/dir/x.json: cannot read: No such file or directory"));
}

void TestLessons::fileTooLarge()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("big.json"));
    QVERIFY(writeFile(path, sceneWith(R"("bodies": [])") + QByteArray(9 * 1024 * 1024, ' ')));
    const lessons::SceneLoadResult result = lessons::loadSceneFile(path);
    QVERIFY(!result.ok);
    QCOMPARE(result.error, path + QStringLiteral(": too large: more than 8388608 bytes (the "
                                                 "limit is 8 MiB)"));
}

void TestLessons::tooManyBodies()
{
    QByteArray bodies;
    for (int i = 0; i <= lessons::kMaxBodies; ++i) {
        bodies += (i ? "," : "") + QByteArray(R"({"id": "b)") + QByteArray::number(i) +
                  R"(", "shape": {"type": "circle", "radius": 1}})";
    }
    const lessons::SceneLoadResult result = lessons::loadSceneJson(
        sceneWith(("\"bodies\": [" + bodies + "]").constData()), QStringLiteral("x.json"));
    QVERIFY(!result.ok);
    QCOMPARE(result.error, QStringLiteral("x.json: bodies: 10001 bodies, more than the limit of "
                                          "10000"));
}

void TestLessons::defaults()
{
    const lessons::SceneLoadResult result =
        lessons::loadSceneJson(oneBody(R"("shape": {"type": "circle", "radius": 0.5})"),
                               QStringLiteral("dir/my_scene.json"));
    QVERIFY2(result.ok, qPrintable(result.error));
    QVERIFY(result.warnings.isEmpty());
    const lessons::Scene& scene = result.scene;
    QCOMPARE(scene.title, QStringLiteral("my_scene"));
    QCOMPARE(scene.description, QString());
    const physics::WorldDef world;
    QCOMPARE(scene.world.gravity, world.gravity);
    QCOMPARE(scene.world.dt, world.dt);
    QCOMPARE(scene.world.integrator, world.integrator);
    QCOMPARE(scene.world.solver, world.solver);
    QCOMPARE(scene.world.iterations, world.iterations);
    QCOMPARE(scene.world.restitution, world.restitution);
    QCOMPARE(scene.world.friction, world.friction);
    QCOMPARE(scene.world.gravitation, world.gravitation);
    QCOMPARE(scene.world.drag, world.drag);
    QCOMPARE(scene.bodies.size(), size_t{1});
    const physics::BodyDef body;
    const physics::BodyDef& got = scene.bodies[0];
    QCOMPARE(got.name, std::string("ball"));
    QCOMPARE(got.type, body.type);
    QVERIFY(got.shape.asCircle());
    QCOMPARE(got.shape.asCircle()->radius, 0.5);
    QCOMPARE(got.position, body.position);
    QCOMPARE(got.angle, body.angle);
    QCOMPARE(got.velocity, body.velocity);
    QCOMPARE(got.angularVelocity, body.angularVelocity);
    QCOMPARE(got.density, body.density);
    QCOMPARE(got.mass, body.mass);
    QCOMPARE(got.restitution, body.restitution);
    QCOMPARE(got.friction, body.friction);
    QCOMPARE(got.collide, body.collide);
    QVERIFY(scene.springs.empty());
    QVERIFY(scene.joints.empty());
}

void TestLessons::sceneTexts_data()
{
    QTest::addColumn<QByteArray>("texts");
    QTest::addColumn<QString>("language");
    QTest::addColumn<QString>("title");
    QTest::addColumn<QString>("description");
    QTest::addColumn<QStringList>("warnings");

    const QByteArray both = R"("title": {"en": "Drop", "cs": "Pád"},
                               "description": {"en": "A ball falls.", "cs": "Míček padá."})";
    QTest::newRow("plain-en") << QByteArray(R"("title": "Drop", "description": "A ball falls.")")
                              << "en"
                              << "Drop"
                              << "A ball falls." << QStringList();
    // A scene in English only is not a translated scene: it warns of nothing.
    QTest::newRow("plain-cs") << QByteArray(R"("title": "Drop", "description": "A ball falls.")")
                              << "cs"
                              << "Drop"
                              << "A ball falls." << QStringList();
    QTest::newRow("object-en") << both << "en"
                               << "Drop"
                               << "A ball falls." << QStringList();
    QTest::newRow("object-cs") << both << "cs"
                               << "Pád"
                               << "Míček padá." << QStringList();
    QTest::newRow("object-missing-cs")
        << QByteArray(R"("title": {"en": "Drop"}, "description": {"en": "A ball falls.",
                         "cs": "Míček padá."})")
        << "cs"
        << "Drop"
        << "Míček padá."
        << QStringList{
               QStringLiteral("x.json: title: no Czech text (\"cs\"): it will show in English")};
    QTest::newRow("plain-beside-object")
        << QByteArray(R"("title": {"en": "Drop", "cs": "Pád"}, "description": "A ball falls.")")
        << "cs"
        << "Pád"
        << "A ball falls."
        << QStringList{QStringLiteral(
               "x.json: description: no Czech text (\"cs\"): it will show in English")};
    // An empty title in the chosen language falls back to the file name, as a plain one does.
    QTest::newRow("object-empty-title")
        << QByteArray(R"("title": {"en": "Drop", "cs": ""})") << "cs"
        << "x" << QString() << QStringList();
}

void TestLessons::sceneTexts()
{
    QFETCH(QByteArray, texts);
    QFETCH(QString, language);
    QFETCH(QString, title);
    QFETCH(QString, description);
    QFETCH(QStringList, warnings);
    const QByteArray json = sceneWith((texts + R"(, "bodies": [])").constData());
    const lessons::SceneLoadResult result =
        lessons::loadSceneJson(json, QStringLiteral("x.json"), lessons::SceneLoadOptions{language});
    QVERIFY2(result.ok, qPrintable(result.error));
    QCOMPARE(result.scene.title, title);
    QCOMPARE(result.scene.description, description);
    QCOMPARE(result.warnings, warnings);
}

void TestLessons::bodyLabels_data()
{
    QTest::addColumn<QByteArray>("label");
    QTest::addColumn<QString>("language");
    QTest::addColumn<QString>("shown");
    QTest::addColumn<bool>("labelled");
    QTest::addColumn<QStringList>("warnings");

    const QByteArray both = R"("label": {"en": "light ball", "cs": "lehká koule"}, )";
    QTest::newRow("object-en") << both << "en"
                               << "light ball" << true << QStringList();
    QTest::newRow("object-cs") << both << "cs"
                               << "lehká koule" << true << QStringList();
    // No label: the id, in every language.
    QTest::newRow("none-en") << QByteArray() << "en"
                             << "ball" << false << QStringList();
    QTest::newRow("none-cs") << QByteArray() << "cs"
                             << "ball" << false << QStringList();
    // A plain label is English: in a translated scene it lacks Czech, as a plain title does.
    QTest::newRow("plain-cs")
        << QByteArray(R"("label": "light ball", )") << "cs"
        << "light ball" << true
        << QStringList{QStringLiteral(
               "x.json: bodies[0].label: no Czech text (\"cs\"): it will show in English")};
    // Spaces around it are not part of the name.
    QTest::newRow("trimmed") << QByteArray(R"("label": {"en": " light ball ", "cs": "koule"}, )")
                             << "en"
                             << "light ball" << true << QStringList();
    // A label in Czech only is shown in Czech in every language, and says so.
    for (const char* language : {"en", "cs"})
        QTest::addRow("czech-only-%s", language)
            << QByteArray(R"("label": {"cs": "lehká koule"}, )") << language << "lehká koule"
            << true
            << QStringList{QStringLiteral(
                   "x.json: bodies[0].label: no English text (\"en\"): it will show in Czech")};
    // In a translated scene a label without Czech warns, as a title does.
    QTest::newRow("missing-cs")
        << QByteArray(R"("label": {"en": "light ball"}, )") << "cs"
        << "light ball" << true
        << QStringList{QStringLiteral(
               "x.json: bodies[0].label: no Czech text (\"cs\"): it will show in English")};
}

void TestLessons::bodyLabels()
{
    QFETCH(QByteArray, label);
    QFETCH(QString, language);
    QFETCH(QString, shown);
    QFETCH(bool, labelled);
    QFETCH(QStringList, warnings);
    // The title is translated, so a text without Czech is worth a warning.
    const QByteArray json =
        sceneWith((R"("title": {"en": "Drop", "cs": "Pád"}, "bodies": [{"id": "ball", )" + label +
                   R"("shape": {"type": "circle", "radius": 0.1}}])")
                      .constData());
    const lessons::SceneLoadResult result =
        lessons::loadSceneJson(json, QStringLiteral("x.json"), lessons::SceneLoadOptions{language});
    QVERIFY2(result.ok, qPrintable(result.error));
    QCOMPARE(result.warnings, warnings);
    QCOMPARE(result.scene.labels.size(), result.scene.bodies.size());
    QCOMPARE(result.scene.hasLabel(0), labelled);
    QCOMPARE(result.scene.bodyLabel(0), shown);
    // The id stays what the file calls the body, for springs, questions and traces.
    QCOMPARE(result.scene.bodies[0].name, std::string("ball"));
    QCOMPARE(result.scene.bodyIndex(QStringLiteral("ball")), std::optional<physics::BodyId>(0));
    // Out of range: nothing, not a crash.
    QCOMPARE(result.scene.bodyLabel(1), QString());
    QCOMPARE(result.scene.bodyLabel(physics::kWorld), QString());
    QVERIFY(!result.scene.hasLabel(1));
}

void TestLessons::rejectsBadBodyLabel_data()
{
    QTest::addColumn<QByteArray>("label");
    QTest::addColumn<QString>("message");

    QTest::newRow("number") << QByteArray(R"("label": 3)")
                            << R"(bodies[0].label: must be a string "...", got 3)";
    QTest::newRow("array") << QByteArray(R"("label": ["light", "ball"])")
                           << R"(bodies[0].label: must be a string "...", got an array)";
    QTest::newRow("empty") << QByteArray(R"("label": " ")")
                           << R"(bodies[0].label: must not be empty (leave "label" out to show )"
                              "the id)";
    // Every language is checked, whichever is shown.
    QTest::newRow("empty-cs") << QByteArray(R"("label": {"en": "light ball", "cs": ""})")
                              << R"(bodies[0].label.cs: must not be empty (leave "label" out to )"
                                 "show the id)";
    QTest::newRow("unknown-language")
        << QByteArray(R"("label": {"en": "light ball", "de": "leichte Kugel"})")
        << R"(bodies[0].label.de: unknown language "de" (expected en, cs))";
    QTest::newRow("no-language") << QByteArray(R"("label": {})")
                                 << R"(bodies[0].label: needs a text in at least one language )"
                                    "(en, cs)";
    QTest::newRow("too-long") << "\"label\": \"" + QByteArray(81, 'x') + '"'
                              << "bodies[0].label: longer than 80 characters";
    QTest::newRow("control") << QByteArray(R"("label": {"en": "light\nball", "cs": "koule"})")
                             << "bodies[0].label.en: must not hold control characters";
}

void TestLessons::rejectsBadBodyLabel()
{
    QFETCH(QByteArray, label);
    QFETCH(QString, message);
    const QByteArray json =
        oneBody((label + R"(, "shape": {"type": "circle", "radius": 0.1})").constData());
    for (const QString& language : {QStringLiteral("en"), QStringLiteral("cs")}) {
        const lessons::SceneLoadResult result = lessons::loadSceneJson(
            json, QStringLiteral("x.json"), lessons::SceneLoadOptions{language});
        QVERIFY(!result.ok);
        QCOMPARE(result.error, QStringLiteral("x.json: ") + message);
    }
}

void TestLessons::rejectsBadSceneText_data()
{
    QTest::addColumn<QByteArray>("texts");
    QTest::addColumn<QString>("message");

    QTest::newRow("unknown-language") << QByteArray(R"("title": {"en": "Drop", "de": "Fall"})")
                                      << R"(title.de: unknown language "de" (expected en, cs))";
    QTest::newRow("no-language") << QByteArray(R"("title": {})")
                                 << R"(title: needs a text in at least one language (en, cs))";
    QTest::newRow("language-not-string")
        << QByteArray(R"("description": {"en": "A ball falls.", "cs": ["Míček", "padá."]})")
        << R"(description.cs: must be a string "...", got an array)";
    QTest::newRow("description-array") << QByteArray(R"("description": ["A ball", "falls."])")
                                       << R"(description: must be a string "...", got an array)";
    // Checked in every language, whichever is kept.
    QTest::newRow("other-language-bad") << QByteArray(R"("title": {"en": 5, "cs": "Pád"})")
                                        << "title.en: must be a string "
                                           "\"...\", got 5";
}

void TestLessons::rejectsBadSceneText()
{
    QFETCH(QByteArray, texts);
    QFETCH(QString, message);
    const QByteArray json = sceneWith((texts + R"(, "bodies": [])").constData());
    for (const QString& language : {QStringLiteral("en"), QStringLiteral("cs")}) {
        const lessons::SceneLoadResult result = lessons::loadSceneJson(
            json, QStringLiteral("x.json"), lessons::SceneLoadOptions{language});
        QVERIFY(!result.ok);
        QCOMPARE(result.error, QStringLiteral("x.json: ") + message);
    }
}

void TestLessons::sceneTextsDefaultToLessonLanguage()
{
    const QByteArray json = sceneWith(R"("title": {"en": "Drop", "cs": "Pád"}, "bodies": [])");
    const QString before = lessons::lessonLanguage();
    QVERIFY(lessons::setLessonLanguage(QStringLiteral("cs")));
    const lessons::SceneLoadResult cs = lessons::loadSceneJson(json, QStringLiteral("x.json"));
    QVERIFY(lessons::setLessonLanguage(QStringLiteral("en")));
    const lessons::SceneLoadResult en = lessons::loadSceneJson(json, QStringLiteral("x.json"));
    QVERIFY(lessons::setLessonLanguage(before));
    QVERIFY2(cs.ok && en.ok, qPrintable(cs.error + en.error));
    QCOMPARE(cs.scene.title, QStringLiteral("Pád"));
    QCOMPARE(en.scene.title, QStringLiteral("Drop"));
}

void TestLessons::everyField()
{
    const QByteArray json = R"({"rigidlab": 1, "title": "T", "description": "D",
      "world": {"gravity": [0.5, -3], "dt": 0.002, "integrator": "rk4",
                "solver": "seed-impulse", "iterations": 7, "restitution": 0.25,
                "friction": 0.75, "gravitation": 2, "drag": 0.125},
      "bodies": [
        {"id": "k", "type": "kinematic", "shape": {"type": "box", "width": 2, "height": 0.5},
         "position": [1, 2], "angle": 0.5, "velocity": [3, 4], "angularVelocity": -1,
         "mass": 3, "restitution": 0.9, "friction": 0.1, "collide": false},
        {"id": "p", "shape": {"type": "polygon", "vertices": [[0, 0], [1, 0], [0, 1]]},
         "density": 2}],
      "springs": [{"a": "k", "anchorA": [0.5, 0], "b": "p", "anchorB": [0, 0.5],
                   "stiffness": 100, "damping": 2, "restLength": 1.5}],
      "joints": [{"type": "pin", "a": "p", "anchorA": [0, 0], "b": null, "anchorB": [0, 0]}]})";
    const lessons::SceneLoadResult result = lessons::loadSceneJson(json, QStringLiteral("x.json"));
    QVERIFY2(result.ok, qPrintable(result.error));
    QVERIFY(result.warnings.isEmpty());
    const lessons::Scene& s = result.scene;
    QCOMPARE(s.title, QStringLiteral("T"));
    QCOMPARE(s.description, QStringLiteral("D"));
    QCOMPARE(s.world.gravity, Vec2(0.5, -3));
    QCOMPARE(s.world.dt, 0.002);
    QCOMPARE(s.world.integrator, physics::IntegratorKind::RK4);
    QCOMPARE(s.world.solver, physics::SolverKind::PaperImpulse);
    QCOMPARE(s.world.iterations, 7);
    QCOMPARE(s.world.restitution, 0.25);
    QCOMPARE(s.world.friction, 0.75);
    QCOMPARE(s.world.gravitation, 2.0);
    QCOMPARE(s.world.drag, 0.125);
    const physics::BodyDef& k = s.bodies[0];
    QCOMPARE(k.type, physics::BodyType::Kinematic);
    QVERIFY(k.shape.asPolygon());
    QCOMPARE(k.shape.asPolygon()->vertices.size(), size_t{4});
    QCOMPARE(k.position, Vec2(1, 2));
    QCOMPARE(k.angle, 0.5);
    QCOMPARE(k.velocity, Vec2(3, 4));
    QCOMPARE(k.angularVelocity, -1.0);
    QCOMPARE(k.mass, 3.0);
    QCOMPARE(k.restitution, 0.9);
    QCOMPARE(k.friction, 0.1);
    QCOMPARE(k.collide, false);
    QCOMPARE(s.bodies[1].density, 2.0);
    QCOMPARE(s.bodies[1].mass, 0.0);
    QCOMPARE(s.springs.size(), size_t{1});
    QCOMPARE(s.springs[0].a, 0);
    QCOMPARE(s.springs[0].b, 1);
    QCOMPARE(s.springs[0].anchorA, Vec2(0.5, 0));
    QCOMPARE(s.springs[0].anchorB, Vec2(0, 0.5));
    QCOMPARE(s.springs[0].stiffness, 100.0);
    QCOMPARE(s.springs[0].damping, 2.0);
    QCOMPARE(s.springs[0].restLength, 1.5);
    QCOMPARE(s.joints.size(), size_t{1});
    QCOMPARE(s.joints[0].a, 1);
    QCOMPARE(s.joints[0].b, physics::kWorld);
    QCOMPARE(s.bodyIndex(QStringLiteral("p")), std::optional<physics::BodyId>(1));
    QCOMPARE(s.bodyIndex(QStringLiteral("q")), std::optional<physics::BodyId>());
}

void TestLessons::nonConvexPolygonWarns()
{
    // An L shape: replaced by its hull, with a warning that names the place.
    const lessons::SceneLoadResult result =
        lessons::loadSceneJson(oneBody(R"("shape": {"type": "polygon",
                    "vertices": [[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]]})"),
                               QStringLiteral("x.json"));
    QVERIFY2(result.ok, qPrintable(result.error));
    QCOMPARE(result.warnings.size(), 1);
    QVERIFY2(result.warnings[0].startsWith(QStringLiteral("x.json: bodies[0].shape.vertices: ")),
             qPrintable(result.warnings[0]));
    QVERIFY(result.warnings[0].contains(QStringLiteral("convex hull")));
    QVERIFY(result.scene.bodies[0].shape.asPolygon());
    QCOMPARE(result.scene.bodies[0].shape.asPolygon()->vertices.size(), size_t{5});
}

void TestLessons::springRestLengthDefaultsToDistance()
{
    // Body origin at (3, 0) turned by 90 degrees: its local anchor (1, 0) is at (3, 1).
    const lessons::SceneLoadResult result = lessons::loadSceneJson(
        sceneWith(R"("bodies": [{"id": "b", "shape": {"type": "circle", "radius": 0.1},
                                  "position": [3, 0], "angle": 1.5707963267948966}],
                     "springs": [{"a": null, "anchorA": [0, 5], "b": "b", "anchorB": [1, 0],
                                  "stiffness": 10}])"),
        QStringLiteral("x.json"));
    QVERIFY2(result.ok, qPrintable(result.error));
    QVERIFY(isClose(result.scene.springs[0].restLength, 5.0));
    QCOMPARE(result.scene.springs[0].a, physics::kWorld);
    QCOMPARE(result.scene.springs[0].anchorA, Vec2(0, 5));
}

void TestLessons::pinAnchorBDefaultsToCoincidentPoint()
{
    const lessons::SceneLoadResult result = lessons::loadSceneJson(sceneWith(R"("bodies": [
                        {"id": "a", "shape": {"type": "circle", "radius": 0.1}, "position": [1, 0]},
                        {"id": "b", "shape": {"type": "circle", "radius": 0.1}, "position": [0, 2],
                         "angle": 1.5707963267948966}],
                     "joints": [{"type": "pin", "a": "a", "anchorA": [0, 1]},
                                {"type": "pin", "a": "a", "anchorA": [0, 1], "b": "b"},
                                {"type": "pin", "a": "a", "anchorB": [5, 5]}])"),
                                                                   QStringLiteral("x.json"));
    QVERIFY2(result.ok, qPrintable(result.error));
    const auto& joints = result.scene.joints;
    QCOMPARE(joints.size(), size_t{3});
    // To the world: the world point where a's anchor is, (1, 1).
    QVERIFY(isClose(joints[0].anchorB.x(), 1) && isClose(joints[0].anchorB.y(), 1));
    // To b: (1, 1) in b's frame (origin (0, 2), turned 90 degrees) is (-1, -1).
    QVERIFY(isClose(joints[1].anchorB.x(), -1) && isClose(joints[1].anchorB.y(), -1));
    // Anchors given apart: loaded, with a warning.
    QCOMPARE(result.warnings.size(), 1);
    QVERIFY2(result.warnings[0].startsWith(QStringLiteral("x.json: joints[2]: the anchors are ")),
             qPrintable(result.warnings[0]));
}

void TestLessons::buildWorldPlacesBodyOrigin()
{
    // A triangle whose centroid is not its origin: the world must keep the origin where the
    // file puts it.
    const lessons::SceneLoadResult result =
        lessons::loadSceneJson(sceneWith(R"("world": {"gravity": [0, 0]},
                     "bodies": [{"id": "t", "shape": {"type": "polygon",
                                 "vertices": [[0, 0], [3, 0], [0, 3]]},
                                 "position": [1, 2], "angle": 0.3},
                                {"id": "g", "type": "static",
                                 "shape": {"type": "box", "width": 1, "height": 1}}],
                     "springs": [{"a": "t", "b": null, "anchorB": [0, 10], "stiffness": 1}])"),
                               QStringLiteral("x.json"));
    QVERIFY2(result.ok, qPrintable(result.error));
    const physics::World world = lessons::buildWorld(result.scene);
    QCOMPARE(world.bodies().size(), size_t{2});
    QCOMPARE(world.springs().size(), size_t{1});
    QCOMPARE(world.bodies()[0].name, std::string("t"));
    const Vec2 origin = world.bodies()[0].origin();
    QVERIFY2(isClose(origin.x(), 1, 1e-12) && isClose(origin.y(), 2, 1e-12),
             qPrintable(QStringLiteral("origin (%1, %2)").arg(origin.x()).arg(origin.y())));
    QVERIFY(isClose(world.bodies()[0].angle, 0.3));
    QCOMPARE(world.bodies()[1].type, physics::BodyType::Static);
}

void TestLessons::formatDocumentExampleLoads()
{
    // The complete example of SCENE_FORMAT.md is the first JSON block after its heading.
    const QByteArray doc = readAll(rigidlab::test::sourcePath(u"/lessons/SCENE_FORMAT.md"));
    const qsizetype heading = doc.indexOf("## A complete example");
    QVERIFY(heading >= 0);
    const qsizetype start = doc.indexOf("```json\n", heading);
    QVERIFY(start >= 0);
    const qsizetype end = doc.indexOf("```", start + 8);
    QVERIFY(end > start);
    const lessons::SceneLoadResult result =
        lessons::loadSceneJson(doc.mid(start + 8, end - start - 8), QStringLiteral("example"));
    QVERIFY2(result.ok, qPrintable(result.error));
    QVERIFY2(result.warnings.isEmpty(), qPrintable(result.warnings.join(u'\n')));
    QCOMPARE(result.scene.bodies.size(), size_t{4});
    QCOMPARE(result.scene.springs.size(), size_t{1});
    QCOMPARE(result.scene.joints.size(), size_t{1});
    QCOMPARE(result.scene.world.sleep, std::optional<bool>(true));
    QCOMPARE(result.scene.bodyLabel(1), QStringLiteral("steel ball"));
    QCOMPARE(result.scene.bodyLabel(0), QStringLiteral("floor")); // no label: the id
    QCOMPARE(result.scene.colourOf(1), QStringLiteral("#d04030"));
}
