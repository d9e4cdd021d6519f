#include "history.h"

#include <algorithm>

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

std::size_t History::snapshotLimit(const physics::World& world) const
{
    // A rough size of one copy: bodies with their shapes, and contacts.
    std::size_t bytes = 512;
    for (const physics::Body& b : world.bodies())
        bytes += sizeof(physics::Body) + 32 * b.shape.polygon.vertices.size();
    bytes += world.contacts().size() * sizeof(physics::Contact);
    return std::clamp<std::size_t>(m_budget / bytes, 4, 2000);
}

void History::addSnapshot(const physics::World& world)
{
    if (!m_snapshots.empty() && m_snapshots.back().step >= world.stepCount())
        return;
    m_snapshots.push_back({world.stepCount(), world});
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

void applyInput(physics::World& world, const UserInput& input)
{
    if (input.body < 0 || input.body >= static_cast<physics::BodyId>(world.bodies().size()))
        return;
    physics::Body& b = world.body(input.body);
    b.force += input.force;
    b.torque += input.torque;
}

} // namespace rigidlab::ui
