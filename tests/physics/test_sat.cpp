// SPDX-License-Identifier: GPL-3.0-or-later
// The separating axis test against an independent method, the Minkowski difference, on
// thousands of random convex polygon pairs (general, touching, and near-parallel), plus named
// box and circle cases whose answers follow from the geometry.
//
// The independent method is in minkowski_reference.h.

#include "minkowski_reference.h"
#include "physics_test_util.h"

#include <rigidlab/physics/sat.h>
#include <rigidlab/physics/shape.h>

#include "test_main.h"

#include <QTest>

#include <cmath>
#include <numbers>
#include <random>

using namespace rigidlab::physics;
using rigidlab::test::isClose;
using rigidlab::test::maxAlong;
using rigidlab::test::minAlong;
using rigidlab::test::Minkowski;
using rigidlab::test::minkowski;

namespace {

constexpr double kPi = std::numbers::pi;

/// A random convex polygon: the hull (the test's own gift wrapping) of 3 to 8 points in a
/// disc (radius 0.2 to 1.5 m) whose centre is off the body origin, made into a Polygon by
/// makePolygon. The hull goes in already convex and counter-clockwise, so makePolygon must
/// keep it as it is (checked by the caller): the SAT is then tested on polygons known to be
/// convex, whatever makePolygon does with other input (tested in test_shapes).
std::vector<Vec2> randomHull(std::mt19937_64& rng)
{
    std::uniform_int_distribution<int> count(3, 8);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (;;) {
        const double radius = 0.2 + 1.3 * unit(rng);
        const Vec2 centre(unit(rng) - 0.5, unit(rng) - 0.5);
        std::vector<Vec2> pts;
        const int n = count(rng);
        for (int i = 0; i < n; ++i) {
            const double r = radius * std::sqrt(unit(rng));
            const double t = 2.0 * kPi * unit(rng);
            pts.push_back(centre + r * Vec2(std::cos(t), std::sin(t)));
        }
        const std::vector<Vec2> hull = rigidlab::test::giftWrapHull(pts);
        // Tiny slivers make tests about rounding, not about the SAT: ask for some area.
        if (hull.size() >= 3 && signedArea(hull) > 0.01 * radius * radius) {
            return hull;
        }
    }
}

/// What one pair gives; counts kept so the test can show it covered the cases it claims to.
struct Tally {
    int pairs = 0, intersecting = 0, separated = 0, ambiguous = 0, normalsCompared = 0;
    int twoPointManifolds = 0;
    int touchingReported = 0;      ///< touching pairs the SAT called intersecting
    int touchingWithoutPoints = 0; ///< ... and gave no contact point
};

enum class PairKind { Random, Touching, NearParallel };

/// B placed on a random face of A (placed by xfA): its lowest vertex along the face's normal at
/// a random point of the face, touching (PairKind::Touching) or turned to lie almost flat on it
/// and sunk a little (PairKind::NearParallel).
Transform placedOnFace(const Polygon& a, const Transform& xfA, const Polygon& b, PairKind kind,
                       std::mt19937_64& rng)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto angle = [&] { return kPi * (2.0 * unit(rng) - 1.0); };
    // One face of A: world vertices p0 -> p1, outward normal n.
    const auto wa = rigidlab::test::worldVertices(a, xfA);
    const std::size_t fa = static_cast<std::size_t>(unit(rng) * wa.size()) % wa.size();
    const Vec2 p0 = wa[fa], p1 = wa[(fa + 1) % wa.size()];
    const Vec2 n = Vec2((p1 - p0).y(), -(p1 - p0).x()).normalized();
    double angleB = angle();
    double overlap = 0.0;
    if (kind == PairKind::NearParallel) {
        // Turn B so that one of its edge normals is -n, then off by a tiny angle.
        const std::size_t fb =
            static_cast<std::size_t>(unit(rng) * b.normals.size()) % b.normals.size();
        const Vec2 nb = b.normals[fb];
        const double target = std::atan2(-n.y(), -n.x());
        const double tilt = (unit(rng) < 0.5 ? -1.0 : 1.0) * std::pow(10.0, -9.0 + 6.0 * unit(rng));
        angleB = target - std::atan2(nb.y(), nb.x()) + tilt;
        overlap = unit(rng) < 0.1 ? 0.0 : 0.2 * unit(rng);
    }
    // Place B's lowest vertex along n at a random point of A's face, sunk by overlap.
    const Transform rotB(Vec2::Zero(), angleB);
    const auto wb0 = rigidlab::test::worldVertices(b, rotB);
    std::size_t low = 0;
    for (std::size_t k = 1; k < wb0.size(); ++k)
        if (wb0[k].dot(n) < wb0[low].dot(n))
            low = k;
    const Vec2 onFace = p0 + unit(rng) * (p1 - p0) - overlap * n;
    return Transform(onFace - wb0[low], angleB);
}

} // namespace

