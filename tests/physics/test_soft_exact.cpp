// SPDX-License-Identifier: GPL-3.0-or-later
// Every solver (the soft step, the lab's default, sequential impulses and the paper's impulse)
// against the textbook where the lab promises exact mechanics: an oblique elastic cut shot of
// equal balls (they leave at 90°, the object ball along the line of centres at the impact), an
// oblique collision of unequal balls with restitution, a box's corner striking another box,
// Newton's cradle, a disc's oblique bounce off a wall with Coulomb friction, and fast bodies
// that must not pass through a thin wall; for the soft step also sliding into rolling (its
// coarse steps: test_soft_coarse.cpp).

#include "physics_test_util.h"

#include <rigidlab/physics/world.h>

#include "test_main.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace rigidlab::physics;
using rigidlab::test::circleBody;
using rigidlab::test::exactWorld;
using rigidlab::test::solverLabel;

namespace {

constexpr double kG = 9.81; // [m/s^2]

constexpr SolverKind kSolvers[] = {SolverKind::SoftStep, SolverKind::SequentialImpulse,
                                   SolverKind::PaperImpulse};

/// The angle between two vectors [rad].
double angleBetween(const Vec2& a, const Vec2& b)
{
    return std::atan2(std::abs(rigidlab::test::cross2(a, b)), a.dot(b));
}

} // namespace

class TestSoftExact : public QObject {
    Q_OBJECT

private slots:
    void cutShot_data();
    void cutShot();
    void obliqueTextbook_data();
    void obliqueTextbook();
    void polygonImpact_data();
    void polygonImpact();
    void newtonsCradle_data();
    void newtonsCradle();
    void wallBounce_data();
    void wallBounce();
    void thinWallStops_data();
    void thinWallStops();
    void slidingIntoRolling_data();
    void slidingIntoRolling();
};

// Equal balls of radius r, e = 1, no friction: the cue ball at v along y = 0, the object ball
// at rest at (0, b). At the impact their centres are 2r apart, the line of centres makes the
// angle asin(b / 2r) with the cue's path, and the impulse acts along it: the object ball
// leaves along it, the cue ball at exactly 90° to it (equal masses, elastic). Both to 1e-9 rad.
void TestSoftExact::cutShot_data()
{
    QTest::addColumn<SolverKind>("solver");
    QTest::addColumn<double>("offset");
    QTest::addColumn<double>("dt");
    for (SolverKind solver : kSolvers) {
        const char* name = solverLabel(solver);
        QTest::addRow("%s, thin cut, 1 ms", name) << solver << 0.9 << 1e-3;
        QTest::addRow("%s, half ball, 1 ms", name) << solver << 0.5 << 1e-3;
        QTest::addRow("%s, full, 1/60 s", name) << solver << 0.2 << 1.0 / 60.0;
        QTest::addRow("%s, half ball, 1/60 s", name) << solver << 0.6 << 1.0 / 60.0;
        QTest::addRow("%s, thin cut, 1/240 s", name) << solver << 0.95 << 1.0 / 240.0;
    }
}

void TestSoftExact::cutShot()
{
    QFETCH(SolverKind, solver);
    QFETCH(double, offset);
    QFETCH(double, dt);
    const double r = 0.5, speed = 3.0;
    World world(exactWorld(solver, dt, 1.0, 0.0));
    const BodyId cue = world.addBody(circleBody(r, Vec2(-2.0, 0.0), Vec2(speed, 0.0)));
    const BodyId object = world.addBody(circleBody(r, Vec2(0.0, offset)));
    bool touched = false;
    for (int i = 0; i < static_cast<int>(2.0 / dt); ++i) {
        world.step();
        touched = touched || !world.contacts().empty();
    }
    QVERIFY(touched);
    const Vec2 vCue = world.body(cue).velocity, vObject = world.body(object).velocity;
    QVERIFY(vObject.norm() > 0.1 * speed && vCue.norm() > 0.01 * speed);
    const double s = offset / (2.0 * r);
    const Vec2 lineOfCentres(std::sqrt(1.0 - s * s), s);
    RL_VERIFY_NEAR(angleBetween(vCue, vObject), std::numbers::pi / 2, 1e-9, 0.0);
    RL_VERIFY_NEAR(angleBetween(vObject, lineOfCentres), 0.0, 1e-9, 0.0);
    RL_VERIFY_NEAR(vObject.norm(), speed * lineOfCentres.x(), 1e-9 * speed, 0.0);
    RL_VERIFY_NEAR(world.body(cue).angularVelocity, 0.0, 1e-12, 0.0);
    RL_VERIFY_NEAR(world.body(object).angularVelocity, 0.0, 1e-12, 0.0);
}

