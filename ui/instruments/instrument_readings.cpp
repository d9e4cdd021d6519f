// SPDX-License-Identifier: GPL-3.0-or-later
#include "instruments/instrument_readings.h"

#include "simulation/step_sampler.h"

#include "rigidlab/physics/touching.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace rigidlab::ui::instruments {

namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

/// Whether body `id` touches another body in this world (physics::touches()).
bool touches(const physics::World& world, physics::BodyId id)
{
    for (const physics::Contact& c : world.contacts())
        if ((c.a == id || c.b == id) && physics::touches(c))
            return true;
    return false;
}

bool atRest(const physics::Body& b)
{
    return b.velocity.norm() < kRestSpeed && std::abs(b.angularVelocity) < kRestTurnRate;
}

bool validBody(const physics::World& world, physics::BodyId id)
{
    return id >= 0 && id < static_cast<physics::BodyId>(world.bodies().size());
}

} // namespace

std::vector<physics::Vec2> bodyVertices(const physics::Body& body)
{
    std::vector<physics::Vec2> out;
    if (const physics::Polygon* polygon = body.shape.asPolygon()) {
        const physics::Transform t = body.transform();
        for (const physics::Vec2& v : polygon->vertices)
            out.push_back(t.apply(v));
    }
    return out;
}

Snap snapPoint(const physics::World& world, const physics::Vec2& p, double radius)
{
    Snap best;
    best.point = p;
    double bestDistance = radius;
    const auto consider = [&](const physics::Vec2& q, physics::BodyId id, bool vertex) {
        const double d = (q - p).norm();
        if (d <= bestDistance) {
            bestDistance = d;
            best = {q, id, vertex};
        }
    };
    const auto count = static_cast<physics::BodyId>(world.bodies().size());
    for (physics::BodyId id = 0; id < count; ++id) {
        const physics::Body& b = world.body(id);
        consider(b.position, id, false);
        for (const physics::Vec2& v : bodyVertices(b))
            consider(v, id, true);
    }
    return best;
}

double angleBetweenDegrees(const physics::Vec2& vertex, const physics::Vec2& a,
                           const physics::Vec2& b)
{
    const physics::Vec2 u = a - vertex, w = b - vertex;
    if (u.norm() == 0.0 || w.norm() == 0.0)
        return std::numeric_limits<double>::quiet_NaN();
    // atan2 of the cross and dot products: accurate at 0° and 180°, where acos is not.
    return std::abs(std::atan2(physics::cross(u, w), u.dot(w))) * kDegreesPerRadian;
}

double bodyAngleDegrees(const physics::Body& body)
{
    double a = std::remainder(body.angle, 2.0 * std::numbers::pi) * kDegreesPerRadian;
    return a <= -180.0 ? a + 360.0 : a;
}

ProbeReading probeBody(const physics::World& world, physics::BodyId id)
{
    ProbeReading r;
    if (!validBody(world, id))
        return r;
    const physics::Body& b = world.body(id);
    r.position = b.position;
    r.velocity = b.velocity;
    r.speed = b.velocity.norm();
    r.angularVelocity = b.angularVelocity;
    r.kinetic = 0.5 * b.mass * b.velocity.squaredNorm() +
                0.5 * b.inertia * b.angularVelocity * b.angularVelocity;
    r.momentum = b.mass * b.velocity;
    r.angularMomentum =
        b.inertia * b.angularVelocity + b.mass * physics::cross(b.position, b.velocity);
    r.weight = b.mass * world.def().gravity;
    // The impulse j n + f t acts on B, its opposite on A (the normal points from A to B).
    physics::Vec2 impulse = physics::Vec2::Zero();
    for (const physics::Contact& c : world.contacts()) {
        if (c.a != id && c.b != id)
            continue;
        const physics::Vec2 n = c.manifold.normal;
        const physics::Vec2 t(n.y(), -n.x());
        for (int i = 0; i < c.manifold.pointCount; ++i) {
            const auto k = static_cast<std::size_t>(i);
            const physics::Vec2 j = c.normalImpulse[k] * n + c.tangentImpulse[k] * t;
            impulse += c.b == id ? j : physics::Vec2(-j);
        }
    }
    if (b.isDynamic() && world.def().dt > 0.0)
        r.contactForce = impulse / world.def().dt;
    return r;
}

