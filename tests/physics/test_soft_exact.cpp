// SPDX-License-Identifier: GPL-3.0-or-later
// The soft step (the lab's default solver) against the textbook where the lab promises exact
// mechanics: an oblique elastic cut shot of equal balls (they leave at 90°, the object ball
// along the line of centres at the impact), an oblique collision of unequal balls with
// restitution, Newton's cradle, a disc's oblique bounce off a wall with Coulomb friction,
// rolling and sliding into rolling, and fast bodies that must not pass through a thin wall.

#include "physics_test_util.h"

#include <rigidlab/physics/world.h>

#include "test_main.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace rigidlab::physics;
using rigidlab::test::circleBody;

namespace {

constexpr double kG = 9.81; // [m/s^2]

WorldDef softWorld(double dt, double e, double friction)
{
    WorldDef def = rigidlab::test::quietWorldDef(IntegratorKind::SymplecticEuler, dt);
    def.solver = SolverKind::SoftStep;
    def.restitution = e;
    def.friction = friction;
    def.sleep = false;
    return def;
}

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
    void newtonsCradle();
    void wallBounce_data();
    void wallBounce();
    void thinWallStops_data();
    void thinWallStops();
    void rollingKeepsSpeed();
    void slidingIntoRolling();
};

// Equal balls of radius r, e = 1, no friction: the cue ball at v along y = 0, the object ball
// at rest at (0, b). At the impact their centres are 2r apart, the line of centres makes the
// angle asin(b / 2r) with the cue's path, and the impulse acts along it: the object ball
// leaves along it, the cue ball at exactly 90° to it (equal masses, elastic). Both to 1e-9 rad.
void TestSoftExact::cutShot_data()
{
    QTest::addColumn<double>("offset");
    QTest::addColumn<double>("dt");
    QTest::newRow("thin cut, 1 ms") << 0.9 << 1e-3;
    QTest::newRow("half ball, 1 ms") << 0.5 << 1e-3;
    QTest::newRow("full, 1/60 s") << 0.2 << 1.0 / 60.0;
    QTest::newRow("half ball, 1/60 s") << 0.6 << 1.0 / 60.0;
}

void TestSoftExact::cutShot()
{
    QFETCH(double, offset);
    QFETCH(double, dt);
    const double r = 0.5, speed = 3.0;
    World world(softWorld(dt, 1.0, 0.0));
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
    QTest::addColumn<double>("e");
    QTest::newRow("elastic") << 1.0;
    QTest::newRow("e=0.6") << 0.6;
    QTest::newRow("e=0") << 0.0;
}

void TestSoftExact::obliqueTextbook()
{
    QFETCH(double, e);
    const double rA = 0.4, rB = 0.25, offset = 0.3;
    const Vec2 vA0(2.5, 0.4), vB0(-1.0, 0.0);
    World world(softWorld(1e-3, e, 0.0));
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
    for (int i = 0; i < 2000; ++i)
        world.step();
    const double tol = 1e-9 * vA0.norm();
    RL_VERIFY_NEAR(world.body(a).velocity.x(), vA.x(), tol, 0.0);
    RL_VERIFY_NEAR(world.body(a).velocity.y(), vA.y(), tol, 0.0);
    RL_VERIFY_NEAR(world.body(b).velocity.x(), vB.x(), tol, 0.0);
    RL_VERIFY_NEAR(world.body(b).velocity.y(), vB.y(), tol, 0.0);
}

// A ball at 1 m/s into a row of four touching equal balls, e = 1, no friction or gravity: the
// striker stops and the last ball leaves at 1 m/s; the others stay at rest. To 1e-9 m/s.
void TestSoftExact::newtonsCradle()
{
    const double r = 0.05, v = 1.0;
    World world(softWorld(1e-3, 1.0, 0.0));
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
    QTest::addColumn<double>("e");
    QTest::addColumn<double>("mu");
    QTest::addColumn<double>("spin");
    QTest::newRow("e=0.8, no friction") << 0.8 << 0.0 << 0.0;
    QTest::newRow("e=0.5, slides through") << 0.5 << 0.1 << 0.0;
    QTest::newRow("e=1, sticks") << 1.0 << 0.9 << 0.0;
    QTest::newRow("e=0.3, spinning, slides") << 0.3 << 0.2 << 25.0;
}

void TestSoftExact::wallBounce()
{
    QFETCH(double, e);
    QFETCH(double, mu);
    QFETCH(double, spin);
    const double r = 0.2;
    const Vec2 v0(4.0, 1.5); // toward the wall's face at x = 2
    World world(softWorld(1.0 / 60.0, e, mu));
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
    QTest::addColumn<bool>("wedge");
    QTest::addColumn<double>("speed");
    QTest::addColumn<double>("angle");
    for (double speed : {40.0, 100.0, 250.0})
        for (double angle : {0.0, 0.5, 0.9}) {
            QTest::addRow("wedge %g m/s at %g rad", speed, angle) << true << speed << angle;
            QTest::addRow("spinning box %g m/s at %g rad", speed, angle) << false << speed << angle;
        }
}

void TestSoftExact::thinWallStops()
{
    QFETCH(bool, wedge);
    QFETCH(double, speed);
    QFETCH(double, angle);
    World world(softWorld(1.0 / 60.0, 0.2, 0.3));
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

// A disc rolling on level ground keeps its speed: friction does no work, and the contact takes
// nothing. Over 10 s after the first second (in which the soft contact settles, the disc
// sinking a fraction of a millimetre and rolling about a point that much nearer its centre),
// to 1e-9 of the speed.
void TestSoftExact::rollingKeepsSpeed()
{
    const double r = 0.2, v = 2.0;
    WorldDef def = softWorld(1.0 / 60.0, 0.0, 0.6);
    def.gravity = Vec2(0.0, -kG);
    World world(def);
    BodyDef ground = rigidlab::test::boxBody(100.0, 1.0, Vec2(40.0, -0.5));
    ground.type = BodyType::Static;
    world.addBody(ground);
    BodyDef disc = circleBody(r, Vec2(0.0, r), Vec2(v, 0.0));
    disc.angularVelocity = -v / r;
    const BodyId id = world.addBody(disc);
    for (int i = 0; i < 60; ++i)
        world.step();
    const Vec2 settled = world.body(id).velocity;
    const double spin = world.body(id).angularVelocity;
    RL_VERIFY_NEAR(settled.x(), v, 0.0, 2e-3);
    for (int i = 0; i < 600; ++i)
        world.step();
    const Body& b = world.body(id);
    RL_VERIFY_NEAR(b.velocity.x(), settled.x(), 1e-9 * v, 0.0);
    RL_VERIFY_NEAR(b.angularVelocity, spin, 1e-9 * v / r, 0.0);
    RL_VERIFY_NEAR(b.position.y(), r, 2e-3, 0.0);
}

// A disc (I = m r^2 / 2) put down sliding at v0 without spin on ground of friction mu: it
// slows and spins up until it rolls, at v0 / (1 + I / (m r^2)) = 2 v0 / 3, after
// v0 / (3 mu g) seconds. At dt = 1 ms the final speed to 1e-5 of v0, and the slip stops
// (to 1e-4 of v0: the soft contact's point lies a few micrometres inside the disc) within
// two steps of that time.
void TestSoftExact::slidingIntoRolling()
{
    const double r = 0.2, v0 = 3.0, mu = 0.3, dt = 1e-3;
    WorldDef def = softWorld(dt, 0.0, mu);
    def.gravity = Vec2(0.0, -kG);
    World world(def);
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
