// SPDX-License-Identifier: GPL-3.0-or-later
// Impacts that conserve what physics conserves, for every solver that bounces (the
// soft step bounces in the sequential solver's collision phase, before its substeps):
//  - an elastic gas (e = 1, no friction, no gravity, balls in a closed box of static walls)
//    keeps its kinetic energy, also when a ball bounces off a wall into a neighbour a few
//    millimetres behind it within one step;
//  - a free off-centre box-box collision timed within a step (e = 0.7, mu = 0.3) conserves
//    linear momentum and angular momentum about any point to round-off;
//  - a ball into a row of touching balls (several contacts at once) gains no energy in any
//    step.

#include "physics_test_util.h"

#include <rigidlab/physics/world.h>

#include "test_main.h"

#include <QTest>

#include <cmath>
#include <cstdint>
#include <utility>

using namespace rigidlab::physics;

namespace {

/// Angular momentum of every body about the point o [kg m^2/s], from its state.
double angularMomentumAbout(const World& world, const Vec2& o)
{
    double l = 0.0;
    for (const Body& b : world.bodies())
        l += b.mass * rigidlab::test::cross2(b.position - o, b.velocity) +
             b.inertia * b.angularVelocity;
    return l;
}

WorldDef elasticWorld(SolverKind solver, double dt)
{
    WorldDef def = rigidlab::test::quietWorldDef(IntegratorKind::SymplecticEuler, dt);
    def.solver = solver;
    def.restitution = 1.0;
    def.friction = 0.0;
    return def;
}

} // namespace

class TestConservation : public QObject {
    Q_OBJECT

private slots:
    void gasKeepsEnergy_data();
    void gasKeepsEnergy();
    void wallBounceIntoNeighbour_data();
    void wallBounceIntoNeighbour();
    void offCentreBoxHitWithinStep_data();
    void offCentreBoxHitWithinStep();
    void touchingRowGainsNothing_data();
    void touchingRowGainsNothing();
};

static void solverRows()
{
    QTest::addColumn<SolverKind>("solver");
    QTest::newRow("seed-impulse") << SolverKind::PaperImpulse;
    QTest::newRow("sequential-impulse") << SolverKind::SequentialImpulse;
    QTest::newRow("soft-step") << SolverKind::SoftStep;
}

void TestConservation::gasKeepsEnergy_data()
{
    solverRows();
}

// 40 balls of radius 0.1 m at up to 5 m/s per component in a closed 4 m x 2.5 m box, dt 1 ms,
// 5 s (some 60 collisions a second). Exact mechanics keeps the kinetic energy; the solver
// before the collision phase lost about 1 % in these 5 s (12 % in 10 s with 100 balls).
void TestConservation::gasKeepsEnergy()
{
    QFETCH(SolverKind, solver);
    World world(elasticWorld(solver, 1e-3));
    const double halfW = 2.0, halfH = 1.25, thick = 1.0; // [m]
    const auto wall = [&](double x, double y, double w, double h) {
        BodyDef d;
        d.type = BodyType::Static;
        d.shape = makePolygonShape(makeBox(w, h));
        d.position = {x, y};
        world.addBody(d);
    };
    wall(0, -halfH - 0.5 * thick, 2 * (halfW + thick), thick);
    wall(0, halfH + 0.5 * thick, 2 * (halfW + thick), thick);
    wall(-halfW - 0.5 * thick, 0, thick, 2 * (halfH + thick));
    wall(halfW + 0.5 * thick, 0, thick, 2 * (halfH + thick));
    std::uint32_t seed = 2024;
    const auto random = [&seed] { // a fixed linear congruential sequence in [-1, 1)
        seed = seed * 1664525u + 1013904223u;
        return static_cast<double>(seed >> 8) / static_cast<double>(1u << 23) - 1.0;
    };
    for (int i = 0; i < 40; ++i)
        world.addBody(rigidlab::test::circleBody(
            0.1, {-halfW + 0.5 * (0.5 + i % 8), -halfH + 0.5 * (0.5 + i / 8)},
            {5.0 * random(), 5.0 * random()}));
    const double start = rigidlab::test::kineticEnergy(world);
    for (int i = 0; i < 5000; ++i)
        world.step();
    RL_VERIFY_NEAR(rigidlab::test::kineticEnergy(world), start, 0.0, 0.01);
    for (const Body& b : world.bodies())
        if (b.isDynamic())
            QVERIFY(std::abs(b.position.x()) < halfW && std::abs(b.position.y()) < halfH);
}

void TestConservation::wallBounceIntoNeighbour_data()
{
    solverRows();
}

// The event the issue traced: a ball meets a wall within the step while an equal ball follows
// it 3 mm behind, both at 4 m/s. After the wall both bounce back, the leader from the wall and
// the follower from the leader (exchanging velocities), and the kinetic energy is as before.
//
//     |wall|  (A) <-- 3 mm --> (B)     both moving left at 4 m/s, A 2 mm from the wall
void TestConservation::wallBounceIntoNeighbour()
{
    QFETCH(SolverKind, solver);
    World world(elasticWorld(solver, 1e-3));
    BodyDef wall;
    wall.type = BodyType::Static;
    wall.shape = makePolygonShape(makeBox(1.0, 4.0));
    wall.position = {-0.5, 0.0};
    world.addBody(wall);
    const BodyId a = world.addBody(rigidlab::test::circleBody(0.1, {0.102, 0.0}, {-4.0, 0.0}));
    const BodyId b = world.addBody(rigidlab::test::circleBody(0.1, {0.305, 0.0}, {-4.0, 0.0}));
    const double start = rigidlab::test::kineticEnergy(world);
    for (int i = 0; i < 50; ++i)
        world.step();
    RL_VERIFY_NEAR(rigidlab::test::kineticEnergy(world), start, 0.0, 1e-9);
    RL_VERIFY_NEAR(world.body(a).velocity.x(), 4.0, 1e-9, 0.0);
    RL_VERIFY_NEAR(world.body(b).velocity.x(), 4.0, 1e-9, 0.0);
}