Observation observeBody(const physics::World& world, physics::BodyId id)
{
    Observation o;
    if (!validBody(world, id))
        return o;
    const physics::Body& b = world.body(id);
    o.valid = true;
    o.y = b.position.y();
    o.atRest = atRest(b);
    o.touching = touches(world, id);
    return o;
}

bool happened(const TriggerSpec& spec, const Observation& before, const Observation& after)
{
    if (!before.valid || !after.valid)
        return false;
    switch (spec.kind) {
    case Trigger::Hand:
        return false;
    case Trigger::FirstContact:
        return !before.touching && after.touching;
    case Trigger::PassesLine:
        return (before.y > spec.lineY) != (after.y > spec.lineY);
    case Trigger::AtRest:
        return !before.atRest && after.atRest;
    }
    return false;
}

bool happened(const TriggerSpec& spec, const physics::World& before, const physics::World& after)
{
    return happened(spec, observeBody(before, spec.body), observeBody(after, spec.body));
}

void Stopwatch::press(const physics::World& world)
{
    m_stopStep.reset();
    if (m_start.kind == Trigger::Hand) {
        m_state = State::Running;
        m_startStep = world.stepCount();
        m_startTime = stepTime(world);
    } else {
        m_state = State::Armed;
        m_startStep.reset();
    }
    m_last = world;
}

void Stopwatch::halt(const physics::World& world)
{
    if (m_state == State::Running) {
        m_state = State::Stopped;
        m_stopStep = world.stepCount();
        m_stopTime = stepTime(world);
    } else if (m_state == State::Armed) {
        m_state = State::Idle;
    }
    m_last.reset();
}

void Stopwatch::reset()
{
    m_state = State::Idle;
    m_startStep.reset();
    m_stopStep.reset();
    m_last.reset();
}

void Stopwatch::observe(const physics::World& world)
{
    // Back on the timeline before the start: the watch waits again as it did then.
    if (m_startStep && world.stepCount() < *m_startStep) {
        const bool byHand = m_start.kind == Trigger::Hand;
        m_state = byHand ? State::Idle : State::Armed;
        m_startStep.reset();
        m_stopStep.reset();
    } else if (m_stopStep && world.stepCount() < *m_stopStep) {
        m_state = State::Running;
        m_stopStep.reset();
    }
    const bool awaiting = (m_state == State::Armed && m_start.kind != Trigger::Hand) ||
                          (m_state == State::Running && m_stop.kind != Trigger::Hand);
    if (!awaiting) {
        m_last.reset();
        return;
    }
    if (m_last && world.stepCount() > m_last->stepCount()) {
        double t = 0;
        if (m_state == State::Armed) {
            if (const auto step = findEvent(m_start, world, t)) {
                m_state = State::Running;
                m_startStep = step;
                m_startTime = t;
            }
        }
        if (m_state == State::Running && m_stop.kind != Trigger::Hand) {
            if (const auto step = findEvent(m_stop, world, t); step && *step > *m_startStep) {
                m_state = State::Stopped;
                m_stopStep = step;
                m_stopTime = t;
            }
        }
    }
    m_last = world;
}

std::optional<long long> Stopwatch::findEvent(const TriggerSpec& spec, const physics::World& now,
                                              double& time) const
{
    // Several steps since the last look (a frame): the same steps again on a copy, one by one,
    // so that the event is timed at the step it happened in, and one over and done within the
    // frame (a bounce) is not missed. Should the copy not find it (the world was pushed by hand
    // meanwhile), an event seen between the two looks stands at the step seen now.
    if (now.stepCount() > m_last->stepCount() + 1) {
        physics::World replay = *m_last;
        Observation before = observeBody(replay, spec.body);
        while (replay.stepCount() < now.stepCount()) {
            replay.step();
            const Observation after = observeBody(replay, spec.body);
            if (happened(spec, before, after)) {
                time = stepTime(replay);
                return replay.stepCount();
            }
            before = after;
        }
    }
    if (!happened(spec, *m_last, now))
        return std::nullopt;
    time = stepTime(now);
    return now.stepCount();
}

double Stopwatch::reading(const physics::World& world) const
{
    switch (m_state) {
    case State::Idle:
    case State::Armed:
        return 0.0;
    case State::Running:
        return std::max(0.0, stepTime(world) - m_startTime);
    case State::Stopped:
        return m_stopTime - m_startTime;
    }
    return 0.0;
}

} // namespace rigidlab::ui::instruments
