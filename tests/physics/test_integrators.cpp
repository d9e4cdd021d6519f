// SPDX-License-Identifier: GPL-3.0-or-later
// The four integrators against exact solutions: one step against its textbook formula, the
// observed order of convergence on a harmonic oscillator, the energy behaviour each method
// is known for (with the exact per-step factors where they exist), and free flight. The
// pendulum is test_pendulum's.

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

/// x'' = -w^2 x, one body's three coordinates: the direct test system for the integrators.
class HarmonicSystem : public OdeSystem {
public:
    explicit HarmonicSystem(double omega) : m_w2(omega * omega) {}
    void acceleration(double, const Eigen::VectorXd& q, const Eigen::VectorXd&,
                      Eigen::VectorXd& a) override
    {
        ++evaluations;
        a = -m_w2 * q;
    }
    int evaluations = 0;

private:
    double m_w2;
};

/// Phase-space error of an oscillator state against the exact one: sqrt(dx^2 + (dv / w)^2).
/// Using both coordinates keeps the error from vanishing by accident at one end time.
double phaseError(double x, double v, double xe, double ve, double omega)
{
    return std::hypot(x - xe, (v - ve) / omega);
}

/// Oscillator energy per the test's own formula (not diagnostics()): m v^2/2 + k x^2/2.
double oscillatorEnergy(const World& w, const rigidlab::test::OscillatorSpec& s)
{
    const Body& b = w.body(0);
    return 0.5 * s.mass * b.velocity.squaredNorm() +
           0.5 * s.stiffness * b.position.x() * b.position.x();
}

} // namespace

class TestIntegrators : public QObject {
    Q_OBJECT

private slots:
    void names();
    void oneStepMatchesFormula_data();
    void oneStepMatchesFormula();
    void freeFlightMatchesDiscreteSolution_data();
    void freeFlightMatchesDiscreteSolution();
    void convergenceOrder_data();
    void convergenceOrder();
    void eulerEnergyGrowsByExactFactor();
    void symplecticEnergyStaysBounded_data();
    void symplecticEnergyStaysBounded();
    void rk4EnergyDecaysByExactFactor();
};

void TestIntegrators::names()
{
    const IntegratorKind kinds[] = {IntegratorKind::Euler, IntegratorKind::SymplecticEuler,
                                    IntegratorKind::Verlet, IntegratorKind::RK4};
    const char* names[] = {"euler", "symplectic-euler", "verlet", "rk4"};
    const int orders[] = {1, 1, 2, 4};
    for (int i = 0; i < 4; ++i) {
        QCOMPARE(QByteArray(integratorName(kinds[i]).data(),
                            static_cast<qsizetype>(integratorName(kinds[i]).size())),
                 QByteArray(names[i]));
        const auto parsed = integratorFromName(names[i]);
        QVERIFY(parsed.has_value());
        QCOMPARE(*parsed, kinds[i]);
        QCOMPARE(integratorOrder(kinds[i]), orders[i]);
        QCOMPARE(makeIntegrator(kinds[i])->kind(), kinds[i]);
    }
    QVERIFY(!integratorFromName("leapfrog").has_value());
}

// One step of each method on x'' = -w^2 x against the method's own formula (the paper's
// equations), so that a method cannot pass the convergence test while being another method.
// Tolerance 1e-14 relative: a handful of rounding errors on numbers of order 1.
void TestIntegrators::oneStepMatchesFormula_data()
{
    QTest::addColumn<IntegratorKind>("kind");
    QTest::newRow("euler") << IntegratorKind::Euler;
    QTest::newRow("symplectic-euler") << IntegratorKind::SymplecticEuler;
    QTest::newRow("verlet") << IntegratorKind::Verlet;
    QTest::newRow("rk4") << IntegratorKind::RK4;
}