void TestConservation::offCentreBoxHitWithinStep_data()
{
    solverRows();
}

// Two boxes in free flight (no gravity, e = 0.7, mu = 0.3) meet off-centre and spinning, at
// 0.37 of a step: the impulse's lever arms are those of that moment, so linear momentum and
// angular momentum about the origin and about another point are what they were, to
// round-off, in every step (taken from the step's start, they changed it by 2e-3 of itself).
//
//      [ A ] -->          <-- [ B ]       B 0.3 m lower, both turning; A twice as dense
void TestConservation::offCentreBoxHitWithinStep()
{
    QFETCH(SolverKind, solver);
    const double dt = 1e-3;
    WorldDef def = rigidlab::test::quietWorldDef(IntegratorKind::SymplecticEuler, dt);
    def.solver = solver;
    def.restitution = 0.7;
    def.friction = 0.3;
    World world(def);
    BodyDef a = rigidlab::test::boxBody(0.6, 0.4, {-0.5, 0.2}, 0.0, 2.0);
    a.velocity = {3.0, 0.1};
    a.angularVelocity = 0.4;
    BodyDef b = rigidlab::test::boxBody(0.5, 0.5, {0.5, -0.1}, 0.0, 1.0);
    b.velocity = {-2.0, 0.0};
    b.angularVelocity = -0.3;
    // Gap between A's right face (x = -0.2) and B's left face (x = 0.25) along x: 0.45 m at
    // 5 m/s is 90 ms; start 0.37 ms of flight earlier than a whole number of steps.
    a.position.x() -= 5.0 * 0.00037 + 0.0;
    const BodyId ia = world.addBody(a);
    const BodyId ib = world.addBody(b);
    const Vec2 other(3.0, -2.0);
    const Vec2 p0 = rigidlab::test::momentum(world);
    const double l0 = angularMomentumAbout(world, Vec2::Zero());
    const double m0 = angularMomentumAbout(world, other);
    const Vec2 va0 = world.body(ia).velocity;
    double worstL = 0, worstM = 0, worstP = 0;
    for (int i = 0; i < 200; ++i) {
        world.step();
        worstL = std::max(worstL, std::abs(angularMomentumAbout(world, Vec2::Zero()) - l0));
        worstM = std::max(worstM, std::abs(angularMomentumAbout(world, other) - m0));
        worstP = std::max(worstP, (rigidlab::test::momentum(world) - p0).norm());
    }
    // They met: A (the heavier) slowed down by more than a third, B turned by the off-centre
    // hit.
    QVERIFY2(world.body(ia).velocity.x() < va0.x() - 1.0,
             qPrintable(QStringLiteral("A's velocity %1").arg(world.body(ia).velocity.x())));
    QVERIFY(std::abs(world.body(ib).angularVelocity + 0.3) > 0.1);
    RL_VERIFY_AT_MOST(worstL, 1e-12 * std::abs(l0));
    RL_VERIFY_AT_MOST(worstM, 1e-12 * std::abs(m0));
    RL_VERIFY_AT_MOST(worstP, 1e-12 * p0.norm() + 1e-15);
}

void TestConservation::touchingRowGainsNothing_data()
{
    QTest::addColumn<SolverKind>("solver");
    QTest::addColumn<double>("gap");
    for (const auto& [name, kind] : {std::pair("seed-impulse", SolverKind::PaperImpulse),
                                     std::pair("sequential-impulse", SolverKind::SequentialImpulse),
                                     std::pair("soft-step", SolverKind::SoftStep)}) {
        QTest::addRow("%s, gap 0.7 mm", name) << kind << 0.0007;
        // The striker touches exactly at the end of a step (1 m/s x 0.5 ms): the soft step's
        // substeps bring it to touching and must not stop it there without a bounce.
        QTest::addRow("%s, gap 0.5 mm", name) << kind << 0.0005;
    }
}

// A ball at 1 m/s into a row of four touching equal balls (e = 1, no gravity): every contact
// of the row acts in the same step. No step may gain energy (relative 1e-9), none is lost
// (the collision phase's sweeps pass the blow along the row), the momentum stays.
void TestConservation::touchingRowGainsNothing()
{
    QFETCH(SolverKind, solver);
    QFETCH(double, gap);
    World world(elasticWorld(solver, 5e-4));
    const double r = 0.05;
    world.addBody(rigidlab::test::circleBody(r, {-2 * r - gap, 0.0}, {1.0, 0.0}));
    for (int i = 0; i < 4; ++i)
        world.addBody(rigidlab::test::circleBody(r, {2 * r * i, 0.0}));
    const Vec2 p0 = rigidlab::test::momentum(world);
    double previous = rigidlab::test::kineticEnergy(world);
    const double start = previous;
    for (int i = 0; i < 200; ++i) {
        world.step();
        const double e = rigidlab::test::kineticEnergy(world);
        RL_VERIFY_AT_MOST(e, previous * (1.0 + 1e-9));
        previous = e;
    }
    QVERIFY((rigidlab::test::momentum(world) - p0).norm() < 1e-12 * p0.norm());
    // The row took the blow, it did not swallow it: e = 1, one ball out at the far end.
    RL_VERIFY_NEAR(previous, start, 0.0, 1e-6);
}

RIGIDLAB_TEST_GUILESS_MAIN(TestConservation)

#include "test_conservation.moc"
