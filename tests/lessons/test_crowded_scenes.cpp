// SPDX-License-Identifier: GPL-3.0-or-later
// A scene's cost is bounded before it runs. 10,000 bodies heaped at one point are within the
// documented limits, but every pair of them is a contact: the loader refuses the heap in one
// line, within 5 s and 1 GB (the child runs under an address-space limit), through
// `rigidlab-cli validate` and `run` alike; a few overlapping bodies load with a warning from
// ten pairs on; a packed pyramid, whose boxes only touch, loads as before. A heap that reaches
// the engine some other way stops before its first step, in the lab's words.

#include "build_paths.h"
#include "format/divergence_message.h"
#include "format/scene_loader.h"
#include "format/scene_overlaps.h"

#include "rigidlab/physics/world.h"

#include "cli_run.h"
#include "test_main.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <sys/resource.h>

using namespace rigidlab;
using rigidlab::test::CliRun;
using rigidlab::test::runCli;

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RIGIDLAB_ASAN
#endif
#endif

namespace {

const QString kSource = rigidlab::test::sourcePath();
/// The most memory the command line may take for the heap [bytes].
constexpr rlim_t kMemory = rlim_t{1} << 30;
constexpr qint64 kMilliseconds = 5000;

/// `count` balls of radius 0.1 m heaped at (0, 1), and a floor: count + 1 bodies.
QByteArray heap(int count)
{
    QJsonArray bodies;
    bodies.append(QJsonObject{{"id", "floor"},
                              {"type", "static"},
                              {"shape", QJsonObject{{"type", "box"}, {"width", 20}, {"height", 1}}},
                              {"position", QJsonArray{0, -0.5}}});
    for (int i = 0; i < count; ++i)
        bodies.append(QJsonObject{{"id", QStringLiteral("ball%1").arg(i)},
                                  {"shape", QJsonObject{{"type", "circle"}, {"radius", 0.1}}},
                                  {"position", QJsonArray{0.001 * (i % 7), 1.0}}});
    return QJsonDocument(QJsonObject{{"rigidlab", 1}, {"bodies", bodies}}).toJson();
}

QString writeScene(const QTemporaryDir& dir, const QString& name, const QByteArray& bytes)
{
    const QString path = dir.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size())
        qFatal("cannot write %s", qPrintable(path));
    return path;
}

/// rigidlab-cli with at most kMemory of address space.
CliRun runLimited(const QStringList& arguments)
{
#if defined(__SANITIZE_ADDRESS__) || defined(RIGIDLAB_ASAN)
    // (AddressSanitizer's shadow memory alone takes terabytes of address space.)
    return runCli(arguments);
#else
    return runCli(arguments, [] {
        const rlimit limit{kMemory, kMemory};
        setrlimit(RLIMIT_AS, &limit);
    });
#endif
}

} // namespace

class TestCrowdedScenes : public QObject {
    Q_OBJECT

private slots:
    void heapIsRefusedQuickly_data()
    {
        QTest::addColumn<QString>("command");
        QTest::newRow("validate") << "validate";
        QTest::newRow("run") << "run";
    }
    void heapIsRefusedQuickly()
    {
        QFETCH(QString, command);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = writeScene(dir, QStringLiteral("heap.json"), heap(9'999));
        const CliRun run = runLimited({command, path});
        QVERIFY2(!run.crashed, run.err.constData());
        QVERIFY2(run.exitCode != 0, run.err.constData());
        QVERIFY2(run.err.contains(path.toUtf8() + ": bodies: more than "), run.err.constData());
        QVERIFY2(run.err.contains("spread them out"), run.err.constData());
        QCOMPARE(run.err.count('\n'), 1);
        qInfo("%s of 10,000 bodies heaped: refused in %lld ms under a 1 GB limit",
              qPrintable(command), run.milliseconds);
        QVERIFY2(run.milliseconds < kMilliseconds, qPrintable(QString::number(run.milliseconds)));
    }

    void fewOverlapsWarn()
    {
        // Six balls at one point: fifteen overlapping pairs, a warning; the scene loads.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const lessons::SceneLoadResult r =
            lessons::loadSceneFile(writeScene(dir, QStringLiteral("few.json"), heap(6)));
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.warnings.size(), 1);
        QVERIFY2(r.warnings.front().contains(
                     QStringLiteral("10 or more pairs of bodies start overlapping (\"ball")),
                 qPrintable(r.warnings.front()));
        // Three: three pairs, loaded without a word (the editor shows them).
        const lessons::SceneLoadResult three =
            lessons::loadSceneFile(writeScene(dir, QStringLiteral("three.json"), heap(3)));
        QVERIFY2(three.ok && three.warnings.isEmpty(), qPrintable(three.warnings.join(u'\n')));
        QCOMPARE(lessons::surveyOverlaps(three.scene, 100).pairs.size(), std::size_t{3});
    }

    void heapBuiltDirectlyStopsWithAMessage()
    {
        // Read without the loader's check (as a program or the editor could build it): the
        // world stops before its first step, and the one message says why, in one line.
        lessons::Scene scene = lessons::loadSceneJson(heap(5), QStringLiteral("few")).scene;
        const physics::BodyDef ball = scene.bodies.back();
        while (scene.bodies.size() < 1001) {
            scene.bodies.push_back(ball);
            scene.bodies.back().name = "ball" + std::to_string(scene.bodies.size());
        }
        physics::World world = lessons::buildWorld(scene);
        world.step();
        QVERIFY(world.divergence());
        QCOMPARE(world.time(), 0.0);
        const QString message = lessons::divergenceMessage(*world.divergence());
        QVERIFY2(message.startsWith(QStringLiteral("stopped at t = 0 s, before step 1: more "
                                                   "than %1 pairs of bodies overlap or nearly "
                                                   "touch (around body \"ball")
                                        .arg(lessons::boxPairBudget(scene))),
                 qPrintable(message));
        QVERIFY2(message.endsWith(QStringLiteral("spread them out")), qPrintable(message));
        QVERIFY(!message.contains(u'\n'));
    }

    void packedPyramidLoads()
    {
        // 820 boxes that touch their neighbours: no overlap, far within the budget.
        const lessons::SceneLoadResult r =
            lessons::loadSceneFile(kSource + QStringLiteral("/lessons/scenes/pyramid40.json"));
        QVERIFY2(r.ok, qPrintable(r.error));
        const lessons::OverlapSurvey survey = lessons::surveyOverlaps(r.scene, 100);
        QVERIFY(!survey.crowded);
        QVERIFY2(survey.pairs.empty(), qPrintable(QString::number(survey.pairs.size())));
        QVERIFY2(survey.boxPairs <= 4 * r.scene.bodies.size(),
                 qPrintable(QString::number(survey.boxPairs)));
    }
};

RIGIDLAB_TEST_GUILESS_MAIN(TestCrowdedScenes)
#include "test_crowded_scenes.moc"
