// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A body that falls off the stage: a cart that runs off the end of its ground and drops
// without end, taking the energy plot to hundreds of joules. The window stops a lesson step's
// run when it happens and the lesson editor warns of it, so that the class never watches a
// run that has left what the lesson is about.
//
//      cart ->                         the stage's floor: the lowest point of the static
//   ==============                     bodies; a body that started above a static body's top
//                 |   o  (fell)        and whose centre is kOffStageDrop below that floor has
//   - - - - - - - | - - - - - - -      left the stage. A body on a spring or a pin (a
//                 v                    pendulum) swings and cannot fall away: never watched.

#include "rigidlab/physics/world.h"

#include <optional>
#include <vector>

namespace rigidlab::lessons {

/// How far below the stage's floor a body's centre must be to have left the stage [m].
inline constexpr double kOffStageDrop = 1.0;

/// What a run is checked against, taken from its world at the start.
struct StageFloor {
    double bottom = 0;         ///< the lowest point of the static bodies [m]
    std::vector<char> watched; ///< per body: 1 when it may fall off
};

/// The floor of `world` as it is now (a run's start). A world without a static body, or with
/// no free dynamic body above one, watches nothing.
StageFloor stageFloor(const physics::World& world);

/// The first body (by id) of `world` that has left the stage `floor`, or nullopt.
std::optional<physics::BodyId> offStage(const physics::World& world, const StageFloor& floor);

struct OffStage {
    physics::BodyId body = 0;
    double time = 0; ///< when it was first off the stage [s]
};

/// Runs a copy of `world` until its time reaches `until` [s] (at most `maxSteps` steps) and
/// says which body leaves the stage first, and when; nullopt when none does (or the run
/// diverges first: that is a finding of its own).
std::optional<OffStage> firstOffStage(const physics::World& world, double until,
                                      long long maxSteps);

} // namespace rigidlab::lessons
