// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzz target: the separating axis test and the contact manifolds (physics/src/sat.cpp).
//
// The bytes are decoded into two shapes (convex polygons made by makePolygon, as a scene file
// makes them, or circles) and their placements, within the limits a scene file allows
// (lessons/limits.h), and a margin. Whatever they are:
//   - every number the SAT returns is finite, every axis and normal is of unit length;
//   - the SAT stops at its first separating axis, and records exactly the axes it tested;
//   - intersecting polygons have a depth >= 0 (the least overlap) and a manifold of 1 or 2
//     points; apart, a gap beyond the margin on the separating axis and no manifold;
//   - every manifold has 0 to 2 points with finite separations and a unit normal.

#include "fuzz_check.h"

#include "rigidlab/physics/sat.h"
#include "rigidlab/physics/shape.h"

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

using namespace rigidlab::physics;

namespace {

// The scene format's bounds (lessons/limits.h; the engine has no Qt, so they are repeated).
constexpr double kMaxVertex = 1e5;   ///< a vertex coordinate [m]
constexpr double kMaxPosition = 1e7; ///< a body origin's coordinate [m]
constexpr double kMaxAngle = 1e6;    ///< [rad]
constexpr double kMinSize = 1e-6;    ///< radius [m]

constexpr double kUnitTolerance = 1e-9;

bool isUnit(const Vec2& v)
{
    return std::abs(v.norm() - 1.0) <= kUnitTolerance;
}

bool isFiniteVec(const Vec2& v)
{
    return std::isfinite(v.x()) && std::isfinite(v.y());
}

/// A length scale, so that tiny and huge shapes are both tried: 1e-6 to 1e5 m.
double consumeScale(FuzzedDataProvider& in)
{
    return std::pow(10.0, in.ConsumeFloatingPointInRange(-6.0, 5.0));
}

std::vector<Vec2> consumeVertices(FuzzedDataProvider& in)
{
    const double scale = consumeScale(in);
    const int count = in.ConsumeIntegralInRange(3, kMaxPolygonVertices);
    std::vector<Vec2> v;
    for (int i = 0; i < count && in.remaining_bytes() > 0; ++i) {
        const double x = in.ConsumeFloatingPointInRange(-1.0, 1.0) * scale;
        const double y = in.ConsumeFloatingPointInRange(-1.0, 1.0) * scale;
        v.emplace_back(std::clamp(x, -kMaxVertex, kMaxVertex),
                       std::clamp(y, -kMaxVertex, kMaxVertex));
    }
    return v;
}

Transform consumeTransform(FuzzedDataProvider& in, double near)
{
    // Mostly near the other shape (where contacts are), sometimes anywhere allowed.
    const double reach = in.ConsumeBool() ? near : kMaxPosition;
    const double x = in.ConsumeFloatingPointInRange(-reach, reach);
    const double y = in.ConsumeFloatingPointInRange(-reach, reach);
    const double angle = in.ConsumeBool() ? in.ConsumeFloatingPointInRange(-kMaxAngle, kMaxAngle)
                                          : in.ConsumeFloatingPointInRange(-4.0, 4.0);
    return Transform(Vec2(x, y), angle);
}

void checkManifold(const Manifold& m)
{
    FUZZ_CHECK(m.pointCount >= 0 && m.pointCount <= 2);
    if (m.pointCount == 0) {
        return;
    }
    FUZZ_CHECK(isFiniteVec(m.normal) && isUnit(m.normal));
    for (int k = 0; k < m.pointCount; ++k) {
        const ContactPoint& p = m.points[static_cast<std::size_t>(k)];
        FUZZ_CHECK(isFiniteVec(p.point));
        FUZZ_CHECK(std::isfinite(p.separation));
    }
}

void checkSat(const Polygon& a, const Transform& xfA, const Polygon& b, const Transform& xfB,
              double margin)
{
    const SatResult r = satPolygons(a, xfA, b, xfB, margin, true);
    const int total = static_cast<int>(a.vertices.size() + b.vertices.size());
    FUZZ_CHECK(r.axesTested >= 1 && r.axesTested <= total);
    FUZZ_CHECK(static_cast<int>(r.axes.size()) == r.axesTested);
    for (const SatAxis& ax : r.axes) {
        FUZZ_CHECK(isFiniteVec(ax.axis) && isUnit(ax.axis));
        FUZZ_CHECK(std::isfinite(ax.minA) && std::isfinite(ax.maxA) && ax.minA <= ax.maxA);
        FUZZ_CHECK(std::isfinite(ax.minB) && std::isfinite(ax.maxB) && ax.minB <= ax.maxB);
        FUZZ_CHECK(std::isfinite(ax.overlap));
    }
    // The early stop: only the last axis tested may separate.
    for (int i = 0; i + 1 < r.axesTested; ++i) {
        FUZZ_CHECK(r.axes[static_cast<std::size_t>(i)].overlap >= -margin);
    }
    if (r.separatingAxis >= 0) {
        FUZZ_CHECK(!r.intersects);
        FUZZ_CHECK(r.separatingAxis == r.axesTested - 1);
        FUZZ_CHECK(r.axes.back().overlap < -margin);
        FUZZ_CHECK(r.manifold.pointCount == 0);
    } else {
        FUZZ_CHECK(r.axesTested == total);
        FUZZ_CHECK(r.leastAxis >= 0 && r.leastAxis < total);
        FUZZ_CHECK(isFiniteVec(r.normal) && isUnit(r.normal));
        FUZZ_CHECK(std::isfinite(r.depth));
        FUZZ_CHECK(r.depth == r.axes[static_cast<std::size_t>(r.leastAxis)].overlap);
    }
    if (r.intersects) {
        FUZZ_CHECK(r.depth >= 0.0);
        FUZZ_CHECK(r.manifold.pointCount >= 1 && r.manifold.pointCount <= 2);
    }
    checkManifold(r.manifold);

    // The engine's fast path (no record) agrees with the recorded one.
    const SatResult fast = satPolygons(a, xfA, b, xfB, margin, false);
    FUZZ_CHECK(fast.intersects == r.intersects && fast.axesTested == r.axesTested);
    FUZZ_CHECK(fast.manifold.pointCount == r.manifold.pointCount);
}

Shape consumeShape(FuzzedDataProvider& in, bool& ok)
{
    if (in.ConsumeBool()) {
        const double radius = std::max(kMinSize, consumeScale(in));
        ok = true;
        return makeCircleShape(radius);
    }
    auto built = makePolygon(consumeVertices(in));
    ok = bool(built);
    if (!ok) {
        return {};
    }
    return makePolygonShape(std::move(built).value().polygon);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    FuzzedDataProvider in(data, size);
    bool okA = false;
    bool okB = false;
    const Shape a = consumeShape(in, okA);
    const Shape b = consumeShape(in, okB);
    if (!okA || !okB) {
        return 0;
    }
    const double margin = in.ConsumeBool() ? 0.0 : consumeScale(in) * 1e-2;
    const Transform xfA = consumeTransform(in, 1.0);
    const Transform xfB = consumeTransform(in, 2.0 * consumeScale(in));

    if (a.asPolygon() && b.asPolygon()) {
        checkSat(*a.asPolygon(), xfA, *b.asPolygon(), xfB, margin);
    }
    const Manifold m = collideShapes(a, xfA, b, xfB, margin);
    checkManifold(m);
    for (int k = 0; k < m.pointCount; ++k) {
        Vec2 normal = Vec2::Zero();
        Vec2 point = Vec2::Zero();
        double separation = 0.0;
        evaluateManifoldPoint(m, k, xfA, xfB, normal, point, separation);
        FUZZ_CHECK(isFiniteVec(normal) && isFiniteVec(point) && std::isfinite(separation));
    }
    return 0;
}
