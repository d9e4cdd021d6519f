// SPDX-License-Identifier: GPL-3.0-or-later
// Shapes and their mass properties against closed forms computed independently here, how
// makePolygon turns a vertex list into a convex polygon (order, hull, errors), and bodies
// placed by their origin but kept at their centre of mass.

#include "physics_test_util.h"

#include <rigidlab/physics/shape.h>
#include <rigidlab/physics/world.h>

#include "test_main.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

using namespace rigidlab::physics;

Q_DECLARE_METATYPE(std::vector<Vec2>)

namespace {

constexpr double kPi = std::numbers::pi;

/// Polar moment of a triangle about its own centroid per unit density, from its side lengths:
/// area * (a^2 + b^2 + c^2) / 36 (the standard result; see also the parallel-axis check below).
double triangleInertiaAboutCentroid(const Vec2& p0, const Vec2& p1, const Vec2& p2)
{
    const double area = 0.5 * std::abs(rigidlab::test::cross2(p1 - p0, p2 - p0));
    const double s2 = (p1 - p0).squaredNorm() + (p2 - p1).squaredNorm() + (p0 - p2).squaredNorm();
    return area * s2 / 36.0;
}

/// Area, centroid and inertia about the centroid of a convex polygon (unit density), by
/// splitting it into a fan of triangles and moving each triangle's inertia to the common
/// centroid with the parallel-axis theorem.
struct Mass2 {
    double area = 0;
    Vec2 centroid = Vec2::Zero();
    double inertia = 0;
};
Mass2 fanMass(const std::vector<Vec2>& v)
{
    Mass2 out;
    std::vector<double> areas;
    std::vector<Vec2> centres;
    for (std::size_t i = 1; i + 1 < v.size(); ++i) {
        const double area = 0.5 * rigidlab::test::cross2(v[i] - v[0], v[i + 1] - v[0]);
        areas.push_back(area);
        centres.push_back((v[0] + v[i] + v[i + 1]) / 3.0);
        out.area += area;
        out.centroid += area * centres.back();
    }
    out.centroid /= out.area;
    for (std::size_t i = 1; i + 1 < v.size(); ++i) {
        out.inertia += triangleInertiaAboutCentroid(v[0], v[i], v[i + 1]) +
                       areas[i - 1] * (centres[i - 1] - out.centroid).squaredNorm();
    }
    return out;
}

} // namespace

class TestShapes : public QObject {
    Q_OBJECT

private slots:
    void circleMass_data();
    void circleMass();
    void boxMass_data();
    void boxMass();
    void polygonMass_data();
    void polygonMass();
    void clockwiseIsReversed();
    void nonConvexBecomesHull();
    void randomCloudsBecomeTheirHull();
    void invalidPolygons_data();
    void invalidPolygons();
    void massOverrideScalesInertia();
    void setBodyMassScalesInertia();
    void setBodyMassChangesTheMotion();
    void bodyKeptAtCentreOfMass();
};

// ---------------------------------------------------------------------------------------------
// Shapes and mass (1e-12 relative throughout: closed forms evaluated two ways)

void TestShapes::circleMass_data()
{
    QTest::addColumn<double>("radius");
    QTest::addColumn<double>("density");
    QTest::addColumn<Vec2>("centre");
    QTest::newRow("unit") << 1.0 << 1.0 << Vec2(0.0, 0.0);
    QTest::newRow("small dense") << 0.05 << 7800.0 << Vec2(0.0, 0.0);
    QTest::newRow("off-centre") << 0.3 << 2.5 << Vec2(0.4, -0.2);
}

void TestShapes::circleMass()
{
    QFETCH(double, radius);
    QFETCH(double, density);
    QFETCH(Vec2, centre);
    const MassProperties mp = computeMass(makeCircleShape(radius, centre), density);
    const double m = density * kPi * radius * radius;
    RL_VERIFY_NEAR(mp.area, kPi * radius * radius, 0.0, 1e-12);
    RL_VERIFY_NEAR(mp.mass, m, 0.0, 1e-12);
    RL_VERIFY_NEAR(mp.inertia, m * radius * radius / 2.0, 0.0, 1e-12);
    RL_VERIFY_NEAR(mp.centroid.x(), centre.x(), 1e-15, 0.0);
    RL_VERIFY_NEAR(mp.centroid.y(), centre.y(), 1e-15, 0.0);
}