// Unequal balls (radii 0.4 m and 0.25 m, densities 1 and 3), no friction, restitution e: the
// components along the line of centres at the impact follow the 1D textbook formulas, those
// across it do not change. To 1e-9 of the speed.
void TestSoftExact::obliqueTextbook_data()
{
    QTest::addColumn<SolverKind>("solver");
    QTest::addColumn<double>("e");
    QTest::addColumn<double>("dt");
    for (SolverKind solver : kSolvers)
        for (double dt : {1e-3, 1.0 / 60.0}) {
            const char* name = solverLabel(solver);
            QTest::addRow("%s, elastic, dt %g", name, dt) << solver << 1.0 << dt;
            QTest::addRow("%s, e=0.6, dt %g", name, dt) << solver << 0.6 << dt;
            QTest::addRow("%s, e=0, dt %g", name, dt) << solver << 0.0 << dt;
        }
}

void TestSoftExact::obliqueTextbook()
{
    QFETCH(SolverKind, solver);
    QFETCH(double, e);
    QFETCH(double, dt);
    const double rA = 0.4, rB = 0.25, offset = 0.3;
    const Vec2 vA0(2.5, 0.4), vB0(-1.0, 0.0);
    World world(exactWorld(solver, dt, e, 0.0));
    // Placed so that they meet: A's centre sweeps toward B's; the impact's geometry is found
    // below from the velocities, independently of the engine.
    const Vec2 xA0(-2.0, offset - 0.4 * 2.0 / 3.5), xB0(1.5, offset);
    const BodyId a = world.addBody(circleBody(rA, xA0, vA0, 1.0));
    const BodyId b = world.addBody(circleBody(rB, xB0, vB0, 3.0));
    const double mA = world.body(a).mass, mB = world.body(b).mass;
    // The moment of impact: |d + t u| = rA + rB, d = xB0 - xA0, u = vB0 - vA0 (no forces).
    const Vec2 d = xB0 - xA0, u = vB0 - vA0;
    const double R = rA + rB, qa = u.squaredNorm(), qb = 2 * d.dot(u), qc = d.squaredNorm() - R * R;
    const double t = (-qb - std::sqrt(qb * qb - 4 * qa * qc)) / (2 * qa);
    QVERIFY(t > 0.1 && t < 1.5);
    const Vec2 n = (d + t * u) / R;
    const double un = vA0.dot(n), wn = vB0.dot(n);
    const double p = mA * un + mB * wn;
    const double unAfter = (p + mB * e * (wn - un)) / (mA + mB);
    const double wnAfter = (p + mA * e * (un - wn)) / (mA + mB);
    const Vec2 vA = vA0 + (unAfter - un) * n, vB = vB0 + (wnAfter - wn) * n;
    for (int i = 0; i < static_cast<int>(2.0 / dt); ++i)
        world.step();
    const double tol = 1e-9 * vA0.norm();
    RL_VERIFY_NEAR(world.body(a).velocity.x(), vA.x(), tol, 0.0);
    RL_VERIFY_NEAR(world.body(a).velocity.y(), vA.y(), tol, 0.0);
    RL_VERIFY_NEAR(world.body(b).velocity.x(), vB.x(), tol, 0.0);
    RL_VERIFY_NEAR(world.body(b).velocity.y(), vB.y(), tol, 0.0);
}

// A box's corner strikes the flat top of a wider box, both free, no gravity or friction,
// restitution e. Box A (w x h, turned by theta, mass mA) moves at vA0 without spin; box B
// (unturned, mass mB) at vB0. A's lowest corner c meets B's top face at the time t* when their
// heights agree; at that moment the contact point p = c(t*), the normal n = (0, 1) (from B
// into A), the lever arms rA = p - centre A and rB = p - centre B, and the impulse
//     j = -(1 + e) un / (1/mA + 1/mB + (rA x n)^2 / IA + (rB x n)^2 / IB),
// un = the relative normal velocity of A's corner against B's point, gives the velocities and
// spins after. Mass ratios 1 and 20 (either way), several dt; to 1e-9 of the speed.
void TestSoftExact::polygonImpact_data()
{
    QTest::addColumn<SolverKind>("solver");
    QTest::addColumn<double>("densityA");
    QTest::addColumn<double>("e");
    QTest::addColumn<double>("dt");
    for (SolverKind solver : kSolvers)
        for (double dt : {1e-3, 1.0 / 60.0, 1.0 / 240.0}) {
            const char* name = solverLabel(solver);
            QTest::addRow("%s, equal, elastic, dt %g", name, dt) << solver << 1.0 << 1.0 << dt;
            QTest::addRow("%s, A heavy, e=0.5, dt %g", name, dt) << solver << 20.0 << 0.5 << dt;
            QTest::addRow("%s, A light, e=0.8, dt %g", name, dt) << solver << 0.05 << 0.8 << dt;
        }
}

