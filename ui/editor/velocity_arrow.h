// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A body's initial velocity drawn as an arrow from its origin, for Edit mode.
//
// The arrow is the path the body would cover in kArrowSeconds at that velocity, so that one
// metre of arrow on the world's scale is one metre per second, and the grid (whose step is in
// metres) reads as a grid of velocities. A body at rest still needs something to grab: a stub
// from the origin to just outside the body, along +x (or along its velocity, when that arrow
// is shorter than the stub).
//
//        origin        tip = origin + v * kArrowSeconds
//          o-------------->
//          o - - - - - - - -(o)   stub: its end is the handle
//                          handle

#include "rigidlab/physics/body.h"
#include "rigidlab/physics/math.h"

#include <optional>

class QPainter;

namespace rigidlab::ui {

/// An arrow of this length [m] stands for 1 m/s times this many seconds: 1 m of arrow = 1 m/s.
inline constexpr double kArrowSeconds = 1.0;

struct VelocityArrow {
    physics::Vec2 tail = physics::Vec2::Zero();   ///< the body's origin [m]
    physics::Vec2 tip = physics::Vec2::Zero();    ///< tail + velocity * kArrowSeconds [m]
    physics::Vec2 handle = physics::Vec2::Zero(); ///< what the pointer grabs [m]: the tip, or
                                                  ///< the stub's end when the arrow is shorter
};

/// The arrow of a body that moves (dynamic or kinematic); nullopt for a static body. `zoom`
/// [px/m] sets the stub: a few pixels beyond the body's outline.
std::optional<VelocityArrow> velocityArrow(const physics::BodyDef& def, double zoom);

/// The velocity [m/s] after the handle was dragged from `press` to `pointer` [m], having been
/// `start` at the press: the arrow follows the pointer. With `step` > 0 [m/s] each component
/// is rounded to a whole number of steps (the grid's step, when snapping is on).
physics::Vec2 draggedVelocity(const physics::Vec2& start, const physics::Vec2& press,
                              const physics::Vec2& pointer, double step);

/// Draws the arrow, its stub and its handle, in world coordinates on `painter`.
void paintVelocityArrow(QPainter* painter, const VelocityArrow& arrow, double zoom);

} // namespace rigidlab::ui
