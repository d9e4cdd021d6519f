// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Which of a run's collisions a lesson step is about, for the collision panel. A run of carts
// on a ground records the carts settling on the ground at the first step before the carts
// hit each other; the class must see the hit the step teaches, not the settling.

#include "run/measurements.h"

#include "rigidlab/physics/world.h"

#include <vector>

namespace rigidlab::lessons {

/// Whether `e` is a body settling on another rather than a hit: the two approached slower
/// than the speed below which `world`'s contacts rest instead of bouncing
/// (physics::restitutionThreshold), as a body placed on the ground does in its first step.
bool isSettling(const CollisionEvent& e, const physics::World& world);

/// The collision of `events` (in time order, as Measurements keeps them) that a step is
/// about, leaving out bodies settling (isSettling): the first between two of the bodies the
/// step names (`named`: its questions' bodies, its SAT pair), else the first that involves one
/// of them, else the first between two dynamic bodies, else the first hit of any kind;
/// nullptr when there is none yet.
const CollisionEvent* featuredCollision(const std::vector<CollisionEvent>& events,
                                        const physics::World& world,
                                        const std::vector<physics::BodyId>& named);

/// The bodies a step names (its measured questions' bodies, then its SAT pair), each once,
/// as ids of `scene`.
std::vector<physics::BodyId> namedBodies(const LessonStep& step, const Scene& scene);

} // namespace rigidlab::lessons
