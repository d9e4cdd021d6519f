// SPDX-License-Identifier: GPL-3.0-or-later
#include "editor/edit_snap.h"

#include <algorithm>
#include <vector>

namespace rigidlab::ui {

using physics::Vec2;

namespace {

/// The point of segment ab nearest to p.
Vec2 nearestOnSegment(const Vec2& a, const Vec2& b, const Vec2& p)
{
    const Vec2 ab = b - a;
    const double length2 = ab.squaredNorm();
    const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    return a + t * ab;
}

/// A body's corners in the world (none for a circle).
std::vector<Vec2> worldVertices(const physics::BodyDef& def)
{
    std::vector<Vec2> out;
    if (const physics::Polygon* poly = def.shape.asPolygon()) {
        const physics::Transform xf(def.position, def.angle);
        for (const Vec2& v : poly->vertices) {
            out.push_back(xf.apply(v));
        }
    }
    return out;
}

/// The body's centres in the world: its origin, and a circle's centre where it differs.
std::vector<Vec2> worldCentres(const physics::BodyDef& def)
{
    std::vector<Vec2> out{def.position};
    if (const physics::Circle* c = def.shape.asCircle(); c && c->center != Vec2::Zero()) {
        out.push_back(physics::Transform(def.position, def.angle).apply(c->center));
    }
    return out;
}

/// The point of the body's outline nearest to p (a circle's, or one of a polygon's sides).
Vec2 nearestOnOutline(const physics::BodyDef& def, const Vec2& p)
{
    const physics::Transform xf(def.position, def.angle);
    return def.shape.visit(physics::Overloaded{
        [&](const physics::Circle& c) -> Vec2 {
            const Vec2 centre = xf.apply(c.center);
            const Vec2 d = p - centre;
            const double n = d.norm();
            // At the centre every point of the circle is as near: the one to the right.
            return centre + c.radius * (n > 0.0 ? Vec2(d / n) : Vec2(1.0, 0.0));
        },
        [&](const physics::Polygon& poly) -> Vec2 {
            Vec2 best = xf.apply(poly.vertices.front());
            double bestDistance = (best - p).norm();
            const size_t n = poly.vertices.size();
            for (size_t i = 0; i < n; ++i) {
                const Vec2 q = nearestOnSegment(xf.apply(poly.vertices[i]),
                                                xf.apply(poly.vertices[(i + 1) % n]), p);
                if (const double d = (q - p).norm(); d < bestDistance) {
                    best = q;
                    bestDistance = d;
                }
            }
            return best;
        }});
}

/// Whether p is strictly inside the body.
bool inside(const physics::BodyDef& def, const Vec2& p)
{
    const Vec2 local = physics::Transform(def.position, def.angle).applyInverse(p);
    return def.shape.visit(physics::Overloaded{
        [&](const physics::Circle& c) { return (local - c.center).norm() < c.radius; },
        [&](const physics::Polygon& poly) {
            for (size_t k = 0; k < poly.vertices.size(); ++k) {
                if (poly.normals[k].dot(local - poly.vertices[k]) >= 0.0) {
                    return false;
                }
            }
            return true;
        }});
}

/// Whether a is a better snap than b: a vertex or a centre before an edge, then the nearer.
bool better(const Snap& a, const std::optional<Snap>& b)
{
    if (!b) {
        return true;
    }
    const bool aEdge = a.kind == Snap::Kind::Edge;
    const bool bEdge = b->kind == Snap::Kind::Edge;
    if (aEdge != bEdge) {
        return !aEdge;
    }
    return a.distance < b->distance;
}

} // namespace

std::optional<Snap> snapToBodies(const lessons::Scene& scene, const Vec2& p, double reach,
                                 physics::BodyId except)
{
    std::optional<Snap> best;
    const auto offer = [&](Snap::Kind kind, const Vec2& q, int body) {
        const Snap s{kind, q, body, (q - p).norm()};
        if (s.distance <= reach && better(s, best)) {
            best = s;
        }
    };
    for (size_t i = 0; i < scene.bodies.size(); ++i) {
        const int body = static_cast<int>(i);
        if (body == except) {
            continue;
        }
        const auto& def = scene.bodies[i];
        for (const Vec2& q : worldCentres(def)) {
            offer(Snap::Kind::Centre, q, body);
        }
        for (const Vec2& q : worldVertices(def)) {
            offer(Snap::Kind::Vertex, q, body);
        }
        offer(Snap::Kind::Edge, nearestOnOutline(def, p), body);
    }
    return best;
}

std::optional<BodySnap> snapMovedBody(const lessons::Scene& scene, physics::BodyId body,
                                      const Vec2& position, const Vec2& grab, double reach)
{
    if (body < 0 || static_cast<size_t>(body) >= scene.bodies.size()) {
        return std::nullopt;
    }
    physics::BodyDef moved = scene.bodies[static_cast<size_t>(body)];
    moved.position = position;

    // The body's own points, each of which may land on something.
    std::vector<Vec2> points{grab};
    for (const Vec2& q : worldCentres(moved)) {
        points.push_back(q);
    }
    for (const Vec2& q : worldVertices(moved)) {
        points.push_back(q);
    }
    std::optional<Snap> best;
    Vec2 shift = Vec2::Zero();
    for (const Vec2& q : points) {
        if (const auto s = snapToBodies(scene, q, reach, body); s && better(*s, best)) {
            best = s;
            shift = s->point - q;
        }
    }

    // A circle rests on an outline: its centre goes one radius from the outline's nearest
    // point, on the side it comes from (not when its centre is inside the other body).
    if (const physics::Circle* c = moved.shape.asCircle()) {
        const Vec2 centre = physics::Transform(moved.position, moved.angle).apply(c->center);
        for (size_t i = 0; i < scene.bodies.size(); ++i) {
            const auto& other = scene.bodies[i];
            if (static_cast<int>(i) == body || inside(other, centre)) {
                continue;
            }
            const Vec2 q = nearestOnOutline(other, centre);
            const Vec2 d = centre - q;
            const double n = d.norm();
            if (n <= 0.0) {
                continue;
            }
            const Snap s{Snap::Kind::Edge, q, static_cast<int>(i), std::abs(n - c->radius)};
            if (s.distance <= reach && better(s, best)) {
                best = s;
                shift = (q + c->radius * d / n) - centre;
            }
        }
    }
    if (!best) {
        return std::nullopt;
    }
    return BodySnap{position + shift, *best};
}

} // namespace rigidlab::ui
