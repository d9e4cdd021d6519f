// SPDX-License-Identifier: GPL-3.0-or-later
// The energy balance: what drag, the dampers of springs and contacts (friction, inelastic
// bounces) take is counted where it happens (Diagnostics::dissipated), so that
// total + dissipated - E0 is the integrator's error alone. Each loss is checked against exact
// mechanics, and the balance against the integrator's known error.

#include "physics_test_util.h"

#include <rigidlab/physics/world.h>

#include "test_main.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <tuple>

using namespace rigidlab::physics;

namespace {

/// The largest |total + dissipated - E0| / E0 over the steps, stepping the world n times.
double worstBalance(World& world, int steps)
{
    world.updateDiagnostics();
    const double e0 = world.diagnostics().total;
    double worst = 0.0;
    for (int i = 0; i < steps; ++i) {
        world.step();
        const Diagnostics& d = world.diagnostics();
        worst = std::max(worst, std::abs(d.total + d.dissipated - e0) / e0);
    }
    return worst;
}

} // namespace

class TestEnergy : public QObject {
    Q_OBJECT

private slots:
    void dampedSpring_data();
    void dampedSpring();
    void drag_data();
    void drag();
    void slidingBlockStops();
    void nothingDissipatesNothingCounted();
    void pendulumBesideRestingBox_data();
    void pendulumBesideRestingBox();
    void rollingDiscBooks_data();
    void rollingDiscBooks();
    void ballDropBooks_data();
    void ballDropBooks();
};

// The damped oscillator of test_world (m = 2 kg, k = 50 N/m, c = 2 N s/m, x0 = 0.3 m,
// v0 = 0.5 m/s; w0 = 5 rad/s, zeta = 0.1), dt = 1e-3, 5 s. Exactly,
//   x(t) = e^(-zeta w0 t) (x0 cos(wd t) + (v0 + zeta w0 x0) / wd sin(wd t)),
// and the damper has taken E0 - E(t) by time t. Over 5 s it takes 99 % of E0, so a balance
// that forgot it would be off by 0.99. Bounds, relative to E0, about three times what each
// method gives (measured: Euler 0.027, symplectic Euler 0.0038 and 0.0015, Verlet 1.9e-5,
// RK4 and dopri5 6.5e-6, the midpoint rule 3e-15 and 1.8e-7):
//   - balance, |E + dissipated - E0|: the integrator's own energy error, first order for the
//     Euler methods (w0 h = 0.005: symplectic Euler's energy wobbles by about w0 h / 2, explicit
//     Euler's grows by (w0 h)^2 a step while the damper shrinks it), (w0 h)^2 for Verlet, and
//     for RK4 and dopri5 the trapezoid rule that counts their loss, of order (w0 h)^2 / 4. The
//     midpoint rule keeps a quadratic energy exactly and its loss is counted at the midpoint,
//     where it acts: rounding alone.
//   - loss against E0 - E_exact(5 s): the balance's error and the integrator's error in E,
//     which for the midpoint rule is of order (w0 h)^2 / 12.
void TestEnergy::dampedSpring_data()
{
    QTest::addColumn<IntegratorKind>("integrator");
    QTest::addColumn<double>("balance");
    QTest::addColumn<double>("loss");
    QTest::newRow("euler") << IntegratorKind::Euler << 0.08 << 0.08;
    QTest::newRow("symplectic-euler") << IntegratorKind::SymplecticEuler << 1e-2 << 5e-3;
    QTest::newRow("verlet") << IntegratorKind::Verlet << 6e-5 << 6e-5;
    QTest::newRow("rk4") << IntegratorKind::RK4 << 2e-5 << 2e-5;
    QTest::newRow("dopri5") << IntegratorKind::DormandPrince << 2e-5 << 2e-5;
    QTest::newRow("implicit-midpoint") << IntegratorKind::ImplicitMidpoint << 1e-12 << 6e-7;
}