Q_DECLARE_METATYPE(PairKind)

class TestSat : public QObject {
    Q_OBJECT

private slots:
    void randomPairsAgreeWithMinkowski_data();
    void randomPairsAgreeWithMinkowski();
    void boxPairs_data();
    void boxPairs();
    void circles();
    void polygonAndCircle();

private:
    bool checkPair(const Polygon& a, const Transform& xfA, const Polygon& b, const Transform& xfB,
                   Tally& tally);
};

/// Compares satPolygons with the Minkowski difference on one pair. Returns false (after a
/// QVERIFY failure) on the first disagreement.
/// Tolerances: verdicts may differ only when the origin is within 1e-9 m of D's boundary
/// (touching); depth 1e-9 m absolute; the normal (when D's nearest face beats every other
/// direction by 1e-6 m) dot > 1 - 1e-9; the recorded axis data 1e-12 (the same projections).
bool TestSat::checkPair(const Polygon& a, const Transform& xfA, const Polygon& b,
                        const Transform& xfB, Tally& tally)
{
    const auto wa = rigidlab::test::worldVertices(a, xfA);
    const auto wb = rigidlab::test::worldVertices(b, xfB);
    Minkowski mink;
    [&] { QVERIFY2(minkowski(wa, wb, mink), "the test's own hull failed"); }();
    if (QTest::currentTestFailed()) {
        return false;
    }
    const SatResult r = satPolygons(a, xfA, b, xfB);
    const int nA = static_cast<int>(a.vertices.size());
    const int nB = static_cast<int>(b.vertices.size());
    ++tally.pairs;

    bool ok = true;
    auto fail = [&](const QString& what) {
        ok = false;
        QTest::qFail(qPrintable(QString("pair %1: %2 (Minkowski max gap %3, nearest c %4, SAT "
                                        "intersects %5 depth %6)")
                                    .arg(tally.pairs)
                                    .arg(what)
                                    .arg(mink.maxGap, 0, 'g', 17)
                                    .arg(mink.c[mink.nearest], 0, 'g', 17)
                                    .arg(r.intersects)
                                    .arg(r.depth, 0, 'g', 17)),
                     __FILE__, __LINE__);
    };

    // The bookkeeping: axes recorded in the order tested (A's edges, then B's), each one the
    // world normal of its edge with the projections of both polygons on it.
    if (static_cast<int>(r.axes.size()) != r.axesTested) {
        fail("axes.size() != axesTested");
        return false;
    }
    if (r.axesTested < 1 || r.axesTested > nA + nB) {
        fail(QString("tested %1 axes for %2 + %3 edges").arg(r.axesTested).arg(nA).arg(nB));
        return false;
    }
    int previousKey = -1;
    for (int i = 0; i < r.axesTested; ++i) {
        const SatAxis& ax = r.axes[i];
        const Polygon& owner = ax.owner == 0 ? a : b;
        const Transform& xf = ax.owner == 0 ? xfA : xfB;
        const int key = ax.owner * 1000 + ax.edge;
        if ((ax.owner != 0 && ax.owner != 1) || ax.edge < 0 ||
            ax.edge >= static_cast<int>(owner.vertices.size()) || key <= previousKey) {
            fail(QString("axis %1 (owner %2 edge %3) out of order")
                     .arg(i)
                     .arg(ax.owner)
                     .arg(ax.edge));
            return false;
        }
        previousKey = key;
        const Vec2 p0 = xf.apply(owner.vertices[ax.edge]);
        const Vec2 p1 = xf.apply(owner.vertices[(ax.edge + 1) % owner.vertices.size()]);
        const Vec2 normal = Vec2((p1 - p0).y(), -(p1 - p0).x()).normalized();
        const double minA = minAlong(wa, ax.axis), maxA = maxAlong(wa, ax.axis);
        const double minB = minAlong(wb, ax.axis), maxB = maxAlong(wb, ax.axis);
        if (ax.axis.dot(normal) < 1.0 - 1e-12 || !isClose(ax.minA, minA, 1e-12) ||
            !isClose(ax.maxA, maxA, 1e-12) || !isClose(ax.minB, minB, 1e-12) ||
            !isClose(ax.maxB, maxB, 1e-12) ||
            !isClose(ax.overlap, std::min(maxA - minB, maxB - minA), 1e-12)) {
            fail(QString("axis %1 (owner %2 edge %3) does not match its edge's projections")
                     .arg(i)
                     .arg(ax.owner)
                     .arg(ax.edge));
            return false;
        }
    }
    // Early out: the SAT stops at the first separating axis.
    if (!r.intersects) {
        if (r.separatingAxis != r.axesTested - 1 || r.axes.back().overlap >= 0.0) {
            fail(QString("separated, but separatingAxis %1 of %2 tested")
                     .arg(r.separatingAxis)
                     .arg(r.axesTested));
            return false;
        }
        for (int i = 0; i + 1 < r.axesTested; ++i) {
            if (r.axes[i].overlap < 0.0) {
                fail(QString("axis %1 separates but the SAT went on").arg(i));
                return false;
            }
        }
    } else if (r.separatingAxis != -1) {
        fail("intersecting with a separating axis");
        return false;
    }

    // The verdict.
    if (std::abs(mink.maxGap) <= 1e-9) {
        ++tally.ambiguous;
        if (r.intersects && r.depth > 1e-9) {
            fail("touching pair reported with a real depth");
        }
        // Touching and reported so: the contact points are where the boundaries meet.
        if (ok && r.intersects) {
            ++tally.touchingReported;
            const Manifold& m = r.manifold;
            if (m.pointCount == 0) {
                ++tally.touchingWithoutPoints; // counted, reported at the end of the row
            } else if (m.pointCount > 2) {
                fail(QString("touching: manifold with %1 points").arg(m.pointCount));
            }
            for (int i = 0; ok && i < m.pointCount; ++i) {
                const ContactPoint& cp = m.points[i];
                const double dA = rigidlab::test::distanceToBoundary(cp.point, wa);
                const double dB = rigidlab::test::distanceToBoundary(cp.point, wb);
                if (std::abs(cp.separation) > 1e-9 || dA > 1e-9 || dB > 1e-9) {
                    fail(QString("touching: contact point %1 separation %2, distance to A %3, "
                                 "to B %4")
                             .arg(i)
                             .arg(cp.separation)
                             .arg(dA)
                             .arg(dB));
                }
            }
        }
        return ok;
    }
    const bool expected = mink.maxGap < 0.0;
    if (r.intersects != expected) {
        fail("verdict differs from the Minkowski difference");
        return false;
    }
    if (!expected) {
        ++tally.separated;
        return ok;
    }
    ++tally.intersecting;

    // Depth and normal.
    const double depth = mink.c[mink.nearest];
    if (!isClose(r.depth, depth, 1e-9)) {
        fail("depth differs");
        return false;
    }
    if (std::abs(r.normal.norm() - 1.0) > 1e-12 || r.leastAxis < 0 || r.leastAxis >= r.axesTested ||
        !isClose(r.axes[r.leastAxis].overlap, r.depth, 1e-12)) {
        fail("normal not unit, or leastAxis does not hold the depth");
        return false;
    }
    const bool unique = mink.secondC - depth > 1e-6;
    const Vec2 minkNormal = -mink.normals[mink.nearest];
    if (unique) {
        ++tally.normalsCompared;
        if (r.normal.dot(minkNormal) < 1.0 - 1e-9) {
            fail(QString("normal (%1, %2) differs from the Minkowski normal (%3, %4)")
                     .arg(r.normal.x())
                     .arg(r.normal.y())
                     .arg(minkNormal.x())
                     .arg(minkNormal.y()));
            return false;
        }
    }

    // The manifold: 1 or 2 points, each no farther outside than touching, and within the
    // penetration along the manifold normal of both boundaries (that penetration is the depth
    // when the manifold's normal is the least axis, which it must be when that is unique by
    // more than 1e-3 m: more than any reference-face preference).
    const Manifold& m = r.manifold;
    if (m.pointCount < 1 || m.pointCount > 2) {
        fail(QString("manifold with %1 points").arg(m.pointCount));
        return false;
    }
    if (m.pointCount == 2) {
        ++tally.twoPointManifolds;
    }
    // The manifold's normal is a reference face's: the least axis, or one whose overlap is
    // within a face preference of it (Box2D prefers A's face unless B's is 0.1 linearSlop =
    // 5e-4 m better; allowed here: 1e-3 m).
    const double penetration = maxAlong(wa, m.normal) - minAlong(wb, m.normal);
    if (std::abs(m.normal.norm() - 1.0) > 1e-12 || penetration < depth - 1e-9 ||
        penetration > depth + 1e-3) {
        fail(QString("manifold normal (%1, %2) not unit or not a near-least axis: penetration "
                     "along it %3; SAT normal (%4, %5)")
                 .arg(m.normal.x(), 0, 'g', 17)
                 .arg(m.normal.y(), 0, 'g', 17)
                 .arg(penetration, 0, 'g', 17)
                 .arg(r.normal.x(), 0, 'g', 17)
                 .arg(r.normal.y(), 0, 'g', 17));
        return false;
    }
    if (mink.secondC - depth > 1e-3 && m.normal.dot(r.normal) < 1.0 - 1e-9) {
        fail("manifold normal is not the clearly least axis");
        return false;
    }
    for (int i = 0; i < m.pointCount; ++i) {
        const ContactPoint& cp = m.points[i];
        const double dA = rigidlab::test::distanceToBoundary(cp.point, wa);
        const double dB = rigidlab::test::distanceToBoundary(cp.point, wb);
        if (cp.separation > 1e-9 || cp.separation < -penetration - 1e-9 ||
            dA > penetration + 1e-9 || dB > penetration + 1e-9) {
            fail(QString("contact point %1 (%2, %3): separation %4, distance to A %5, to B %6, "
                         "penetration along normal %7")
                     .arg(i)
                     .arg(cp.point.x(), 0, 'g', 17)
                     .arg(cp.point.y(), 0, 'g', 17)
                     .arg(cp.separation, 0, 'g', 17)
                     .arg(dA, 0, 'g', 17)
                     .arg(dB, 0, 'g', 17)
                     .arg(penetration, 0, 'g', 17));
            return false;
        }
    }
    return ok;
}

