// SPDX-License-Identifier: GPL-3.0-or-later
// The soft step with smooth forces (springs, pins, gravitation) and every integrator: the
// integrator carries the smooth motion and the substeps the contacts (soft_step.cpp). Checked
// against each integrator's own discrete solution, with contacts absent and with a contact
// elsewhere in the scene (so that the substeps run), and where a contact meets a pinned body.

#include "physics_test_util.h"

#include <rigidlab/physics/world.h>

#include "test_main.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace rigidlab::physics;
using rigidlab::test::boxBody;
using rigidlab::test::circleBody;

namespace {

constexpr double kG = 9.81; // [m/s^2]

/// A box standing on a static floor far from everything else: a contact in every step, so that
/// the soft step runs its substeps.
void addRestingBox(World& world)
{
    // 500 m below: farther than any body here moves in a step, so that no speculative contact
    // of a fast body reaches it.
    BodyDef floor = boxBody(4.0, 1.0, Vec2(0.0, -500.5));
    floor.type = BodyType::Static;
    world.addBody(floor);
    world.addBody(boxBody(0.5, 0.5, Vec2(0.0, -499.75)));
}

/// The angle per step of an integrator's discrete solution of x'' = -w^2 x at z = w h: the
/// argument of its amplification matrix's eigenvalue, from its one-step formula.
double discreteAngle(IntegratorKind kind, double z)
{
    switch (kind) {
    case IntegratorKind::Euler: // [[1, h], [-w^2 h, 1]]: 1 +- i z
        return std::atan(z);
    case IntegratorKind::SymplecticEuler: // trace 2 - z^2, determinant 1
    case IntegratorKind::Verlet:          // the same map on positions
        return std::acos(1.0 - z * z / 2.0);
    case IntegratorKind::RK4: // the Taylor polynomial of exp(i z) to fourth order
        return std::atan2(z - z * z * z / 6.0, 1.0 - z * z / 2.0 + z * z * z * z / 24.0);
    default:
        return NAN;
    }
}

/// The angle per step of a sampled damped or growing oscillation x_n = r^n A cos(n theta + p),
/// from the positions alone: such a sequence obeys x_{n+1} = T x_n - D x_{n-1} with
/// T = 2 r cos(theta), D = r^2, found here by least squares over the whole run.
double measuredAngle(const std::vector<double>& x)
{
    double a11 = 0, a12 = 0, a22 = 0, b1 = 0, b2 = 0;
    for (size_t n = 1; n + 1 < x.size(); ++n) {
        a11 += x[n] * x[n];
        a12 -= x[n] * x[n - 1];
        a22 += x[n - 1] * x[n - 1];
        b1 += x[n + 1] * x[n];
        b2 -= x[n + 1] * x[n - 1];
    }
    const double det = a11 * a22 - a12 * a12;
    const double T = (b1 * a22 - a12 * b2) / det, D = (a11 * b2 - a12 * b1) / det;
    return std::acos(T / (2.0 * std::sqrt(D)));
}

/// Total energy plus what was dissipated: constant but for the integrator's error.
double energyBalance(const World& world)
{
    return world.diagnostics().total + world.diagnostics().dissipated;
}

} // namespace

class TestSoftSmooth : public QObject {
    Q_OBJECT

private slots:
    void springPeriodIsIntegrators_data();
    void springPeriodIsIntegrators();
    void sameStepAsIntegrator_data();
    void sameStepAsIntegrator();
    void doublePendulumKeepsEnergy_data();
    void doublePendulumKeepsEnergy();
    void pendulumStrikesBox_data();
    void pendulumStrikesBox();
};

// A spring oscillator (m = 1 kg, k = 4 N/m: w = 2 rad/s) at the coarse step w h = 0.5 under
// the soft step: its period is the integrator's own, 2 pi h / theta with theta the angle per
// step of the integrator's discrete solution (discreteAngle, from its one-step formula), not
// the exact 2 pi / w (which differs from it by 0.02 % to 7 %). Measured from 60 steps of the
// body's positions (measuredAngle), to 1e-9 relative; alone, and beside a box standing on a
// floor (the substeps then run each step).
void TestSoftSmooth::springPeriodIsIntegrators_data()
{
    QTest::addColumn<IntegratorKind>("kind");
    QTest::addColumn<bool>("contact");
    for (IntegratorKind kind : {IntegratorKind::Euler, IntegratorKind::SymplecticEuler,
                                IntegratorKind::Verlet, IntegratorKind::RK4})
        for (bool contact : {false, true})
            QTest::addRow("%s%s", std::string(integratorName(kind)).c_str(),
                          contact ? ", beside a resting box" : "")
                << kind << contact;
}

