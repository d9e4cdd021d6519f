// SPDX-License-Identifier: GPL-3.0-or-later
// The world as a whole: force elements (springs, drag, gravitation) against exact solutions,
// determinism (identical worlds and copied worlds), and a stack of boxes that must stand.

#include "physics_test_util.h"

#include <rigidlab/physics/world.h>

#include "test_main.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <vector>

using namespace rigidlab::physics;

namespace {

constexpr double kPi = std::numbers::pi;

/// Every double of every body's state, to compare worlds bit for bit.
std::vector<double> stateOf(const World& w)
{
    std::vector<double> s;
    for (const Body& b : w.bodies()) {
        s.insert(s.end(), {b.position.x(), b.position.y(), b.angle, b.velocity.x(), b.velocity.y(),
                           b.angularVelocity});
    }
    s.push_back(w.diagnostics().total);
    s.push_back(w.diagnostics().collisionLoss);
    s.push_back(w.time());
    return s;
}

bool bitIdentical(const std::vector<double>& a, const std::vector<double>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

/// A scene with every feature: a static ground, falling boxes and circles that collide, a
/// spring between two bodies and one to the world, a pendulum pinned to the world and a second
/// link pinned to it, drag.
World buildFullScene(SolverKind solver, IntegratorKind integrator)
{
    WorldDef def;
    def.dt = 1.0 / 240.0;
    def.solver = solver;
    def.integrator = integrator;
    def.drag = 0.05;
    World world(def);
    BodyDef ground = rigidlab::test::boxBody(20.0, 1.0, Vec2(0.0, -0.5));
    ground.type = BodyType::Static;
    world.addBody(ground);
    for (int i = 0; i < 5; ++i) {
        world.addBody(rigidlab::test::boxBody(0.8, 0.4, Vec2(0.1 * i, 0.3 + 0.6 * i), 0.05 * i));
    }
    for (int i = 0; i < 3; ++i) {
        world.addBody(rigidlab::test::circleBody(0.2 + 0.05 * i, Vec2(-1.5 + 0.3 * i, 1.0 + i),
                                                 Vec2(0.5, 0.0)));
    }
    SpringDef between;
    between.a = 2;
    between.b = 6;
    between.stiffness = 30.0;
    between.damping = 0.5;
    between.restLength = 1.0;
    world.addSpring(between);
    SpringDef toWorld;
    toWorld.a = 7;
    toWorld.anchorA = Vec2(0.1, 0.0);
    toWorld.b = kWorld;
    toWorld.anchorB = Vec2(-2.0, 4.0);
    toWorld.stiffness = 20.0;
    toWorld.restLength = 0.5;
    world.addSpring(toWorld);
    const BodyId link1 = world.addBody(rigidlab::test::boxBody(1.0, 0.1, Vec2(4.5, 4.0)));
    const BodyId link2 = world.addBody(rigidlab::test::boxBody(1.0, 0.1, Vec2(5.5, 4.0)));
    world.addPinJoint({link1, Vec2(-0.5, 0.0), kWorld, Vec2(4.0, 4.0)});
    world.addPinJoint({link2, Vec2(-0.5, 0.0), link1, Vec2(0.5, 0.0)});
    return world;
}

} // namespace

class TestWorld : public QObject {
    Q_OBJECT

private slots:
    // Forces.
    void dampedSpring();
    void twoBodySpring();
    void drag_data();
    void drag();
    void gravitationOrbit_data();
    void gravitationOrbit();
    // Determinism.
    void identicalWorldsAreBitIdentical_data();
    void identicalWorldsAreBitIdentical();
    void copiedWorldContinuesIdentically();
    void touchingPointsCountedWhenAsked();
    // Stacking.
    void boxStackStands_data();
    void boxStackStands();
};

// ---------------------------------------------------------------------------------------------
// Forces

// m x'' = -k x - c x' with zeta = c / (2 sqrt(k m)) = 0.1 < 1 (m = 2, k = 50, c = 2):
//   x(t) = e^(-zeta w0 t) (x0 cos(wd t) + (v0 + zeta w0 x0) / wd sin(wd t)), wd = w0 sqrt(1 -
//   zeta^2).
// RK4, dt = 1e-3, 5 s: within 1e-9 m of an amplitude of 0.3 m (RK4's error here is ~1e-11).
// The energy never rises (dE/dt = -c v^2 <= 0).
void TestWorld::dampedSpring()
{
    rigidlab::test::OscillatorSpec spec;
    spec.mass = 2.0;
    spec.stiffness = 50.0;
    spec.damping = 2.0;
    spec.x0 = 0.3;
    spec.v0 = 0.5;
    const double w0 = std::sqrt(spec.stiffness / spec.mass);
    const double zeta = spec.damping / (2.0 * std::sqrt(spec.stiffness * spec.mass));
    QVERIFY(zeta < 1.0);
    const double wd = w0 * std::sqrt(1.0 - zeta * zeta);
    const double bCoef = (spec.v0 + zeta * w0 * spec.x0) / wd;
    const double h = 1e-3;
    World world = rigidlab::test::makeOscillator(IntegratorKind::RK4, h, spec);
    world.updateDiagnostics();
    double previousEnergy = world.diagnostics().total;
    for (int i = 1; i <= 5000; ++i) {
        world.step();
        const double t = i * h;
        const double x =
            std::exp(-zeta * w0 * t) * (spec.x0 * std::cos(wd * t) + bCoef * std::sin(wd * t));
        RL_VERIFY_NEAR(world.body(0).position.x(), x, 1e-9, 0.0);
        const double e = world.diagnostics().total;
        RL_VERIFY_AT_MOST(e, previousEnergy + 1e-15);
        previousEnergy = e;
    }
}

// Two free bodies (1 kg and 3 kg) joined by a spring k = 12 N/m, rest length 1 m, along x.
// The stretch s = x2 - x1 - L0 obeys s'' = -(k / mu) s with mu = m1 m2 / (m1 + m2), so
// w = 4 rad/s; the centre of mass moves uniformly. RK4, dt = 1e-3, 3 s: positions within
// 1e-9 m; momentum to 1e-12 of its scale (the spring forces cancel exactly).
void TestWorld::twoBodySpring()
{
    const double m1 = 1.0, m2 = 3.0, k = 12.0, l0 = 1.0;
    const double x1 = 0.0, x2 = 1.2, v1 = 0.4, v2 = -0.1;
    World world(rigidlab::test::quietWorldDef(IntegratorKind::RK4, 1e-3));
    BodyDef a = rigidlab::test::circleBody(0.1, Vec2(x1, 0.0), Vec2(v1, 0.0));
    a.mass = m1;
    a.collide = false;
    BodyDef b = rigidlab::test::circleBody(0.1, Vec2(x2, 0.0), Vec2(v2, 0.0));
    b.mass = m2;
    b.collide = false;
    const BodyId ia = world.addBody(a);
    const BodyId ib = world.addBody(b);
    world.addSpring({ia, Vec2::Zero(), ib, Vec2::Zero(), k, 0.0, l0});

    const double mTotal = m1 + m2, mu = m1 * m2 / mTotal, w = std::sqrt(k / mu);
    const double X0 = (m1 * x1 + m2 * x2) / mTotal, V = (m1 * v1 + m2 * v2) / mTotal;
    const double s0 = x2 - x1 - l0, sd0 = v2 - v1;
    const double pScale = m1 * std::abs(v1) + m2 * std::abs(v2);
    for (int i = 1; i <= 3000; ++i) {
        world.step();
        const double t = i * 1e-3;
        const double s = s0 * std::cos(w * t) + sd0 / w * std::sin(w * t);
        const double X = X0 + V * t;
        RL_VERIFY_NEAR(world.body(ia).position.x(), X - m2 / mTotal * (s + l0), 1e-9, 0.0);
        RL_VERIFY_NEAR(world.body(ib).position.x(), X + m1 / mTotal * (s + l0), 1e-9, 0.0);
        RL_VERIFY_NEAR(rigidlab::test::momentum(world).x(), mTotal * V, 1e-12 * pScale, 0.0);
    }
}

// Linear drag F = -c m v, M = -c I w on a free box (RK4, dt = 1e-3, 3 s, c = 0.7 /s):
//   v(t) = v0 e^(-ct) + (g/c)(1 - e^(-ct)),  x(t) = x0 + (g/c) t + (v0 - g/c)(1 - e^(-ct))/c,
//   w(t) = w0 e^(-ct),  angle(t) = angle0 + w0 (1 - e^(-ct)) / c.
// Velocities and spin within 1e-8 relative (plus 1e-12 absolute where they pass near zero),
// positions within 1e-8 m.
void TestWorld::drag_data()
{
    QTest::addColumn<Vec2>("gravity");
    QTest::newRow("no gravity") << Vec2(0.0, 0.0);
    QTest::newRow("with gravity") << Vec2(0.0, -9.81);
}

void TestWorld::drag()
{
    QFETCH(Vec2, gravity);
    const double c = 0.7, h = 1e-3;
    const Vec2 x0(1.0, 2.0), v0(3.0, -1.0);
    const double a0 = 0.2, w0 = 2.0;
    WorldDef def = rigidlab::test::quietWorldDef(IntegratorKind::RK4, h);
    def.drag = c;
    def.gravity = gravity;
    World world(def);
    BodyDef box = rigidlab::test::boxBody(0.5, 0.3, x0, a0);
    box.velocity = v0;
    box.angularVelocity = w0;
    world.addBody(box);
    const double vScale = std::max(v0.norm(), gravity.norm() / c);
    for (int i = 1; i <= 3000; ++i) {
        world.step();
        const double t = i * h, decay = std::exp(-c * t);
        const Vec2 ve = v0 * decay + gravity / c * (1.0 - decay);
        const Vec2 xe = x0 + gravity / c * t + (v0 - gravity / c) * (1.0 - decay) / c;
        const Body& b = world.body(0);
        RL_VERIFY_NEAR(b.velocity.x(), ve.x(), 1e-12 * vScale, 1e-8);
        RL_VERIFY_NEAR(b.velocity.y(), ve.y(), 1e-12 * vScale, 1e-8);
        RL_VERIFY_NEAR(b.angularVelocity, w0 * decay, 1e-12, 1e-8);
        RL_VERIFY_NEAR(b.position.x(), xe.x(), 1e-8, 0.0);
        RL_VERIFY_NEAR(b.position.y(), xe.y(), 1e-8, 0.0);
        RL_VERIFY_NEAR(b.angle, a0 + w0 * (1.0 - decay) / c, 1e-8, 0.0);
    }
}

// Two bodies under gravitation (G = 1, masses 3 and 1, 2 m apart, centre of mass at rest at
// the origin), launched with f times the circular speed sqrt(G M / r). The orbit's semi-major
// axis is a = 1 / (2/r - v^2/(G M)) (vis-viva) and its period T = 2 pi sqrt(a^3 / (G M))
// (Kepler). RK4 with T / 4000 per step, one period:
//   every step: momentum within 1e-12 of its scale; energy and angular momentum within 1e-8
//   relative; diagnostics' potential = -G m1 m2 / r (1e-12); circular: r within 1e-6 relative;
//   after T: both bodies back where they started within 1e-6 r (circular) or 1e-5 r.
void TestWorld::gravitationOrbit_data()
{
    QTest::addColumn<double>("f");
    QTest::addColumn<double>("returnTol");
    QTest::addColumn<SolverKind>("solver");
    for (SolverKind solver : {SolverKind::SequentialImpulse, SolverKind::SoftStep}) {
        const char* name = solver == SolverKind::SoftStep ? "soft step" : "sequential";
        QTest::addRow("circular, %s", name) << 1.0 << 1e-6 << solver;
        QTest::addRow("eccentric, %s", name) << 0.8 << 1e-5 << solver;
    }
}

void TestWorld::gravitationOrbit()
{
    QFETCH(double, f);
    QFETCH(double, returnTol);
    QFETCH(SolverKind, solver);
    const double G = 1.0, m1 = 3.0, m2 = 1.0, r0 = 2.0, M = m1 + m2;
    const double vRel = f * std::sqrt(G * M / r0);
    const double a = 1.0 / (2.0 / r0 - vRel * vRel / (G * M));
    const double period = 2.0 * kPi * std::sqrt(a * a * a / (G * M));
    const int steps = 4000;
    WorldDef def = rigidlab::test::quietWorldDef(IntegratorKind::RK4, period / steps);
    def.gravitation = G;
    def.solver = solver;
    World world(def);
    const Vec2 p1(-m2 / M * r0, 0.0), p2(m1 / M * r0, 0.0);
    BodyDef b1 = rigidlab::test::circleBody(0.05, p1, Vec2(0.0, -m2 / M * vRel));
    b1.mass = m1;
    b1.collide = false;
    BodyDef b2 = rigidlab::test::circleBody(0.05, p2, Vec2(0.0, m1 / M * vRel));
    b2.mass = m2;
    b2.collide = false;
    world.addBody(b1);
    world.addBody(b2);

    auto energy = [&] {
        const double r = (world.body(1).position - world.body(0).position).norm();
        return rigidlab::test::kineticEnergy(world) - G * m1 * m2 / r;
    };
    auto angularMomentum = [&] {
        double l = 0.0;
        for (const Body& b : world.bodies()) {
            l += b.mass * cross(b.position, b.velocity) + b.inertia * b.angularVelocity;
        }
        return l;
    };
    const double e0 = energy(), l0 = angularMomentum();
    const double pScale = 2.0 * m1 * m2 / M * vRel;
    for (int i = 1; i <= steps; ++i) {
        world.step();
        const double r = (world.body(1).position - world.body(0).position).norm();
        const Diagnostics& d = world.diagnostics();
        RL_VERIFY_NEAR(d.gravitationPotential, -G * m1 * m2 / r, 0.0, 1e-12);
        RL_VERIFY_NEAR(d.total, energy(), 0.0, 1e-12);
        RL_VERIFY_NEAR(energy(), e0, 0.0, 1e-8);
        RL_VERIFY_NEAR(angularMomentum(), l0, 0.0, 1e-8);
        RL_VERIFY_NEAR(d.angularMomentum, l0, 0.0, 1e-8);
        RL_VERIFY_NEAR(rigidlab::test::momentum(world).norm(), 0.0, 1e-12 * pScale, 0.0);
        if (f == 1.0) {
            RL_VERIFY_NEAR(r, r0, 0.0, 1e-6);
        }
    }
    RL_VERIFY_NEAR((world.body(0).position - p1).norm(), 0.0, returnTol * r0, 0.0);
    RL_VERIFY_NEAR((world.body(1).position - p2).norm(), 0.0, returnTol * r0, 0.0);
}

// ---------------------------------------------------------------------------------------------
// Determinism

// Two worlds built the same way and stepped 1500 times with every feature give the same bits.
void TestWorld::identicalWorldsAreBitIdentical_data()
{
    QTest::addColumn<SolverKind>("solver");
    QTest::addColumn<IntegratorKind>("integrator");
    QTest::newRow("sequential symplectic-euler")
        << SolverKind::SequentialImpulse << IntegratorKind::SymplecticEuler;
    QTest::newRow("sequential rk4") << SolverKind::SequentialImpulse << IntegratorKind::RK4;
    QTest::newRow("seed verlet") << SolverKind::PaperImpulse << IntegratorKind::Verlet;
    QTest::newRow("seed euler") << SolverKind::PaperImpulse << IntegratorKind::Euler;
}

void TestWorld::identicalWorldsAreBitIdentical()
{
    QFETCH(SolverKind, solver);
    QFETCH(IntegratorKind, integrator);
    World a = buildFullScene(solver, integrator);
    World b = buildFullScene(solver, integrator);
    int contactSteps = 0;
    for (int i = 1; i <= 1500; ++i) {
        a.step();
        b.step();
        contactSteps += a.diagnostics().contacts > 0 ? 1 : 0;
        if (i % 50 == 0) {
            QVERIFY2(bitIdentical(stateOf(a), stateOf(b)),
                     qPrintable(QString("differ at step %1").arg(i)));
        }
    }
    QVERIFY(contactSteps > 100); // the scene really exercised the contacts
    for (const Body& body : a.bodies()) {
        QVERIFY(isFinite(body.position) && isFinite(body.velocity));
    }
}

// A copy (constructor or assignment) taken mid-run, with contacts alive, continues exactly
// as the original; and it is a deep copy: stepping the copy leaves the original untouched.
void TestWorld::copiedWorldContinuesIdentically()
{
    World original = buildFullScene(SolverKind::SequentialImpulse, IntegratorKind::SymplecticEuler);
    for (int i = 0; i < 300; ++i) {
        original.step();
    }
    QVERIFY(!original.contacts().empty());
    World copied(original);
    World assigned = buildFullScene(SolverKind::PaperImpulse, IntegratorKind::Euler);
    assigned.step();
    assigned = original;
    QVERIFY(bitIdentical(stateOf(copied), stateOf(original)));

    const auto before = stateOf(original);
    World scratch(original);
    for (int i = 0; i < 100; ++i) {
        scratch.step();
    }
    QVERIFY(bitIdentical(stateOf(original), before));
    QVERIFY(!bitIdentical(stateOf(scratch), before));

    for (int i = 1; i <= 1000; ++i) {
        original.step();
        copied.step();
        assigned.step();
        if (i % 50 == 0) {
            QVERIFY2(bitIdentical(stateOf(copied), stateOf(original)),
                     qPrintable(QString("copy differs at step %1").arg(i)));
            QVERIFY2(bitIdentical(stateOf(assigned), stateOf(original)),
                     qPrintable(QString("assigned differs at step %1").arg(i)));
        }
    }
}

// The diagnostics' count of touching points is counted when first asked for after a step: a
// world asked only now and then, and a copy taken between its asks, report what a world asked
// after every step reports, however many steps went by unasked.
void TestWorld::touchingPointsCountedWhenAsked()
{
    World everyStep = buildFullScene(SolverKind::SoftStep, IntegratorKind::SymplecticEuler);
    World seldom = buildFullScene(SolverKind::SoftStep, IntegratorKind::SymplecticEuler);
    std::vector<int> counts;
    for (int i = 1; i <= 600; ++i) {
        everyStep.step();
        const int expected = everyStep.diagnostics().contacts;
        seldom.step();
        if (i % 37 == 0) {
            const World copied(seldom);
            QCOMPARE(copied.diagnostics().contacts, expected);
            QCOMPARE(seldom.diagnostics().contacts, expected);
            counts.push_back(expected);
        }
    }
    // The count changed between asks: a count kept from an earlier ask would have shown.
    std::sort(counts.begin(), counts.end());
    QVERIFY2(std::unique(counts.begin(), counts.end()) - counts.begin() >= 3,
             qPrintable(QString("counts: %1 to %2").arg(counts.front()).arg(counts.back())));
}

// ---------------------------------------------------------------------------------------------
// Stacking

// Ten 1 m x 0.5 m boxes on a static ground, sequential impulses with the default iterations,
// friction 0.5, restitution 0, 10 s. From its position at t = 0.5 s (settled) the top box
// drifts less than 1 cm in x and in y; no box ever turns more than 0.05 rad; the stack keeps
// its height within 5 cm (each of 10 contacts may sink by about linearSlop = 0.005 m).
void TestWorld::boxStackStands_data()
{
    QTest::addColumn<double>("dt");
    QTest::newRow("dt=1/120") << 1.0 / 120.0;
    QTest::newRow("dt=1e-3") << 1e-3;
}

void TestWorld::boxStackStands()
{
    QFETCH(double, dt);
    WorldDef def;
    def.dt = dt;
    def.solver = SolverKind::SequentialImpulse;
    def.friction = 0.5;
    def.restitution = 0.0;
    World world(def);
    BodyDef ground = rigidlab::test::boxBody(20.0, 1.0, Vec2(0.0, -0.5));
    ground.type = BodyType::Static;
    world.addBody(ground);
    const int n = 10;
    const double w = 1.0, h = 0.5;
    for (int i = 0; i < n; ++i) {
        world.addBody(rigidlab::test::boxBody(w, h, Vec2(0.0, h / 2 + h * i)));
    }
    const BodyId top = n;
    const int settle = static_cast<int>(std::lround(0.5 / dt));
    const int steps = static_cast<int>(std::lround(10.0 / dt));
    Vec2 settled = Vec2::Zero();
    double maxTurn = 0.0, maxDx = 0.0, maxDy = 0.0;
    for (int i = 1; i <= steps; ++i) {
        world.step();
        for (BodyId id = 1; id <= n; ++id) {
            maxTurn = std::max(maxTurn, std::abs(world.body(id).angle));
        }
        if (i == settle) {
            settled = world.body(top).position;
        } else if (i > settle) {
            maxDx = std::max(maxDx, std::abs(world.body(top).position.x() - settled.x()));
            maxDy = std::max(maxDy, std::abs(world.body(top).position.y() - settled.y()));
        }
    }
    RL_VERIFY_AT_MOST(maxDx, 0.01);
    RL_VERIFY_AT_MOST(maxDy, 0.01);
    RL_VERIFY_AT_MOST(maxTurn, 0.05);
    RL_VERIFY_NEAR(world.body(top).position.y(), h / 2 + h * (n - 1), 0.05, 0.0);
}

RIGIDLAB_TEST_GUILESS_MAIN(TestWorld)
#include "test_world.moc"
