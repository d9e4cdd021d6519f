// SPDX-License-Identifier: GPL-3.0-or-later
#include "run/off_stage.h"

#include "run/swept_bounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rigidlab::lessons {

StageFloor stageFloor(const physics::World& world)
{
    const auto& bodies = world.bodies();
    StageFloor floor;
    floor.watched.assign(bodies.size(), 0);
    double bottom = std::numeric_limits<double>::infinity();
    double lowestTop = std::numeric_limits<double>::infinity();
    for (const physics::Body& b : bodies)
        if (!b.moves()) {
            const QRectF box = bodyBounds(b);
            bottom = std::min(bottom, box.top()); // QRectF's top() is the least y
            lowestTop = std::min(lowestTop, box.bottom());
        }
    if (!std::isfinite(bottom))
        return floor;
    floor.bottom = bottom;
    std::vector<char> held(bodies.size(), 0);
    const auto hold = [&](physics::BodyId id) {
        if (id >= 0 && static_cast<std::size_t>(id) < held.size())
            held[static_cast<std::size_t>(id)] = 1;
    };
    for (const physics::SpringDef& s : world.springs()) {
        hold(s.a);
        hold(s.b);
    }
    for (const physics::PinJointDef& j : world.joints()) {
        hold(j.a);
        hold(j.b);
    }
    for (std::size_t i = 0; i < bodies.size(); ++i)
        floor.watched[i] = bodies[i].isDynamic() && !held[i] && bodies[i].position.y() >= lowestTop;
    return floor;
}

std::optional<physics::BodyId> offStage(const physics::World& world, const StageFloor& floor)
{
    const auto& bodies = world.bodies();
    const std::size_t n = std::min(bodies.size(), floor.watched.size());
    for (std::size_t i = 0; i < n; ++i)
        if (floor.watched[i] && bodies[i].position.y() < floor.bottom - kOffStageDrop)
            return static_cast<physics::BodyId>(i);
    return std::nullopt;
}

std::optional<OffStage> firstOffStage(const physics::World& world, double until, long long maxSteps)
{
    const StageFloor floor = stageFloor(world);
    if (std::none_of(floor.watched.begin(), floor.watched.end(), [](char w) { return w != 0; }))
        return std::nullopt;
    physics::World copy(world);
    const double dt = copy.def().dt;
    for (long long k = 0; copy.time() < until - 0.5 * dt && k < maxSteps; ++k) {
        copy.step();
        if (copy.divergence())
            return std::nullopt;
        if (const auto body = offStage(copy, floor))
            return OffStage{*body, copy.time()};
    }
    return std::nullopt;
}

} // namespace rigidlab::lessons