// 10,000 random pairs; 2,000 touching pairs (B's lowest vertex along one of A's face normals
// placed exactly on that face); 2,000 near-parallel pairs (one of B's edges turned 1e-9 to
// 1e-3 rad from facing one of A's, overlapping it by 0 to 0.2 m). Each row must produce both
// verdicts (or touching) in the proportions it was built for, so the test cannot pass vacuously.
void TestSat::randomPairsAgreeWithMinkowski_data()
{
    QTest::addColumn<PairKind>("kind");
    QTest::addColumn<int>("count");
    QTest::newRow("random") << PairKind::Random << 10000;
    QTest::newRow("touching") << PairKind::Touching << 2000;
    QTest::newRow("near-parallel") << PairKind::NearParallel << 2000;
}

void TestSat::randomPairsAgreeWithMinkowski()
{
    QFETCH(PairKind, kind);
    QFETCH(int, count);
    std::mt19937_64 rng(20240611u + static_cast<unsigned>(kind));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto angle = [&] { return kPi * (2.0 * unit(rng) - 1.0); };
    Tally tally;
    auto polygonOf = [](const std::vector<Vec2>& hull, Polygon& out) {
        auto built = makePolygon(hull);
        if (!built.ok() || !rigidlab::test::sameLoop(built.value().polygon.vertices, hull))
            return false;
        out = built.value().polygon;
        return true;
    };
    for (int i = 0; i < count; ++i) {
        Polygon a, b;
        const auto hullA = randomHull(rng), hullB = randomHull(rng);
        QVERIFY2(polygonOf(hullA, a) && polygonOf(hullB, b),
                 "makePolygon changed a convex counter-clockwise vertex list");
        const Transform xfA(Vec2(4.0 * unit(rng) - 2.0, 4.0 * unit(rng) - 2.0), angle());
        Transform xfB;
        if (kind == PairKind::Random) {
            const double dist = 3.0 * unit(rng);
            const double dir = angle();
            xfB = Transform(xfA.p + dist * Vec2(std::cos(dir), std::sin(dir)), angle());
        } else {
            xfB = placedOnFace(a, xfA, b, kind, rng);
        }
        if (!checkPair(a, xfA, b, xfB, tally)) {
            return;
        }
    }
    const QString summary = QString("pairs %1: intersecting %2, separated %3, touching %4, "
                                    "normals compared %5, two-point manifolds %6; touching pairs "
                                    "called intersecting %7, of which without contact points %8")
                                .arg(tally.pairs)
                                .arg(tally.intersecting)
                                .arg(tally.separated)
                                .arg(tally.ambiguous)
                                .arg(tally.normalsCompared)
                                .arg(tally.twoPointManifolds)
                                .arg(tally.touchingReported)
                                .arg(tally.touchingWithoutPoints);
    qInfo("%s", qPrintable(summary));
    QCOMPARE(tally.pairs, count);
    // Intersecting (touching included) means a manifold of 1 or 2 points.
    QVERIFY2(tally.touchingWithoutPoints == 0, qPrintable(summary));
    switch (kind) {
    case PairKind::Random:
        QVERIFY2(tally.intersecting > count / 5 && tally.separated > count / 5,
                 qPrintable(summary));
        QVERIFY2(tally.normalsCompared > count / 10, qPrintable(summary));
        break;
    case PairKind::Touching:
        // Built to touch: the origin is on D's boundary up to rounding.
        QVERIFY2(tally.ambiguous == count, qPrintable(summary));
        break;
    case PairKind::NearParallel:
        QVERIFY2(tally.intersecting > count / 2, qPrintable(summary));
        QVERIFY2(tally.twoPointManifolds > count / 4, qPrintable(summary));
        break;
    }
}