void TestIntegrators::oneStepMatchesFormula()
{
    QFETCH(IntegratorKind, kind);
    const double w = 1.7, h = 0.13;
    const double w2 = w * w;
    Eigen::VectorXd q(3), v(3);
    q << 0.4, -0.3, 1.1;
    v << 0.2, 0.9, -0.5;
    const Eigen::VectorXd q0 = q, v0 = v;

    Eigen::VectorXd qe(3), ve(3);
    switch (kind) {
    case IntegratorKind::Euler: // x1 = x0 + h v0, v1 = v0 + h a(x0)
        qe = q0 + h * v0;
        ve = v0 - h * w2 * q0;
        break;
    case IntegratorKind::SymplecticEuler: // v1 = v0 + h a(x0), x1 = x0 + h v1
        ve = v0 - h * w2 * q0;
        qe = q0 + h * ve;
        break;
    case IntegratorKind::Verlet: // x1 = x0 + h v0 + h^2/2 a0, v1 = v0 + h/2 (a0 + a1)
        qe = q0 + h * v0 - 0.5 * h * h * w2 * q0;
        ve = v0 + 0.5 * h * (-w2 * q0 - w2 * qe);
        break;
    case IntegratorKind::RK4: {
        // For y' = A y the classic RK4 step is y1 = (I + hA + (hA)^2/2 + (hA)^3/6 + (hA)^4/24) y0
        // with A = [[0, 1], [-w^2, 0]] per coordinate.
        Eigen::Matrix2d A;
        A << 0.0, 1.0, -w2, 0.0;
        const Eigen::Matrix2d hA = h * A;
        const Eigen::Matrix2d R = Eigen::Matrix2d::Identity() + hA + hA * hA / 2.0 +
                                  hA * hA * hA / 6.0 + hA * hA * hA * hA / 24.0;
        for (int i = 0; i < 3; ++i) {
            const Eigen::Vector2d y = R * Eigen::Vector2d(q0[i], v0[i]);
            qe[i] = y[0];
            ve[i] = y[1];
        }
        break;
    }
    default:
        QFAIL("no textbook formula for this integrator here (see test_stability)");
    }

    HarmonicSystem system(w);
    auto integrator = makeIntegrator(kind);
    integrator->step(system, 0.0, h, q, v);
    for (int i = 0; i < 3; ++i) {
        RL_VERIFY_NEAR(q[i], qe[i], 1e-14, 1e-14);
        RL_VERIFY_NEAR(v[i], ve[i], 1e-14, 1e-14);
    }
    // The method reports the force evaluations it really makes (give or take one a0 that a
    // method may evaluate on its first step only).
    QVERIFY2(std::abs(system.evaluations - integrator->evaluationsPerStep()) <= 1,
             qPrintable(QString("made %1 evaluations, reports %2")
                            .arg(system.evaluations)
                            .arg(integrator->evaluationsPerStep())));
    if (kind == IntegratorKind::RK4) {
        QCOMPARE(system.evaluations, 4);
    }
}

// A free body under constant gravity g: the discrete solutions are known exactly.
//   explicit Euler:    x_n = x0 + n h v0 + g h^2 n (n - 1) / 2
//   symplectic Euler:  x_n = x0 + n h v0 + g h^2 n (n + 1) / 2
//   Verlet, RK4:       x_n = x0 + v0 t + g t^2 / 2 (exact for constant acceleration)
// and v_n = v0 + g n h for all. The spin is untouched: angle = angle0 + w t.
// Tolerance 1e-10 absolute on values of order 10 after 500 steps (round-off only).
void TestIntegrators::freeFlightMatchesDiscreteSolution_data()
{
    QTest::addColumn<IntegratorKind>("kind");
    QTest::addColumn<double>("factor"); // the k in n (n + k) / 2 of the g h^2 term
    QTest::newRow("euler") << IntegratorKind::Euler << -1.0;
    QTest::newRow("symplectic-euler") << IntegratorKind::SymplecticEuler << 1.0;
    QTest::newRow("verlet") << IntegratorKind::Verlet << 0.0;
    QTest::newRow("rk4") << IntegratorKind::RK4 << 0.0;
}

