// SPDX-License-Identifier: GPL-3.0-or-later
// Hostile files: every limit of the scene and lesson formats is enforced with its place and
// its range (lessons/limits.h), and a lesson reads only plain files inside its own folder.

#include "test_limits.h"

#include "format/lesson.h"
#include "format/limits.h"
#include "format/scene_loader.h"
#include "rigidlab/physics/sat.h"
#include "rigidlab/physics/shape.h"

#include "near.h"
#include "test_files.h"
#include "test_main.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

#include <cmath>

using namespace rigidlab;

using rigidlab::test::writeFile;

namespace {

/// A scene whose only body holds `fields` after its id, in a world holding `world`.
QByteArray scene(const QByteArray& fields, const QByteArray& world = "{}")
{
    return R"({"rigidlab": 1, "world": )" + world +
           R"(, "bodies": [{"id": "b", "shape": {"type": "circle", "radius": 0.5})" +
           (fields.isEmpty() ? QByteArray() : ", " + fields) + "}]}";
}

/// A scene with the given shape for its only body.
QByteArray shapeScene(const QByteArray& shape)
{
    return R"({"rigidlab": 1, "bodies": [{"id": "b", "shape": )" + shape + "}]}";
}

/// A scene with bodies a and b and one spring or joint between them.
QByteArray linkScene(const QByteArray& key, const QByteArray& link)
{
    return R"({"rigidlab": 1, "bodies": [)"
           R"({"id": "a", "shape": {"type": "circle", "radius": 0.5}},)"
           R"({"id": "b", "shape": {"type": "circle", "radius": 0.5}, "position": [2, 0]}], ")" +
           key + R"(": [)" + link + "]}";
}

/// A lesson of one step whose scene is `scene` (a JSON value: a path string or an object).
QByteArray lessonWithScene(const QByteArray& scene, const QByteArray& more = {})
{
    return R"({"rigidlab-lesson": 1, "title": "t", "steps": [{"title": "s", "scene": )" + scene +
           more + "}]}";
}

} // namespace

// --- magnitudes: refused at load with the place and the allowed range ---------------