// Named box pairs whose answers follow from the geometry: A is a w x h box at the origin,
// B a box placed by (x, y, angle). Expected depth and normal are computed here from the
// extents; 1e-12 tolerances.
void TestSat::boxPairs_data()
{
    QTest::addColumn<double>("bx");
    QTest::addColumn<double>("by");
    QTest::addColumn<double>("bAngle");
    QTest::addColumn<bool>("intersects");
    QTest::addColumn<double>("depth");
    QTest::addColumn<Vec2>("normal");
    QTest::addColumn<int>("points");
    // A: 2 x 1 box; B: 1 x 1 box. Half extents 1, 0.5 and 0.5, 0.5.
    QTest::newRow("overlap along +x")
        << 1.4 << 0.2 << 0.0 << true << (1.0 + 0.5 - 1.4) << Vec2(1.0, 0.0) << 2;
    QTest::newRow("overlap along -y")
        << -0.3 << -0.9 << 0.0 << true << (0.5 + 0.5 - 0.9) << Vec2(0.0, -1.0) << 2;
    QTest::newRow("separated along x") << 1.6 << 0.0 << 0.0 << false << 0.0 << Vec2(0.0, 0.0) << 0;
    // B turned 45 degrees, corner down into A's top face: its corner reaches sqrt(2)/2 below
    // its centre; one contact point.
    QTest::newRow("corner into top face")
        << 0.1 << (0.5 + std::sqrt(0.5) - 0.05) << kPi / 4 << true << 0.05 << Vec2(0.0, 1.0) << 1;
    QTest::newRow("diagonal gap") << 1.6 << 1.1 << 0.0 << false << 0.0 << Vec2(0.0, 0.0) << 0;
}