void TestIntegrators::freeFlightMatchesDiscreteSolution()
{
    QFETCH(IntegratorKind, kind);
    QFETCH(double, factor);
    const double h = 0.01;
    const Vec2 g(0.3, -9.81);
    WorldDef def = rigidlab::test::quietWorldDef(kind, h);
    def.gravity = g;
    World world(def);
    BodyDef b = rigidlab::test::circleBody(0.2, Vec2(1.0, 2.0), Vec2(2.0, 5.0));
    b.angularVelocity = 0.7;
    b.angle = 0.1;
    world.addBody(b);

    const int n = 500;
    for (int i = 0; i < n; ++i) {
        world.step();
    }
    const double nn = n;
    const Vec2 xe = Vec2(1.0, 2.0) + nn * h * Vec2(2.0, 5.0) + g * h * h * nn * (nn + factor) / 2.0;
    const Vec2 ve = Vec2(2.0, 5.0) + g * nn * h;
    const Body& body = world.body(0);
    RL_VERIFY_NEAR(body.position.x(), xe.x(), 1e-10, 0.0);
    RL_VERIFY_NEAR(body.position.y(), xe.y(), 1e-10, 0.0);
    RL_VERIFY_NEAR(body.velocity.x(), ve.x(), 1e-10, 0.0);
    RL_VERIFY_NEAR(body.velocity.y(), ve.y(), 1e-10, 0.0);
    RL_VERIFY_NEAR(body.angle, 0.1 + 0.7 * nn * h, 1e-10, 0.0);
    RL_VERIFY_NEAR(body.angularVelocity, 0.7, 1e-12, 0.0);
    RL_VERIFY_NEAR(world.time(), nn * h, 1e-10, 0.0);
    QCOMPARE(world.stepCount(), static_cast<long long>(n));
}

// Observed order: the error at a fixed end time T against dt = T / N, fitted as a
// least-squares slope of log(error) against log(dt) over 5 step sizes halving each time.
// Oscillator w = 2 rad/s, amplitude 0.5 m, T = 2.3 s (wT = 4.6 rad: neither sin nor cos of
// it is small, so no error component vanishes at T by accident). The ranges keep each method
// in its asymptotic regime (w h <= 0.2) and its smallest error far above round-off:
//   Euler, symplectic Euler: h = 0.01 ... 6.25e-4   (errors ~1e-2 ... 1e-3)
//   Verlet:                  h = 0.02 ... 1.25e-3   (errors ~1e-4 ... 1e-7)
//   RK4:                     h = 0.1  ... 6.25e-3   (errors ~1e-5 ... 1e-10)
// Expected slope: the theoretical order, within +-0.2.
void TestIntegrators::convergenceOrder_data()
{
    QTest::addColumn<IntegratorKind>("kind");
    QTest::addColumn<int>("order");
    QTest::addColumn<int>("coarsestSteps");
    QTest::newRow("euler") << IntegratorKind::Euler << 1 << 230;
    QTest::newRow("symplectic-euler") << IntegratorKind::SymplecticEuler << 1 << 230;
    QTest::newRow("verlet") << IntegratorKind::Verlet << 2 << 115;
    QTest::newRow("rk4") << IntegratorKind::RK4 << 4 << 23;
}

