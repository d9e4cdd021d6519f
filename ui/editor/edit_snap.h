// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where the editor's pointer snaps to other bodies: their vertices and centres, and
// the nearest point of their edges. Pure geometry on the scene being edited; the reach comes
// in metres (the editor turns its few pixels into metres at the zoom of the moment, so that
// snapping feels the same at every zoom).
//
//        vertex (wins when near)
//          o--------x--------o      x: the nearest point of the edge to the pointer p,
//          |        :        |         taken when no vertex or centre is within reach
//          |        p        |
//
// A body being moved snaps by one of its own points: the grab point, its centre or one of its
// vertices, whichever is nearest to something; a circle also rests on an edge (its surface
// snaps), so a box or a ball is set down exactly on a ramp.

#include "format/scene.h"

#include "rigidlab/physics/forces.h"
#include "rigidlab/physics/math.h"

#include <optional>

namespace rigidlab::ui {

struct Snap {
    enum class Kind {
        Vertex, ///< a polygon's corner
        Centre, ///< a body's origin or a circle's centre
        Edge,   ///< the nearest point of a polygon's side or of a circle
    };
    Kind kind = Kind::Vertex;
    physics::Vec2 point = physics::Vec2::Zero(); ///< where the point goes [m]
    physics::BodyId body = physics::kWorld;      ///< the body snapped to
    double distance = 0.0;                       ///< from the point before the snap [m]
};

/// The feature of a body of `scene` nearest to `p` within `reach` [m], `except` left out: a
/// vertex or a centre within reach wins over any edge. nullopt when nothing is within reach.
std::optional<Snap> snapToBodies(const lessons::Scene& scene, const physics::Vec2& p, double reach,
                                 physics::BodyId except = physics::kWorld);

/// A body being moved: where its origin goes so that one of its points lands on another body.
struct BodySnap {
    physics::Vec2 position = physics::Vec2::Zero(); ///< the body's origin, snapped [m]
    Snap target;                                    ///< what it snapped to (for the marker)
};

/// Snaps body `body` of `scene` placed with its origin at `position` (its angle as in the scene)
/// and dragged by the world point `grab` [m]: the grab point, the body's centre, its vertices
/// and (a circle) its surface are tried against every other body within `reach` [m]; the
/// nearest wins, vertices and centres before edges. nullopt when nothing is within reach.
std::optional<BodySnap> snapMovedBody(const lessons::Scene& scene, physics::BodyId body,
                                      const physics::Vec2& position, const physics::Vec2& grab,
                                      double reach);

} // namespace rigidlab::ui