void TestLimits::magnitudesAreRefused_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");

    QTest::newRow("mass-1e300") << scene(R"("mass": 1e300)")
                                << "bodies[0].mass: must be from 1e-09 to 1e+12 kg, got 1e+300";
    QTest::newRow("mass-tiny") << scene(R"("mass": 1e-300)")
                               << "bodies[0].mass: must be from 1e-09 to 1e+12 kg, got 1e-300";
    QTest::newRow("position-1e200")
        << scene(R"("position": [0, 1e200])")
        << "bodies[0].position[1]: must be from -1e+07 to 1e+07 m, got 1e+200";
    QTest::newRow("velocity-1e200")
        << scene(R"("velocity": [-1e200, 0])")
        << "bodies[0].velocity[0]: must be from -1e+06 to 1e+06 m/s, got -1e+200";
    QTest::newRow("angle") << scene(R"("angle": 1e20)")
                           << "bodies[0].angle: must be from -1e+06 to 1e+06 rad, got 1e+20";
    QTest::newRow("angular-velocity")
        << scene(R"("angularVelocity": 1e7)")
        << "bodies[0].angularVelocity: must be from -1e+06 to 1e+06 rad/s, got 1e+07";
    QTest::newRow("density") << scene(R"("density": 1e10)")
                             << "bodies[0].density: must be from 1e-09 to 1e+09 kg/m^2, got "
                                "1e+10";
    // Each is allowed, their product is not: 1e9 kg/m² over a 1e4 m square.
    QTest::newRow("mass-from-density")
        << shapeScene(R"({"type": "box", "width": 1e4, "height": 1e4}, "density": 1e9)")
        << "bodies[0].density: the mass works out as 1e+17 kg (density times "
           "area); it must be from 1e-09 to 1e+12 kg";
    QTest::newRow("friction") << scene(R"("friction": 1000)")
                              << "bodies[0].friction: must be from 0 to 100, got 1000";
    QTest::newRow("radius") << shapeScene(R"({"type": "circle", "radius": 1e300})")
                            << "bodies[0].shape.radius: must be from 1e-06 to 1e+05 m, got "
                               "1e+300";
    QTest::newRow("radius-tiny") << shapeScene(R"({"type": "circle", "radius": 1e-300})")
                                 << "bodies[0].shape.radius: must be from 1e-06 to 1e+05 m, "
                                    "got 1e-300";
    QTest::newRow("box-width") << shapeScene(R"({"type": "box", "width": 1e6, "height": 1})")
                               << "bodies[0].shape.width: must be from 1e-06 to 1e+05 m, got "
                                  "1e+06";
    QTest::newRow("vertex")
        << shapeScene(R"({"type": "polygon", "vertices": [[0, 0], [1e9, 0], [0, 1]]})")
        << "bodies[0].shape.vertices[1][0]: must be from -1e+05 to 1e+05 m, got 1e+09";
    QTest::newRow("gravity") << scene("", R"({"gravity": [0, -1e300]})")
                             << "world.gravity[1]: must be from -10000 to 10000 m/s^2, got "
                                "-1e+300";
    QTest::newRow("gravitation")
        << scene("", R"({"gravitation": 1e30})")
        << "world.gravitation: must be from 0 to 1e+06 m^3/(kg s^2), got 1e+30";
    QTest::newRow("drag") << scene("", R"({"drag": 1e5})")
                          << "world.drag: must be from 0 to 10000 1/s, got 1e+05";
    QTest::newRow("world-friction")
        << scene("", R"({"friction": 101})") << "world.friction: must be from 0 to 100, got 101";
    QTest::newRow("tolerance") << scene("", R"({"tolerance": 1e-300})")
                               << "world.tolerance: must be from 1e-15 to 1, got 1e-300";
    QTest::newRow("stiffness") << linkScene("springs",
                                            R"({"a": "a", "b": "b", "stiffness": 1e300})")
                               << "springs[0].stiffness: must be from 0 to 1e+10 N/m, got 1e+300";
    QTest::newRow("damping") << linkScene("springs", R"({"a": "a", "b": "b", "damping": 1e9})")
                             << "springs[0].damping: must be from 0 to 1e+08 N s/m, got "
                                "1e+09";
    QTest::newRow("rest-length") << linkScene("springs",
                                              R"({"a": "a", "b": "b", "restLength": 1e8})")
                                 << "springs[0].restLength: must be from 0 to 1e+07 m, got 1e+08";
    QTest::newRow("spring-anchor")
        << linkScene("springs", R"({"a": "a", "b": null, "anchorB": [1e300, 0]})")
        << "springs[0].anchorB[0]: must be from -1e+07 to 1e+07 m, got 1e+300";
    QTest::newRow("joint-anchor")
        << linkScene("joints", R"({"type": "pin", "a": "a", "anchorA": [0, -2e7]})")
        << "joints[0].anchorA[1]: must be from -1e+07 to 1e+07 m, got -2e+07";
}
void TestLimits::magnitudesAreRefused()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    const lessons::SceneLoadResult r = lessons::loadSceneJson(json, QStringLiteral("x.json"));
    QVERIFY2(!r.ok, json.constData());
    QCOMPARE(r.error, QStringLiteral("x.json: ") + message);
}

