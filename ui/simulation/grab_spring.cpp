// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulation/grab_spring.h"

#include <algorithm>
#include <numbers>

namespace rigidlab::ui {

void GrabSpring::grab(const physics::World& world, physics::BodyId id,
                      const physics::Vec2& worldPoint)
{
    if (id < 0 || id >= static_cast<physics::BodyId>(world.bodies().size()) ||
        !world.body(id).isDynamic())
        return;
    m_hold = Hold{id, world.body(id).transform().applyInverse(worldPoint), worldPoint};
}

void GrabSpring::dragTo(const physics::Vec2& worldPoint)
{
    if (m_hold)
        m_hold->target = worldPoint;
}

std::optional<UserInput> GrabSpring::input(const physics::World& world) const
{
    if (!m_hold)
        return std::nullopt;
    const physics::Body& b = world.body(m_hold->body);
    const physics::Vec2 p = b.transform().apply(m_hold->localPoint);
    const double h = world.def().dt;
    // Stiffer than the step can follow would oscillate: at most half a radian per step.
    const double w = std::min(2.0 * std::numbers::pi * kGrabFrequency, 0.5 / h);
    const physics::Vec2 f = b.mass * (w * w * (m_hold->target - p) - 2.0 * w * b.pointVelocity(p));
    return UserInput{m_hold->body, f, physics::cross(physics::Vec2(p - b.position), f)};
}

bool GrabSpring::line(const physics::World& world, physics::Vec2& from, physics::Vec2& to) const
{
    if (!m_hold)
        return false;
    from = world.body(m_hold->body).transform().apply(m_hold->localPoint);
    to = m_hold->target;
    return true;
}

} // namespace rigidlab::ui
