// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulation/history.h"

#include "simulation/step_sampler.h"

#include <algorithm>
#include <limits>

namespace rigidlab::ui {

History::History(int snapshotEvery, std::size_t budgetBytes)
    : m_every(std::max(1, snapshotEvery)), m_budget(budgetBytes)
{
}

void History::reset(const physics::World& start)
{
    m_snapshots.clear();
    m_inputs.clear();
    m_latest = start.stepCount();
    addSnapshot(start);
}

std::size_t History::snapshotBytes(const physics::World& world)
{
    // Every heap block costs its size rounded up to 16 bytes plus a 16-byte header (glibc).
    const auto block = [](std::size_t bytes) { return bytes ? ((bytes + 15) / 16 + 1) * 16 : 0; };
    std::size_t bytes = sizeof(physics::World) + 4096; // the world, its integrator, its scratch
    bytes += block(world.bodies().capacity() * sizeof(physics::Body));
    for (const physics::Body& b : world.bodies()) {
        bytes += b.shape.visit(
            physics::Overloaded{[](const physics::Circle&) -> std::size_t { return 0; },
                                [&](const physics::Polygon& p) {
                                    return block(p.vertices.size() * sizeof(physics::Vec2)) +
                                           block(p.normals.size() * sizeof(physics::Vec2));
                                }});
        bytes += b.name.size() > 15 ? block(b.name.size() + 1) : 0;
    }
    bytes += 3 * block(world.bodies().size() * sizeof(double)); // moving, slot, sweep
    bytes += block(world.contacts().size() * sizeof(physics::Contact));
    bytes += block(world.springs().size() * sizeof(physics::SpringDef));
    bytes += block(world.joints().size() * sizeof(physics::PinJointDef));
    return bytes;
}

std::size_t History::snapshotLimit(const physics::World& world) const
{
    return std::clamp<std::size_t>(m_budget / snapshotBytes(world), 4, 2000);
}

void History::setBudget(std::size_t bytes)
{
    m_budget = bytes;
    if (!m_snapshots.empty())
        trim(m_snapshots.back().world);
}

void History::addSnapshot(const physics::World& world)
{
    if (!m_snapshots.empty() && m_snapshots.back().step >= world.stepCount())
        return;
    m_snapshots.push_back({world.stepCount(), world});
    trim(world);
}

void History::trim(const physics::World& world)
{
    const std::size_t limit = snapshotLimit(world);
    while (m_snapshots.size() > limit) {
        m_snapshots.pop_front();
        // Inputs before the earliest snapshot can never be replayed again.
        m_inputs.erase(m_inputs.begin(), m_inputs.lower_bound(m_snapshots.front().step));
    }
}

void History::recorded(const physics::World& world, const UserInput* input)
{
    const long long step = world.stepCount();
    if (input)
        m_inputs[step - 1] = *input;
    m_latest = std::max(m_latest, step);
    if (step % m_every == 0)
        addSnapshot(world);
}

void History::branchAt(const physics::World& world)
{
    const long long step = world.stepCount();
    while (!m_snapshots.empty() && m_snapshots.back().step >= step)
        m_snapshots.pop_back();
    m_inputs.erase(m_inputs.lower_bound(step), m_inputs.end());
    m_latest = step;
    addSnapshot(world);
}

long long History::earliest() const
{
    return m_snapshots.empty() ? m_latest : m_snapshots.front().step;
}

double History::earliestTime() const
{
    return m_snapshots.empty() ? std::numeric_limits<double>::quiet_NaN()
                               : stepTime(m_snapshots.front().world);
}

const UserInput* History::inputFor(long long step) const
{
    auto it = m_inputs.find(step);
    return it == m_inputs.end() ? nullptr : &it->second;
}

physics::World History::restore(long long step) const
{
    step = std::clamp(step, earliest(), m_latest);
    // The last snapshot at or before `step`, then replay.
    auto it = std::upper_bound(m_snapshots.begin(), m_snapshots.end(), step,
                               [](long long s, const Snapshot& snap) { return s < snap.step; });
    physics::World world = std::prev(it)->world;
    while (world.stepCount() < step) {
        if (const UserInput* in = inputFor(world.stepCount()))
            applyInput(world, *in);
        world.step();
    }
    return world;
}

void History::replay(physics::World& world, long long to,
                     const std::function<void(const physics::World&)>& each) const
{
    to = std::min(to, m_latest);
    auto next = std::upper_bound(m_snapshots.begin(), m_snapshots.end(), world.stepCount(),
                                 [](long long s, const Snapshot& snap) { return s < snap.step; });
    while (world.stepCount() < to) {
        if (const UserInput* in = inputFor(world.stepCount()))
            applyInput(world, *in);
        world.step();
        each(world);
        // A snapshot holds what was edited at its step (a setting, a body moved): the run went
        // on from it. Without an edit it is the state just replayed.
        if (next != m_snapshots.end() && next->step == world.stepCount())
            world = (next++)->world;
    }
}

void applyInput(physics::World& world, const UserInput& input)
{
    if (input.body < 0 || input.body >= static_cast<physics::BodyId>(world.bodies().size()))
        return;
    // The pulled body wakes if it was asleep (and its island with it, at this step), live and
    // in a replay alike, whatever the force.
    world.applyForce(input.body, input.force, input.torque);
}

} // namespace rigidlab::ui