void TestLimits::valuesAtTheLimitsLoadAndStayFinite()
{
    // Every bound at once, at its edge: the world builds with finite energy and steps.
    const QByteArray json =
        R"({"rigidlab": 1,)"
        R"("world": {"gravity": [1e4, -1e4], "gravitation": 1e6, "drag": 1e4, "friction": 100,)"
        R"("tolerance": 1e-15},)"
        R"("bodies": [)"
        R"({"id": "a", "shape": {"type": "circle", "radius": 1e5}, "mass": 1e12,)"
        R"("position": [1e7, -1e7], "velocity": [1e6, -1e6], "angle": 1e6,)"
        R"("angularVelocity": -1e6, "friction": 100},)"
        R"({"id": "b", "shape": {"type": "polygon", "vertices": [[-1e5, 0], [1e5, 0], [0, 1e5]]},)"
        R"("mass": 1e-9, "position": [-1e7, 1e7]},)"
        R"({"id": "c", "shape": {"type": "box", "width": 1e-6, "height": 1e-6},)"
        R"("density": 1e9}],)"
        R"("springs": [{"a": "a", "b": "b", "stiffness": 1e10, "damping": 1e8, "restLength": 1e7}])"
        R"(})";
    const lessons::SceneLoadResult r = lessons::loadSceneJson(json, QStringLiteral("x.json"));
    QVERIFY2(r.ok, qPrintable(r.error));
    physics::World world = lessons::buildWorld(r.scene);
    world.updateDiagnostics();
    QVERIFY(std::isfinite(world.diagnostics().total));
    QVERIFY(std::isfinite(world.diagnostics().angularMomentum));
    world.step(); // may diverge (it is meant to be extreme), but never crashes
}

// --- size, count and nesting ---------------------------------------------------------

void TestLimits::deepNestingIsRefused()
{
    const QByteArray deep = R"({"rigidlab": 1, "bodies": [], "title": )" +
                            QByteArray(lessons::limits::kMaxJsonDepth, '[') +
                            QByteArray(lessons::limits::kMaxJsonDepth, ']') + "}";
    const lessons::SceneLoadResult r = lessons::loadSceneJson(deep, QStringLiteral("x.json"));
    QCOMPARE(r.error, QStringLiteral("x.json: line 1, column 71: arrays and objects nested "
                                     "deeper than 32 levels (the limit)"));
    // A million brackets: refused at once, never handed to a recursive parser.
    const QByteArray hostile = QByteArray(1000000, '[');
    QVERIFY(lessons::loadSceneJson(hostile, QStringLiteral("x.json"))
                .error.contains(QStringLiteral("nested deeper than 32 levels")));
    // Brackets inside strings are text, not nesting.
    const QByteArray inString =
        R"({"rigidlab": 1, "bodies": [], "title": ")" + QByteArray(100, '[') + R"(\"[{"})";
    const lessons::SceneLoadResult text =
        lessons::loadSceneJson(inString, QStringLiteral("x.json"));
    QVERIFY2(text.ok, qPrintable(text.error));
    QCOMPARE(text.scene.title.size(), 103);
    // The same limit for lessons.
    const QByteArray lesson =
        R"({"rigidlab-lesson": 1, "summary": )" + QByteArray(40, '[') + QByteArray(40, ']') + "}";
    QVERIFY(lessons::loadLessonJson(lesson, QStringLiteral("l.json"))
                .error.contains(QStringLiteral("nested deeper than 32 levels")));
}

void TestLimits::messagesAreOneLine()
{
    // What the file puts in a message (a key, a name, an id) cannot break it into lines.
    const lessons::SceneLoadResult key = lessons::loadSceneJson(
        R"({"rigidlab": 1, "bodies": [], "a\nb\u0001": 1})", QStringLiteral("x.json"));
    QVERIFY(key.error.startsWith(QStringLiteral(R"(x.json: a\nb\u0001: unknown key)")));
    const lessons::SceneLoadResult type =
        lessons::loadSceneJson(scene(R"("type": "dyn\r\namic")"), QStringLiteral("x.json"));
    QVERIFY2(type.error.startsWith(
                 QStringLiteral(R"(x.json: bodies[0].type: unknown body type "dyn\r\namic")")),
             qPrintable(type.error));
    QVERIFY(!type.error.contains(u'\n') && !type.error.contains(u'\r'));
}