void TestSoftSmooth::springPeriodIsIntegrators()
{
    QFETCH(IntegratorKind, kind);
    QFETCH(bool, contact);
    rigidlab::test::OscillatorSpec spec; // m = 1, k = 4, x0 = 0.5
    // The anchor far away: the spring stays linear while explicit Euler's amplitude grows
    // eightfold per 3 s.
    spec.restLength = 1e4;
    const double w = std::sqrt(spec.stiffness / spec.mass), h = 0.5 / w;
    World world = rigidlab::test::makeOscillator(kind, h, spec);
    world.setSolver(SolverKind::SoftStep);
    if (contact) // without gravity: the box touches the floor, and the contact stays
        addRestingBox(world);
    const double own = 2.0 * std::numbers::pi * h / discreteAngle(kind, w * h);
    const double exact = 2.0 * std::numbers::pi / w;
    QVERIFY(std::abs(own - exact) > 1e-4 * exact);
    std::vector<double> x{world.body(0).position.x()};
    for (int i = 0; i < 60; ++i) {
        world.step();
        x.push_back(world.body(0).position.x());
    }
    const double measured = 2.0 * std::numbers::pi * h / measuredAngle(x);
    qInfo("%s: period %.12f s, the integrator's own %.12f s, exact %.12f s",
          std::string(integratorName(kind)).c_str(), measured, own, exact);
    RL_VERIFY_NEAR(measured, own, 0.0, 1e-9);
}

// Without contacts the soft step's step is the integrator's, bit for bit: a pinned pendulum,
// a spring oscillator and a two-body orbit under gravitation, every integrator, 500 steps,
// the same state as the sequential-impulse solver's (which leaves the bodies to the
// integrator when nothing touches).
void TestSoftSmooth::sameStepAsIntegrator_data()
{
    QTest::addColumn<IntegratorKind>("kind");
    QTest::addColumn<int>("scene");
    for (IntegratorKind kind : kAllIntegrators)
        for (int scene : {0, 1, 2})
            QTest::addRow("%s, %s", std::string(integratorName(kind)).c_str(),
                          scene == 0   ? "pendulum"
                          : scene == 1 ? "oscillator"
                                       : "orbit")
                << kind << scene;
}

void TestSoftSmooth::sameStepAsIntegrator()
{
    QFETCH(IntegratorKind, kind);
    QFETCH(int, scene);
    auto run = [&](SolverKind solver) {
        World world = scene == 0 ? rigidlab::test::makePendulum(kind, 1e-2)
                                 : rigidlab::test::makeOscillator(kind, 1e-2);
        if (scene == 2) {
            WorldDef def = rigidlab::test::quietWorldDef(kind, 1e-2);
            def.gravitation = 1.0;
            world = World(def);
            BodyDef sun = circleBody(0.1, Vec2(0.0, 0.0), Vec2(0.0, -0.25));
            sun.mass = 3.0;
            BodyDef planet = circleBody(0.05, Vec2(2.0, 0.0), Vec2(0.0, 0.75 * 1.0));
            planet.mass = 1.0;
            world.addBody(sun);
            world.addBody(planet);
        }
        world.setSolver(solver);
        for (int i = 0; i < 500; ++i)
            world.step();
        std::vector<double> state;
        for (const Body& b : world.bodies())
            state.insert(state.end(), {b.position.x(), b.position.y(), b.angle, b.velocity.x(),
                                       b.velocity.y(), b.angularVelocity});
        return state;
    };
    QVERIFY(run(SolverKind::SoftStep) == run(SolverKind::SequentialImpulse));
}

// A double pendulum (two discs, the first pinned to the world, the second to the first) let
// go from 90° and 0°, RK4 at 1 ms for 5 s: the energy stays within 1e-6 of its scale (the
// integrator's error with the pins projected after each step), alone and beside a box resting
// on a floor (the substeps then run, and the pendulum's motion goes through them).
void TestSoftSmooth::doublePendulumKeepsEnergy_data()
{
    QTest::addColumn<bool>("contact");
    QTest::newRow("alone") << false;
    QTest::newRow("beside a resting box") << true;
}

