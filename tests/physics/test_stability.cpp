// SPDX-License-Identifier: GPL-3.0-or-later
// The integrators beyond the paper's, and what keeps the engine honest on extreme cases:
//  - Dormand-Prince 5(4): fifth order at fixed substeps, its error estimate, tolerance control;
//  - implicit midpoint: second order, and stable on the stiffest spring (k = 1e7 at m = 1)
//    where every explicit method diverges;
//  - divergence is detected and diagnosed (body, quantity, time, dt, integrator), never NaN;
//  - continuous collision: a 5 cm bullet at 300 m/s does not pass a 10 cm wall with it and
//    does without it.

#include "physics_test_util.h"

#include <rigidlab/physics/integrator.h>
#include <rigidlab/physics/world.h>

#include "test_main.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace rigidlab::physics;
using rigidlab::test::OscillatorSpec;

namespace {

/// Phase-space error of the oscillator at time t against x(t) = x0 cos(w t).
double oscillatorError(const World& w, const OscillatorSpec& s)
{
    const double omega = std::sqrt(s.stiffness / s.mass);
    const double t = w.time();
    const Body& b = w.body(0);
    const double xe = s.x0 * std::cos(omega * t), ve = -s.x0 * omega * std::sin(omega * t);
    return std::hypot(b.position.x() - xe, (b.velocity.x() - ve) / omega);
}

double observedOrder(IntegratorKind kind, const Tolerances& tol, std::vector<double> hs)
{
    const OscillatorSpec spec;
    const double tEnd = 2.0;
    std::vector<double> lx, ly;
    for (double h : hs) {
        World w = rigidlab::test::makeOscillator(kind, h, spec);
        w.setTolerances(tol);
        const long long n = std::llround(tEnd / h);
        for (long long i = 0; i < n; ++i)
            w.step();
        lx.push_back(std::log(h));
        ly.push_back(std::log(oscillatorError(w, spec)));
    }
    return rigidlab::test::leastSquaresSlope(lx, ly);
}

/// A 5 cm bullet at 300 m/s towards a 10 cm wall; returns where it is after 0.05 s.
double bulletX(bool continuous)
{
    WorldDef def = rigidlab::test::quietWorldDef(IntegratorKind::SymplecticEuler, 0.005);
    def.continuous = continuous;
    def.restitution = 0.2;
    World w(def);
    BodyDef wall = rigidlab::test::boxBody(0.1, 2.0, Vec2(1.0, 0.0));
    wall.type = BodyType::Static;
    w.addBody(wall);
    BodyDef bullet = rigidlab::test::circleBody(0.025, Vec2(0.0, 0.0), Vec2(300.0, 0.0), 7800);
    w.addBody(bullet);
    for (int i = 0; i < 10; ++i)
        w.step();
    return w.body(1).position.x();
}

/// x'' = -x on one coordinate (w = 1), without the world: the integrator alone.
class UnitOscillator : public OdeSystem {
public:
    void acceleration(double, const Eigen::VectorXd& q, const Eigen::VectorXd&,
                      Eigen::VectorXd& a) override
    {
        a = -q;
    }
};

/// The largest |x| over `steps` steps of `kind` at step h from x = 1, v = 0 (w = 1).
double largestExcursion(IntegratorKind kind, double h, int steps)
{
    UnitOscillator system;
    auto integrator = makeIntegrator(kind);
    Eigen::VectorXd q = Eigen::VectorXd::Ones(1), v = Eigen::VectorXd::Zero(1);
    double largest = 1.0;
    for (int i = 0; i < steps && std::isfinite(q[0]); ++i) {
        integrator->step(system, i * h, h, q, v);
        largest = std::max(largest, std::abs(q[0]));
    }
    return std::isfinite(q[0]) ? largest : HUGE_VAL;
}

} // namespace

class TestStability : public QObject {
    Q_OBJECT

private slots:
    void names();
    void stabilityBoundIsTheMethods();
    void dopri5FifthOrderAtFixedSubsteps();
    void dopri5MeetsItsTolerance();
    void implicitMidpointSecondOrder();
    void stiffSpring_data();
    void stiffSpring();
    void divergenceDiagnosed();
    void nonFiniteDiagnosed();
    void bulletTunnelsOnlyWithoutContinuous();
};