void TestLimits::oversizedFilesAreRefused()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("big.json"));
    QByteArray big = R"({"rigidlab": 1, "bodies": [], "description": ")";
    big += QByteArray(lessons::kMaxSceneFileBytes, 'x');
    big += "\"}";
    QVERIFY(writeFile(path, big));
    const lessons::SceneLoadResult r = lessons::loadSceneFile(path);
    QVERIFY(!r.ok);
    QVERIFY2(r.error.contains(QStringLiteral("too large")) &&
                 r.error.contains(QStringLiteral("8 MiB")),
             qPrintable(r.error));
    QVERIFY(lessons::loadLessonFile(path).error.contains(QStringLiteral("too large")));
    // A polygon's vertices and the number of bodies have their limits too.
    QByteArray vertices;
    for (int i = 0; i <= lessons::kMaxPolygonVertices; ++i) {
        const double a = 2 * M_PI * i / (lessons::kMaxPolygonVertices + 1);
        vertices += (i ? "," : "") + QByteArray("[") + QByteArray::number(std::cos(a)) + "," +
                    QByteArray::number(std::sin(a)) + "]";
    }
    QCOMPARE(
        lessons::loadSceneJson(shapeScene(R"({"type": "polygon", "vertices": [)" + vertices + "]}"),
                               QStringLiteral("x.json"))
            .error,
        QStringLiteral("x.json: bodies[0].shape.vertices: a polygon needs 3 to 64 "
                       "vertices, got 65"));
}

void TestLimits::lessonBodiesAreCountedOverItsSteps()
{
    // One scene file of 8000 bodies is fine; three steps reading it are 24000 in all.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QByteArray bodies;
    for (int i = 0; i < 8000; ++i)
        bodies += (i ? "," : "") + QByteArray(R"({"id": "b)") + QByteArray::number(i) +
                  R"(", "shape": {"type": "circle", "radius": 0.1}, "position": [)" +
                  QByteArray::number(i) + ", 0]}";
    QVERIFY(writeFile(dir.filePath(QStringLiteral("many.json")),
                      R"({"rigidlab": 1, "bodies": [)" + bodies + "]}"));
    QByteArray steps;
    for (int i = 0; i < 3; ++i)
        steps += (i ? "," : "") + QByteArray(R"({"title": "s", "scene": "many.json"})");
    const QString path = dir.filePath(QStringLiteral("lesson.json"));
    QVERIFY(writeFile(path, R"({"rigidlab-lesson": 1, "title": "t", "steps": [)" + steps + "]}"));
    const lessons::LessonLoadResult r = lessons::loadLessonFile(path);
    QCOMPARE(r.error, path + QStringLiteral(": steps[2].scene: the steps up to this one hold "
                                            "24000 bodies in all, more than the limit of "
                                            "20000 for a lesson"));
}

void TestLimits::lessonMagnitudesAreRefused_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");
    const QByteArray ball =
        R"({"rigidlab": 1, "bodies": [{"id": "b", "shape": {"type": "circle", "radius": 1}}]})";
    QTest::newRow("settings-friction")
        << lessonWithScene(ball, R"(, "settings": {"friction": 1e300})")
        << "steps[0].settings.friction: must be from 0 to 100, got 1e+300";
    QTest::newRow("compare-offset")
        << lessonWithScene(ball, R"(, "compare": {"integrators": ["euler", "rk4"],)"
                                 R"("offset": [1e300, 0]})")
        << "steps[0].compare.offset[0]: must be from -1e+07 to 1e+07 m, got 1e+300";
    QTest::newRow("measure-above")
        << lessonWithScene(ball, R"(, "questions": [{"prompt": "p",)"
                                 R"("measure": {"kind": "apex", "body": "b", "above": -1e300}}])")
        << "steps[0].questions[0].measure.above: must be from -1e+07 to 1e+07 m, got -1e+300";
    QTest::newRow("absolute-tolerance")
        << lessonWithScene(
               ball,
               R"(, "questions": [{"prompt": "p",)"
               R"("measure": {"kind": "speed", "body": "b", "time": 1}, "absoluteTolerance": 1e300}])")
        << "steps[0].questions[0].absoluteTolerance: must be from 0 to 1e+09, got 1e+300";
    QTest::newRow("inline-scene-mass")
        << lessonWithScene(R"({"rigidlab": 1, "bodies": [{"id": "b", "mass": 1e300,)"
                           R"("shape": {"type": "circle", "radius": 1}}]})")
        << "steps[0].scene.bodies[0].mass: must be from 1e-09 to 1e+12 kg, got 1e+300";
}
void TestLimits::lessonMagnitudesAreRefused()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    const lessons::LessonLoadResult r = lessons::loadLessonJson(json, QStringLiteral("l.json"));
    QVERIFY(!r.ok);
    QCOMPARE(r.error, QStringLiteral("l.json: ") + message);
}

