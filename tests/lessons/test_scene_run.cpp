// SPDX-License-Identifier: GPL-3.0-or-later
// The shipped scenes, validation, the headless runner and the SAT report.

#include "test_lessons.h"

#include "format/document.h"
#include "format/sat_report.h"
#include "run/scene_run.h"
#include "run/swept_bounds.h"

#include "near.h"
#include "test_main.h"

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

using namespace rigidlab;
using namespace rigidlab::test;
using physics::Vec2;

void TestLessons::shippedScenesLoad_data()
{
    QTest::addColumn<QString>("path");
    const QStringList required = {
        QStringLiteral("ball_drop"),       QStringLiteral("two_ball_collision"),
        QStringLiteral("offcentre_rod"),   QStringLiteral("newtons_cradle"),
        QStringLiteral("billiards_break"), QStringLiteral("box_stack"),
        QStringLiteral("pendulum"),        QStringLiteral("spring_oscillator"),
        QStringLiteral("two_body_orbit"),  QStringLiteral("welcome"),
    };
    const QStringList files =
        QDir(kScenesDir).entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    for (const QString& name : required) {
        QVERIFY2(files.contains(name + QStringLiteral(".json")), qPrintable(name));
    }
    for (const QString& file : files) {
        QTest::newRow(qPrintable(file)) << QDir(kScenesDir).filePath(file);
    }
}

void TestLessons::shippedScenesLoad()
{
    QFETCH(QString, path);
    const lessons::SceneLoadResult result = lessons::loadSceneFile(path);
    QVERIFY2(result.ok, qPrintable(result.error));
    // The separating axis lesson's non-convex polygon is there to be replaced by its hull,
    // and warned of; every other shipped scene is clean.
    if (path.endsWith(QStringLiteral("sat_non_convex.json")))
        QVERIFY2(result.warnings.size() == 1 &&
                     result.warnings.front().contains(QStringLiteral("not convex")),
                 qPrintable(result.warnings.join(u'\n')));
    else
        QVERIFY2(result.warnings.isEmpty(), qPrintable(result.warnings.join(u'\n')));
    QVERIFY(!result.scene.title.isEmpty());
    QVERIFY2(result.scene.description.size() >= 80, "a description a teacher can use");
    QVERIFY(!result.scene.bodies.empty());
    // A short run stays finite.
    lessons::RunOptions options;
    options.time = 0.2;
    const lessons::RunReport report = lessons::runScene(result.scene, options, path);
    QVERIFY2(report.status == lessons::RunStatus::Ok, qPrintable(report.error));
    // The summary names the solver that ran, the scene's.
    const QString summary = report.summary(path);
    QCOMPARE(report.solver, result.scene.world.solver);
    const QString ran =
        QStringLiteral("the %1 solver.").arg(QLatin1String(physics::solverName(report.solver)));
    QVERIFY2(summary.contains(ran), qPrintable(summary));
}

void TestLessons::summaryBooksContactsThatAddEnergy()
{
    // A kinematic paddle pushes a resting ball: the contacts pass energy on to it, and the
    // summary says they added it, never that they "took" a negative amount.
    const lessons::SceneLoadResult loaded =
        lessons::loadSceneJson(test::sceneWith(R"("world": {"gravity": [0, 0], "dt": 0.002},
            "bodies": [
              {"id": "ball", "shape": {"type": "circle", "radius": 0.1}, "position": [0, 0]},
              {"id": "paddle", "type": "kinematic", "shape": {"type": "box", "width": 0.2,
               "height": 0.4}, "position": [-0.5, 0], "velocity": [2, 0]}])"),
                               QStringLiteral("paddle.json"));
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    lessons::RunOptions options;
    options.time = 0.5;
    const lessons::RunReport report = lessons::runScene(loaded.scene, options, "paddle.json");
    QVERIFY2(report.status == lessons::RunStatus::Ok, qPrintable(report.error));
    QVERIFY2(report.collisionLoss < 0, qPrintable(QString::number(report.collisionLoss)));
    const QString summary = report.summary(QStringLiteral("paddle.json"));
    QVERIFY2(summary.contains(QStringLiteral("; contacts added ")), qPrintable(summary));
    QVERIFY2(!summary.contains(QStringLiteral("contacts took")), qPrintable(summary));
}

