// SPDX-License-Identifier: GPL-3.0-or-later
// The benchmark's table (bench/bench_run.cpp): every row's ratio and whether it counts are
// against the lab's default solver, the soft step ("RigidLab SS"), when it ran, else against
// the first RigidLab engine that ran; the header line names that engine. The engines take turns,
// a run each.

#include "bench.h"

#include "test_main.h"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

using namespace rigidlab;

namespace {

/// A result on pyramid-40 with the given time and top drift, nothing moved.
bench::BenchResult result(const std::string& engine, double msPerStep, double topDrift)
{
    bench::BenchResult r;
    r.engine = engine;
    r.scene = "pyramid-40";
    r.bodies = 820;
    r.msPerStep = msPerStep;
    r.topDrift = topDrift;
    return r;
}

/// The line of the table that starts with `engine` followed by spaces.
QString row(const QString& table, const QString& engine)
{
    for (const QString& line : table.split(u'\n'))
        if (line.startsWith(engine + QStringLiteral("  ")))
            return line;
    return {};
}

/// An engine that only writes in a log shared by all when it builds a scene, and hashes to how
/// many times it built one.
class LoggingEngine : public bench::BenchEngine {
public:
    LoggingEngine(std::string name, std::vector<std::string>& log)
        : m_name(std::move(name)), m_log(log)
    {
    }
    std::string name() const override { return m_name; }
    std::string settings() const override { return {}; }
    void build(const bench::BenchScene&) override
    {
        m_log.push_back(m_name);
        ++m_builds;
    }
    void step() override {}
    void poses(std::vector<bench::BenchPose>& out) const override { out.clear(); }
    std::optional<std::uint64_t> stateHash() const override { return m_builds; }

private:
    std::string m_name;
    std::vector<std::string>& m_log;
    std::uint64_t m_builds = 0;
};

} // namespace

class TestBenchTable : public QObject {
    Q_OBJECT

private slots:
    void enginesTakeTurns()
    {
        // A run each, round after round, so that a drift in the machine's speed reaches every
        // engine alike: never two runs of one engine in a row.
        std::vector<std::string> log;
        LoggingEngine a("A", log), b("B", log);
        bench::BenchScene scene;
        scene.name = "empty";
        bench::BenchOptions options;
        options.steps = 3;
        options.runs = 3;
        const std::vector<bench::BenchResult> results = bench::runInTurns({&a, &b}, scene, options);
        QCOMPARE(log, (std::vector<std::string>{"A", "B", "A", "B", "A", "B"}));
        QCOMPARE(results.size(), size_t(2));
        QCOMPARE(results[0].engine, std::string("A"));
        QCOMPARE(results[1].engine, std::string("B"));
        for (const bench::BenchResult& r : results) {
            QCOMPARE(r.runs.size(), size_t(3));
            // The state is the first run's, as a single engine's runs keep it.
            QCOMPARE(r.hash, std::optional<std::uint64_t>(1));
        }
    }

    void ratiosRoundByRound()
    {
        // The soft step against Box2D v3 round by round: 3/1, 2/4 and 6/2, median 3.00 and
        // range 0.50-3.00, beside the ratio of the medians, 3/2.
        bench::BenchResult soft = result("RigidLab SS", 3.0, -0.001);
        soft.runs = {3.0, 2.0, 6.0};
        bench::BenchResult v3 = result("Box2D v3 SSE2", 2.0, -0.020);
        v3.runs = {1.0, 4.0, 2.0};
        QCOMPARE(bench::pairedRatios(soft, v3), (std::vector<double>{3.0, 0.5, 3.0}));
        const QString targets = QString::fromStdString(bench::softStepTargets({soft, v3}));
        QVERIFY2(targets.contains(QStringLiteral("1.500x Box2D v3 SSE2's time (at most 1.00: "
                                                 "MISSED; round by round 3.00 (0.50-3.00))")),
                 qPrintable(targets));
        // Only the rounds both ran are paired.
        v3.runs.pop_back();
        QCOMPARE(bench::pairedRatios(soft, v3), (std::vector<double>{3.0, 0.5}));
        QCOMPARE(bench::pairedRatios(soft, bench::BenchResult{}), std::vector<double>{});
    }

    void ratioPrintedAsJudged()
    {
        // A ratio just over its bound reads over it: 1.004, not "1.00x ... MISSED".
        const bench::BenchResult soft = result("RigidLab SS", 1.004, -0.001);
        const bench::BenchResult v3 = result("Box2D v3 SSE2", 1.0, -0.020);
        const QString over = QString::fromStdString(bench::softStepTargets({soft, v3}));
        QVERIFY2(over.contains(QStringLiteral("1.004x Box2D v3 SSE2's time (at most 1.00: MISSED")),
                 qPrintable(over));
        const bench::BenchResult under = result("RigidLab SS", 0.9996, -0.001);
        const QString met = QString::fromStdString(bench::softStepTargets({under, v3}));
        QVERIFY2(met.contains(QStringLiteral("1.000x Box2D v3 SSE2's time (at most 1.00: met")),
                 qPrintable(met));
    }