// --- geometry at the limits ------------------------------------------------------------

void TestLimits::sliverDeepInsideAPolygonHasAContact()
{
    // Found by fuzz_sat: a sliver triangle (one edge 7e-7 m long) deep inside a large
    // polygon, both at the far corner of the allowed world. The SAT says they intersect;
    // clipping the incident edge to the tiny reference face keeps nothing, and the manifold
    // used to come back empty, so the solver never pushed them apart.
    auto a = physics::makePolygon({{-0.34987670006560634, -5.0918696812662088},
                                   {-22.392248644060906, -22.392248987356872},
                                   {-22.39224794975356, -22.392248987387433}});
    auto b = physics::makePolygon({{-71.276180403643068, -71.276180403643068},
                                   {-0.056692388901329799, -71.276180403643068},
                                   {37.151643862123365, -71.276180403642584},
                                   {50.295847444480806, -25.735827684386106},
                                   {61.013990244173328, 41.095164138100344},
                                   {-2.0136028130011097, 70.393384394076435},
                                   {-36.488755529728024, 71.187418037283479},
                                   {-51.199895267559718, 71.276180403642172},
                                   {-71.276180370452508, 71.272272769084509},
                                   {-71.276180403643068, -14.744409936363652}});
    QVERIFY(a && b);
    const physics::Transform xf(physics::Vec2(-1e7, -1e7),
                                std::atan2(0.7568024953079282, -0.65364362086361194));
    for (const double margin : {0.0, 1e-8}) {
        const physics::SatResult r =
            physics::satPolygons(a.value().polygon, xf, b.value().polygon, xf, margin);
        QVERIFY(r.intersects);
        QVERIFY(r.depth > 60);
        QCOMPARE(r.manifold.pointCount, 1);
        QVERIFY(r.manifold.points[0].separation < -60);
        RL_VERIFY_NEAR(r.manifold.normal.norm(), 1, 1e-12, 0);
    }
}

// --- paths: only plain files inside the lesson's folder; nothing is run ----------------

