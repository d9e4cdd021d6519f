// SPDX-License-Identifier: GPL-3.0-or-later
// The work-precision sweep and the stress suite: observed orders from the sweep on the
// oscillator (1, 1, 2, 4, 5 or 4 for the embedded pair, 2 for implicit midpoint, and
// Boost.Odeint's methods beside ours), exact references checked against each other, and every
// stress case ending with its documented verdict.

#include "numerics/error_vs_time.h"
#include "numerics/reference_problems.h"
#include "numerics/stress.h"

#include "near.h"
#include "test_main.h"

#include <QLocale>
#include <QTest>

#include <cmath>
#include <numbers>

using namespace rigidlab;

class TestNumerics : public QObject {
    Q_OBJECT

private slots:
    void ellipticFunctions();
    void keplerEquation();
    void observedOrders_data();
    void observedOrders();
    void csvHeader();
    void badOptions();
    void stressVerdicts();
};

void TestNumerics::ellipticFunctions()
{
    // sn^2 + cn^2 = 1, dn^2 + m sn^2 = 1, sn(K) = 1, and m = 0 gives sin and cos.
    for (double m : {0.0, 0.3, 0.9, 0.99}) {
        const double k = lessons::ellipticK(m);
        RL_VERIFY_NEAR(lessons::jacobiElliptic(k, m).sn, 1.0, 1e-14, 0);
        for (double u : {-7.3, -0.4, 0.0, 1.1, 12.0}) {
            const auto f = lessons::jacobiElliptic(u, m);
            RL_VERIFY_NEAR(f.sn * f.sn + f.cn * f.cn, 1.0, 1e-14, 0);
            RL_VERIFY_NEAR(f.dn * f.dn + m * f.sn * f.sn, 1.0, 1e-13, 0);
        }
    }
    RL_VERIFY_NEAR(lessons::jacobiElliptic(0.7, 0.0).sn, std::sin(0.7), 1e-16, 0);
    // K(0) = pi/2.
    RL_VERIFY_NEAR(lessons::ellipticK(0.0), std::numbers::pi / 2, 1e-15, 0);
}

void TestNumerics::keplerEquation()
{
    for (double e : {0.0, 0.5, 0.9})
        for (double m : {-20.0, 0.0, 0.3, 3.1, 100.0}) {
            const double big = lessons::solveKepler(m, e);
            QVERIFY(std::abs(big - e * std::sin(big) - m) < 1e-12 * std::max(1.0, std::abs(m)));
        }
}

void TestNumerics::observedOrders_data()
{
    QTest::addColumn<QString>("integrator");
    QTest::addColumn<double>("low");
    QTest::addColumn<double>("high");
    QTest::newRow("euler") << "euler" << 0.8 << 1.2;
    QTest::newRow("symplectic-euler") << "symplectic-euler" << 0.8 << 1.2;
    QTest::newRow("verlet") << "verlet" << 1.8 << 2.2;
    QTest::newRow("rk4") << "rk4" << 3.7 << 4.3;
    QTest::newRow("dopri5") << "dopri5" << 3.7 << 5.5;
    QTest::newRow("implicit-midpoint") << "implicit-midpoint" << 1.8 << 2.2;
    QTest::newRow("odeint-rk4") << "odeint-rk4" << 3.7 << 4.3;
    QTest::newRow("odeint-dopri5") << "odeint-dopri5" << 3.7 << 5.5;
}