void TestIntegrators::convergenceOrder()
{
    QFETCH(IntegratorKind, kind);
    QFETCH(int, order);
    QFETCH(int, coarsestSteps);
    QCOMPARE(integratorOrder(kind), order);

    const rigidlab::test::OscillatorSpec spec; // m = 1, k = 4, x0 = 0.5, v0 = 0
    const double w = std::sqrt(spec.stiffness / spec.mass);
    const double T = 2.3;
    const double xe = spec.x0 * std::cos(w * T);
    const double ve = -spec.x0 * w * std::sin(w * T);

    std::vector<double> logH, logErr;
    QString table;
    for (int steps = coarsestSteps; steps <= coarsestSteps * 16; steps *= 2) {
        const double h = T / steps;
        World world = rigidlab::test::makeOscillator(kind, h, spec);
        for (int i = 0; i < steps; ++i) {
            world.step();
        }
        const Body& b = world.body(0);
        const double err = phaseError(b.position.x(), b.velocity.x(), xe, ve, w);
        QVERIFY2(err > 0.0 && std::isfinite(err), "error must be positive and finite");
        // Motion stays on the x axis: the spring pulls only along x.
        RL_VERIFY_NEAR(b.position.y(), 0.0, 1e-12, 0.0);
        logH.push_back(std::log(h));
        logErr.push_back(std::log(err));
        table += QString(" h=%1 err=%2;").arg(h, 0, 'g', 4).arg(err, 0, 'g', 4);
    }
    const double slope = rigidlab::test::leastSquaresSlope(logH, logErr);
    QVERIFY2(std::abs(slope - order) <= 0.2,
             qPrintable(QString("observed order %1, expected %2 +- 0.2;%3")
                            .arg(slope, 0, 'f', 3)
                            .arg(order)
                            .arg(table)));
}

// Explicit Euler on m x'' = -k x maps (w x, v) by [[1, h w], [-h w, 1]], whose squared norm
// factor is exactly 1 + (w h)^2 for every state: E_n = E_0 (1 + (w h)^2)^n. Checked at every
// step to 1e-9 relative (round-off over 1000 steps is ~1e-13), with strict growth each step.
// Also: diagnostics() agrees with the energy computed here (1e-12 relative).
void TestIntegrators::eulerEnergyGrowsByExactFactor()
{
    const rigidlab::test::OscillatorSpec spec;
    const double w = std::sqrt(spec.stiffness / spec.mass);
    const double h = 0.01;
    World world = rigidlab::test::makeOscillator(IntegratorKind::Euler, h, spec);
    world.updateDiagnostics();
    const double e0 = oscillatorEnergy(world, spec);
    RL_VERIFY_NEAR(world.diagnostics().total, e0, 0.0, 1e-12);
    double previous = e0;
    const int n = 1000; // 10 s, 3.2 periods
    for (int i = 1; i <= n; ++i) {
        world.step();
        const double e = oscillatorEnergy(world, spec);
        QVERIFY2(e > previous, qPrintable(QString("energy fell at step %1").arg(i)));
        RL_VERIFY_NEAR(e, e0 * std::pow(1.0 + w * w * h * h, i), 0.0, 1e-9);
        RL_VERIFY_NEAR(world.diagnostics().total, e, 0.0, 1e-12);
        RL_VERIFY_NEAR(world.diagnostics().springPotential,
                       0.5 * spec.stiffness * std::pow(world.body(0).position.x(), 2), 1e-15,
                       1e-12);
        previous = e;
    }
    // (1.0004)^1000 = e^0.39992: the growth is large, not a rounding effect.
    QVERIFY(previous / e0 > 1.49);
}

// The symplectic methods keep a modified energy exactly, so E stays in a band and does not
// trend. For x0 = A, v0 = 0, with u = w h (checked in the test's derivation, see below):
//   symplectic Euler keeps Q = v^2 + w^2 x^2 - h w^2 x v, and |h w^2 x v| <= (u/2)(v^2 + w^2 x^2),
//     so E / E0 lies in [1 / (1 + u/2), 1 / (1 - u/2)]: max |E/E0 - 1| = (u/2) / (1 - u/2);
//   velocity Verlet keeps Q = v^2 + w^2 (1 - u^2/4) x^2, so E / E0 lies in [1 - u^2/4, 1]:
//     max |E/E0 - 1| = u^2 / 4.
// Over 100 periods: the deviation stays within the bound (+1e-9 relative slack) and reaches
// at least 90 % of it (it is this method, not a better one), and the largest deviation over
// the last 10 periods is no more than 1 % above that of the first 10 (no trend; 1 % covers
// sampling a peak of frequency 2w at step h).
void TestIntegrators::symplecticEnergyStaysBounded_data()
{
    QTest::addColumn<IntegratorKind>("kind");
    QTest::newRow("symplectic-euler") << IntegratorKind::SymplecticEuler;
    QTest::newRow("verlet") << IntegratorKind::Verlet;
}