void TestShapes::boxMass_data()
{
    QTest::addColumn<double>("w");
    QTest::addColumn<double>("h");
    QTest::addColumn<double>("density");
    QTest::newRow("unit") << 1.0 << 1.0 << 1.0;
    QTest::newRow("plank") << 4.0 << 0.2 << 600.0;
    QTest::newRow("rod") << 0.2 << 2.0 << 1.0;
}

void TestShapes::boxMass()
{
    QFETCH(double, w);
    QFETCH(double, h);
    QFETCH(double, density);
    const Polygon box = makeBox(w, h);
    QCOMPARE(box.vertices.size(), size_t(4));
    for (const Vec2& v : box.vertices) {
        QCOMPARE(std::abs(v.x()), w / 2);
        QCOMPARE(std::abs(v.y()), h / 2);
    }
    const MassProperties mp = computeMass(makePolygonShape(box), density);
    const double m = density * w * h;
    RL_VERIFY_NEAR(mp.area, w * h, 0.0, 1e-12);
    RL_VERIFY_NEAR(mp.mass, m, 0.0, 1e-12);
    RL_VERIFY_NEAR(mp.inertia, m * (w * w + h * h) / 12.0, 0.0, 1e-12);
    RL_VERIFY_NEAR(mp.centroid.norm(), 0.0, 1e-15, 0.0);
}

// Off-centre polygons. A triangle: centroid = mean of the vertices; inertia about it by the
// side-length formula, and again as (inertia about the origin) - m |c|^2 with the origin
// integral  rho A/6 (|p0|^2 + |p1|^2 + |p2|^2 + p0.p1 + p1.p2 + p2.p0). A pentagon: by a
// fan of triangles and the parallel-axis theorem (fanMass).
void TestShapes::polygonMass_data()
{
    QTest::addColumn<std::vector<Vec2>>("vertices");
    QTest::addColumn<double>("density");
    QTest::newRow("triangle") << std::vector<Vec2>{{1.0, 1.0}, {3.0, 1.5}, {1.5, 3.0}} << 2.0;
    QTest::newRow("pentagon")
        << std::vector<Vec2>{{2.0, -1.0}, {3.5, -0.5}, {3.8, 1.0}, {2.5, 2.0}, {1.6, 0.4}} << 0.7;
}

void TestShapes::polygonMass()
{
    QFETCH(std::vector<Vec2>, vertices);
    QFETCH(double, density);
    auto built = makePolygon(vertices);
    QVERIFY2(built.ok(), built.ok() ? "" : built.error().c_str());
    QVERIFY(built.value().warning.empty());
    const MassProperties mp = computeMass(makePolygonShape(built.value().polygon), density);
    const Mass2 fan = fanMass(vertices);
    if (vertices.size() == 3) {
        const Vec2 mean = (vertices[0] + vertices[1] + vertices[2]) / 3.0;
        RL_VERIFY_NEAR(fan.centroid.x(), mean.x(), 1e-15, 1e-14);
        RL_VERIFY_NEAR(fan.centroid.y(), mean.y(), 1e-15, 1e-14);
        const Vec2 &p0 = vertices[0], &p1 = vertices[1], &p2 = vertices[2];
        const double aboutOrigin = fan.area / 6.0 *
                                   (p0.squaredNorm() + p1.squaredNorm() + p2.squaredNorm() +
                                    p0.dot(p1) + p1.dot(p2) + p2.dot(p0));
        RL_VERIFY_NEAR(aboutOrigin - fan.area * mean.squaredNorm(), fan.inertia, 0.0, 1e-12);
    }
    RL_VERIFY_NEAR(mp.area, fan.area, 0.0, 1e-12);
    RL_VERIFY_NEAR(mp.mass, density * fan.area, 0.0, 1e-12);
    RL_VERIFY_NEAR(mp.centroid.x(), fan.centroid.x(), 0.0, 1e-12);
    RL_VERIFY_NEAR(mp.centroid.y(), fan.centroid.y(), 0.0, 1e-12);
    RL_VERIFY_NEAR(mp.inertia, density * fan.inertia, 0.0, 1e-12);
}

