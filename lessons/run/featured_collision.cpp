// SPDX-License-Identifier: GPL-3.0-or-later
#include "run/featured_collision.h"

#include <algorithm>
#include <functional>

namespace rigidlab::lessons {

bool isSettling(const CollisionEvent& e, const physics::World& world)
{
    // approach < 0 is approaching; a body resting on the ground after one step of gravity
    // approaches at g dt, below the threshold (which is at least g dt).
    return -e.approach < physics::restitutionThreshold(world.def(), world.contactSettings());
}

const CollisionEvent* featuredCollision(const std::vector<CollisionEvent>& events,
                                        const physics::World& world,
                                        const std::vector<physics::BodyId>& named)
{
    const auto isNamed = [&](physics::BodyId id) {
        return std::find(named.begin(), named.end(), id) != named.end();
    };
    const auto dynamic = [&](physics::BodyId id) {
        return id >= 0 && static_cast<std::size_t>(id) < world.bodies().size() &&
               world.body(id).isDynamic();
    };
    const std::function<bool(const CollisionEvent&)> rules[] = {
        [&](const CollisionEvent& e) { return isNamed(e.a) && isNamed(e.b); },
        [&](const CollisionEvent& e) { return isNamed(e.a) || isNamed(e.b); },
        [&](const CollisionEvent& e) { return dynamic(e.a) && dynamic(e.b); },
        [](const CollisionEvent&) { return true; },
    };
    for (const auto& rule : rules)
        for (const CollisionEvent& e : events)
            if (!isSettling(e, world) && rule(e))
                return &e;
    return nullptr;
}

std::vector<physics::BodyId> namedBodies(const LessonStep& step, const Scene& scene)
{
    QStringList ids;
    for (const Question& q : step.questions)
        if (const MeasuredQuestion* m = q.as<MeasuredQuestion>(); m && !m->measure.body.isEmpty())
            ids << m->measure.body;
    if (step.sat)
        ids << step.sat->first << step.sat->second;
    std::vector<physics::BodyId> out;
    for (const QString& id : ids)
        if (const auto index = scene.bodyIndex(id);
            index && std::find(out.begin(), out.end(), *index) == out.end())
            out.push_back(*index);
    return out;
}

} // namespace rigidlab::lessons