    void substepsAreTheBenchs()
    {
        // --substeps: the soft step's count reaches the world and the settings line.
        bench::RigidLabBenchSettings settings;
        settings.solver = physics::SolverKind::SoftStep;
        QCOMPARE(settings.substeps, physics::SoftStepSettings{}.substeps);
        settings.substeps = 3;
        const physics::World world =
            bench::buildBenchWorld(*bench::makeBenchScene("pyramid-20"), settings);
        QCOMPARE(world.contactSettings().soft.substeps, 3);
        const std::string line = bench::makeRigidLabBenchEngine(settings)->settings();
        QVERIFY2(line.find(", 3 substeps,") != std::string::npos, line.c_str());
    }

    void softStepIsTheReference()
    {
        // The sequential solver first, as rigidlab-bench runs them: still the soft step is
        // the reference, and it is the most stable here.
        const std::vector<bench::BenchResult> results = {result("RigidLab", 4.0, -0.050),
                                                         result("RigidLab SS", 2.0, -0.001),
                                                         result("Box2D v3 SSE2", 1.0, -0.020)};
        QCOMPARE(bench::referenceEngine(results), std::string("RigidLab SS"));
        const QString table = QString::fromStdString(bench::benchTable(results));
        const QString header = table.section(u'\n', 0, 0);
        QVERIFY2(header.startsWith(QStringLiteral("engine")), qPrintable(table));
        QVERIFY2(header.contains(QStringLiteral("against RigidLab SS")), qPrintable(table));
        // The results' runs were 0 s long (made here, not run): the column says so.
        QVERIFY2(header.contains(QStringLiteral("stability (0 s)")), qPrintable(table));
        // Ratios over the soft step's 2 ms: 2.00, 1.00 and 0.50.
        QVERIFY2(row(table, QStringLiteral("RigidLab")).contains(QStringLiteral(" 2.00 ")),
                 qPrintable(table));
        QVERIFY2(row(table, QStringLiteral("RigidLab SS")).contains(QStringLiteral(" 1.00 ")),
                 qPrintable(table));
        const QString v3 = row(table, QStringLiteral("Box2D v3 SSE2"));
        QVERIFY2(v3.contains(QStringLiteral(" 0.50 ")), qPrintable(table));
        // The soft step sank less than Box2D v3: the ratio counts.
        QVERIFY2(v3.endsWith(QStringLiteral("yes")), qPrintable(table));
        QVERIFY2(!table.contains(QStringLiteral("less stable")), qPrintable(table));
    }

    void softStepAloneHasRatios()
    {
        const std::vector<bench::BenchResult> results = {result("RigidLab SS", 2.0, -0.001),
                                                         result("Box2D v3 AVX2", 1.5, -0.020)};
        const QString table = QString::fromStdString(bench::benchTable(results));
        QVERIFY2(row(table, QStringLiteral("Box2D v3 AVX2")).contains(QStringLiteral(" 0.75 ")),
                 qPrintable(table));
    }

    void otherwiseTheFirstRigidLabEngine()
    {
        // Without the soft step: the first RigidLab engine that ran, and a peer more stable
        // than it does not count.
        const std::vector<bench::BenchResult> results = {result("Box2D 2.4", 3.0, 0.0),
                                                         result("RigidLab SS f32", 1.5, -0.005),
                                                         result("RigidLab", 6.0, -0.050)};
        QCOMPARE(bench::referenceEngine(results), std::string("RigidLab SS f32"));
        const QString table = QString::fromStdString(bench::benchTable(results));
        QVERIFY2(table.section(u'\n', 0, 0).contains(QStringLiteral("against RigidLab SS f32")),
                 qPrintable(table));
        QVERIFY2(row(table, QStringLiteral("RigidLab")).contains(QStringLiteral(" 4.00 ")),
                 qPrintable(table));
        QVERIFY2(row(table, QStringLiteral("RigidLab")).endsWith(QStringLiteral("yes")),
                 qPrintable(table));
        QVERIFY2(row(table, QStringLiteral("Box2D 2.4"))
                     .endsWith(QStringLiteral("no: RigidLab SS f32 less stable")),
                 qPrintable(table));
        QCOMPARE(bench::referenceEngine({result("Chipmunk", 1.0, 0.0)}), std::string());
    }
};

RIGIDLAB_TEST_GUILESS_MAIN(TestBenchTable)
#include "test_bench_table.moc"