// A clockwise list comes back counter-clockwise: the same vertices, positive signed area,
// outward unit normals perpendicular to their edges.
void TestShapes::clockwiseIsReversed()
{
    const std::vector<Vec2> cw = {{0.0, 0.0}, {0.5, 1.5}, {2.0, 1.0}, {1.5, -0.5}};
    double shoelace = 0.0;
    for (std::size_t i = 0; i < cw.size(); ++i) {
        shoelace += rigidlab::test::cross2(cw[i], cw[(i + 1) % cw.size()]) / 2.0;
    }
    QVERIFY(shoelace < 0.0); // the input really is clockwise
    auto built = makePolygon(cw);
    QVERIFY(built.ok());
    const Polygon& p = built.value().polygon;
    QCOMPARE(p.vertices.size(), cw.size());
    RL_VERIFY_NEAR(signedArea(p.vertices), -shoelace, 0.0, 1e-12);
    RL_VERIFY_NEAR(signedArea(cw), shoelace, 0.0, 1e-12);
    for (const Vec2& v : cw) {
        QVERIFY(std::find(p.vertices.begin(), p.vertices.end(), v) != p.vertices.end());
    }
    const Vec2 centre = fanMass(p.vertices).centroid;
    QCOMPARE(p.normals.size(), p.vertices.size());
    for (std::size_t i = 0; i < p.vertices.size(); ++i) {
        const Vec2 e = p.vertices[(i + 1) % p.vertices.size()] - p.vertices[i];
        QVERIFY(rigidlab::test::cross2(e, p.vertices[(i + 2) % p.vertices.size()] - p.vertices[i]) >
                0.0);
        RL_VERIFY_NEAR(p.normals[i].norm(), 1.0, 1e-15, 0.0);
        RL_VERIFY_NEAR(p.normals[i].dot(e), 0.0, 1e-15, 0.0);
        QVERIFY(p.normals[i].dot(centre - p.vertices[i]) < 0.0);
    }
}

// A non-convex list becomes its convex hull, as the test's own gift wrapping finds it, with a
// warning saying so: a dart with a reflex vertex, a four-pointed star with reflex vertices,
// and a pentagram (a regular pentagon's corners visited two apart: every turn is to the left,
// yet the loop crosses itself and winds twice). A convex list gets no warning.
void TestShapes::nonConvexBecomesHull()
{
    std::vector<Vec2> pentagram;
    for (int i = 0; i < 5; ++i) {
        const double a = kPi / 2 + 2.0 * (2.0 * kPi / 5.0) * i;
        pentagram.push_back(Vec2(std::cos(a), std::sin(a)));
    }
    const std::vector<std::vector<Vec2>> inputs = {
        {{0.0, 0.0}, {2.0, 0.0}, {2.0, 2.0}, {1.0, 0.5}, {0.0, 2.0}},
        {{1.0, 0.0},
         {0.3, 0.3},
         {0.0, 1.0},
         {-0.3, 0.3},
         {-1.0, 0.0},
         {-0.3, -0.3},
         {0.0, -1.0},
         {0.3, -0.3}},
        pentagram,
    };
    for (const auto& input : inputs) {
        auto built = makePolygon(input);
        QVERIFY(built.ok());
        const auto hull = rigidlab::test::giftWrapHull(input);
        const auto& got = built.value().polygon.vertices;
        RL_VERIFY_NEAR(signedArea(got), signedArea(hull), 0.0, 1e-12);
        QVERIFY(rigidlab::test::sameLoop(got, hull));
        QVERIFY2(!built.value().warning.empty(), "a non-convex input must carry a warning");
    }
    auto convex = makePolygon({{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}});
    QVERIFY(convex.ok());
    QVERIFY(convex.value().warning.empty());
}

// 5,000 random clouds of 3 to 8 points (fixed seed) through makePolygon: the result is the
// convex hull as the test's own gift wrapping finds it (the same loop, counter-clockwise,
// possibly starting elsewhere), and any input that is not already a convex loop (interior
// points, or hull points in a crossing order such as a star) carries a warning.
void TestShapes::randomCloudsBecomeTheirHull()
{
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<int> count(3, 8);
    int nonConvexInputs = 0;
    for (int trial = 0; trial < 5000; ++trial) {
        std::vector<Vec2> pts;
        const int n = count(rng);
        for (int i = 0; i < n; ++i) {
            pts.push_back(Vec2(unit(rng), unit(rng)));
        }
        const auto hull = rigidlab::test::giftWrapHull(pts);
        if (hull.size() < 3 || signedArea(hull) < 1e-6) {
            continue; // (nearly) degenerate: not what this test is about
        }
        QString input;
        for (const Vec2& p : pts) {
            input += QString("(%1, %2) ").arg(p.x(), 0, 'g', 17).arg(p.y(), 0, 'g', 17);
        }
        auto built = makePolygon(pts);
        QVERIFY2(built.ok(), qPrintable("rejected " + input));
        const auto& got = built.value().polygon.vertices;
        QVERIFY2(rigidlab::test::sameLoop(got, hull),
                 qPrintable(QString("trial %1: %2 vertices for a hull of %3; input %4")
                                .arg(trial)
                                .arg(got.size())
                                .arg(hull.size())
                                .arg(input)));
        if (!rigidlab::test::isConvexLoop(pts)) {
            ++nonConvexInputs;
            QVERIFY2(
                !built.value().warning.empty(),
                qPrintable(QString("trial %1: no warning for input %2").arg(trial).arg(input)));
        }
    }
    QVERIFY(nonConvexInputs > 1000);
}