void TestSoftSmooth::doublePendulumKeepsEnergy()
{
    QFETCH(bool, contact);
    WorldDef def = rigidlab::test::quietWorldDef(IntegratorKind::RK4, 1e-3);
    def.solver = SolverKind::SoftStep;
    def.gravity = Vec2(0.0, -kG);
    World world(def);
    const BodyId first = world.addBody(circleBody(0.05, Vec2(1.0, 0.0)));
    const BodyId second = world.addBody(circleBody(0.05, Vec2(1.0, -0.8)));
    world.addPinJoint({kWorld, Vec2(0.0, 0.0), first, Vec2(-1.0, 0.0)});
    world.addPinJoint({first, Vec2(0.0, 0.0), second, Vec2(0.0, 0.8)});
    if (contact)
        addRestingBox(world);
    // The pendulum's own energy, from the two discs' states.
    const auto energy = [&] {
        double e = 0.0;
        for (BodyId id : {first, second}) {
            const Body& b = world.body(id);
            e += 0.5 * b.mass * b.velocity.squaredNorm() +
                 0.5 * b.inertia * b.angularVelocity * b.angularVelocity +
                 b.mass * kG * b.position.y();
        }
        return e;
    };
    const double e0 = energy();
    const double scale = world.body(first).mass * kG * 1.8; // the drop of both discs, at most
    double worst = 0.0;
    for (int i = 0; i < 5000; ++i) {
        world.step();
        worst = std::max(worst, std::abs(energy() - e0));
    }
    qInfo("double pendulum, RK4, 5 s: largest energy error %.3e J of %.3g J", worst, scale);
    RL_VERIFY_AT_MOST(worst, 1e-6 * scale);
    RL_VERIFY_NEAR(world.body(first).position.norm(), 1.0, 1e-9, 0.0);
}

// A pendulum's bob (a 0.1 m disc on a 1 m rod, from 60°) swings into a box resting on the
// floor under its lowest point, with restitution 0.5 and friction, under the soft step with
// every integrator at 1/60 s: the pin holds (to 1e-9 m), the box is pushed away from the bob
// along +x, and the energy the bodies keep plus what the contacts and the rest took stays
// within 1 % of the start (a single-step integrator's error, which the pendulum alone shows
// too) over 4 s.
void TestSoftSmooth::pendulumStrikesBox_data()
{
    QTest::addColumn<IntegratorKind>("kind");
    for (IntegratorKind kind : {IntegratorKind::SymplecticEuler, IntegratorKind::Verlet,
                                IntegratorKind::RK4, IntegratorKind::ImplicitMidpoint})
        QTest::newRow(std::string(integratorName(kind)).c_str()) << kind;
}

void TestSoftSmooth::pendulumStrikesBox()
{
    QFETCH(IntegratorKind, kind);
    WorldDef def = rigidlab::test::quietWorldDef(kind, 1.0 / 60.0);
    def.solver = SolverKind::SoftStep;
    def.gravity = Vec2(0.0, -kG);
    def.restitution = 0.5;
    def.friction = 0.3;
    def.sleep = false;
    World world(def);
    BodyDef floor = boxBody(10.0, 1.0, Vec2(0.0, -1.7));
    floor.type = BodyType::Static;
    world.addBody(floor);
    const double theta0 = std::numbers::pi / 3.0;
    BodyDef bob = circleBody(0.1, Vec2(-std::sin(theta0), -std::cos(theta0)));
    bob.angle = -theta0;
    const BodyId id = world.addBody(bob);
    world.addPinJoint({id, Vec2(0.0, 1.0), kWorld, Vec2::Zero()});
    const BodyId box = world.addBody(boxBody(0.2, 0.4, Vec2(0.25, -1.0)));
    world.step();
    const double e0 = energyBalance(world), scale = energyParts(world.diagnostics());
    double worst = 0.0;
    for (int i = 0; i < 240; ++i) {
        world.step();
        worst = std::max(worst, std::abs(energyBalance(world) - e0));
        const Body& b = world.body(id);
        const Vec2 anchor = b.position + Rotation(b.angle).apply(Vec2(0.0, 1.0));
        RL_VERIFY_NEAR(anchor.norm(), 0.0, 1e-9, 0.0);
    }
    qInfo("%s: largest energy error %.3e J of %.3g J; box at x = %.3f m",
          std::string(integratorName(kind)).c_str(), worst, scale, world.body(box).position.x());
    QVERIFY(world.body(box).position.x() > 0.3);
    RL_VERIFY_AT_MOST(worst, 0.01 * scale);
}

RIGIDLAB_TEST_GUILESS_MAIN(TestSoftSmooth)
#include "test_soft_smooth.moc"