void TestLessons::validateRecognisesScenes()
{
    const lessons::DocumentCheck check =
        lessons::checkDocumentFile(QDir(kScenesDir).filePath(QStringLiteral("pendulum.json")));
    QVERIFY2(check.ok, qPrintable(check.error));
    QCOMPARE(check.kind, QStringLiteral("scene"));
    QCOMPARE(check.summary, QStringLiteral("1 body, 0 springs, 1 joint"));

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("other.json"));
    QVERIFY(writeFile(path, R"({"name": "not ours"})"));
    const lessons::DocumentCheck other = lessons::checkDocumentFile(path);
    QVERIFY(!other.ok);
    QCOMPARE(other.error, path + QStringLiteral(": not a RigidLab document: no format version key "
                                                "(\"rigidlab\" for a scene, "
                                                "\"rigidlab-lesson\" for a lesson, "
                                                "\"rigidlab-lesson-file\" for a lesson in one "
                                                "file (.rlesson))"));
}

void TestLessons::runWritesHeadersAndRows()
{
    QTemporaryDir dir;
    const lessons::SceneLoadResult loaded = lessons::loadSceneJson(
        sceneWith(R"("bodies": [{"id": "a,\"b\"", "shape": {"type": "circle", "radius": 0.1}},
                                {"id": "floor", "type": "static", "position": [0, -5],
                                 "shape": {"type": "box", "width": 10, "height": 1}},
                                {"id": "c", "shape": {"type": "circle", "radius": 0.1},
                                 "position": [1, 0]}])"),
        QStringLiteral("x.json"));
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    lessons::RunOptions options;
    options.steps = 10;
    options.every = 4;
    options.tracePath = dir.filePath(QStringLiteral("t.csv"));
    options.diagnosticsPath = dir.filePath(QStringLiteral("d.csv"));
    const lessons::RunReport report =
        lessons::runScene(loaded.scene, options, QStringLiteral("x.json"));
    QVERIFY2(report.status == lessons::RunStatus::Ok, qPrintable(report.error));
    QCOMPARE(report.steps, 10);

    const QList<QByteArray> trace = readAll(options.tracePath).split('\n');
    QCOMPARE(trace.front(), lessons::traceHeader().join(u',').toUtf8());
    QCOMPARE(trace.back(), QByteArray()); // ends with a line break
    // Steps 0, 4, 8 and the last, 10; the two dynamic bodies each; the static one never.
    QCOMPARE(trace.size(), 1 + 4 * 2 + 1);
    QVERIFY(trace[1].startsWith("0,0,\"a,\"\"b\"\"\",0,0,0,"));
    QVERIFY(trace[2].startsWith("0,0,c,1,0,0,"));
    QVERIFY(trace[3].startsWith("4,"));
    QVERIFY(trace[7].startsWith("10,"));
    QCOMPARE(trace[7].count(','), 8 + 1); // the quoted id holds a comma
    QCOMPARE(trace[8].count(','), 8);

    const QList<QByteArray> diagnostics = readAll(options.diagnosticsPath).split('\n');
    QCOMPARE(diagnostics.front(), lessons::diagnosticsHeader().join(u',').toUtf8());
    QCOMPARE(diagnostics.size(), 1 + 4 + 1);
    QVERIFY(diagnostics[1].startsWith("0,0,0,"));
    QVERIFY(diagnostics[4].startsWith("10,"));
    QCOMPARE(diagnostics[4].count(','), 10);
}

void TestLessons::runIsDeterministic()
{
    QTemporaryDir dir;
    const lessons::SceneLoadResult loaded =
        lessons::loadSceneFile(QDir(kScenesDir).filePath(QStringLiteral("box_stack.json")));
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    QByteArray traces[2];
    for (int i = 0; i < 2; ++i) {
        lessons::RunOptions options;
        options.time = 0.5;
        options.tracePath = dir.filePath(QStringLiteral("t%1.csv").arg(i));
        const lessons::RunReport report =
            lessons::runScene(loaded.scene, options, QStringLiteral("box_stack.json"));
        QVERIFY2(report.status == lessons::RunStatus::Ok, qPrintable(report.error));
        traces[i] = readAll(options.tracePath);
    }
    QVERIFY(traces[0].size() > 1000);
    QVERIFY(traces[0] == traces[1]);
}