void TestSoftExact::polygonImpact()
{
    QFETCH(SolverKind, solver);
    QFETCH(double, densityA);
    QFETCH(double, e);
    QFETCH(double, dt);
    const double w = 0.6, hA = 0.3, theta = 0.4;
    const Vec2 xA0(-1.3, 1.2), vA0(1.1, -2.0), xB0(0.0, 0.0), vB0(-0.2, 0.5);
    const double wB = 4.0, hB = 0.5;
    World world(exactWorld(solver, dt, e, 0.0));
    BodyDef defA = rigidlab::test::boxBody(w, hA, xA0, theta, densityA);
    defA.velocity = vA0;
    const BodyId a = world.addBody(defA);
    BodyDef defB = rigidlab::test::boxBody(wB, hB, xB0);
    defB.velocity = vB0;
    const BodyId b = world.addBody(defB);
    const double mA = densityA * w * hA, mB = wB * hB;
    const double iA = mA * (w * w + hA * hA) / 12.0, iB = mB * (wB * wB + hB * hB) / 12.0;
    // A's lowest corner, from its centre: the corners (+-w/2, +-h/2) turned by theta.
    const double c = std::cos(theta), sn = std::sin(theta);
    Vec2 corner(0.0, INFINITY);
    for (double sx : {-1.0, 1.0})
        for (double sy : {-1.0, 1.0}) {
            const Vec2 k(c * sx * w / 2 - sn * sy * hA / 2, sn * sx * w / 2 + c * sy * hA / 2);
            if (k.y() < corner.y())
                corner = k;
        }
    const double gap = (xA0.y() + corner.y()) - (xB0.y() + hB / 2);
    const double tStar = gap / (vB0.y() - vA0.y());
    QVERIFY(tStar > 0.1 && tStar < 1.0);
    const Vec2 centreA = xA0 + tStar * vA0, centreB = xB0 + tStar * vB0;
    const Vec2 p = centreA + corner, n(0.0, 1.0);
    QVERIFY(std::abs(p.x() - centreB.x()) < wB / 2 - 0.1);
    const Vec2 rA = p - centreA, rB = p - centreB;
    const double rnA = rigidlab::test::cross2(rA, n), rnB = rigidlab::test::cross2(rB, n);
    const double un = (vA0 - vB0).dot(n);
    const double j = -(1.0 + e) * un / (1 / mA + 1 / mB + rnA * rnA / iA + rnB * rnB / iB);
    const Vec2 vA = vA0 + (j / mA) * n, vB = vB0 - (j / mB) * n;
    const double wA = j * rnA / iA, wBAfter = -j * rnB / iB;
    // Shortly after the impact, before the turning box could bring another corner down.
    for (int i = 0; i < static_cast<int>((tStar + 0.03) / dt) + 1; ++i)
        world.step();
    const double tol = 1e-9 * vA0.norm();
    RL_VERIFY_NEAR(world.body(a).velocity.x(), vA.x(), tol, 0.0);
    RL_VERIFY_NEAR(world.body(a).velocity.y(), vA.y(), tol, 0.0);
    RL_VERIFY_NEAR(world.body(a).angularVelocity, wA, tol, 0.0);
    RL_VERIFY_NEAR(world.body(b).velocity.x(), vB.x(), tol, 0.0);
    RL_VERIFY_NEAR(world.body(b).velocity.y(), vB.y(), tol, 0.0);
    RL_VERIFY_NEAR(world.body(b).angularVelocity, wBAfter, tol, 0.0);
}

// A ball at 1 m/s into a row of four touching equal balls, e = 1, no friction or gravity: the
// striker stops and the last ball leaves at 1 m/s; the others stay at rest. To 1e-9 m/s.
void TestSoftExact::newtonsCradle_data()
{
    QTest::addColumn<SolverKind>("solver");
    for (SolverKind solver : kSolvers)
        QTest::newRow(solverLabel(solver)) << solver;
}

