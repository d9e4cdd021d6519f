// SPDX-License-Identifier: GPL-3.0-or-later
// The integrators on a pendulum (a body on a pin joint): explicit Euler's gain of energy takes
// it over the top as the paper warns, the others keep its amplitude; the period of a
// large-amplitude swing against the elliptic-integral formula; a pinned body's spin stays
// uniform. The oscillator and free flight are test_integrators'.

#include "elliptic.h"
#include "physics_test_util.h"

#include <rigidlab/physics/integrator.h>
#include <rigidlab/physics/world.h>

#include "test_main.h"

#include <QTest>

#include <cmath>
#include <numbers>
#include <vector>

using namespace rigidlab::physics;
using rigidlab::test::isClose;

namespace {

/// The pendulum angle from straight down, from the bob's centre (not from its angle field).
double pendulumAngle(const World& w, const Vec2& pivot)
{
    const Vec2 d = w.body(0).position - pivot;
    return std::atan2(d.x(), -d.y());
}

} // namespace

class TestPendulum : public QObject {
    Q_OBJECT

private slots:
    void eulerPendulumGoesOverTheTop_data();
    void eulerPendulumGoesOverTheTop();
    void pendulumPeriodMatchesElliptic_data();
    void pendulumPeriodMatchesElliptic();
    void pinnedSpinStaysUniform_data();
    void pinnedSpinStaysUniform();
};

// The paper's warning: with explicit Euler a frictionless pendulum gains energy until it goes
// over the top. Pendulum L = 1 m, theta0 = 1 rad, g = 9.81, dt = 0.01 s. Why 60 s is enough:
// in the linearised model Euler scales the energy by 1 + (w0 h)^2 per step, w0^2 = g/L, i.e.
// at a rate of about w0^2 h = 0.098 per second; the energy must grow from
// (1 - cos 1) m g L to 2 m g L, a factor 4.35, which takes ~15 s; the angle form of Euler is
// slower at large amplitude (~28 s by the same step rule), so 60 s is a safe limit.
// The other methods, same dt and time: the amplitude stays within 0.05 rad of theta0
// (symplectic Euler's band is ~u/2 = 1.6 % of the energy, i.e. ~0.01 rad).
void TestPendulum::eulerPendulumGoesOverTheTop_data()
{
    QTest::addColumn<IntegratorKind>("kind");
    QTest::addColumn<bool>("overTheTop");
    QTest::newRow("euler") << IntegratorKind::Euler << true;
    QTest::newRow("symplectic-euler") << IntegratorKind::SymplecticEuler << false;
    QTest::newRow("verlet") << IntegratorKind::Verlet << false;
    QTest::newRow("rk4") << IntegratorKind::RK4 << false;
}

void TestPendulum::eulerPendulumGoesOverTheTop()
{
    QFETCH(IntegratorKind, kind);
    QFETCH(bool, overTheTop);
    rigidlab::test::PendulumSpec spec;
    spec.theta0 = 1.0;
    const double h = 0.01;
    World world = rigidlab::test::makePendulum(kind, h, spec);
    const int steps = static_cast<int>(60.0 / h);
    double maxAngle = 0.0;
    double maxPinError = 0.0;
    int topStep = -1;
    for (int i = 1; i <= steps; ++i) {
        world.step();
        const Body& bob = world.body(0);
        maxAngle = std::max(maxAngle, std::abs(pendulumAngle(world, spec.pivot)));
        const Vec2 anchor = bob.transform().apply(Vec2(0.0, spec.length));
        maxPinError = std::max(maxPinError, (anchor - spec.pivot).norm());
        if (bob.position.y() > spec.pivot.y()) {
            topStep = i;
            break;
        }
    }
    // Whatever the method, the pin holds: projected after every step (1e-9 m).
    RL_VERIFY_AT_MOST(maxPinError, 1e-9);
    if (overTheTop) {
        QVERIFY2(topStep > 0, qPrintable(QString("never rose above the pivot in 60 s; max "
                                                 "angle %1 rad")
                                             .arg(maxAngle)));
    } else {
        QVERIFY2(topStep == -1, qPrintable(QString("went over the top: the bob rose above the "
                                                   "pivot at step %1 (t = %2 s)")
                                               .arg(topStep)
                                               .arg(topStep * h)));
        RL_VERIFY_AT_MOST(maxAngle, spec.theta0 + 0.05);
    }
}

