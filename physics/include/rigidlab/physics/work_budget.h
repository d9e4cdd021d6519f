// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The work a step may take, in proportion to its bodies. Every pair of bodies whose boxes
// overlap is a pair the broad phase keeps and a contact the solver works on, so a heap of n
// bodies at one point costs n (n - 1) / 2 of them: 10,000 bodies, 50 million pairs and 8 GB
// before the first step ends. A scene that crowds past the budget is refused by the loader
// and the editor (lessons/format/scene_overlaps.h) with a message; a world built some other
// way stops at the step that crosses it, with a diagnosis (Divergence::Kind::Crowded), instead
// of taking the machine down. Numbers only: the callers word them.

#include <cstddef>

namespace rigidlab::physics {

/// Pairs of overlapping boxes per body, and a floor for small scenes: a packed pyramid or box
/// of balls has about four per body, far fewer than all pairs of a heap.
inline constexpr std::size_t kPairsPerBody = 8;
inline constexpr std::size_t kPairsAlways = 1000;

/// The most pairs of overlapping boxes (each grown by the contact margin) a world of `bodies`
/// bodies may handle in one step.
constexpr std::size_t pairBudget(std::size_t bodies)
{
    return kPairsPerBody * bodies + kPairsAlways;
}

/// The broad phase also keeps the pairs of its "fat" boxes (grown by 0.1 m and by the motion
/// of a couple of steps, broad_phase.cpp), many more than touch among small bodies: at most
/// this many times pairBudget(), its memory (10,000 bodies: about 5 million pairs, 130 MB).
inline constexpr std::size_t kFatPairsPerPair = 64;

} // namespace rigidlab::physics