void TestEnergy::dampedSpring()
{
    QFETCH(IntegratorKind, integrator);
    QFETCH(double, balance);
    QFETCH(double, loss);
    rigidlab::test::OscillatorSpec spec;
    spec.mass = 2.0;
    spec.stiffness = 50.0;
    spec.damping = 2.0;
    spec.x0 = 0.3;
    spec.v0 = 0.5;
    const double h = 1e-3, time = 5.0;
    World world = rigidlab::test::makeOscillator(integrator, h, spec);
    world.updateDiagnostics();
    const double e0 = world.diagnostics().total;
    RL_VERIFY_NEAR(e0,
                   0.5 * spec.stiffness * spec.x0 * spec.x0 + 0.5 * spec.mass * spec.v0 * spec.v0,
                   0.0, 1e-12);
    const double worst = worstBalance(world, static_cast<int>(std::lround(time / h)));
    RL_VERIFY_AT_MOST(worst, balance);

    const double w0 = std::sqrt(spec.stiffness / spec.mass);
    const double zeta = spec.damping / (2.0 * std::sqrt(spec.stiffness * spec.mass));
    const double wd = w0 * std::sqrt(1.0 - zeta * zeta);
    const double b = (spec.v0 + zeta * w0 * spec.x0) / wd;
    const double decay = std::exp(-zeta * w0 * time);
    const double x = decay * (spec.x0 * std::cos(wd * time) + b * std::sin(wd * time));
    const double v = decay * ((b * wd - zeta * w0 * spec.x0) * std::cos(wd * time) -
                              (spec.x0 * wd + zeta * w0 * b) * std::sin(wd * time));
    const double lossExact = e0 - (0.5 * spec.stiffness * x * x + 0.5 * spec.mass * v * v);
    QVERIFY(lossExact > 0.98 * e0);
    const Diagnostics& d = world.diagnostics();
    RL_VERIFY_NEAR(d.dampingLoss, lossExact, loss * e0, 0.0);
    QCOMPARE(d.dissipated, d.dampingLoss);
    QCOMPARE(d.dragLoss, 0.0);
    QCOMPARE(d.collisionLoss, 0.0);
}

// Linear drag (c = 0.7 /s) on a free spinning box without gravity: v = v0 e^(-ct),
// w = w0 e^(-ct), so drag has taken (m v0^2 + I w0^2) / 2 (1 - e^(-2ct)) by time t (3 s:
// 98.5 %). Symplectic Euler here takes the direct path on the bodies, RK4 the ODE system.
// Bounds relative to E0, about three times what each gives:
//   - balance: for symplectic Euler drag's exact share of each step (rounding alone, measured
//     2e-15); for RK4 the trapezoid count, of order (c h)^2 (measured 4e-8).
//   - loss against the exact one: symplectic Euler's velocity decays as (1 - c h)^n, not
//     e^(-ct), an error of order c h (measured 2.2e-5); RK4's is the balance's.
void TestEnergy::drag_data()
{
    QTest::addColumn<IntegratorKind>("integrator");
    QTest::addColumn<double>("balance");
    QTest::addColumn<double>("loss");
    QTest::newRow("symplectic-euler (direct)") << IntegratorKind::SymplecticEuler << 1e-12 << 7e-5;
    QTest::newRow("rk4") << IntegratorKind::RK4 << 1.5e-7 << 1.5e-7;
}

void TestEnergy::drag()
{
    QFETCH(IntegratorKind, integrator);
    QFETCH(double, balance);
    QFETCH(double, loss);
    const double c = 0.7, h = 1e-3, time = 3.0;
    WorldDef def = rigidlab::test::quietWorldDef(integrator, h);
    def.drag = c;
    World world(def);
    BodyDef box = rigidlab::test::boxBody(0.5, 0.3, Vec2(1.0, 2.0), 0.2);
    box.velocity = Vec2(3.0, -1.0);
    box.angularVelocity = 2.0;
    world.addBody(box);
    world.updateDiagnostics();
    const double e0 = world.diagnostics().total;
    const double worst = worstBalance(world, static_cast<int>(std::lround(time / h)));
    RL_VERIFY_AT_MOST(worst, balance);
    const double lossExact = e0 * (1.0 - std::exp(-2.0 * c * time));
    const Diagnostics& d = world.diagnostics();
    RL_VERIFY_NEAR(d.dragLoss, lossExact, loss * e0, 0.0);
    QCOMPARE(d.dissipated, d.dragLoss);
}

