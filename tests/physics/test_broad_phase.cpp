// SPDX-License-Identifier: GPL-3.0-or-later
// The broad phase (physics/src/stages/broad_phase.h) on its own: at every step of a random
// walk its pairs are exactly those of a brute-force comparison of every two boxes, in order.
// The walk has what its shortcuts rely on: bodies that stay inside their fat boxes (their kept
// pairs are not looked at again) next to bodies that jump out of theirs, pairs whose fat boxes
// part, bodies that stop and start colliding, bodies asleep, fast bodies' grown boxes and
// excluded pairs.

#include "broad_phase.h"

#include "physics_test_util.h"
#include "test_main.h"

#include <QTest>

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

using namespace rigidlab::physics;
using rigidlab::test::boxBody;
using rigidlab::test::circleBody;

namespace {

using Pairs = std::vector<std::pair<int, int>>;

/// The body's box from its corners or its circle, one vertex at a time, grown by `margin`.
Aabb bruteBox(const Body& b, double margin)
{
    const Transform xf = b.transform();
    if (const Circle* c = b.shape.asCircle()) {
        const Vec2 at = xf.apply(c->center);
        const double r = c->radius + margin;
        return {at - Vec2(r, r), at + Vec2(r, r)};
    }
    const Polygon& p = *b.shape.asPolygon();
    double lx = INFINITY, ly = INFINITY, hx = -INFINITY, hy = -INFINITY;
    for (const Vec2& v : p.vertices) {
        const Vec2 w = xf.apply(v);
        lx = std::min(lx, w.x());
        ly = std::min(ly, w.y());
        hx = std::max(hx, w.x());
        hy = std::max(hy, w.y());
    }
    return {Vec2(lx - margin, ly - margin), Vec2(hx + margin, hy + margin)};
}

/// Every pair (a < b) of colliding bodies, not both static or kinematic, not excluded, whose
/// boxes overlap: O(n^2), with no tree and nothing kept.
Pairs brutePairs(const std::vector<Body>& bodies, double margin, const std::vector<double>& grow,
                 const Pairs& excluded)
{
    Pairs out;
    for (size_t i = 0; i < bodies.size(); ++i)
        for (size_t j = i + 1; j < bodies.size(); ++j) {
            const Body& a = bodies[i];
            const Body& b = bodies[j];
            if (!a.collide || !b.collide || (!a.isDynamic() && !b.isDynamic()))
                continue;
            const std::pair<int, int> p(static_cast<int>(i), static_cast<int>(j));
            if (std::find(excluded.begin(), excluded.end(), p) != excluded.end())
                continue;
            const Aabb ba = bruteBox(a, margin + (grow.empty() ? 0.0 : grow[i]));
            const Aabb bb = bruteBox(b, margin + (grow.empty() ? 0.0 : grow[j]));
            const bool apart = ba.hi.x() < bb.lo.x() || bb.hi.x() < ba.lo.x() ||
                               ba.hi.y() < bb.lo.y() || bb.hi.y() < ba.lo.y();
            if (!apart)
                out.push_back(p);
        }
    return out;
}

/// Bodies built by a world, to be moved by hand: a floor, a static post, a kinematic bar, and
/// boxes and balls packed closely enough in 6 m x 6 m to touch their neighbours.
template <typename Uniform> std::vector<Body> scatteredBodies(Uniform& uniform)
{
    World world;
    BodyDef floor = boxBody(8.0, 0.5, Vec2(0.0, -0.25));
    floor.type = BodyType::Static;
    world.addBody(floor);
    BodyDef post = boxBody(0.5, 3.0, Vec2(0.0, 1.5));
    post.type = BodyType::Static;
    world.addBody(post);
    BodyDef bar = boxBody(2.0, 0.2, Vec2(1.0, 0.5));
    bar.type = BodyType::Kinematic;
    world.addBody(bar);
    for (int i = 0; i < 80; ++i) {
        const Vec2 at(uniform(-3.0, 3.0), uniform(0.0, 6.0));
        world.addBody(i % 3 ? boxBody(uniform(0.2, 0.8), uniform(0.2, 0.8), at, uniform(-3, 3))
                            : circleBody(uniform(0.1, 0.4), at));
    }
    return world.bodies();
}

QString describe(const Pairs& pairs)
{
    QStringList items;
    for (const auto& [a, b] : pairs)
        items << QString("(%1,%2)").arg(a).arg(b);
    return items.join(' ');
}

} // namespace