void TestIntegrators::symplecticEnergyStaysBounded()
{
    QFETCH(IntegratorKind, kind);
    const rigidlab::test::OscillatorSpec spec;
    const double w = std::sqrt(spec.stiffness / spec.mass);
    const double h = 0.01;
    const double u = w * h;
    const double bound = kind == IntegratorKind::Verlet ? u * u / 4.0 : (u / 2.0) / (1.0 - u / 2.0);

    World world = rigidlab::test::makeOscillator(kind, h, spec);
    const double e0 = oscillatorEnergy(world, spec);
    const double period = 2.0 * std::numbers::pi / w;
    const int steps = static_cast<int>(100.0 * period / h);
    const int window = static_cast<int>(10.0 * period / h);
    double maxDev = 0.0, firstWindow = 0.0, lastWindow = 0.0;
    for (int i = 1; i <= steps; ++i) {
        world.step();
        const double dev = std::abs(oscillatorEnergy(world, spec) / e0 - 1.0);
        maxDev = std::max(maxDev, dev);
        if (i <= window) {
            firstWindow = std::max(firstWindow, dev);
        }
        if (i > steps - window) {
            lastWindow = std::max(lastWindow, dev);
        }
    }
    RL_VERIFY_AT_MOST(maxDev, bound * (1.0 + 1e-9));
    QVERIFY2(maxDev >= 0.9 * bound,
             rigidlab::test::boundMessage("deviation below 90% of the method's band", maxDev,
                                          0.9 * bound)
                 .constData());
    RL_VERIFY_AT_MOST(lastWindow, 1.01 * firstWindow);
}

// RK4 on the oscillator multiplies (w x, v) by R(hA) with hA skew-symmetric in those units,
// a normal matrix: every state's energy is scaled by |R(i u)|^2 = 1 - u^6/72 + u^8/576 per
// step, u = w h. So RK4 loses energy slowly and monotonically: E_n = E_0 (1 - u^6/72 + u^8/576)^n.
// Checked every step to 1e-9 relative, strict decrease each step, and a small total loss.
void TestIntegrators::rk4EnergyDecaysByExactFactor()
{
    const rigidlab::test::OscillatorSpec spec;
    const double w = std::sqrt(spec.stiffness / spec.mass);
    const double h = 0.05;
    const double u = w * h; // 0.1: the per-step loss is 1.4e-8, far above round-off
    const double factor = 1.0 - std::pow(u, 6) / 72.0 + std::pow(u, 8) / 576.0;
    World world = rigidlab::test::makeOscillator(IntegratorKind::RK4, h, spec);
    const double e0 = oscillatorEnergy(world, spec);
    double previous = e0;
    const int n = 10000; // 500 s, 159 periods
    for (int i = 1; i <= n; ++i) {
        world.step();
        const double e = oscillatorEnergy(world, spec);
        QVERIFY2(e < previous, qPrintable(QString("energy rose at step %1").arg(i)));
        RL_VERIFY_NEAR(e, e0 * std::pow(factor, i), 0.0, 1e-9);
        previous = e;
    }
    const double loss = 1.0 - previous / e0; // ~1.4e-4
    QVERIFY2(loss > 0.0 && loss < 1e-3, qPrintable(QString("relative loss %1").arg(loss)));
}

RIGIDLAB_TEST_GUILESS_MAIN(TestIntegrators)
#include "test_integrators.moc"