void TestStability::names()
{
    QCOMPARE(integratorName(IntegratorKind::DormandPrince), std::string_view("dopri5"));
    QCOMPARE(integratorName(IntegratorKind::ImplicitMidpoint),
             std::string_view("implicit-midpoint"));
    QCOMPARE(integratorFromName("dopri5"), std::optional(IntegratorKind::DormandPrince));
    QCOMPARE(integratorFromName("implicit-midpoint"),
             std::optional(IntegratorKind::ImplicitMidpoint));
    QCOMPARE(integratorOrder(IntegratorKind::DormandPrince), 5);
    QCOMPARE(integratorOrder(IntegratorKind::ImplicitMidpoint), 2);
    for (IntegratorKind k : kAllIntegrators)
        QCOMPARE(integratorFromName(integratorName(k)), std::optional(k));
}

// An integrator's stated stability bound (IntegratorInfo, what the stress suite prints) is its
// own: on x'' = -w^2 x a step 2 % under w dt = bound stays bounded, 2 % over it grows without
// bound. (Under it symplectic Euler and Verlet swing out to 1 / sqrt(1 - (w dt / 2)^2), about
// 5 times the start at 0.98 of the bound; RK4 decays.)
void TestStability::stabilityBoundIsTheMethods()
{
    int bounded = 0;
    for (const IntegratorInfo& info : kIntegrators) {
        QCOMPARE(info.stabilityBound > 0.0, info.stability == Stability::Bounded);
        if (info.stability != Stability::Bounded)
            continue;
        ++bounded;
        const double under = largestExcursion(info.kind, 0.98 * info.stabilityBound, 4000);
        const double over = largestExcursion(info.kind, 1.02 * info.stabilityBound, 4000);
        QVERIFY2(under < 10.0, qPrintable(QStringLiteral("%1 under its bound: |x| up to %2")
                                              .arg(info.name.data())
                                              .arg(under)));
        QVERIFY2(
            over > 1e6,
            qPrintable(
                QStringLiteral("%1 over its bound: |x| up to %2").arg(info.name.data()).arg(over)));
    }
    QCOMPARE(bounded, 3); // symplectic Euler, Verlet, RK4
}

void TestStability::dopri5FifthOrderAtFixedSubsteps()
{
    // Tolerances so loose that every step is one substep: the plain fifth-order method.
    const double p = observedOrder(IntegratorKind::DormandPrince, {1e3, 1e3}, {0.2, 0.1, 0.05});
    QVERIFY2(std::abs(p - 5.0) < 0.3, qPrintable(QString::number(p)));
}

void TestStability::dopri5MeetsItsTolerance()
{
    const OscillatorSpec spec;
    double previous = INFINITY;
    for (double tol : {1e-4, 1e-7, 1e-10}) {
        World w = rigidlab::test::makeOscillator(IntegratorKind::DormandPrince, 0.5, spec);
        w.setTolerances({tol, tol});
        for (int i = 0; i < 10; ++i)
            w.step();
        QVERIFY(w.integrator().errorEstimate().has_value());
        QVERIFY(*w.integrator().errorEstimate() <= 10 * tol);
        QVERIFY(w.integrator().substeps() >= 1);
        const double e = oscillatorError(w, spec);
        QVERIFY2(e < 100 * tol, qPrintable(QStringLiteral("tol %1 error %2").arg(tol).arg(e)));
        QVERIFY(e < previous);
        previous = e;
    }
    World fixed = rigidlab::test::makeOscillator(IntegratorKind::RK4, 0.5, spec);
    QVERIFY(!fixed.integrator().errorEstimate());
}

void TestStability::implicitMidpointSecondOrder()
{
    const double p = observedOrder(IntegratorKind::ImplicitMidpoint, {}, {0.04, 0.02, 0.01});
    QVERIFY2(std::abs(p - 2.0) < 0.15, qPrintable(QString::number(p)));
}