// A 0.4 m x 0.2 m block slides at v0 = 2 m/s on a static floor, friction 0.5 (each body's,
// so the pair's too), no bounce, g = 9.81. Exactly it stops after v0 / (mu g) = 0.41 s and
// v0^2 / (2 mu g) = 0.408 m, and friction has taken all its kinetic energy, m v0^2 / 2. Run
// 1 s, sequential impulses (the paper's one impulse per point leaves the block rocking). The
// block rests on the floor all along, and a resting contact takes nothing (the normal impulse
// cancels gravity within the step), while friction's impulses add up to the kinetic energy
// exactly (m dv . (v0 + v1) / 2 summed over the steps telescopes). So the count is exact but
// for rounding and for any rocking of the block on its two contact points: a bound of 1e-6 of
// m v0^2 / 2 (measured: 0, and the balance 2e-16). The distance is the discrete
// deceleration's, within a step's travel v0 h = 2 mm of the exact one.
void TestEnergy::slidingBlockStops()
{
    const double mu = 0.5, v0 = 2.0, g = 9.81, h = 1e-3;
    WorldDef def = rigidlab::test::quietWorldDef(IntegratorKind::SymplecticEuler, h);
    def.gravity = Vec2(0.0, -g);
    def.solver = SolverKind::SequentialImpulse;
    def.restitution = 0.0;
    def.friction = mu;
    World world(def);
    BodyDef floor = rigidlab::test::boxBody(4.0, 0.2, Vec2(0.0, -0.1));
    floor.type = BodyType::Static;
    world.addBody(floor);
    BodyDef block = rigidlab::test::boxBody(0.4, 0.2, Vec2(-1.0, 0.1));
    block.velocity = Vec2(v0, 0.0);
    const BodyId id = world.addBody(block);
    const double m = world.body(id).mass;
    const double k0 = 0.5 * m * v0 * v0;

    const double worst = worstBalance(world, 1000);
    const Body& b = world.body(id);
    RL_VERIFY_NEAR(b.velocity.norm(), 0.0, 1e-6, 0.0);
    RL_VERIFY_NEAR(b.position.x() + 1.0, v0 * v0 / (2.0 * mu * g), v0 * h, 0.0);
    const Diagnostics& d = world.diagnostics();
    RL_VERIFY_NEAR(d.collisionLoss, k0, 1e-6 * k0, 0.0);
    QCOMPARE(d.dissipated, d.collisionLoss);
    // The balance, relative to E0 = k0 + m g y0, holds as tightly.
    RL_VERIFY_AT_MOST(worst, 1e-6);
}

// Without drag, dampers or contacts nothing is counted: the balance is the plain energy.
void TestEnergy::nothingDissipatesNothingCounted()
{
    rigidlab::test::OscillatorSpec spec;
    World world = rigidlab::test::makeOscillator(IntegratorKind::SymplecticEuler, 1e-3, spec);
    worstBalance(world, 1000);
    const Diagnostics& d = world.diagnostics();
    QCOMPARE(d.dissipated, 0.0);
}

// A pendulum on a pin (a 6 kg ball, 3.2 m from the pin, let go at 40°) swings freely beside a
// box resting on the floor, out of its reach: the box's resting contact must not touch the
// pendulum's energy. (The joints were projected again after every contact solve that pushed
// anything, and the pendulum's chord velocities, from the SHAKE step, projected onto its
// tangent gained it 3 % in 2 minutes.) Over 30 s the pendulum's energy stays within the
// integrator's wobble, 1e-4 of it, as alone; the contacts take nothing (sequential impulses,
// to 1e-9 J), or the soft contact's settling of the box into the floor by 50 nm in its first
// steps (the soft step: 2.4e-7 J, bound 3e-7 J): what the box lost, to 1e-3 of it.
void TestEnergy::pendulumBesideRestingBox_data()
{
    QTest::addColumn<SolverKind>("solver");
    QTest::addColumn<double>("settling");
    QTest::newRow("sequential") << SolverKind::SequentialImpulse << 1e-9;
    QTest::newRow("soft step") << SolverKind::SoftStep << 3e-7;
}

