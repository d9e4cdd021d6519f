// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the instruments read off the world, without Qt widgets: where a ruler's end snaps to,
// the angles a protractor shows, the probe's quantities of a body, and the events a stopwatch
// starts or stops on. Everything reads the world through World's public API.

#include "rigidlab/physics/world.h"

#include <optional>
#include <vector>

namespace rigidlab::ui::instruments {

/// A point a ruler or protractor end snapped to.
struct Snap {
    physics::Vec2 point = physics::Vec2::Zero(); ///< [m]
    physics::BodyId body = -1;                   ///< -1: not snapped
    bool vertex = false;                         ///< a vertex, else the centre of mass
};

/// The corners of a body's polygon in the world [m] (none for a circle).
std::vector<physics::Vec2> bodyVertices(const physics::Body& body);
/// The body centre or vertex nearest to `p` within `radius` [m]; else `p` itself, unsnapped.
Snap snapPoint(const physics::World& world, const physics::Vec2& p, double radius);

/// The angle at `vertex` between the rays to `a` and to `b`, in [0, 180] [°]; NaN when a ray
/// has no length.
double angleBetweenDegrees(const physics::Vec2& vertex, const physics::Vec2& a,
                           const physics::Vec2& b);
/// A body's turn θ, wrapped to (−180, 180] [°].
double bodyAngleDegrees(const physics::Body& body);

/// What the probe shows of a body, in SI units, in the lab frame.
struct ProbeReading {
    physics::Vec2 position = physics::Vec2::Zero(); ///< centre of mass [m]
    physics::Vec2 velocity = physics::Vec2::Zero(); ///< of the centre of mass [m/s]
    double speed = 0;                               ///< |v| [m/s]
    double angularVelocity = 0;                     ///< ω [rad/s]
    double kinetic = 0;                             ///< ½ m v² + ½ I ω² [J]
    physics::Vec2 momentum = physics::Vec2::Zero(); ///< m v [kg m/s]
    double angularMomentum = 0;                   ///< about the origin: I ω + m r × v [kg m²/s]
    physics::Vec2 weight = physics::Vec2::Zero(); ///< m g [N]
    /// The contact forces of the last step: the impulses on the body divided by dt [N].
    physics::Vec2 contactForce = physics::Vec2::Zero();
};
ProbeReading probeBody(const physics::World& world, physics::BodyId id);

/// What starts or stops the stopwatch.
enum class Trigger {
    Hand,         ///< the Start or Stop button
    FirstContact, ///< the body touches anything
    PassesLine,   ///< the body's centre crosses the height y = lineY
    AtRest,       ///< the body, moving before, comes to rest
};
struct TriggerSpec {
    Trigger kind = Trigger::Hand;
    physics::BodyId body = 0;
    double lineY = 0; ///< [m]
};
/// Below these a body is at rest [m/s], [rad/s].
inline constexpr double kRestSpeed = 1e-3;
inline constexpr double kRestTurnRate = 1e-3;
/// What the triggers look at in a body at one moment.
struct Observation {
    bool valid = false;    ///< the body exists
    double y = 0;          ///< its centre's height [m]
    bool atRest = false;   ///< below kRestSpeed and kRestTurnRate
    bool touching = false; ///< in contact with another body
};
Observation observeBody(const physics::World& world, physics::BodyId id);
bool happened(const TriggerSpec& spec, const Observation& before, const Observation& after);
/// Whether the event happened between two moments of the world, `before` and `after` (one
/// step apart, or more). A hand trigger never happens.
bool happened(const TriggerSpec& spec, const physics::World& before, const physics::World& after);

/// A stopwatch over a world's steps: started and stopped by hand or on an event, timed at the
/// step the event happened, read in the step's resolution. When the run took several steps
/// between two looks (a frame), the steps in between are replayed on a copy of the world to
/// find the one the event happened in.
class Stopwatch {
public:
    enum class State { Idle, Armed, Running, Stopped };

    void setStart(const TriggerSpec& spec) { m_start = spec; }
    void setStop(const TriggerSpec& spec) { m_stop = spec; }
    const TriggerSpec& start() const { return m_start; }
    const TriggerSpec& stop() const { return m_stop; }

    /// Start by hand: runs from the world's time now, or waits for the start event.
    void press(const physics::World& world);
    /// Stop by hand at the world's time now.
    void halt(const physics::World& world);
    void reset();
    /// The world is at a new moment (stepped, or moved on the timeline).
    void observe(const physics::World& world);

    State state() const { return m_state; }
    /// The time on the watch [s]: 0 before it starts, running, or as stopped.
    double reading(const physics::World& world) const;
    /// The step the watch started and stopped at (when it did).
    std::optional<long long> startStep() const { return m_startStep; }
    std::optional<long long> stopStep() const { return m_stopStep; }

private:
    /// The step in (last seen, now] at which `spec` happened, if it did.
    std::optional<long long> findEvent(const TriggerSpec& spec, const physics::World& now,
                                       double& time) const;

    TriggerSpec m_start, m_stop;
    State m_state = State::Idle;
    std::optional<physics::World> m_last; ///< the world as last seen, while an event is awaited
    std::optional<long long> m_startStep, m_stopStep;
    double m_startTime = 0, m_stopTime = 0; ///< [s]
};

} // namespace rigidlab::ui::instruments