// The period of a large-amplitude pendulum: T = 4 sqrt(L_eq / g) K(sin(theta0 / 2)) with K
// computed here by the AGM (and checked against Simpson's rule to 1e-10). The bob is a disc
// of radius r = 0.05 m turning with the rod: a physical pendulum, exact with
// L_eq = I_pivot / (m L) = L + r^2 / (2 L) (see makePendulum). RK4 at dt = 1e-3; the period
// is the mean over 5 periods between upward zero crossings of the angle, each located by
// linear interpolation between steps (the angle's curvature vanishes at a crossing, so the
// interpolation error is far below the tolerance). Tolerance: 1e-4 relative. The point-mass
// formula (L instead of L_eq) is off by 6e-4, so the test can tell the two apart.
void TestPendulum::pendulumPeriodMatchesElliptic_data()
{
    QTest::addColumn<double>("theta0");
    QTest::addColumn<SolverKind>("solver");
    for (SolverKind solver : {SolverKind::SequentialImpulse, SolverKind::SoftStep}) {
        const char* name = solver == SolverKind::SoftStep ? "soft step" : "sequential";
        QTest::addRow("1.0 rad, %s", name) << 1.0 << solver;
        QTest::addRow("2.5 rad, %s", name) << 2.5 << solver;
    }
}

void TestPendulum::pendulumPeriodMatchesElliptic()
{
    QFETCH(double, theta0);
    QFETCH(SolverKind, solver);
    rigidlab::test::PendulumSpec spec;
    spec.theta0 = theta0;
    const double k = std::sin(theta0 / 2.0);
    const double K = rigidlab::test::ellipticK(k);
    RL_VERIFY_NEAR(K, rigidlab::test::ellipticKSimpson(k, 20000), 0.0, 1e-10);
    RL_VERIFY_NEAR(rigidlab::test::ellipticK(0.0), std::numbers::pi / 2.0, 0.0, 1e-15);

    const double leq = rigidlab::test::pendulumEquivalentLength(spec);
    const double exact = 4.0 * std::sqrt(leq / spec.gravity) * K;
    const double pointMass = 4.0 * std::sqrt(spec.length / spec.gravity) * K;
    const double tol = 1e-4;
    QVERIFY(std::abs(pointMass - exact) > 3.0 * tol * exact);

    const double h = 1e-3;
    World world = rigidlab::test::makePendulum(IntegratorKind::RK4, h, spec);
    world.setSolver(solver);
    std::vector<double> crossings;
    double previous = pendulumAngle(world, spec.pivot);
    const int maxSteps = static_cast<int>(7.0 * exact / h);
    for (int i = 1; i <= maxSteps && crossings.size() < 6; ++i) {
        world.step();
        const double angle = pendulumAngle(world, spec.pivot);
        if (previous < 0.0 && angle >= 0.0) {
            const double t0 = (i - 1) * h;
            crossings.push_back(t0 + h * (-previous) / (angle - previous));
        }
        previous = angle;
    }
    QCOMPARE(crossings.size(), size_t(6));
    const double measured = (crossings.back() - crossings.front()) / 5.0;
    QVERIFY2(isClose(measured, exact, 0.0, tol),
             qPrintable(QString("period %1 s, exact (physical pendulum) %2 s, point-mass %3 s")
                            .arg(measured, 0, 'g', 12)
                            .arg(exact, 0, 'g', 12)
                            .arg(pointMass, 0, 'g', 12)));
    // The amplitude is kept too (RK4's slow loss is tiny here): within 1e-4 rad.
    double maxAngle = 0.0;
    const int oneMore = static_cast<int>(exact / h) + 1;
    for (int i = 0; i < oneMore; ++i) {
        world.step();
        maxAngle = std::max(maxAngle, std::abs(pendulumAngle(world, spec.pivot)));
    }
    RL_VERIFY_NEAR(maxAngle, theta0, 1e-4, 0.0);
}