void TestEnergy::pendulumBesideRestingBox()
{
    QFETCH(SolverKind, solver);
    QFETCH(double, settling);
    const auto run = [solver](bool box) {
        WorldDef def = rigidlab::test::quietWorldDef(IntegratorKind::SymplecticEuler, 1e-3);
        def.gravity = Vec2(0.0, -9.81);
        def.solver = solver;
        def.sleep = false;
        World world(def);
        BodyDef floor = rigidlab::test::boxBody(8.0, 0.3, Vec2(0.0, -0.15));
        floor.type = BodyType::Static;
        world.addBody(floor);
        if (box)
            world.addBody(rigidlab::test::boxBody(0.35, 0.35, Vec2(2.0, 0.175), 0.0, 4.0));
        const Vec2 pin(-1.6, 4.2);
        const double length = 3.2, start = -0.6981317007977318;
        const BodyId b = world.addBody(rigidlab::test::circleBody(
            0.22, pin + length * Vec2(std::sin(start), -std::cos(start)), Vec2::Zero(), 20.0));
        PinJointDef joint;
        joint.a = b;
        joint.anchorA = pin - world.body(b).position;
        joint.b = kWorld;
        joint.anchorB = pin;
        world.addPinJoint(joint);
        const auto energy = [&] {
            const Body& p = world.body(b);
            return 0.5 * p.mass * p.velocity.squaredNorm() +
                   0.5 * p.inertia * p.angularVelocity * p.angularVelocity +
                   p.mass * 9.81 * (p.position.y() - pin.y());
        };
        // The box's energy, kinetic and potential (0 without it) [J].
        const auto boxEnergy = [&] {
            if (!box)
                return 0.0;
            const Body& p = world.body(1);
            return 0.5 * p.mass * p.velocity.squaredNorm() +
                   0.5 * p.inertia * p.angularVelocity * p.angularVelocity +
                   p.mass * 9.81 * p.position.y();
        };
        const double e0 = energy(), box0 = boxEnergy();
        double worst = 0.0;
        for (int i = 0; i < 30000; ++i) {
            world.step();
            worst = std::max(worst, std::abs(energy() - e0));
        }
        return std::tuple(world.body(b).position, worst / std::abs(e0),
                          world.diagnostics().collisionLoss, box0 - boxEnergy());
    };
    const auto [alone, alonesWobble, none, nothing] = run(false);
    const auto [beside, wobble, loss, settled] = run(true);
    qInfo("pendulum energy wobble over 30 s: %.3g alone, %.3g beside the box; the contacts "
          "took %.3g J, the box lost %.3g J",
          alonesWobble, wobble, loss, settled);
    QCOMPARE(beside, alone); // the box's contact leaves the pendulum's motion alone
    RL_VERIFY_AT_MOST(wobble, 1e-3);
    RL_VERIFY_AT_MOST(std::abs(loss), settling);
    RL_VERIFY_NEAR(loss, settled, 1e-12, 1e-3); // the books close
    QCOMPARE(none, 0.0);
    QCOMPARE(nothing, 0.0);
}

// A disc (r = 0.1 m, 1 kg, I = m r^2 / 2) rolling without slip on level ground in the soft step
// (the default solver), dt = 1/60 s: friction does no work and the ground none either, so its
// energy stays, and the books must say that the contacts took nothing. After the first second
// (the soft contact settles the disc into the ground, rolling), over 10 s: the energy within
// 1e-9 of it, what the contacts took within 1e-9 of it, and from the start the balance
// total + dissipated - E0 within 1e-9 of E0 (the settling into the soft contact included). (The
// books counted the load's work at the relaxed velocities of each substep instead of those that
// moved the disc: they said the contacts took 6.4 J in 10 s, 160 % of its energy, while the disc
// kept it.)
void TestEnergy::rollingDiscBooks_data()
{
    QTest::addColumn<double>("speed"); // [m/s]
    QTest::newRow("1 m/s") << 1.0;
    QTest::newRow("2 m/s") << 2.0;
    QTest::newRow("4 m/s") << 4.0;
}