void TestLessons::runStopsOnNonFinite()
{
    // A stiff spring under explicit Euler with a huge step: |amplification| = sqrt(1 + (w h)^2)
    // with w h = 1000, so the state overflows within about a hundred steps.
    QTemporaryDir dir;
    const lessons::SceneLoadResult loaded = lessons::loadSceneJson(
        sceneWith(R"("world": {"integrator": "euler", "dt": 0.1, "gravity": [0, 0]},
                     "bodies": [{"id": "m", "shape": {"type": "circle", "radius": 0.1},
                                 "mass": 0.001, "position": [1, 0]}],
                     "springs": [{"a": "m", "b": null, "stiffness": 100000, "restLength": 0.5}])"),
        QStringLiteral("x.json"));
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    lessons::RunOptions options;
    options.steps = 5000;
    options.tracePath = dir.filePath(QStringLiteral("t.csv"));
    options.diagnosticsPath = dir.filePath(QStringLiteral("d.csv"));
    const lessons::RunReport report =
        lessons::runScene(loaded.scene, options, QStringLiteral("x.json"));
    QCOMPARE(report.status, lessons::RunStatus::NonFinite);
    QVERIFY2(report.error.startsWith(QStringLiteral("x.json: the simulation blew up at step ")),
             qPrintable(report.error));
    // The world's diagnosis: when, with which dt and integrator, which body and quantity.
    QVERIFY2(report.error.contains(QStringLiteral("diverged at t = ")) &&
                 report.error.contains(QStringLiteral("dt = 0.1 s, euler")) &&
                 report.error.contains(QStringLiteral("body \"m\"")) &&
                 report.error.contains(QStringLiteral("; nothing was written")),
             qPrintable(report.error));
    QVERIFY(!QFile::exists(options.tracePath));
    QVERIFY(!QFile::exists(options.diagnosticsPath));
    QVERIFY(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).isEmpty());
}

void TestLessons::runFailsOnUnwritableOutput()
{
    QTemporaryDir dir;
    const lessons::SceneLoadResult loaded = lessons::loadSceneJson(
        oneBody(R"("shape": {"type": "circle", "radius": 0.1})"), QStringLiteral("x.json"));
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    lessons::RunOptions options;
    options.steps = 10;
    options.diagnosticsPath = dir.filePath(QStringLiteral("d.csv"));
    options.tracePath = QStringLiteral("/nonexistent/dir/x.csv");
    const lessons::RunReport report =
        lessons::runScene(loaded.scene, options, QStringLiteral("x.json"));
    QCOMPARE(report.status, lessons::RunStatus::OutputError);
    QVERIFY2(report.error.startsWith(QStringLiteral("x.json: cannot write /nonexistent/dir/x.csv")),
             qPrintable(report.error));
    QVERIFY(!QFile::exists(options.diagnosticsPath));
    QVERIFY(!QFile::exists(options.tracePath));

    options.tracePath = options.diagnosticsPath;
    const lessons::RunReport same =
        lessons::runScene(loaded.scene, options, QStringLiteral("x.json"));
    QCOMPARE(same.status, lessons::RunStatus::BadOptions);
}

void TestLessons::stepsForTime_data()
{
    QTest::addColumn<double>("time");
    QTest::addColumn<double>("dt");
    QTest::addColumn<long long>("steps");
    QTest::newRow("5s-at-1ms") << 5.0 << 0.001 << 5000LL;
    QTest::newRow("0.3s-at-0.1s") << 0.3 << 0.1 << 3LL;
    QTest::newRow("zero") << 0.0 << 0.001 << 0LL;
    QTest::newRow("rounds-up") << 0.25 << 0.1 << 3LL;
    QTest::newRow("1s-at-1/60") << 1.0 << 1.0 / 60 << 60LL;
}

void TestLessons::stepsForTime()
{
    QFETCH(double, time);
    QFETCH(double, dt);
    QFETCH(long long, steps);
    QCOMPARE(lessons::stepsForTime(time, dt), steps);
}

void TestLessons::satReport()
{
    // Two unit squares, the second shifted by (0.75, 0.25): they overlap by 0.25 along x.
    const lessons::SatReport overlapping = lessons::satReportJson(
        R"({"a": {"vertices": [[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]]},
            "b": {"vertices": [[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]],
                  "position": [0.75, 0.25], "angle": 0}})",
        QStringLiteral("pair.json"));
    QVERIFY2(overlapping.ok, qPrintable(overlapping.error));
    const QJsonObject o = QJsonDocument::fromJson(overlapping.json).object();
    for (const char* key :
         {"intersects", "axes", "separatingAxis", "leastAxis", "normal", "depth", "contacts"}) {
        QVERIFY2(o.contains(QLatin1StringView(key)), key);
    }
    QCOMPARE(o[u"intersects"].toBool(), true);
    QVERIFY(o[u"separatingAxis"].isNull());
    QCOMPARE(o[u"axes"].toArray().size(), 8);
    RL_VERIFY_NEAR(o[u"depth"].toDouble(), 0.25, 1e-12, 0.0);
    RL_VERIFY_NEAR(o[u"normal"].toArray()[0].toDouble(), 1.0, 1e-12, 0.0);
    QVERIFY(!o[u"contacts"].toArray().isEmpty());
    const QJsonObject axis = o[u"axes"].toArray()[0].toObject();
    for (const char* key : {"owner", "edge", "axis", "a", "b", "overlap"}) {
        QVERIFY2(axis.contains(QLatin1StringView(key)), key);
    }

    // An array of pairs gives an array; separated pairs give a separating axis and no normal.
    const lessons::SatReport separated = lessons::satReportJson(
        R"([{"a": {"vertices": [[0, 0], [1, 0], [0, 1]]},
             "b": {"vertices": [[0, 0], [1, 0], [0, 1]], "position": [3, 0]}}])",
        QStringLiteral("pairs.json"));
    QVERIFY2(separated.ok, qPrintable(separated.error));
    const QJsonArray list = QJsonDocument::fromJson(separated.json).array();
    QCOMPARE(list.size(), 1);
    const QJsonObject s = list[0].toObject();
    QCOMPARE(s[u"intersects"].toBool(), false);
    QVERIFY(s[u"separatingAxis"].isDouble());
    QVERIFY(s[u"normal"].isNull());
    QVERIFY(s[u"depth"].isNull());
    QVERIFY(s[u"contacts"].toArray().isEmpty());
    const int index = s[u"separatingAxis"].toInt();
    QVERIFY(s[u"axes"].toArray()[index].toObject()[u"overlap"].toDouble() < 0);
}