void TestSoftExact::newtonsCradle()
{
    QFETCH(SolverKind, solver);
    const double r = 0.05, v = 1.0;
    World world(exactWorld(solver, 1e-3, 1.0, 0.0));
    world.addBody(circleBody(r, Vec2(-2 * r - 0.003, 0.0), Vec2(v, 0.0)));
    for (int i = 0; i < 4; ++i)
        world.addBody(circleBody(r, Vec2(2 * r * i, 0.0)));
    for (int i = 0; i < 300; ++i)
        world.step();
    for (int i = 0; i < 4; ++i) {
        RL_VERIFY_NEAR(world.body(i).velocity.x(), 0.0, 1e-9, 0.0);
        RL_VERIFY_NEAR(world.body(i).velocity.y(), 0.0, 1e-12, 0.0);
    }
    RL_VERIFY_NEAR(world.body(4).velocity.x(), v, 1e-9, 0.0);
}

// A disc thrown obliquely at a static wall, no gravity: the impulsive textbook collision with
// Coulomb friction. The normal impulse turns the approach un into -e un:
//     Jn = m (1 + e) |un|;
// the tangential impulse stops the contact point's slip ut = vt + w r if that takes no more
// than mu Jn (the disc's tangential effective mass is m / 3: 1/m + r^2 / (m r^2 / 2) = 3/m),
// else it is mu Jn against the slip. Velocities and spin after, to 1e-9 of the speed, at
// dt = 1/60 s (the impact falls within a step).
void TestSoftExact::wallBounce_data()
{
    QTest::addColumn<SolverKind>("solver");
    QTest::addColumn<double>("e");
    QTest::addColumn<double>("mu");
    QTest::addColumn<double>("spin");
    for (SolverKind solver : kSolvers) {
        const char* name = solverLabel(solver);
        QTest::addRow("%s, e=0.8, no friction", name) << solver << 0.8 << 0.0 << 0.0;
        QTest::addRow("%s, e=0.5, slides through", name) << solver << 0.5 << 0.1 << 0.0;
        QTest::addRow("%s, e=1, sticks", name) << solver << 1.0 << 0.9 << 0.0;
        QTest::addRow("%s, e=0.3, spinning, slides", name) << solver << 0.3 << 0.2 << 25.0;
    }
}

void TestSoftExact::wallBounce()
{
    QFETCH(SolverKind, solver);
    QFETCH(double, e);
    QFETCH(double, mu);
    QFETCH(double, spin);
    const double r = 0.2;
    const Vec2 v0(4.0, 1.5); // toward the wall's face at x = 2
    World world(exactWorld(solver, 1.0 / 60.0, e, mu));
    BodyDef wall = rigidlab::test::boxBody(0.2, 20.0, Vec2(2.1, 0.0));
    wall.type = BodyType::Static;
    world.addBody(wall);
    BodyDef disc = circleBody(r, Vec2(0.0, 0.0), v0);
    disc.angularVelocity = spin;
    const BodyId id = world.addBody(disc);
    const double m = world.body(id).mass;
    // Normal n = (-1, 0) from the disc into the wall... in the wall's terms the disc's
    // velocity along x reverses; along y (the tangent) friction acts at the point (r, 0).
    const double un = v0.x(), jn = m * (1.0 + e) * un;
    const double slip = v0.y() + spin * r; // the contact point's velocity along y
    const double stick = m * slip / 3.0;
    const double jt = std::abs(stick) <= mu * jn ? stick : std::copysign(mu * jn, slip);
    const Vec2 v1(-e * un, v0.y() - jt / m);
    const double w1 = spin - jt * r / (0.5 * m * r * r);
    for (int i = 0; i < 60; ++i)
        world.step();
    const Body& b = world.body(id);
    RL_VERIFY_NEAR(b.velocity.x(), v1.x(), 1e-9 * v0.norm(), 0.0);
    RL_VERIFY_NEAR(b.velocity.y(), v1.y(), 1e-9 * v0.norm(), 0.0);
    RL_VERIFY_NEAR(b.angularVelocity, w1, 1e-9 * v0.norm() / r, 0.0);
}