void TestShapes::invalidPolygons_data()
{
    QTest::addColumn<std::vector<Vec2>>("vertices");
    QTest::newRow("empty") << std::vector<Vec2>{};
    QTest::newRow("one point") << std::vector<Vec2>{{0.0, 0.0}};
    QTest::newRow("two points") << std::vector<Vec2>{{0.0, 0.0}, {1.0, 0.0}};
    QTest::newRow("three collinear") << std::vector<Vec2>{{0.0, 0.0}, {1.0, 1.0}, {2.0, 2.0}};
    QTest::newRow("four collinear")
        << std::vector<Vec2>{{0.0, 0.0}, {3.0, 0.0}, {1.0, 0.0}, {2.0, 0.0}};
    QTest::newRow("a repeated point") << std::vector<Vec2>{{0.0, 0.0}, {0.0, 0.0}, {1.0, 1.0}};
}

void TestShapes::invalidPolygons()
{
    QFETCH(std::vector<Vec2>, vertices);
    auto built = makePolygon(vertices);
    QVERIFY(!built.ok());
    QVERIFY(!built.error().empty());
}

// mass > 0 overrides the density and the inertia scales with it: I = m (w^2 + h^2) / 12.
void TestShapes::massOverrideScalesInertia()
{
    World world;
    BodyDef byDensity = rigidlab::test::boxBody(2.0, 1.0, Vec2::Zero(), 0.0, 3.0);
    BodyDef byMass = byDensity;
    byMass.mass = 5.0;
    const BodyId a = world.addBody(byDensity);
    const BodyId b = world.addBody(byMass);
    RL_VERIFY_NEAR(world.body(a).mass, 6.0, 0.0, 1e-12);
    RL_VERIFY_NEAR(world.body(a).inertia, 6.0 * 5.0 / 12.0, 0.0, 1e-12);
    RL_VERIFY_NEAR(world.body(b).mass, 5.0, 0.0, 1e-12);
    RL_VERIFY_NEAR(world.body(b).inertia, 5.0 * 5.0 / 12.0, 0.0, 1e-12);
    RL_VERIFY_NEAR(world.body(b).invMass, 1.0 / 5.0, 0.0, 1e-12);
    RL_VERIFY_NEAR(world.body(b).invInertia, 12.0 / 25.0, 0.0, 1e-12);
}

// World::setBodyMass (the inspector's mass field): the box keeps its shape's distribution,
// I = m (w^2 + h^2) / 12 for the new m; velocities stay; other bodies and invalid masses
// change nothing.
void TestShapes::setBodyMassScalesInertia()
{
    World world;
    BodyDef box = rigidlab::test::boxBody(2.0, 1.0, Vec2(1.0, 2.0), 0.3, 3.0);
    box.velocity = Vec2(0.5, -1.0);
    box.angularVelocity = 2.0;
    const BodyId a = world.addBody(box);
    BodyDef ground = rigidlab::test::boxBody(10.0, 1.0, Vec2(0.0, -5.0));
    ground.type = BodyType::Static;
    const BodyId g = world.addBody(ground);
    const Vec2 position = world.body(a).position;
    const Vec2 velocity = world.body(a).velocity;
    QVERIFY(world.setBodyMass(a, 5.0));
    const Body& b = world.body(a);
    RL_VERIFY_NEAR(b.mass, 5.0, 0.0, 1e-15);
    RL_VERIFY_NEAR(b.inertia, 5.0 * 5.0 / 12.0, 0.0, 1e-12);
    RL_VERIFY_NEAR(b.invMass, 1.0 / 5.0, 0.0, 1e-12);
    RL_VERIFY_NEAR(b.invInertia, 12.0 / 25.0, 0.0, 1e-12);
    QVERIFY(b.position == position && b.velocity == velocity);
    QCOMPARE(b.angularVelocity, 2.0);
    QVERIFY(b.awake);
    for (double bad : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()})
        QVERIFY(!world.setBodyMass(a, bad));
    QVERIFY(!world.setBodyMass(g, 1.0));
    QVERIFY(!world.setBodyMass(7, 1.0));
    QCOMPARE(world.body(a).mass, 5.0);
    QCOMPARE(world.body(g).mass, 0.0);
    QCOMPARE(world.body(g).invMass, 0.0);
}