void TestSat::boxPairs()
{
    QFETCH(double, bx);
    QFETCH(double, by);
    QFETCH(double, bAngle);
    QFETCH(bool, intersects);
    QFETCH(double, depth);
    QFETCH(Vec2, normal);
    QFETCH(int, points);
    const Polygon a = makeBox(2.0, 1.0);
    const Polygon b = makeBox(1.0, 1.0);
    const SatResult r = satPolygons(a, Transform(), b, Transform(Vec2(bx, by), bAngle));
    QCOMPARE(r.intersects, intersects);
    if (!intersects) {
        QVERIFY(r.separatingAxis >= 0);
        return;
    }
    RL_VERIFY_NEAR(r.depth, depth, 1e-12, 0.0);
    RL_VERIFY_NEAR(r.normal.x(), normal.x(), 1e-12, 0.0);
    RL_VERIFY_NEAR(r.normal.y(), normal.y(), 1e-12, 0.0);
    QCOMPARE(r.axesTested, 8);
    QCOMPARE(r.manifold.pointCount, points);
    for (int i = 0; i < points; ++i) {
        RL_VERIFY_NEAR(r.manifold.points[i].separation, -depth, 1e-12, 0.0);
    }
}

// Two circles: separation = |cB - cA| - rA - rB, normal the unit vector from A's centre to
// B's, the point halfway between the two surfaces; nothing beyond the margin. 1e-12.
void TestSat::circles()
{
    const Circle a{Vec2(0.1, 0.0), 0.5};
    const Circle b{Vec2::Zero(), 0.3};
    const Transform xfA(Vec2(1.0, 1.0), 0.0);
    const Transform xfB(Vec2(1.5, 1.6), 0.7);
    const Vec2 ca = xfA.apply(a.center), cb = xfB.apply(b.center);
    const double d = (cb - ca).norm();
    const Vec2 n = (cb - ca) / d;
    const double separation = d - 0.5 - 0.3; // -0.05: overlapping
    const Manifold m = collideCircles(a, xfA, b, xfB, 0.0);
    QCOMPARE(m.pointCount, 1);
    RL_VERIFY_NEAR(m.points[0].separation, separation, 1e-12, 0.0);
    RL_VERIFY_NEAR(m.normal.dot(n), 1.0, 1e-12, 0.0);
    const Vec2 mid = 0.5 * ((ca + 0.5 * n) + (cb - 0.3 * n));
    RL_VERIFY_NEAR((m.points[0].point - mid).norm(), 0.0, 1e-12, 0.0);

    const Transform far(Vec2(3.0, 1.0), 0.0);
    QCOMPARE(collideCircles(a, xfA, b, far, 0.01).pointCount, 0);
    // Generic dispatch, both orders: the normal always points from the first to the second.
    const Manifold ab =
        collideShapes(makeCircleShape(0.5, Vec2(0.1, 0.0)), xfA, makeCircleShape(0.3), xfB, 0.0);
    const Manifold ba =
        collideShapes(makeCircleShape(0.3), xfB, makeCircleShape(0.5, Vec2(0.1, 0.0)), xfA, 0.0);
    RL_VERIFY_NEAR(ab.normal.dot(n), 1.0, 1e-12, 0.0);
    RL_VERIFY_NEAR(ba.normal.dot(-n), 1.0, 1e-12, 0.0);
}