void TestLessons::satReportRejects_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");
    const char* square = R"({"vertices": [[0, 0], [1, 0], [1, 1], [0, 1]]})";
    QTest::newRow("b-missing") << QByteArray(R"({"a": )") + square + "}"
                               << "pair.json: b: required, but missing";
    QTest::newRow("unknown-key") << QByteArray(R"({"a": )") + square + R"(, "b": )" + square +
                                        R"(, "c": 1})"
                                 << "pair.json: c: unknown key (allowed here: a, b)";
    QTest::newRow("collinear-in-array")
        << QByteArray(R"([{"a": )") + square + R"(, "b": {"vertices": [[0, 0], [1, 0], [2, 0]]}}])"
        << "pair.json: [0].b.vertices: the polygon has no area (its vertices are repeated or on "
           "one line)";
    QTest::newRow("angle-not-number")
        << QByteArray(R"({"a": )") + square + R"(, "b": {"vertices": [[0, 0], [1, 0], [0, 1]],
                                                          "angle": "90deg"}})"
        << R"(pair.json: b.angle: must be a number, got "90deg")";
    QTest::newRow("not-object") << QByteArray("[3]")
                                << "pair.json: [0]: must be an object {...}, got 3";
}

void TestLessons::satReportRejects()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    const lessons::SatReport report = lessons::satReportJson(json, QStringLiteral("pair.json"));
    QVERIFY(!report.ok);
    QCOMPARE(report.error, message);
}

RIGIDLAB_TEST_GUILESS_MAIN(TestLessons)

/// A lesson step frames where its bodies will go: a free ball at 2 m/s for 1.5 s sweeps
/// from x = -r to 3 + r, exactly as uniform motion says; a falling box sweeps down by g t²/2;
/// the world itself is not stepped; a static body adds nothing.
void TestLessons::sweptBoundsFollowTheMotion()
{
    physics::WorldDef def;
    def.gravity = Vec2::Zero();
    def.dt = 0.01;
    physics::World world(def);
    const double r = 0.25;
    physics::BodyDef ball;
    ball.shape = physics::makeCircleShape(r);
    ball.velocity = Vec2(2.0, 0.0);
    world.addBody(ball);
    physics::BodyDef wall;
    wall.type = physics::BodyType::Static;
    wall.shape = physics::makeCircleShape(1.0);
    wall.position = Vec2(0.0, -50.0);
    world.addBody(wall);
    const QRectF box = lessons::sweptBounds(world, 1.5);
    RL_VERIFY_NEAR(box.left(), -r, 1e-9, 0.0);
    RL_VERIFY_NEAR(box.right(), 3.0 + r, 1e-9, 0.0);
    RL_VERIFY_NEAR(box.top(), -r, 1e-9, 0.0);
    RL_VERIFY_NEAR(box.bottom(), r, 1e-9, 0.0);
    QCOMPARE(world.time(), 0.0);

    physics::WorldDef fallDef;
    fallDef.dt = 0.001;
    physics::World fall(fallDef);
    physics::BodyDef box1;
    box1.shape = physics::makePolygonShape(physics::makeBox(0.5, 0.5));
    fall.addBody(box1);
    const QRectF swept = lessons::sweptBounds(fall, 1.0);
    const double drop = 0.5 * 9.81 * 1.0 * 1.0; // symplectic Euler adds g·dt·t/2 more
    RL_VERIFY_NEAR(swept.top(), -0.25 - drop, 9.81 * 0.001 * 1.0, 0.0);
    RL_VERIFY_NEAR(swept.bottom(), 0.25, 1e-12, 0.0);
    RL_VERIFY_NEAR(swept.width(), 0.5, 1e-12, 0.0);
}