// Fast bodies at a thin static wall (5 cm, its near face at x = 2.975), dt = 1/60 s, no
// gravity: a sharp wedge obliquely and a box spinning at 60 rad/s, at speeds that carry them
// metres per step. None may end a step beyond the wall's near face.
void TestSoftExact::thinWallStops_data()
{
    QTest::addColumn<SolverKind>("solver");
    QTest::addColumn<bool>("wedge");
    QTest::addColumn<double>("speed");
    QTest::addColumn<double>("angle");
    for (SolverKind solver : kSolvers)
        for (double speed : {40.0, 100.0, 250.0})
            for (double angle : {0.0, 0.5, 0.9}) {
                const char* name = solverLabel(solver);
                QTest::addRow("%s, wedge %g m/s at %g rad", name, speed, angle)
                    << solver << true << speed << angle;
                QTest::addRow("%s, spinning box %g m/s at %g rad", name, speed, angle)
                    << solver << false << speed << angle;
            }
}

void TestSoftExact::thinWallStops()
{
    QFETCH(SolverKind, solver);
    QFETCH(bool, wedge);
    QFETCH(double, speed);
    QFETCH(double, angle);
    World world(exactWorld(solver, 1.0 / 60.0, 0.2, 0.3));
    BodyDef wall = rigidlab::test::boxBody(0.05, 400.0, Vec2(3.0, 0.0));
    wall.type = BodyType::Static;
    world.addBody(wall);
    BodyDef body;
    if (wedge) {
        const auto shape = makePolygon({Vec2(0, 0), Vec2(0.2, 0.05), Vec2(0, 0.1)});
        QVERIFY(shape.ok());
        body.shape = makePolygonShape(shape.value().polygon);
    } else {
        body = rigidlab::test::boxBody(0.3, 0.1, Vec2::Zero());
        body.angularVelocity = 60.0;
    }
    body.velocity = speed * Vec2(std::cos(angle), std::sin(angle));
    const BodyId id = world.addBody(body);
    double farthest = -INFINITY;
    for (int i = 0; i < 60; ++i) {
        world.step();
        for (const Vec2& v : rigidlab::test::worldVertices(*world.body(id).shape.asPolygon(),
                                                           world.body(id).transform()))
            farthest = std::max(farthest, v.x());
    }
    RL_VERIFY_AT_MOST(farthest, 2.975);
    QVERIFY(world.body(id).velocity.x() <= 0.0); // it came back
}

// A disc (I = m r^2 / 2) put down sliding at v0 without spin on ground of friction mu: it
// slows and spins up until it rolls, at v0 / (1 + I / (m r^2)) = 2 v0 / 3, after
// v0 / (3 mu g) seconds. At dt = 1 ms the final speed to 1e-5 of v0, and the slip stops
// (to 1e-4 of v0: the soft contact's point lies a few micrometres inside the disc) within
// two steps of that time. The same with the contact passes in single precision
// (SoftStepSettings::singlePrecision; with the floats' velocities absolute and the ground's
// 40 m lever arm in the separation, the disc missed its rolling speed by 4.8e-5 of v0).
void TestSoftExact::slidingIntoRolling_data()
{
    QTest::addColumn<bool>("single");
    QTest::newRow("double precision") << false;
    QTest::newRow("single precision") << true;
}

void TestSoftExact::slidingIntoRolling()
{
    QFETCH(bool, single);
    const double r = 0.2, v0 = 3.0, mu = 0.3, dt = 1e-3;
    WorldDef def = exactWorld(SolverKind::SoftStep, dt, 0.0, mu);
    def.gravity = Vec2(0.0, -kG);
    World world(def);
    world.contactSettings().soft.singlePrecision = single;
    BodyDef ground = rigidlab::test::boxBody(100.0, 1.0, Vec2(40.0, -0.5));
    ground.type = BodyType::Static;
    world.addBody(ground);
    const BodyId id = world.addBody(circleBody(r, Vec2(0.0, r), Vec2(v0, 0.0)));
    const double rollsAt = v0 / (3.0 * mu * kG);
    double rolled = -1.0;
    for (int i = 1; i <= static_cast<int>(2.0 * rollsAt / dt); ++i) {
        world.step();
        const Body& b = world.body(id);
        if (rolled < 0 && std::abs(b.velocity.x() + b.angularVelocity * r) < 1e-4 * v0)
            rolled = i * dt;
    }
    const Body& b = world.body(id);
    RL_VERIFY_NEAR(b.velocity.x(), 2.0 * v0 / 3.0, 1e-5 * v0, 0.0);
    RL_VERIFY_NEAR(rolled, rollsAt, 2 * dt, 0.0);
}

RIGIDLAB_TEST_GUILESS_MAIN(TestSoftExact)
#include "test_soft_exact.moc"
