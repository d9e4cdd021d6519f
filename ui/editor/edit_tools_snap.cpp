// SPDX-License-Identifier: GPL-3.0-or-later
// Where the editor's pointer is and where it snaps: the body or spring under it, the grid,
// other bodies' vertices, centres and edges (editor/edit_snap.h), a moved body set down on
// another. What the tools (editor/tools/) build their gestures from.

#include "editor/edit_tools.h"

#include "editor/scene_document.h"

#include "view/world_view.h"

#include <QAction>

#include <algorithm>
#include <cmath>

namespace rigidlab::ui {

using physics::Vec2;

namespace {

/// A pointer this close to another body's vertex, centre or edge snaps to it [px].
constexpr double kVertexSnapPixels = 8.0;
/// A grid point this close to an edge, in grid steps, lies on it (rounding aside).
constexpr double kOnEdge = 1e-9;

} // namespace

const lessons::Scene& EditTools::scene() const
{
    return m_document.scene();
}

bool EditTools::snapping() const
{
    return m_snapAction->isChecked();
}

double EditTools::pixelsToMetres(double pixels) const
{
    return pixels / std::max(m_view.zoom(), 1e-9);
}

Vec2 EditTools::viewCentre() const
{
    const QPointF middle = m_view.mapToScene(m_view.viewport()->rect().center());
    return snapToGrid(Vec2(middle.x(), middle.y()));
}

std::optional<VelocityArrow> EditTools::selectedArrow() const
{
    const lessons::Scene& scene = m_document.scene();
    if (m_selected < 0 || static_cast<size_t>(m_selected) >= scene.bodies.size()) {
        return std::nullopt;
    }
    return velocityArrow(scene.bodies[static_cast<size_t>(m_selected)], m_view.zoom());
}

int EditTools::bodyAt(const Vec2& p) const
{
    const auto& bodies = m_document.scene().bodies;
    for (int i = static_cast<int>(bodies.size()) - 1; i >= 0; --i) {
        const auto& def = bodies[static_cast<size_t>(i)];
        const Vec2 local = physics::Transform(def.position, def.angle).applyInverse(p);
        const bool inside = def.shape.visit(physics::Overloaded{
            [&](const physics::Circle& c) { return (local - c.center).norm() <= c.radius; },
            [&](const physics::Polygon& poly) {
                for (size_t k = 0; k < poly.vertices.size(); ++k) {
                    if (poly.normals[k].dot(local - poly.vertices[k]) > 0) {
                        return false;
                    }
                }
                return true;
            }});
        if (inside) {
            return i;
        }
    }
    return -1;
}

int EditTools::springAt(const Vec2& p) const
{
    const lessons::Scene& scene = m_document.scene();
    const double reach = pixelsToMetres(kVertexSnapPixels);
    const auto end = [&scene](physics::BodyId body, const Vec2& anchor) {
        if (body == physics::kWorld) {
            return anchor;
        }
        const auto& def = scene.bodies[static_cast<size_t>(body)];
        return physics::Transform(def.position, def.angle).apply(anchor);
    };
    for (int i = static_cast<int>(scene.springs.size()) - 1; i >= 0; --i) {
        const auto& s = scene.springs[static_cast<size_t>(i)];
        const Vec2 a = end(s.a, s.anchorA);
        const Vec2 b = end(s.b, s.anchorB);
        const Vec2 ab = b - a;
        const double t =
            ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
        if ((a + t * ab - p).norm() <= reach) {
            return i;
        }
    }
    return -1;
}

Vec2 EditTools::snapToGrid(const Vec2& p) const
{
    const double step = gridStep();
    return Vec2(std::round(p.x() / step) * step, std::round(p.y() / step) * step);
}

Vec2 EditTools::snapped(const Vec2& p, int except) const
{
    if (!m_snapAction->isChecked()) {
        return p;
    }
    // Another body's vertex, centre or edge first: a ball's centre exactly on a corner or on
    // a ramp's surface.
    if (const auto snap = featureSnap(p, except)) {
        return snap->point;
    }
    return snapToGrid(p);
}

std::optional<Snap> EditTools::featureSnap(const Vec2& p, int except) const
{
    if (!m_snapAction->isChecked()) {
        return std::nullopt;
    }
    const auto snap =
        snapToBodies(m_document.scene(), p, pixelsToMetres(kVertexSnapPixels), except);
    if (!snap || snap->kind != Snap::Kind::Edge) {
        return snap;
    }
    // On an edge, a point on the grid where there is one on that body's outline: the grid
    // point itself, else the edge's point at the grid's x (a floor) or y (a wall). A box drawn
    // from a floor's surface on a 1 m grid is whole metres wide.
    const Vec2 grid = snapToGrid(p);
    for (const Vec2& candidate :
         {grid, Vec2(grid.x(), snap->point.y()), Vec2(snap->point.x(), grid.y())}) {
        const auto there =
            snapToBodies(m_document.scene(), candidate, kOnEdge * gridStep(), except);
        if (there && there->body == snap->body) {
            return Snap{snap->kind, candidate, snap->body, (candidate - p).norm()};
        }
    }
    return snap;
}

int EditTools::bodyAtOrSnapped(const Vec2& raw) const
{
    if (const int body = bodyAt(raw); body >= 0) {
        return body;
    }
    const auto snap = featureSnap(raw);
    return snap ? snap->body : -1;
}

Vec2 EditTools::movedBodyTarget(int body, const Vec2& grabOffset, const Vec2& raw)
{
    const Vec2 free = raw + grabOffset;
    m_bodySnap.reset();
    if (!m_snapAction->isChecked()) {
        return free;
    }
    const lessons::Scene& scene = m_document.scene();
    const double reach = pixelsToMetres(kVertexSnapPixels);
    const auto snap = snapMovedBody(scene, body, free, raw, reach);
    if (!snap) {
        return snapToGrid(free);
    }
    m_bodySnap = snap->target;
    // Set down on an edge: its origin on the grid along that edge where the body still
    // touches it there (a box slid along a floor stays on the grid; a wall, the same upright).
    if (snap->target.kind == Snap::Kind::Edge) {
        const Vec2 grid = snapToGrid(free);
        const Vec2 at = snap->position;
        for (const Vec2& candidate : {grid, Vec2(grid.x(), at.y()), Vec2(at.x(), grid.y())}) {
            const Vec2 grab = raw + (candidate - free); // the same point of the body
            const auto there = snapMovedBody(scene, body, candidate, grab, kOnEdge * gridStep());
            if (there && there->target.body == snap->target.body) {
                m_bodySnap->point += candidate - at;
                return candidate;
            }
        }
    }
    return snap->position;
}

} // namespace rigidlab::ui
