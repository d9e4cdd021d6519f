// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where a run's moving bodies will be: the region they sweep from now to a given time, so
// that a lesson step can frame its whole event before the student starts it.

#include "rigidlab/physics/world.h"

#include <QRectF>

namespace rigidlab::lessons {

/// The most body-steps sweptBounds() computes (bodies × steps): a tenth of a second or so on
/// the project's machine, so that opening a step does not freeze the window. A run longer
/// than that is followed as far as the budget goes.
inline constexpr double kSweepBodyStepBudget = 4e5;

/// The axis-aligned box of one body where it is now [m] (QRectF's top() is its least y).
QRectF bodyBounds(const physics::Body& body);

/// The bounding box [m] of every moving body of `world` at every step from now until the
/// world's time reaches `until` [s], computed on a copy (the world is not changed). Stops at
/// a divergence (the bodies that fly off then are not the event), where a body leaves the
/// stage (off_stage.h: a cart falling off the end of the ground is not the event either) and
/// at the budget above.
/// Empty when nothing moves.
QRectF sweptBounds(const physics::World& world, double until);

} // namespace rigidlab::lessons