void TestLimits::scenePathsStayInside_data()
{
    QTest::addColumn<QString>("scenePath");
    QTest::addColumn<QString>("message");
    QTest::newRow("parent")
        << "../outside/secret.json"
        << R"(must not leave the lesson's folder, got "../outside/secret.json")";
    QTest::newRow("parent-inside")
        << "scenes/../../outside/secret.json"
        << R"(must not leave the lesson's folder, got "scenes/../../outside/secret.json")";
    QTest::newRow("absolute")
        << "/etc/passwd"
        << R"(must be a path relative to the lesson's folder, got "/etc/passwd")";
    QTest::newRow("drive")
        << "C:secret.json"
        << R"(must be a path relative to the lesson's folder, got "C:secret.json")";
    QTest::newRow("backslash") << "..\\outside\\secret.json"
                               << R"(use '/' between folders, got "..\outside\secret.json")";
    QTest::newRow("control") << "ok.json\n../x"
                             << "must not hold control characters";
    QTest::newRow("link-to-file")
        << "link.json"
        << R"("link.json" leads out of the lesson's folder (through a symbolic link))";
    QTest::newRow("link-to-folder")
        << "linked/secret.json"
        << R"("linked/secret.json" leads out of the lesson's folder (through a symbolic link))";
    QTest::newRow("folder") << "scenes"
                            << R"("scenes" is not a plain file)";
    QTest::newRow("fifo") << "pipe.json"
                          << R"("pipe.json" is not a plain file)";
}
void TestLimits::scenePathsStayInside()
{
    QFETCH(QString, scenePath);
    QFETCH(QString, message);
    QTemporaryDir root;
    QVERIFY(root.isValid());
    const QDir top(root.path());
    QVERIFY(top.mkpath(QStringLiteral("lesson/scenes")) && top.mkpath(QStringLiteral("outside")));
    const QByteArray good =
        R"({"rigidlab": 1, "bodies": [{"id": "b", "shape": {"type": "circle", "radius": 1}}]})";
    QVERIFY(writeFile(top.filePath(QStringLiteral("outside/secret.json")), good));
    QVERIFY(writeFile(top.filePath(QStringLiteral("lesson/scenes/ok.json")), good));
    QVERIFY(QFile::link(top.filePath(QStringLiteral("outside/secret.json")),
                        top.filePath(QStringLiteral("lesson/link.json"))));
    QVERIFY(QFile::link(top.filePath(QStringLiteral("outside")),
                        top.filePath(QStringLiteral("lesson/linked"))));
    QVERIFY(mkfifo(QFile::encodeName(top.filePath(QStringLiteral("lesson/pipe.json"))), 0600) == 0);

    QString escaped = scenePath;
    escaped.replace(u'\\', QStringLiteral("\\\\")).replace(u'\n', QStringLiteral("\\n"));
    const QString path = top.filePath(QStringLiteral("lesson/lesson.json"));
    QVERIFY(writeFile(path, lessonWithScene('"' + escaped.toUtf8() + '"')));
    const lessons::LessonLoadResult r = lessons::loadLessonFile(path);
    QVERIFY(!r.ok);
    QCOMPARE(r.error, path + QStringLiteral(": steps[0].scene: ") + message);

    // A link that stays inside the folder is fine, and so is a plain relative path.
    QVERIFY(QFile::link(top.filePath(QStringLiteral("lesson/scenes/ok.json")),
                        top.filePath(QStringLiteral("lesson/inside.json"))));
    for (const char* fine : {"scenes/ok.json", "inside.json", "./scenes/ok.json"}) {
        QVERIFY(writeFile(path, lessonWithScene('"' + QByteArray(fine) + '"')));
        const lessons::LessonLoadResult ok = lessons::loadLessonFile(path);
        QVERIFY2(ok.ok, qPrintable(ok.error));
    }
}

void TestLimits::scenePathsStayInsideTheDataFolder_data()
{
    // A lesson in the lessons/ folder of a data folder (one that holds scenes/ too) reads the
    // data folder's scenes, and nothing above it.
    QTest::addColumn<QString>("scenePath");
    QTest::addColumn<QString>("message");
    const QString data = QStringLiteral("must not leave the data folder (scenes/ and lessons/)");
    QTest::newRow("shared-scene") << "../scenes/ok.json" << QString();
    QTest::newRow("own-folder") << "mine.json" << QString();
    QTest::newRow("through-lessons") << "../lessons/../scenes/ok.json" << QString();
    QTest::newRow("above-data") << "../../outside/secret.json"
                                << data + R"(, got "../../outside/secret.json")";
    QTest::newRow("above-data-inside") << "../scenes/../../outside/secret.json"
                                       << data + R"(, got "../scenes/../../outside/secret.json")";
    QTest::newRow("link-out-of-data")
        << "../scenes/link.json"
        << R"("../scenes/link.json" leads out of the data folder (scenes/ and lessons/) )"
           "(through a symbolic link)";
}