void TestNumerics::observedOrders()
{
    QFETCH(QString, integrator);
    QFETCH(double, low);
    QFETCH(double, high);
    lessons::SweepOptions o;
    o.problems = {QStringLiteral("oscillator")};
    o.integrators = {integrator};
    o.points = 4;
    // The adaptive ones integrate in 50 chunks: a longer run leaves their steps free.
    const bool adaptive = integrator.contains(QLatin1String("dopri5"));
    o.tEnd = adaptive ? 10.0 : 2.0;
    // Euler needs small steps before its error is under 1e-2.
    const bool firstOrder = integrator.contains(QLatin1String("euler"));
    o.dtFrom = firstOrder ? 2e-3 : 0.05;
    o.dtTo = firstOrder ? 2e-4 : 5e-3;
    o.tolFrom = 1e-5;
    o.tolTo = 1e-10;
    o.minTimingSeconds = 0;
    o.minRepeats = 1;
    int calls = 0;
    const auto rows = lessons::runSweep(o, [&](const lessons::SweepRow&, int done, int total) {
        ++calls;
        return done <= total;
    });
    QCOMPARE(int(rows.size()), 4);
    QCOMPARE(calls, 4);
    for (const auto& r : rows) {
        QVERIFY(r.evaluations >= r.steps);
        QVERIFY(r.seconds >= 0 && r.repeats >= 1);
        QVERIFY(r.maxError >= r.error);
    }
    const auto p = lessons::observedOrder(rows, QStringLiteral("oscillator"), integrator);
    QVERIFY(p.has_value());
    QVERIFY2(*p > low && *p < high, qPrintable(QString::number(*p)));
}

void TestNumerics::csvHeader()
{
    lessons::SweepOptions o;
    o.problems = {QStringLiteral("spinning-body")};
    o.integrators = {QStringLiteral("verlet")};
    o.points = 2;
    o.minTimingSeconds = 0;
    o.minRepeats = 1;
    bool cancelled = false;
    const auto rows = lessons::runSweep(o, [&](const lessons::SweepRow&, int, int) {
        cancelled = true;
        return false; // cancel after the first row
    });
    QVERIFY(cancelled);
    QCOMPARE(int(rows.size()), 1);
    const QByteArray csv = lessons::sweepCsv(rows);
    QVERIFY2(csv.startsWith("problem,integrator,dt [s],steps,evaluations,error,max_error,"
                            "energy_error,seconds [s]\nspinning-body,verlet,"),
             csv.constData());
    // Shortest round trip: the step reads back as the run's dt, in few digits.
    const QList<QByteArray> cells = csv.split('\n').at(1).split(',');
    QCOMPARE(cells.at(2).toDouble(), rows.front().dt);
    QVERIFY2(cells.at(2).size() <= 17, cells.at(2).constData());
    // The Czech spreadsheet dialect: BOM, ';' and decimal comma.
    const QByteArray czech = lessons::sweepCsv(
        rows, lessons::csvConventions(lessons::CsvDialect::Spreadsheet, QStringLiteral("cs")));
    QVERIFY(czech.startsWith("\xEF\xBB\xBFproblem;integrator;dt [s];"));
    const QList<QByteArray> czechCells = czech.split('\n').at(1).split(';');
    QCOMPARE(QLocale(QLocale::Czech).toDouble(QString::fromUtf8(czechCells.at(2))),
             rows.front().dt);
}

void TestNumerics::badOptions()
{
    lessons::SweepOptions o;
    o.problems = {QStringLiteral("nope")};
    QVERIFY(lessons::checkSweepOptions(o).contains(QStringLiteral("unknown problem")));
    QVERIFY(lessons::runSweep(o).empty());
    o.problems.clear();
    o.integrators = {QStringLiteral("leapfrog")};
    QVERIFY(lessons::checkSweepOptions(o).contains(QStringLiteral("unknown integrator")));
    o.integrators.clear();
    o.points = 1;
    QVERIFY(!lessons::checkSweepOptions(o).isEmpty());
}

void TestNumerics::stressVerdicts()
{
    // Every case but the 1e-6 s ball drop (a million steps) is small: run them all.
    const auto rows = lessons::runStress();
    QVERIFY(rows.size() >= 30);
    for (const auto& r : rows)
        QVERIFY2(r.asDocumented(),
                 qPrintable(QStringLiteral("%1, %2, %3: %4, documented %5")
                                .arg(r.caseName, r.setup, r.integrator, r.verdict, r.expected)));
    for (const QString& c : lessons::stressCaseNames())
        QVERIFY2(std::any_of(rows.begin(), rows.end(),
                             [&](const lessons::StressRow& r) { return r.caseName == c; }),
                 qPrintable(c));
}

RIGIDLAB_TEST_GUILESS_MAIN(TestNumerics)
#include "test_numerics.moc"