// A circle over a box's face and over its corner. Face: separation = (cy - h/2) - r along the
// face normal; corner: separation = distance to the corner - r along the corner direction.
void TestSat::polygonAndCircle()
{
    const Polygon box = makeBox(2.0, 1.0);
    const Circle c{Vec2::Zero(), 0.25};
    {
        const Manifold m =
            collidePolygonCircle(box, Transform(), c, Transform(Vec2(0.3, 0.7), 0.0), 0.0);
        QCOMPARE(m.pointCount, 1);
        RL_VERIFY_NEAR(m.points[0].separation, 0.7 - 0.5 - 0.25, 1e-12, 0.0);
        RL_VERIFY_NEAR(m.normal.y(), 1.0, 1e-12, 0.0);
        RL_VERIFY_NEAR(m.points[0].point.x(), 0.3, 1e-12, 0.0);
    }
    {
        const Vec2 corner(1.0, 0.5);
        const Vec2 centre = corner + 0.2 * Vec2(1.0, 2.0).normalized();
        const Manifold m = collidePolygonCircle(box, Transform(), c, Transform(centre, 0.0), 0.0);
        QCOMPARE(m.pointCount, 1);
        RL_VERIFY_NEAR(m.points[0].separation, 0.2 - 0.25, 1e-12, 0.0);
        RL_VERIFY_NEAR(m.normal.dot(Vec2(1.0, 2.0).normalized()), 1.0, 1e-12, 0.0);
    }
    {
        // Rotated box, the circle beyond the margin.
        const Manifold m = collidePolygonCircle(box, Transform(Vec2::Zero(), 0.4), c,
                                                Transform(Vec2(0.0, 2.0), 0.0), 0.01);
        QCOMPARE(m.pointCount, 0);
    }
}

RIGIDLAB_TEST_GUILESS_MAIN(TestSat)
#include "test_sat.moc"