void TestLimits::scenePathsStayInsideTheDataFolder()
{
    QFETCH(QString, scenePath);
    QFETCH(QString, message);
    QTemporaryDir root;
    QVERIFY(root.isValid());
    const QDir top(root.path());
    QVERIFY(top.mkpath(QStringLiteral("data/scenes")) &&
            top.mkpath(QStringLiteral("data/lessons")) && top.mkpath(QStringLiteral("outside")));
    const QByteArray good =
        R"({"rigidlab": 1, "bodies": [{"id": "b", "shape": {"type": "circle", "radius": 1}}]})";
    for (const char* file :
         {"outside/secret.json", "data/scenes/ok.json", "data/lessons/mine.json"})
        QVERIFY(writeFile(top.filePath(QLatin1StringView(file)), good));
    QVERIFY(QFile::link(top.filePath(QStringLiteral("outside/secret.json")),
                        top.filePath(QStringLiteral("data/scenes/link.json"))));

    const QString path = top.filePath(QStringLiteral("data/lessons/lesson.json"));
    QVERIFY(writeFile(path, lessonWithScene('"' + scenePath.toUtf8() + '"')));
    const lessons::LessonLoadResult r = lessons::loadLessonFile(path);
    if (message.isEmpty()) {
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(QFileInfo(r.lesson.steps.front().scenePath).canonicalFilePath(),
                 QFileInfo(QDir(top.filePath(QStringLiteral("data/lessons"))).filePath(scenePath))
                     .canonicalFilePath());
    } else {
        QVERIFY(!r.ok);
        QCOMPARE(r.error, path + QStringLiteral(": steps[0].scene: ") + message);
    }

    // Without scenes/ beside it, lessons/ is just a folder: the same lesson may not go up.
    QVERIFY(QDir(top.filePath(QStringLiteral("data/scenes"))).removeRecursively());
    if (scenePath.startsWith(u"../")) {
        const lessons::LessonLoadResult alone = lessons::loadLessonFile(path);
        QVERIFY(!alone.ok);
        QVERIFY2(alone.error.contains(QStringLiteral("must not leave the lesson's folder")),
                 qPrintable(alone.error));
    }
}

void TestLimits::nothingInAFileIsRun()
{
    // A "scene" that is a shell script beside the lesson, executable and named as a scene:
    // it is read as text, refused as JSON, and never run (it would leave a mark).
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString mark = dir.filePath(QStringLiteral("ran"));
    const QString script = dir.filePath(QStringLiteral("scene.json"));
    QVERIFY(writeFile(script, "#!/bin/sh\ntouch '" + mark.toUtf8() + "'\n"));
    QVERIFY(QFile::setPermissions(script, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner));
    const QString path = dir.filePath(QStringLiteral("lesson.json"));
    QVERIFY(writeFile(path, lessonWithScene(R"("scene.json")")));
    const lessons::LessonLoadResult r = lessons::loadLessonFile(path);
    QVERIFY(!r.ok);
    QVERIFY2(r.error.contains(QStringLiteral(": line 1, column ")), qPrintable(r.error));
    QVERIFY(!lessons::loadSceneFile(script).ok);
    QVERIFY(!QFileInfo::exists(mark));
    // Names in a lesson are looked up, never evaluated: a command where a name belongs is
    // an unknown name.
    const QByteArray ball =
        R"({"rigidlab": 1, "bodies": [{"id": "b", "shape": {"type": "circle", "radius": 1}}]})";
    const lessons::LessonLoadResult named =
        lessons::loadLessonJson(lessonWithScene(ball, R"x(, "plots": ["$(touch ran)"])x"), path);
    QVERIFY(named.error.contains(QStringLiteral("unknown plot \"$(touch ran)\"")));
    QVERIFY(!QFileInfo::exists(mark));
}

RIGIDLAB_TEST_GUILESS_MAIN(TestLimits)
