// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Bodies that overlap as a scene places them. A few are the editor's business (the contacts
// push them apart at once, which a teacher should know); thousands at one point are a scene
// the engine cannot run: every pair of overlapping boxes is a pair its broad phase keeps and
// a contact it solves, so its memory and time grow with the square of the bodies (10,000
// bodies at one point: 50 million pairs, 8 GB). The survey itself stays bounded: a sweep along
// x over the sorted boxes that stops once the pairs exceed a budget in proportion to the
// bodies.

#include "format/scene.h"

#include <QString>
#include <QStringList>

#include <cstddef>
#include <utility>
#include <vector>

namespace rigidlab::lessons {

struct OverlapSurvey {
    /// Pairs (i < j) of colliding bodies, at least one of them dynamic, that overlap by more
    /// than the engine's resting slop (touching is not overlapping), in sweep order.
    std::vector<std::pair<physics::BodyId, physics::BodyId>> pairs;
    bool more = false; ///< there are more than `most`
    /// Pairs of such bodies whose bounding boxes overlap (the broad phase's pairs), counted
    /// up to the budget.
    std::size_t boxPairs = 0;
    /// More box pairs than the budget: the survey stopped there, and the scene is too crowded
    /// to run (crowdedAt is one body of the pair that crossed it).
    bool crowded = false;
    physics::BodyId crowdedAt = 0;
};

/// The overlapping pairs of the scene, at most `most` of them, and whether its boxes crowd
/// past boxPairBudget().
OverlapSurvey surveyOverlaps(const Scene& scene, std::size_t most);

/// The most pairs of overlapping bounding boxes a scene may start with: the engine's work
/// budget of a step (physics::pairBudget, work_budget.h), which a world built otherwise meets
/// at its first step.
std::size_t boxPairBudget(const Scene& scene);

/// From this many overlapping pairs on, validating a scene warns.
inline constexpr std::size_t kManyOverlaps = 10;

/// The loader's check: "SOURCE: bodies: more than N pairs ... spread them out" when the
/// scene's boxes crowd past the budget, else empty; from kManyOverlaps overlapping pairs on,
/// a line in `warnings`.
QString checkCrowding(const Scene& scene, const QString& source, QStringList& warnings);

} // namespace rigidlab::lessons