// A body pinned to a world point, no gravity, set spinning rigidly about the pivot
// (v = w x r): the exact motion is uniform rotation, the pin force purely centripetal.
//  - Symplectic Euler, Verlet, RK4, at a fine step (w h = 0.05 rad, 126 steps a turn) and a
//    coarse one (w h = 0.4): the pin holds (1e-9 m, projected after every step) for 2000
//    steps and the state stays finite. At the fine step they also keep the spin:
//    |w / w0 - 1| <= w h = 0.05 over 2000 steps (16 turns), the size of a first-order
//    method's energy band (symplectic Euler's is ~u/2 in energy, see
//    symplecticEnergyStaysBounded); a method that gains energy every turn leaves it.
//  - Explicit Euler gains energy (the paper's point): its spin never falls; and its pin holds
//    as long as the step stays a sensible one (w h < 1 rad per step; Euler's spin-up makes
//    it leave that range, after which nothing is asked of it).
void TestPendulum::pinnedSpinStaysUniform_data()
{
    QTest::addColumn<IntegratorKind>("kind");
    QTest::addColumn<double>("wh");
    QTest::addColumn<bool>("checkSpin");
    QTest::newRow("euler wh=0.05") << IntegratorKind::Euler << 0.05 << true;
    const std::pair<const char*, IntegratorKind> kinds[] = {
        {"symplectic-euler", IntegratorKind::SymplecticEuler},
        {"verlet", IntegratorKind::Verlet},
        {"rk4", IntegratorKind::RK4}};
    for (const auto& [name, kind] : kinds) {
        QTest::addRow("%s wh=0.05", name) << kind << 0.05 << true;
        QTest::addRow("%s wh=0.4", name) << kind << 0.4 << false;
    }
}

void TestPendulum::pinnedSpinStaysUniform()
{
    QFETCH(IntegratorKind, kind);
    QFETCH(double, wh);
    QFETCH(bool, checkSpin);
    const double h = 0.01, w0 = wh / h, length = 1.0;
    rigidlab::test::PendulumSpec spec;
    spec.gravity = 0.0;
    spec.theta0 = 0.0;
    spec.length = length;
    World world = rigidlab::test::makePendulum(kind, h, spec);
    // Rigid rotation about the pivot: the bob centre at (0, -L) moves at w0 x (0, -L) = (w0 L, 0).
    world.setBodyVelocity(0, Vec2(w0 * length, 0.0), w0);
    const bool euler = kind == IntegratorKind::Euler;
    double maxPinError = 0.0;
    double previousSpin = w0;
    int steps = 0;
    for (; steps < 2000; ++steps) {
        if (euler && std::abs(world.body(0).angularVelocity) * h >= 1.0) {
            break;
        }
        world.step();
        const Body& bob = world.body(0);
        const double err = (bob.transform().apply(Vec2(0.0, length)) - spec.pivot).norm();
        maxPinError = std::max(maxPinError, std::isfinite(err) ? err : INFINITY);
        if (euler) {
            QVERIFY2(bob.angularVelocity >= previousSpin * (1.0 - 1e-12),
                     qPrintable(QString("Euler's spin fell at step %1").arg(steps + 1)));
            previousSpin = bob.angularVelocity;
        }
    }
    RL_VERIFY_AT_MOST(maxPinError, 1e-9);
    const double ratio = world.body(0).angularVelocity / w0;
    QVERIFY2(std::isfinite(ratio), "spin is not finite");
    if (checkSpin && !euler) {
        RL_VERIFY_NEAR(ratio, 1.0, wh, 0.0);
    }
}

RIGIDLAB_TEST_GUILESS_MAIN(TestPendulum)
#include "test_pendulum.moc"
