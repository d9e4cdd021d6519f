// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The fit's exact model of the commonest measurement: one ball dropped or thrown straight up
// and down onto a flat floor. Between bounces it flies a parabola, each bounce sends it up
// with e times the speed it arrived with, and both have closed forms:
//
//        y ^   .-.                 the ball's centre, c = floor top + radius
//          |  /   \     .-.        flight i ends when y = c: t_hit = t_i + (v + √(v² + 2g(y−c)))/g
//          | /     \   /   \  .    arriving at u = √(v² + 2g(y−c)), leaving at e·u
//        c +/-------\-/-----\/---  flight i+1 lasts 2 e u / g
//
// So the fit needs no time step there: its values have no discretisation error at all, and
// cost one pass over the measured times. The limit of the lab's own run as dt → 0 is this
// model (impacts slower than the lab's rest threshold of 0.01 m/s rest). Any other scene (a
// second moving body, a spin, a sideways speed, a sloping or missing floor, drag, springs)
// is left to the lab's run.

#include "format/scene.h"
#include "measure/measurement.h"

#include <optional>
#include <vector>

namespace rigidlab::measure {

struct Target;

/// The target's values at `times` (rising, >= 0) [m, m/s], exactly, when `scene` is one ball
/// moving straight up and down above a flat floor (see above) and the target is that ball;
/// else nullopt.
std::optional<std::vector<double>> exactFlightsAt(const lessons::Scene& scene, const Target& target,
                                                  const std::vector<double>& times);

} // namespace rigidlab::measure
