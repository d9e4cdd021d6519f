// SPDX-License-Identifier: GPL-3.0-or-later
// Shapes: convex polygons from vertex lists, and mass properties.

#include "rigidlab/physics/shape.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rigidlab::physics {

namespace {

// Points closer than this are one point; areas smaller than its square are zero [m].
constexpr double kLengthTolerance = 1e-9;

std::vector<Vec2> edgeNormals(const std::vector<Vec2>& v)
{
    std::vector<Vec2> normals(v.size());
    for (size_t i = 0; i < v.size(); ++i) {
        const Vec2 edge = v[(i + 1) % v.size()] - v[i];
        normals[i] = Vec2(edge.y(), -edge.x()).normalized();
    }
    return normals;
}

/// Convex and counter-clockwise: every corner turns left, and the turns add up to one full
/// turn (a star such as a pentagram turns left everywhere but winds twice).
bool isConvexCounterClockwise(const std::vector<Vec2>& v)
{
    const size_t n = v.size();
    double turning = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const Vec2 e0 = v[(i + 1) % n] - v[i];
        const Vec2 e1 = v[(i + 2) % n] - v[(i + 1) % n];
        const double c = cross(e0, e1);
        if (c <= 0.0)
            return false;
        turning += std::atan2(c, e0.dot(e1));
    }
    return std::abs(turning - 2.0 * std::numbers::pi) < 1e-6;
}

} // namespace

double signedArea(const std::vector<Vec2>& v)
{
    double twice = 0.0;
    for (size_t i = 0; i < v.size(); ++i)
        twice += cross(v[i], v[(i + 1) % v.size()]);
    return 0.5 * twice;
}

std::vector<Vec2> convexHull(std::vector<Vec2> points)
{
    // Andrew's monotone chain: sort by x then y, build the lower and upper chains keeping
    // only left turns. Collinear points are dropped (cross <= 0 pops).
    std::sort(points.begin(), points.end(), [](const Vec2& a, const Vec2& b) {
        return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
    });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3)
        return points;
    std::vector<Vec2> hull(2 * points.size());
    size_t k = 0;
    for (const Vec2& p : points) {
        while (k >= 2 && cross(Vec2(hull[k - 1] - hull[k - 2]), Vec2(p - hull[k - 2])) <= 0.0)
            --k;
        hull[k++] = p;
    }
    const size_t lower = k + 1;
    for (size_t i = points.size() - 1; i-- > 0;) {
        const Vec2& p = points[i];
        while (k >= lower && cross(Vec2(hull[k - 1] - hull[k - 2]), Vec2(p - hull[k - 2])) <= 0.0)
            --k;
        hull[k++] = p;
    }
    hull.resize(k - 1);
    return hull;
}

Result<PolygonBuild> makePolygon(const std::vector<Vec2>& input)
{
    if (input.size() < 3)
        return Error{"a polygon needs at least 3 vertices, got " + std::to_string(input.size())};
    if (input.size() > static_cast<size_t>(kMaxPolygonVertices))
        return Error{"a polygon may have at most " + std::to_string(kMaxPolygonVertices) +
                     " vertices, got " + std::to_string(input.size())};
    for (const Vec2& p : input)
        if (!isFinite(p))
            return Error{"a vertex is not a finite number"};

    // Drop repeated consecutive vertices, then orient counter-clockwise.
    std::vector<Vec2> v;
    for (const Vec2& p : input)
        if (v.empty() || (p - v.back()).norm() > kLengthTolerance)
            v.push_back(p);
    while (v.size() > 1 && (v.front() - v.back()).norm() <= kLengthTolerance)
        v.pop_back();

    double extent = 0.0;
    for (const Vec2& p : v)
        extent = std::max(extent, (p - v.front()).norm());
    const double area = signedArea(v);
    if (v.size() < 3 || std::abs(area) <= kLengthTolerance * std::max(extent, 1.0))
        return Error{"the polygon has no area (its vertices are repeated or on one line)"};

    PolygonBuild out;
    if (area < 0.0)
        std::reverse(v.begin(), v.end());
    if (!isConvexCounterClockwise(v)) {
        std::vector<Vec2> hull = convexHull(v);
        out.warning = "the polygon is not convex; it was replaced by its convex hull (" +
                      std::to_string(hull.size()) + " of " + std::to_string(input.size()) +
                      " vertices), so collisions are exact only for the hull";
        v = std::move(hull);
    }
    out.polygon.normals = edgeNormals(v);
    out.polygon.vertices = std::move(v);
    return out;
}

Polygon makeBox(double width, double height)
{
    const double hx = 0.5 * width, hy = 0.5 * height;
    Polygon box;
    box.vertices = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
    box.normals = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
    return box;
}

Shape makeCircleShape(double radius, const Vec2& center)
{
    Shape s;
    s.geometry = Circle{center, radius};
    return s;
}

Shape makePolygonShape(Polygon polygon)
{
    Shape s;
    s.geometry = std::move(polygon);
    return s;
}

namespace {

MassProperties circleMass(const Circle& circle, double density)
{
    MassProperties m;
    const double r = circle.radius;
    m.area = std::numbers::pi * r * r;
    m.mass = density * m.area;
    m.centroid = circle.center;
    m.inertia = 0.5 * m.mass * r * r;
    return m;
}

MassProperties polygonMass(const Polygon& polygon, double density)
{
    MassProperties m;
    // Fan of triangles from a point inside (the first vertex keeps round-off small).
    // For a triangle (0, e1, e2) about its own apex: area = cross(e1, e2) / 2,
    // second moment about the apex = area / 6 * (e1.e1 + e1.e2 + e2.e2).
    const std::vector<Vec2>& v = polygon.vertices;
    const Vec2 origin = v[0];
    double area = 0.0, secondMoment = 0.0;
    Vec2 firstMoment = Vec2::Zero();
    for (size_t i = 1; i + 1 < v.size(); ++i) {
        const Vec2 e1 = v[i] - origin, e2 = v[i + 1] - origin;
        const double a = 0.5 * cross(e1, e2);
        area += a;
        firstMoment += a * (e1 + e2) / 3.0;
        secondMoment += a / 6.0 * (e1.dot(e1) + e1.dot(e2) + e2.dot(e2));
    }
    const Vec2 c = firstMoment / area; // relative to origin
    m.area = area;
    m.mass = density * area;
    m.centroid = origin + c;
    // Parallel axis: move the second moment from `origin` to the centroid.
    m.inertia = density * (secondMoment - area * c.dot(c));
    return m;
}

} // namespace

MassProperties computeMass(const Shape& shape, double density)
{
    return shape.visit(Overloaded{[density](const Circle& c) { return circleMass(c, density); },
                                  [density](const Polygon& p) { return polygonMass(p, density); }});
}

} // namespace rigidlab::physics
