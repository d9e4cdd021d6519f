// SPDX-License-Identifier: GPL-3.0-or-later
// Stage::NarrowPhase (profile.h), its contact manifolds: two polygons by clipping the
// incident edge against the SAT's reference face (sat.cpp), circles in closed form, and the
// dispatch over pairs of shapes.
//
// Manifold by clipping (as in Box2D's b2CollidePolygons):
//
//            incident edge (of the other polygon), clipped to the side planes
//               v1 o-----------o v2
//       ............|..........|..........  reference face (of the axis' owner)
//        side plane |  contact |  side plane
//   ----------------+==========+-----------
//                  r1          r2
//
// Clipped points deeper than the margin are kept; each contact point is reported halfway
// between the incident point and the reference face.

#include "manifold.h"

#include <algorithm>
#include <cmath>

namespace rigidlab::physics {

namespace {

// Clipped points within this of the margin still count: the separation of a point exactly on
// the reference face rounds to either side of zero [m].
constexpr double kTouchTolerance = 1e-9;

// A later edge is more aligned only when its cosine is larger by this: nearly equal
// normals keep the first.
constexpr double kAlignedTie = 1e-12;

int mostAligned(const WorldPolygon& p, const Vec2& dir)
{
    int best = 0;
    double bestDot = -2.0;
    for (int i = 0; i < p.count; ++i) {
        const double d = p.n[static_cast<size_t>(i)].dot(dir);
        if (d > bestDot + kAlignedTie) {
            bestDot = d;
            best = i;
        }
    }
    return best;
}

/// Clips segment (p[0], p[1]) to the half plane normal.x <= offset; false if nothing is left.
/// A clipped end stays at its index, so that p[0] is always the end that came from the
/// incident edge's first vertex.
bool clipSegment(std::array<Vec2, 2>& p, const Vec2& normal, double offset)
{
    const double d0 = normal.dot(p[0]) - offset;
    const double d1 = normal.dot(p[1]) - offset;
    if (d0 > 0 && d1 > 0)
        return false;
    if (d0 > 0 || d1 > 0) {
        const double t = d0 / (d0 - d1);
        const Vec2 x = p[0] + t * (p[1] - p[0]);
        p[d0 > 0 ? 0 : 1] = x;
    }
    return true;
}

} // namespace

int incidentEdge(const WorldPolygon& ref, int refEdge, const WorldPolygon& inc, double* lead)
{
    // The other polygon's edge most anti-parallel to the reference normal.
    const Vec2 dir = -ref.n[static_cast<size_t>(refEdge)];
    const int best = mostAligned(inc, dir);
    if (lead) {
        double next = -2.0;
        for (int i = 0; i < inc.count; ++i)
            if (i != best)
                next = std::max(next, inc.n[static_cast<size_t>(i)].dot(dir));
        *lead = inc.n[static_cast<size_t>(best)].dot(dir) - next - kAlignedTie;
    }
    return best;
}

namespace {

/// The next vertex's index around a polygon of `count` vertices.
int nextIndex(int i, int count)
{
    return i + 1 == count ? 0 : i + 1;
}

} // namespace

FacePoints facePoints(const Polygon& ref, const Transform& xfRef, const Polygon& inc,
                      const Transform& xfInc, const Faces& faces)
{
    // The arithmetic of the polygons' placement (placePolygon, sat.cpp): xf.apply of each
    // vertex, xf.q.apply of the normal.
    const auto vertex = [](const Polygon& p, int i, const Transform& xf) {
        return xf.apply(p.vertices[static_cast<size_t>(i)]);
    };
    const auto count = [](const Polygon& p) { return static_cast<int>(p.vertices.size()); };
    return {xfRef.q.apply(ref.normals[static_cast<size_t>(faces.refEdge)]),
            vertex(ref, faces.refEdge, xfRef),
            vertex(ref, nextIndex(faces.refEdge, count(ref)), xfRef),
            vertex(inc, faces.incEdge, xfInc),
            vertex(inc, nextIndex(faces.incEdge, count(inc)), xfInc)};
}

bool clipFaces(const FacePoints& f, const Transform& xfRef, const Transform& xfInc,
               const Faces& faces, double margin, bool intersecting, Manifold& m)
{
    const int owner = faces.owner, refEdge = faces.refEdge, incEdge = faces.incEdge;
    const Vec2 refNormal = f.normal, r1 = f.r1, r2 = f.r2;
    std::array<Vec2, 2> p{f.i1, f.i2};
    const Vec2 tangent = (r2 - r1).normalized();
    // Side planes: keep tangent.x >= tangent.r1 and tangent.x <= tangent.r2.
    const bool clipped = clipSegment(p, Vec2(-tangent), -tangent.dot(r1)) &&
                         clipSegment(p, tangent, tangent.dot(r2));
    if (!clipped && !intersecting)
        return false;

    m.type = owner == 0 ? ManifoldType::FaceA : ManifoldType::FaceB;
    m.normal = owner == 0 ? refNormal : Vec2(-refNormal);
    m.localNormal = xfRef.q.applyInverse(refNormal);
    m.localPoint = xfRef.applyInverse(r1);
    m.radiusA = m.radiusB = 0.0;
    m.pointCount = 0;
    const std::array<double, 2> seps{refNormal.dot(p[0] - r1), refNormal.dot(p[1] - r1)};
    for (size_t k = 0; k < 2 && clipped; ++k) {
        const double sep = seps[k];
        if (sep > margin + kTouchTolerance)
            continue;
        ContactPoint& cp = m.points[static_cast<size_t>(m.pointCount)];
        cp.point = p[k] - 0.5 * sep * refNormal;
        cp.separation = sep;
        // The features: reference face, incident edge, and which end of the clipped incident
        // edge. Not whether that end was clipped: with two faces of equal length, exactly
        // aligned, an end is clipped or not by round-off, and a changing id would throw away
        // the warm start that holds a heavy box on a light one.
        cp.id = static_cast<std::uint32_t>(owner << 24 | refEdge << 16 | incEdge << 8 | k);
        m.localIncident[static_cast<size_t>(m.pointCount)] = xfInc.applyInverse(p[k]);
        ++m.pointCount;
    }
    return m.pointCount > 0;
}

bool clipPolygonManifold(const WorldPolygon& ref, const Transform& xfRef, const WorldPolygon& inc,
                         const Transform& xfInc, const Faces& faces, double margin,
                         bool intersecting, Manifold& m)
{
    const auto at = [](const Vec2* v, int i) { return v[static_cast<size_t>(i)]; };
    const FacePoints f{at(ref.n, faces.refEdge), at(ref.v, faces.refEdge),
                       at(ref.v, nextIndex(faces.refEdge, ref.count)), at(inc.v, faces.incEdge),
                       at(inc.v, nextIndex(faces.incEdge, inc.count))};
    if (clipFaces(f, xfRef, xfInc, faces, margin, intersecting, m))
        return true;
    if (!intersecting)
        return false;
    // Intersecting, and clipping kept nothing: the incident edge lies beside the reference
    // face rather than across it (a sliver deep inside a large polygon, or a reference face
    // far shorter than the incident one). The incident polygon's deepest vertex along the
    // normal is the contact then; it penetrates by the overlap on this axis, so it is kept.
    const Vec2 refNormal = f.normal;
    int deepest = 0;
    for (int i = 1; i < inc.count; ++i)
        if (refNormal.dot(at(inc.v, i)) < refNormal.dot(at(inc.v, deepest)))
            deepest = i;
    const Vec2 v = at(inc.v, deepest);
    const double sep = refNormal.dot(v - f.r1);
    ContactPoint& cp = m.points[0];
    cp.point = v - 0.5 * sep * refNormal;
    cp.separation = sep;
    cp.id = static_cast<std::uint32_t>(faces.owner << 24 | faces.refEdge << 16 | deepest << 8 | 2);
    m.localIncident[0] = xfInc.applyInverse(v);
    m.pointCount = 1;
    return false;
}

Manifold collideCircles(const Circle& a, const Transform& xfA, const Circle& b,
                        const Transform& xfB, double margin)
{
    Manifold m;
    const Vec2 ca = xfA.apply(a.center), cb = xfB.apply(b.center);
    const Vec2 d = cb - ca;
    const double dist = d.norm();
    const double sep = dist - a.radius - b.radius;
    if (sep > margin)
        return m;
    m.type = ManifoldType::Circles;
    m.normal = dist > 1e-12 ? Vec2(d / dist) : Vec2(0.0, 1.0);
    m.localPoint = a.center;
    m.localIncident[0] = b.center;
    m.radiusA = a.radius;
    m.radiusB = b.radius;
    m.pointCount = 1;
    m.points[0].point = ca + (a.radius + 0.5 * sep) * m.normal;
    m.points[0].separation = sep;
    m.points[0].id = 0;
    return m;
}

Manifold collidePolygonCircle(const Polygon& a, const Transform& xfA, const Circle& b,
                              const Transform& xfB, double margin)
{
    Manifold m;
    // Work in A's frame: the circle centre c against the edges of A.
    const Vec2 c = xfA.applyInverse(xfB.apply(b.center));
    const std::vector<Vec2>& v = a.vertices;
    const size_t n = v.size();
    double best = -1e300;
    size_t edge = 0;
    for (size_t i = 0; i < n; ++i) {
        const double s = a.normals[i].dot(c - v[i]);
        if (s > b.radius + margin)
            return m; // this edge's line separates them
        if (s > best) {
            best = s;
            edge = i;
        }
    }
    const Vec2 v1 = v[edge], v2 = v[(edge + 1) % n];
    auto vertexContact = [&](const Vec2& corner, std::uint32_t id) {
        const Vec2 d = c - corner;
        const double dist = d.norm();
        const double sep = dist - b.radius;
        if (sep > margin)
            return;
        m.type = ManifoldType::Circles;
        const Vec2 localNormal = dist > 1e-12 ? Vec2(d / dist) : a.normals[edge];
        m.normal = xfA.q.apply(localNormal);
        m.localPoint = corner;
        m.localIncident[0] = b.center;
        m.radiusA = 0.0;
        m.radiusB = b.radius;
        m.pointCount = 1;
        m.points[0].point = xfA.apply(corner) + 0.5 * sep * m.normal;
        m.points[0].separation = sep;
        m.points[0].id = id;
    };
    if (best > 1e-12) {
        // Centre outside A: the closest feature is a vertex or the edge itself.
        if ((c - v1).dot(v2 - v1) <= 0.0)
            return vertexContact(v1, 0x100u | static_cast<std::uint32_t>(edge)), m;
        if ((c - v2).dot(v1 - v2) <= 0.0)
            return vertexContact(v2, 0x100u | static_cast<std::uint32_t>((edge + 1) % n)), m;
    }
    const double sep = best - b.radius;
    m.type = ManifoldType::FaceA;
    m.normal = xfA.q.apply(a.normals[edge]);
    m.localNormal = a.normals[edge];
    m.localPoint = v1;
    m.localIncident[0] = b.center;
    m.radiusA = 0.0;
    m.radiusB = b.radius;
    m.pointCount = 1;
    const Vec2 cw = xfB.apply(b.center);
    m.points[0].point = cw - (b.radius + 0.5 * sep) * m.normal;
    m.points[0].separation = sep;
    m.points[0].id = 0x200u | static_cast<std::uint32_t>(edge);
    return m;
}

Manifold collideShapes(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB,
                       double margin)
{
    // One case per ordered pair of alternatives; std::visit over two variants dispatches on
    // both indices at once (a table, no allocation, no copy of the vertices).
    return std::visit(Overloaded{[&](const Circle& ca, const Circle& cb) {
                                     return collideCircles(ca, xfA, cb, xfB, margin);
                                 },
                                 [&](const Polygon& pa, const Polygon& pb) {
                                     return satPolygons(pa, xfA, pb, xfB, margin, false).manifold;
                                 },
                                 [&](const Polygon& pa, const Circle& cb) {
                                     return collidePolygonCircle(pa, xfA, cb, xfB, margin);
                                 },
                                 [&](const Circle& ca, const Polygon& pb) {
                                     // Collide the other way round and swap the roles back.
                                     Manifold m = collidePolygonCircle(pb, xfB, ca, xfA, margin);
                                     m.normal = -m.normal;
                                     if (m.type == ManifoldType::FaceA) {
                                         m.type = ManifoldType::FaceB;
                                         std::swap(m.radiusA, m.radiusB);
                                     } else {
                                         std::swap(m.localPoint, m.localIncident[0]);
                                         std::swap(m.radiusA, m.radiusB);
                                     }
                                     return m;
                                 }},
                      a.geometry, b.geometry);
}

void evaluateManifoldPoint(const Manifold& m, int k, const Transform& xfA, const Transform& xfB,
                           Vec2& normal, Vec2& point, double& separation)
{
    switch (m.type) {
    case ManifoldType::Circles: {
        const Vec2 ca = xfA.apply(m.localPoint), cb = xfB.apply(m.localIncident[0]);
        const Vec2 d = cb - ca;
        const double dist = d.norm();
        normal = dist > 1e-12 ? Vec2(d / dist) : m.normal;
        separation = dist - m.radiusA - m.radiusB;
        point = ca + (m.radiusA + 0.5 * separation) * normal;
        return;
    }
    case ManifoldType::FaceA: {
        normal = xfA.q.apply(m.localNormal);
        const Vec2 ref = xfA.apply(m.localPoint);
        const Vec2 inc = xfB.apply(m.localIncident[static_cast<size_t>(k)]);
        separation = normal.dot(inc - ref) - m.radiusA - m.radiusB;
        point = inc - (m.radiusB + 0.5 * separation) * normal;
        return;
    }
    case ManifoldType::FaceB: {
        const Vec2 refNormal = xfB.q.apply(m.localNormal);
        const Vec2 ref = xfB.apply(m.localPoint);
        const Vec2 inc = xfA.apply(m.localIncident[static_cast<size_t>(k)]);
        separation = refNormal.dot(inc - ref) - m.radiusA - m.radiusB;
        point = inc - (m.radiusA + 0.5 * separation) * refNormal;
        normal = -refNormal;
        return;
    }
    }
}

} // namespace rigidlab::physics