class TestBroadPhase : public QObject {
    Q_OBJECT
private slots:
    void pairsAreTheBruteForceOnes_data();
    void pairsAreTheBruteForceOnes();
};

void TestBroadPhase::pairsAreTheBruteForceOnes_data()
{
    QTest::addColumn<unsigned>("seed");
    QTest::addColumn<double>("jumpChance");   // of a body leaving its fat box in a step
    QTest::addColumn<double>("toggleChance"); // of a body's collide flag flipping in a step
    QTest::addColumn<double>("growChance");   // of a body being fast in a step
    QTest::newRow("jitter, few jumps") << 1u << 0.02 << 0.0 << 0.0;
    QTest::newRow("many jumps") << 2u << 0.3 << 0.0 << 0.0;
    QTest::newRow("collide toggled") << 3u << 0.05 << 0.03 << 0.0;
    QTest::newRow("fast bodies") << 4u << 0.05 << 0.0 << 0.1;
    QTest::newRow("all at once") << 5u << 0.1 << 0.02 << 0.05;
}

void TestBroadPhase::pairsAreTheBruteForceOnes()
{
    QFETCH(unsigned, seed);
    QFETCH(double, jumpChance);
    QFETCH(double, toggleChance);
    QFETCH(double, growChance);
    std::mt19937 random(seed);
    auto uniform = [&](double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(random);
    };
    auto chance = [&](double p) { return uniform(0.0, 1.0) < p; };

    std::vector<Body> bodies = scatteredBodies(uniform);
    const size_t n = bodies.size();
    // Two bodies asleep: they keep their boxes (and do not move here).
    bodies[10].awake = false;
    bodies[11].awake = false;
    const Pairs excluded = {{3, 4}, {5, 20}, {12, 13}};
    const double margin = 0.01;
    const double dt = 1.0 / 60.0;

    BroadPhase broad;
    Pairs pairs;
    int keptSteps = 0;  // steps where some colliding bodies stayed in their fat boxes
    int apartPairs = 0; // pairs of one step not in the next
    Pairs last;
    for (int step = 0; step < 300; ++step) {
        std::vector<double> grow;
        for (size_t i = 2; i < n; ++i) {
            Body& b = bodies[i];
            if (i == 10 || i == 11)
                continue;
            if (chance(toggleChance))
                b.collide = !b.collide;
            if (chance(jumpChance)) {
                b.position += Vec2(uniform(-1.0, 1.0), uniform(-1.0, 1.0));
                b.angle += uniform(-1.0, 1.0);
            } else {
                b.position += Vec2(uniform(-0.01, 0.01), uniform(-0.01, 0.01));
                b.angle += uniform(-0.01, 0.01);
            }
            b.position = b.position.cwiseMax(Vec2(-4.0, -1.0)).cwiseMin(Vec2(4.0, 7.0));
            b.velocity = Vec2(uniform(-2.0, 2.0), uniform(-2.0, 2.0));
            if (chance(growChance)) {
                grow.resize(n, 0.0);
                grow[i] = uniform(0.0, 0.5);
            }
        }
        std::vector<Transform> xf;
        for (const Body& b : bodies)
            xf.push_back(b.transform());
        broad.findPairs(bodies, xf, margin, grow, dt, excluded, 100000, pairs);
        const Pairs expected = brutePairs(bodies, margin, grow, excluded);
        QVERIFY2(pairs == expected, qPrintable(QString("step %1: found %2\nexpected %3")
                                                   .arg(step)
                                                   .arg(describe(pairs), describe(expected))));
        int colliding = 0;
        for (const Body& b : bodies)
            colliding += b.collide ? 1 : 0;
        if (broad.refitted() < colliding)
            ++keptSteps;
        for (const auto& p : last)
            if (!std::binary_search(pairs.begin(), pairs.end(), p))
                ++apartPairs;
        last = pairs;
    }
    // The walk did what it is for: bodies kept their fat boxes, and pairs came apart.
    QVERIFY2(keptSteps >= 290,
             qPrintable(QString("%1 of 300 steps kept a fat box").arg(keptSteps)));
    QVERIFY2(apartPairs > 500, qPrintable(QString("%1 pairs came apart").arg(apartPairs)));
}

RIGIDLAB_TEST_GUILESS_MAIN(TestBroadPhase)
#include "test_broad_phase.moc"
