// SPDX-License-Identifier: GPL-3.0-or-later
// The accumulators of one body, force by force: each force is evaluated by the engine's own
// law (appliedLoad, Dynamics::appliedAccelerations) with only that force present.

#include "rigidlab/physics/force_breakdown.h"

#include "dynamics.h"

namespace rigidlab::physics {

namespace {

/// The bodies as the world has them, without the user's accumulators.
std::vector<Body> withoutAccumulators(const World& world)
{
    std::vector<Body> bodies = world.bodies();
    for (Body& b : bodies) {
        b.force = Vec2::Zero();
        b.torque = 0.0;
    }
    return bodies;
}

/// The state slots as the world numbers them: moving bodies in id order.
std::vector<int> slotsOf(const World& world)
{
    std::vector<int> slot;
    int next = 0;
    for (const Body& b : world.bodies())
        slot.push_back(b.type != BodyType::Static ? next++ : -1);
    return slot;
}

/// Force and torque on body `id` from the applied forces of a world reduced to `def` and
/// `springs` (gravity, drag and gravitation as `def` has them), by the engine's force sum.
std::pair<Vec2, double> loadOf(const World& world, BodyId id, const WorldDef& def,
                               const std::vector<SpringDef>& springs)
{
    const std::vector<Body> bodies = withoutAccumulators(world);
    const std::vector<int> slot = slotsOf(world);
    const Dynamics dynamics(forceField(def), bodies, slot, springs, {});
    Eigen::VectorXd q, v, a;
    world.getState(q, v);
    a.resize(q.size());
    dynamics.appliedAccelerations(q, v, a);
    const Eigen::Index i = 3 * static_cast<Eigen::Index>(slot[static_cast<std::size_t>(id)]);
    const Body& b = world.body(id);
    return {Vec2(a[i], a[i + 1]) * b.mass, a[i + 2] * b.inertia};
}

} // namespace

ForceBreakdown forceBreakdown(const World& world, BodyId id)
{
    ForceBreakdown out;
    const Body& b = world.body(id);
    if (!b.isDynamic())
        return out;
    const auto add = [&](ForceKind kind, int index, const Vec2& force, const Vec2& point,
                         double torque) {
        if (force.squaredNorm() == 0.0 && torque == 0.0)
            return;
        out.terms.push_back({kind, index, force, point, torque});
        out.force += force;
        out.torque += torque;
    };
    WorldDef only = world.def();
    only.drag = 0.0;
    only.gravitation = 0.0;
    const auto weight = loadOf(world, id, only, {});
    add(ForceKind::Weight, -1, weight.first, b.position, weight.second);
    only.gravity = Vec2::Zero();
    only.drag = world.def().drag;
    const auto drag = loadOf(world, id, only, {});
    add(ForceKind::Drag, -1, drag.first, b.position, drag.second);
    only.drag = 0.0;
    Eigen::VectorXd q, v;
    world.getState(q, v);
    const std::vector<Body> bodies = withoutAccumulators(world);
    const std::vector<int> slot = slotsOf(world);
    const Dynamics geometry(forceField(only), bodies, slot, world.springs(), {});
    for (std::size_t s = 0; s < world.springs().size(); ++s) {
        const SpringDef& spring = world.springs()[s];
        if (spring.a != id && spring.b != id)
            continue;
        const auto load = loadOf(world, id, only, {spring});
        const Dynamics::SpringEnds ends = geometry.springEnds(spring, q, v);
        add(ForceKind::Spring, static_cast<int>(s), load.first, spring.a == id ? ends.pA : ends.pB,
            load.second);
    }
    add(ForceKind::Applied, -1, b.force, b.position, b.torque);
    if (world.def().gravitation != 0.0) {
        only.gravitation = world.def().gravitation;
        const auto pull = loadOf(world, id, only, {});
        add(ForceKind::Gravitation, -1, pull.first, b.position, pull.second);
    }
    return out;
}

} // namespace rigidlab::physics