void TestEnergy::rollingDiscBooks()
{
    QFETCH(double, speed);
    const double r = 0.1, dt = 1.0 / 60.0;
    WorldDef def = rigidlab::test::exactWorld(SolverKind::SoftStep, dt, 0.0, 0.5);
    def.gravity = Vec2(0.0, -9.81);
    World world(def);
    BodyDef ground = rigidlab::test::boxBody(200.0, 0.4, Vec2(0.0, -0.2));
    ground.type = BodyType::Static;
    world.addBody(ground);
    BodyDef disc = rigidlab::test::circleBody(r, Vec2(-50.0, r), Vec2(speed, 0.0));
    disc.mass = 1.0;
    disc.angularVelocity = -speed / r;
    world.addBody(disc);
    world.updateDiagnostics();
    const double e0 = world.diagnostics().total;
    for (int i = 0; i < 60; ++i)
        world.step();
    const double e1 = world.diagnostics().total, taken1 = world.diagnostics().collisionLoss;
    for (int i = 0; i < 600; ++i)
        world.step();
    const Diagnostics& d = world.diagnostics();
    qInfo("rolling at %g m/s: energy %.9f J after 1 s, %.9f J after 11 s; the contacts took "
          "%.3g J in between; balance %.3g of E0",
          speed, e1, d.total, d.collisionLoss - taken1, (d.total + d.dissipated - e0) / e0);
    RL_VERIFY_NEAR(d.total, e1, 0.0, 1e-9);
    RL_VERIFY_NEAR(d.collisionLoss - taken1, 0.0, 1e-9 * e1, 0.0);
    RL_VERIFY_NEAR(d.total + d.dissipated, e0, 0.0, 1e-9);
}

// The ball drop (balls of e = 0.9, 0.6 and 0.3, 0.5 kg, r = 0.1 m, 1 m apart, dropped from 2 m
// onto a floor of e = 0) in the soft step at dt 0.01-0.2 s, until all three rest (30 s): the
// contacts took what the balls lost, total + dissipated = E0 to 1e-9 of E0. (The bounces were
// booked at the velocity of the step's line, half a substep behind the substeps' parabola, and
// a ball resting at long steps was lifted back after the books had counted its sink: at
// dt = 0.2 s the books were 11.8 J out of 30.9 J.)
void TestEnergy::ballDropBooks_data()
{
    QTest::addColumn<double>("dt");
    for (double dt : {0.01, 0.1, 0.15, 0.2})
        QTest::addRow("dt %g s", dt) << dt;
}

void TestEnergy::ballDropBooks()
{
    QFETCH(double, dt);
    WorldDef def = rigidlab::test::exactWorld(SolverKind::SoftStep, dt, 0.5, 0.3);
    def.gravity = Vec2(0.0, -9.81);
    World world(def);
    BodyDef floor = rigidlab::test::boxBody(6.0, 0.4, Vec2(0.0, -0.2));
    floor.type = BodyType::Static;
    floor.restitution = 0.0;
    world.addBody(floor);
    const double restitution[] = {0.9, 0.6, 0.3};
    for (int k = 0; k < 3; ++k) {
        BodyDef ball = rigidlab::test::circleBody(0.1, Vec2(k - 1.0, 2.1));
        ball.mass = 0.5;
        ball.restitution = restitution[k];
        world.addBody(ball);
    }
    world.updateDiagnostics();
    const double e0 = world.diagnostics().total;
    for (int i = 0; i < static_cast<int>(std::lround(30.0 / dt)); ++i)
        world.step();
    const Diagnostics& d = world.diagnostics();
    double fastest = 0.0;
    for (const Body& b : world.bodies())
        fastest = std::max(fastest, b.velocity.norm());
    qInfo("dt = %g s: the contacts took %.9f J, the balls lost %.9f J", dt, d.collisionLoss,
          e0 - d.total);
    RL_VERIFY_AT_MOST(fastest, 1e-6); // all at rest
    RL_VERIFY_NEAR(d.total + d.dissipated, e0, 0.0, 1e-9);
}

RIGIDLAB_TEST_GUILESS_MAIN(TestEnergy)
#include "test_energy.moc"
