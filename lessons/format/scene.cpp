// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/scene.h"

#include <cassert>

namespace rigidlab::lessons {

std::optional<physics::BodyId> Scene::bodyIndex(const QString& id) const
{
    const std::string key = id.toStdString();
    for (size_t i = 0; i < bodies.size(); ++i) {
        if (bodies[i].name == key) {
            return static_cast<physics::BodyId>(i);
        }
    }
    return std::nullopt;
}

bool Scene::hasLabel(physics::BodyId index) const
{
    return index >= 0 && static_cast<size_t>(index) < labels.size() &&
           !labels[static_cast<size_t>(index)].isEmpty();
}

QString Scene::bodyLabel(physics::BodyId index) const
{
    if (hasLabel(index)) {
        return labels[static_cast<size_t>(index)];
    }
    if (index < 0 || static_cast<size_t>(index) >= bodies.size()) {
        return QString();
    }
    return QString::fromStdString(bodies[static_cast<size_t>(index)].name);
}

physics::World buildWorld(const Scene& scene)
{
    physics::World world(scene.world);
    for (const physics::BodyDef& def : scene.bodies) {
        [[maybe_unused]] const physics::BodyId id = world.addBody(def);
        assert(static_cast<size_t>(id) + 1 == world.bodies().size());
    }
    for (const physics::SpringDef& spring : scene.springs) {
        world.addSpring(spring);
    }
    for (const physics::PinJointDef& joint : scene.joints) {
        world.addPinJoint(joint);
    }
    return world;
}

} // namespace rigidlab::lessons
