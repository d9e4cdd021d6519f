// SPDX-License-Identifier: GPL-3.0-or-later
// The benchmark's table (bench/bench_run.cpp): every row's ratio and whether it counts are
// against the lab's default solver, the soft step ("RigidLab SS"), when it ran, else against
// the first RigidLab engine that ran; the header line names that engine.

#include "bench.h"

#include "test_main.h"

#include <string>
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

} // namespace

class TestBenchTable : public QObject {
    Q_OBJECT

private slots:
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