void TestStability::stiffSpring_data()
{
    QTest::addColumn<IntegratorKind>("kind");
    QTest::addColumn<bool>("stable");
    QTest::newRow("euler") << IntegratorKind::Euler << false;
    QTest::newRow("symplectic-euler") << IntegratorKind::SymplecticEuler << false;
    QTest::newRow("verlet") << IntegratorKind::Verlet << false;
    QTest::newRow("rk4") << IntegratorKind::RK4 << false;
    QTest::newRow("implicit-midpoint") << IntegratorKind::ImplicitMidpoint << true;
}

void TestStability::stiffSpring()
{
    // k = 1e7 N/m at m = 1 kg: w = 3162 rad/s, and w dt = 3.16 at dt = 1 ms, past every
    // explicit method's limit (2 for Verlet and symplectic Euler, 2.83 for RK4).
    QFETCH(IntegratorKind, kind);
    QFETCH(bool, stable);
    OscillatorSpec spec;
    spec.stiffness = 1e7;
    spec.x0 = 0.01;
    World w = rigidlab::test::makeOscillator(kind, 1e-3, spec);
    w.updateDiagnostics();
    const double e0 = w.diagnostics().total;
    for (int i = 0; i < 2000 && !w.divergence(); ++i)
        w.step();
    if (stable) {
        QVERIFY(!w.divergence());
        // The implicit midpoint rule keeps a linear oscillator's energy exactly.
        RL_VERIFY_NEAR(w.diagnostics().total, e0, 0.0, 1e-6);
    } else {
        QVERIFY2(w.divergence().has_value(), "an explicit method stayed stable past its limit");
        QCOMPARE(w.divergence()->integrator, kind);
    }
}

void TestStability::divergenceDiagnosed()
{
    OscillatorSpec spec;
    spec.stiffness = 1e7;
    spec.x0 = 0.01;
    World w = rigidlab::test::makeOscillator(IntegratorKind::Euler, 1e-3, spec);
    w.mutableBody(0).name = "mass";
    for (int i = 0; i < 10000 && !w.divergence(); ++i)
        w.step();
    QVERIFY(w.divergence());
    const Divergence d = *w.divergence();
    QCOMPARE(d.kind, Divergence::Kind::EnergyGrowth);
    QCOMPARE(d.body, 0);
    QCOMPARE(d.quantity, Divergence::Quantity::TotalEnergy);
    QCOMPARE(d.dt, 1e-3);
    QVERIFY(std::isfinite(w.body(0).position.x()));
    // The diagnosis carries what the words need: integrator, body, and the energies.
    QCOMPARE(d.integrator, IntegratorKind::Euler);
    QCOMPARE(d.bodyName, std::string("mass"));
    QVERIFY2(d.value > d.bound && d.bound > d.start && d.start > 0,
             qPrintable(QStringLiteral("%1 %2 %3").arg(d.value).arg(d.bound).arg(d.start)));
    // The world stays stopped where it diverged.
    const long long steps = w.stepCount();
    w.step();
    QCOMPARE(w.stepCount(), steps);
    QCOMPARE(w.time(), d.time);
}

void TestStability::nonFiniteDiagnosed()
{
    World w = rigidlab::test::makeOscillator(IntegratorKind::Verlet, 1e-3);
    w.mutableBody(0).name = "ball";
    w.step();
    w.mutableBody(0).force = Vec2(INFINITY, 0.0);
    w.step();
    QVERIFY(w.divergence());
    QCOMPARE(w.divergence()->kind, Divergence::Kind::NonFinite);
    QCOMPARE(w.divergence()->bodyName, std::string("ball"));
    QCOMPARE(w.divergence()->step, 2);
    // Verlet moves the position first, with the infinite acceleration.
    QCOMPARE(w.divergence()->quantity, Divergence::Quantity::Position);
}

void TestStability::bulletTunnelsOnlyWithoutContinuous()
{
    // The wall's near face is at x = 0.95; the bullet moves 1.5 m per step.
    QVERIFY2(bulletX(true) < 0.95, qPrintable(QString::number(bulletX(true))));
    QVERIFY2(bulletX(false) > 1.05, qPrintable(QString::number(bulletX(false))));
}

RIGIDLAB_TEST_GUILESS_MAIN(TestStability)
#include "test_stability.moc"
