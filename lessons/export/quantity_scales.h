// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a quantity is worth in a scene, in its own unit: the scale its noise floor is taken of
// (noise_floor.h). The plots' samples and the command line's diagnostics use the same scales,
// so that a momentum drawn flat in the window is written as 0 in a file.

#include "rigidlab/physics/world.h"

namespace rigidlab::lessons {

/// What momenta are worth in a scene, from its bodies as they are now: each body's mass times
/// its speed plus the speed of a fall across the scene, sqrt(2 |g| extent), and for angular
/// momentum that times the extent (the farthest centre of mass from the origin, at least
/// kMinExtent) plus I |omega|.
struct MomentumScales {
    double linear = 0;  ///< [kg m/s]
    double angular = 0; ///< [kg m^2/s]
};
inline constexpr double kMinExtent = 0.1; ///< [m]
MomentumScales momentumScales(const physics::World& world);

} // namespace rigidlab::lessons