// The integrator takes the new mass at once: a body on a spring of k = 4 N/m, given 4 kg
// instead of 1 kg, oscillates with omega = sqrt(k / m) = 1 rad/s, x(t) = x0 cos(t). RK4 at
// dt = 1 ms is within 1e-9 m over half a period.
void TestShapes::setBodyMassChangesTheMotion()
{
    rigidlab::test::OscillatorSpec spec;
    spec.mass = 1.0;
    spec.stiffness = 4.0;
    World world = rigidlab::test::makeOscillator(IntegratorKind::RK4, 1e-3, spec);
    QVERIFY(world.setBodyMass(0, 4.0));
    const int steps = 3142;
    for (int i = 0; i < steps; ++i)
        world.step();
    const double t = world.time();
    RL_VERIFY_NEAR(world.body(0).position.x(), spec.x0 * std::cos(t), 1e-9, 0.0);
    QVERIFY(!world.divergence());
}

// A body is placed by its origin and kept at its centre of mass: position = origin + R c;
// origin() gives the origin back; the origin's velocity is v + w x (origin - position), and
// setBodyVelocity / setBodyOrigin invert that. 1e-12.
void TestShapes::bodyKeptAtCentreOfMass()
{
    const std::vector<Vec2> tri = {{1.0, 1.0}, {3.0, 1.5}, {1.5, 3.0}};
    const Vec2 c = (tri[0] + tri[1] + tri[2]) / 3.0;
    World world;
    BodyDef def;
    def.shape = makePolygonShape(makePolygon(tri).value().polygon);
    def.position = Vec2(-2.0, 0.5);
    def.angle = 0.6;
    def.velocity = Vec2(1.0, -0.5);
    def.angularVelocity = 2.0;
    const BodyId id = world.addBody(def);
    const Body& b = world.body(id);
    const Vec2 expected = def.position + Rotation(def.angle).apply(c);
    RL_VERIFY_NEAR((b.localCenter - c).norm(), 0.0, 1e-12, 0.0);
    RL_VERIFY_NEAR((b.position - expected).norm(), 0.0, 1e-12, 0.0);
    RL_VERIFY_NEAR((b.origin() - def.position).norm(), 0.0, 1e-12, 0.0);
    // BodyDef.velocity is the origin's; the centre of mass moves with v + w x (com - origin).
    const Vec2 vCom = def.velocity + cross(def.angularVelocity, Vec2(expected - def.position));
    RL_VERIFY_NEAR((b.velocity - vCom).norm(), 0.0, 1e-12, 0.0);
    RL_VERIFY_NEAR((world.originVelocity(id) - def.velocity).norm(), 0.0, 1e-12, 0.0);

    world.setBodyOrigin(id, Vec2(3.0, 4.0), -1.0);
    RL_VERIFY_NEAR((world.body(id).origin() - Vec2(3.0, 4.0)).norm(), 0.0, 1e-12, 0.0);
    RL_VERIFY_NEAR((world.body(id).position - (Vec2(3.0, 4.0) + Rotation(-1.0).apply(c))).norm(),
                   0.0, 1e-12, 0.0);
    world.setBodyVelocity(id, Vec2(0.5, 0.25), -3.0);
    RL_VERIFY_NEAR((world.originVelocity(id) - Vec2(0.5, 0.25)).norm(), 0.0, 1e-12, 0.0);
    RL_VERIFY_NEAR(world.body(id).angularVelocity, -3.0, 1e-15, 0.0);
}

RIGIDLAB_TEST_GUILESS_MAIN(TestShapes)
#include "test_shapes.moc"
