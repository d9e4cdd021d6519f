// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Time travel: a bounded history of world states. A snapshot (a copy of the whole world)
// is kept every so often; any step in between is reached by copying the snapshot before it
// and replaying. The engine is deterministic, so a replay gives bit-identical states.
// The user's pushes (dragging a body) are logged per step and replayed with the rest.
//
// Changing a parameter at some step makes a branch: what was computed after it is dropped.

#include "rigidlab/physics/world.h"

#include <cstdint>
#include <deque>
#include <functional>
#include <map>

namespace rigidlab::ui {

/// A force the user applied to one body during one step (through the accumulators).
struct UserInput {
    physics::BodyId body = -1;
    physics::Vec2 force = physics::Vec2::Zero(); ///< [N]
    double torque = 0.0;                         ///< [N m]
};

class History {
public:
    /// snapshotEvery: steps between snapshots; budgetBytes: the most the snapshots may take.
    explicit History(int snapshotEvery = 100, std::size_t budgetBytes = 96u << 20);

    /// Forgets everything and starts from this world (at its current step).
    void reset(const physics::World& start);
    /// Called after the world made step `world.stepCount()`, with the input it applied.
    void recorded(const physics::World& world, const UserInput* input);
    /// Drops everything after `step` (a branch), and snapshots the world there as it is now.
    void branchAt(const physics::World& world);
    /// The earliest and latest steps one can go to.
    long long earliest() const;
    long long latest() const { return m_latest; }
    /// The time of the earliest step one can go to [s]; NaN before reset().
    double earliestTime() const;
    /// Restores the world as it was after `step` (clamped to [earliest, latest]).
    physics::World restore(long long step) const;
    /// Walks the run on from `world` (a state restore() gave) to step `to`, as restore()
    /// replays it, calling `each` with the world after every step: the states the run had,
    /// bit for bit, before any edit made at that step (an edit's snapshot is taken up after
    /// `each` saw the step).
    void replay(physics::World& world, long long to,
                const std::function<void(const physics::World&)>& each) const;
    /// The input logged for the step that leads to `step + 1`, or nullptr.
    const UserInput* inputFor(long long step) const;
    /// The most the snapshots may take [bytes]; the oldest go first when it shrinks.
    void setBudget(std::size_t bytes);
    std::size_t budget() const { return m_budget; }
    /// What one snapshot of this world takes, heap included [bytes] (an estimate from the
    /// sizes of its parts; a test compares it with the resident memory that copies take).
    static std::size_t snapshotBytes(const physics::World& world);

private:
    struct Snapshot {
        long long step = 0;
        physics::World world;
    };
    void addSnapshot(const physics::World& world);
    void trim(const physics::World& world);
    std::size_t snapshotLimit(const physics::World& world) const;

    int m_every;
    std::size_t m_budget;
    std::deque<Snapshot> m_snapshots;
    std::map<long long, UserInput> m_inputs; ///< keyed by the step the input was applied from
    long long m_latest = 0;
};

/// Applies a logged input to the world's accumulators before a step.
void applyInput(physics::World& world, const UserInput& input);

} // namespace rigidlab::ui
