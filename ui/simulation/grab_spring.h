// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Dragging a body with the mouse: a stiff, critically damped spring from a point of the body
// to the cursor. Its force goes through the world's force accumulators like any other push
// (history.h: UserInput), so the physics stays physical and a release throws the body with
// the velocity it has.

#include "simulation/history.h"

#include "rigidlab/physics/world.h"

#include <optional>

namespace rigidlab::ui {

/// The grab spring's natural frequency [Hz] (never above what the step can follow).
inline constexpr double kGrabFrequency = 3.0;

class GrabSpring {
public:
    /// Takes hold of body `id` of `world` at `worldPoint`. Anything but a dynamic body of the
    /// world changes nothing.
    void grab(const physics::World& world, physics::BodyId id, const physics::Vec2& worldPoint);
    /// Moves the spring's cursor end (nothing when nothing is held).
    void dragTo(const physics::Vec2& worldPoint);
    void release() { m_hold.reset(); }
    std::optional<physics::BodyId> body() const
    {
        return m_hold ? std::optional(m_hold->body) : std::nullopt;
    }
    /// The spring's push on the held body for the next step of `world`: k = m w^2, critically
    /// damped, at the grabbed point. Nothing when nothing is held.
    std::optional<UserInput> input(const physics::World& world) const;
    /// The spring's two ends for drawing, when a body is held.
    bool line(const physics::World& world, physics::Vec2& from, physics::Vec2& to) const;

private:
    struct Hold {
        physics::BodyId body = -1;
        physics::Vec2 localPoint = physics::Vec2::Zero(); ///< in the body's origin frame [m]
        physics::Vec2 target = physics::Vec2::Zero();     ///< the cursor [m]
    };
    std::optional<Hold> m_hold;
};

} // namespace rigidlab::ui
