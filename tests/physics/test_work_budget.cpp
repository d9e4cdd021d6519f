// SPDX-License-Identifier: GPL-3.0-or-later
// A world built through its API (the editor's scene, a program's own) is bounded like a scene
// from a file: a step whose bodies crowd past the work budget (work_budget.h) stops the world
// with a diagnosis before it moves anything, within seconds and in memory in proportion to the
// bodies, instead of growing to gigabytes. Packed scenes, whose boxes only touch, run on.

#include "rigidlab/physics/work_budget.h"

#include "physics_test_util.h"
#include "test_main.h"

#include <QElapsedTimer>

#include <sys/resource.h>

using namespace rigidlab;
using namespace rigidlab::physics;
using rigidlab::test::boxBody;
using rigidlab::test::circleBody;

namespace {

/// The longest a crowded world's first step may take [ms].
constexpr qint64 kMilliseconds = 5000;

/// A floor and `count` balls of radius 0.1 m heaped at (0, 1).
World heap(int count)
{
    World w;
    BodyDef floor = boxBody(40.0, 1.0, Vec2(0.0, -0.5));
    floor.type = BodyType::Static;
    w.addBody(floor);
    for (int i = 0; i < count; ++i)
        w.addBody(circleBody(0.1, Vec2(0.001 * (i % 7), 1.0 + 0.001 * (i % 11))));
    return w;
}

/// The resident memory of this process at its peak [bytes].
long long peakMemory()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<long long>(usage.ru_maxrss) * 1024;
}

} // namespace

class TestWorkBudget : public QObject {
    Q_OBJECT

private slots:
    void heapStopsAtTheFirstStep_data()
    {
        QTest::addColumn<int>("count");
        QTest::newRow("1,000 balls") << 1000;
        QTest::newRow("10,000 balls") << 10000;
    }
    void heapStopsAtTheFirstStep()
    {
        QFETCH(int, count);
        World w = heap(count);
        const std::vector<Body> before = w.bodies();
        QElapsedTimer clock;
        clock.start();
        w.step();
        const qint64 ms = clock.elapsed();
        const auto& d = w.divergence();
        QVERIFY(d.has_value());
        QCOMPARE(d->kind, Divergence::Kind::Crowded);
        QCOMPARE(d->quantity, Divergence::Quantity::BodyPairs);
        QCOMPARE(d->bound, double(pairBudget(w.bodies().size())));
        QVERIFY2(d->value > d->bound,
                 qPrintable(QStringLiteral("%1 pairs, budget %2").arg(d->value).arg(d->bound)));
        QVERIFY(d->body > 0); // a ball, not the floor
        QCOMPARE(d->step, 0);
        QCOMPARE(d->time, 0.0);
        // Stopped before anything moved: the crowded start is what the user sees.
        QCOMPARE(w.time(), 0.0);
        for (std::size_t i = 0; i < before.size(); ++i)
            QVERIFY(w.bodies()[i].position == before[i].position);
        QVERIFY(w.contacts().empty());
        w.step(); // and no more steps
        QCOMPARE(w.stepCount(), 0);
        qInfo("%d balls at one point: stopped at %g pairs (budget %g) in %lld ms, peak memory "
              "%lld MB",
              count, d->value, d->bound, ms, peakMemory() >> 20);
        RL_VERIFY_AT_MOST(ms, kMilliseconds);
        RL_VERIFY_AT_MOST(peakMemory(), 1LL << 30);
    }

    void packedBallsRunOn()
    {
        // 1,600 balls in a square grid, each touching its four neighbours, on a floor: about
        // four overlapping boxes per ball (the diagonals' boxes touch at a corner too), within
        // the budget step after step as they settle.
        World w;
        BodyDef floor = boxBody(40.0, 1.0, Vec2(0.0, -0.5));
        floor.type = BodyType::Static;
        w.addBody(floor);
        const double r = 0.05;
        for (int row = 0; row < 40; ++row)
            for (int col = 0; col < 40; ++col)
                w.addBody(circleBody(r, Vec2(-2.0 + 2 * r * col, r + 2 * r * row)));
        for (int i = 0; i < 30; ++i) {
            w.step();
            QVERIFY2(!w.divergence(), "stopped");
            RL_VERIFY_AT_MOST(std::size_t(w.profile().pairs), pairBudget(w.bodies().size()));
        }
        QVERIFY(w.profile().pairs > 0);
    }

    void budgetGrowsWithTheBodies()
    {
        // A few pairs per body and a floor: 40 balls at one point (780 pairs) run; a step's
        // budget of pairs is what the loader and the editor refuse a scene past.
        QCOMPARE(pairBudget(0), kPairsAlways);
        QCOMPARE(pairBudget(1000) - pairBudget(999), kPairsPerBody);
        World w = heap(40);
        w.step();
        QVERIFY(!w.divergence() || w.divergence()->kind != Divergence::Kind::Crowded);
        QVERIFY(w.profile().pairs >= 40 * 39 / 2);
    }
};

RIGIDLAB_TEST_GUILESS_MAIN(TestWorkBudget)
#include "test_work_budget.moc"
