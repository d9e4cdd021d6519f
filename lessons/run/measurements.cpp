// SPDX-License-Identifier: GPL-3.0-or-later
// What a lesson measures while its world runs, and how a typed answer is judged.
//
// Bounces and apexes: a bounce is the vertical velocity of a body's centre of mass turning
// from down to up between two steps; the apex after it is the highest point the centre
// reaches before it turns down again (the highest of the stepped positions: with dt = 1 ms
// that is within g dt^2 / 2 = 5 um of the true top).
//
// Collisions: a pair of bodies (both dynamic, or one dynamic and one static) that a positive
// normal impulse pushed apart this step but not in the step before. The velocities before
// are those after the previous step. The spins the impulse formula predicts use the
// contact's point and normal, the masses and moments of inertia and the pair's restitution:
//
//     j = -(1 + e) v_rel.n / (1/mA + 1/mB + (rA x n)^2 / IA + (rB x n)^2 / IB)
//     wA' = wA - (rA x n) j / IA,   wB' = wB + (rB x n) j / IB
//
// and, as the paper prints it (its equation 1.4), without the two rotational terms in
// the denominator: the same spins from a larger j.

#include "run/measurements.h"
#include "run/scene_run.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace rigidlab::lessons {

using physics::BodyId;
using physics::Vec2;

namespace {

/// A vertical velocity turning up faster than this is a bounce, not rounding noise of a body
/// at rest [m/s].
constexpr double kBounceSpeed = 1e-3;

/// Steps reach a time t when they are within this of it (t accumulates dt in floating point).
double timeSlack(double t)
{
    return 1e-9 * std::max(1.0, std::abs(t));
}

bool sameMeasure(const Measure& a, const Measure& b)
{
    return a.kind == b.kind && a.body == b.body && a.n == b.n && a.above == b.above &&
           a.time == b.time;
}

bool countsForCollisions(const physics::Body& b)
{
    return b.type != physics::BodyType::Kinematic;
}

const std::vector<ApexEvent> kNoApexes;
const std::vector<double> kNoBounces;

} // namespace

void Measurements::reset(const physics::World& world, const std::vector<Measure>& watched)
{
    const std::size_t n = world.bodies().size();
    m_apexes.assign(n, {});
    m_bounces.assign(n, {});
    m_bounceY.assign(n, {});
    m_peaks.assign(n, {});
    m_collisions.clear();
    m_timed.clear();
    for (const Measure& m : watched) {
        if (m.kind != Measure::Kind::Apex) {
            m_timed.push_back({m, std::nullopt, 0});
        }
    }
    // Drift relative to |E0|; when E0 is near zero, to the size of its parts instead (as the
    // window's energy-drift plot does). What contacts, drag and dampers take is added back: the
    // drift is the numerical error alone.
    const physics::Diagnostics& d = world.diagnostics();
    m_energy0 = d.total - d.dissipated;
    m_energyScale = energyScale(d);
    readState(world);
    touchingPairs(world, m_touching);
    m_resync = false;
    recordTimed(world);
}

void Measurements::readState(const physics::World& world)
{
    const auto& bodies = world.bodies();
    m_lastVelocity.resize(bodies.size());
    m_lastAngular.resize(bodies.size());
    m_lastPosition.resize(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        m_lastVelocity[i] = bodies[i].velocity;
        m_lastAngular[i] = bodies[i].angularVelocity;
        m_lastPosition[i] = bodies[i].position;
    }
}

bool Measurements::touchingPairs(const physics::World& world, std::vector<Pair>& pairs)
{
    pairs.clear();
    bool ordered = true;
    for (const physics::Contact& c : world.contacts()) {
        if (c.normalImpulse[0] > 0 || c.normalImpulse[1] > 0) {
            ordered = ordered && (pairs.empty() || pairs.back() < Pair(c.a, c.b));
            pairs.emplace_back(c.a, c.b);
        }
    }
    if (!ordered)
        std::sort(pairs.begin(), pairs.end());
    return ordered;
}

void Measurements::recordTimed(const physics::World& world)
{
    const double t = world.time();
    const physics::Diagnostics& d = world.diagnostics();
    for (Timed& timed : m_timed) {
        const Measure& m = timed.measure;
        if (timed.value || t + timeSlack(m.time) < m.time) {
            continue;
        }
        double v = 0;
        const physics::Body* body = nullptr;
        if (!m.body.isEmpty()) {
            const std::string name = m.body.toStdString();
            for (const physics::Body& b : world.bodies()) {
                if (b.name == name) {
                    body = &b;
                    break;
                }
            }
            if (!body) {
                continue; // not this world's body: a programming error, never measured
            }
        }
        switch (m.kind) {
        case Measure::Kind::Apex:
            continue;
        case Measure::Kind::Speed:
            v = body->velocity.norm();
            break;
        case Measure::Kind::VelocityX:
            v = body->velocity.x();
            break;
        case Measure::Kind::VelocityY:
            v = body->velocity.y();
            break;
        case Measure::Kind::AngularVelocity:
            v = body->angularVelocity;
            break;
        case Measure::Kind::PositionX:
            v = body->origin().x();
            break;
        case Measure::Kind::PositionY:
            v = body->origin().y();
            break;
        case Measure::Kind::EnergyDrift:
            v = (d.total + d.dissipated - m_energy0) / m_energyScale * 100.0;
            break;
        case Measure::Kind::MomentumX:
            v = d.momentum.x();
            break;
        case Measure::Kind::MomentumY:
            v = d.momentum.y();
            break;
        }
        timed.value = v;
        timed.recordedAt = t;
    }
}

CollisionEvent Measurements::collisionEvent(const physics::World& world,
                                            const physics::Contact& c) const
{
    CollisionEvent e;
    e.t = world.time();
    e.a = c.a;
    e.b = c.b;
    const std::array<BodyId, 2> ids{c.a, c.b};
    for (std::size_t k = 0; k < 2; ++k) {
        const auto i = static_cast<std::size_t>(ids[k]);
        const physics::Body& body = world.body(ids[k]);
        e.velocityBefore[k] = m_lastVelocity[i];
        e.velocityAfter[k] = body.velocity;
        e.angularBefore[k] = m_lastAngular[i];
        e.angularAfter[k] = body.angularVelocity;
    }

    // The point the impulse acted at: the manifold's points weighted by their impulses.
    const physics::Manifold& m = c.manifold;
    Vec2 point = Vec2::Zero();
    double total = 0;
    for (int k = 0; k < m.pointCount; ++k) {
        const double j = std::max(0.0, c.normalImpulse[static_cast<std::size_t>(k)]);
        point += j * m.points[static_cast<std::size_t>(k)].point;
        total += j;
    }
    point /= total;
    const Vec2& n = m.normal;
    const physics::Body& a = world.body(c.a);
    const physics::Body& b = world.body(c.b);
    const auto ia = static_cast<std::size_t>(c.a);
    const auto ib = static_cast<std::size_t>(c.b);
    const Vec2 rA = point - m_lastPosition[ia];
    const Vec2 rB = point - m_lastPosition[ib];
    const Vec2 vA = m_lastVelocity[ia] + physics::cross(m_lastAngular[ia], rA);
    const Vec2 vB = m_lastVelocity[ib] + physics::cross(m_lastAngular[ib], rB);
    const double vn = (vB - vA).dot(n);
    // The sequential-impulse solver lets slow approaches rest instead of bouncing.
    const bool bounces = world.def().solver == physics::SolverKind::PaperImpulse ||
                         vn < -physics::restitutionThreshold(world.def(), world.contactSettings());
    const double restitution = bounces ? c.restitution : 0.0;
    const double rnA = physics::cross(rA, n);
    const double rnB = physics::cross(rB, n);
    const double linear = a.invMass + b.invMass;
    const double full = linear + a.invInertia * rnA * rnA + b.invInertia * rnB * rnB;
    const double jFull = full > 0 ? -(1.0 + restitution) * vn / full : 0.0;
    const double jLinear = linear > 0 ? -(1.0 + restitution) * vn / linear : 0.0;
    e.predictedFull[0] = m_lastAngular[ia] - a.invInertia * rnA * jFull;
    e.predictedFull[1] = m_lastAngular[ib] + b.invInertia * rnB * jFull;
    e.predictedWithoutRotation[0] = m_lastAngular[ia] - a.invInertia * rnA * jLinear;
    e.predictedWithoutRotation[1] = m_lastAngular[ib] + b.invInertia * rnB * jLinear;
    e.point = point;
    e.normal = n;
    e.lever[0] = rA;
    e.lever[1] = rB;
    e.approach = vn;
    e.restitution = restitution;
    e.impulse = jFull;
    return e;
}

bool Measurements::findBounces(const physics::World& world)
{
    const auto& bodies = world.bodies();
    m_bouncing.assign(bodies.size(), 0);
    bool any = false;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const physics::Body& b = bodies[i];
        if (b.isDynamic() && m_lastVelocity[i].y() < 0 && b.velocity.y() > kBounceSpeed &&
            m_bounces[i].size() < kMaxBouncesPerBody) {
            m_bouncing[i] = 1;
            any = true;
        }
    }
    return any;
}

void Measurements::findTouchdowns(const physics::World& world)
{
    // The step's contacts were made from the poses before it: the centre then, moved across
    // the gap along the normal (a pointing to b), is where the surfaces met. Of several points the
    // one with the least gap meets first: a box lands on its lowest corner. One pass over the
    // contacts for all the bodies that bounce: a pile that settles bounces thousands of bodies
    // in one step, and each would search every contact.
    constexpr double kNone = -std::numeric_limits<double>::infinity();
    m_touchdown.assign(world.bodies().size(), kNone);
    for (const physics::Contact& c : world.contacts()) {
        const auto ia = static_cast<std::size_t>(c.a), ib = static_cast<std::size_t>(c.b);
        if (!m_bouncing[ia] && !m_bouncing[ib])
            continue;
        const physics::Manifold& m = c.manifold;
        for (int k = 0; k < m.pointCount; ++k) {
            if (!(c.normalImpulse[static_cast<std::size_t>(k)] > 0))
                continue;
            const double shift = m.points[static_cast<std::size_t>(k)].separation * m.normal.y();
            if (m_bouncing[ia])
                m_touchdown[ia] = std::max(m_touchdown[ia], m_lastPosition[ia].y() + shift);
            if (m_bouncing[ib])
                m_touchdown[ib] = std::max(m_touchdown[ib], m_lastPosition[ib].y() - shift);
        }
    }
    // A body that bounced with no contact pushing it: its height now.
    for (std::size_t i = 0; i < m_touchdown.size(); ++i)
        if (m_bouncing[i] && m_touchdown[i] == kNone)
            m_touchdown[i] = world.bodies()[i].position.y();
}

void Measurements::observe(const physics::World& world)
{
    const auto& bodies = world.bodies();
    if (m_resync || m_lastVelocity.size() != bodies.size()) {
        m_apexes.resize(bodies.size());
        m_bounces.resize(bodies.size());
        m_bounceY.resize(bodies.size());
        m_peaks.resize(bodies.size());
        readState(world);
        touchingPairs(world, m_touching);
        m_resync = false;
        recordTimed(world);
        return;
    }
    const double t = world.time();

    // Bounces and apexes.
    if (findBounces(world))
        findTouchdowns(world);
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const physics::Body& b = bodies[i];
        if (!b.isDynamic()) {
            continue;
        }
        const double vy = b.velocity.y();
        const double y = b.position.y();
        Peak& peak = m_peaks[i];
        if (m_bouncing[i]) {
            const double touch = m_touchdown[i];
            m_bounces[i].push_back(t);
            m_bounceY[i].push_back(touch);
            peak = {true, t, y, touch};
        } else if (peak.armed) {
            if (y > peak.y) {
                peak.t = t;
                peak.y = y;
            }
            if (vy <= 0) {
                m_apexes[i].push_back({peak.t, peak.y, peak.bounceY});
                peak.armed = false;
            }
        }
    }

    // Collisions: pairs pushed apart now that were not in the step before. With the contacts
    // in the order of their pairs, one cursor walks the step before's pairs along with them;
    // else each pair is searched for.
    const bool ordered = touchingPairs(world, m_touchingNow);
    std::size_t cursor = 0;
    const auto touchedBefore = [&](const Pair& pair) {
        if (!ordered)
            return std::binary_search(m_touching.begin(), m_touching.end(), pair);
        while (cursor < m_touching.size() && m_touching[cursor] < pair)
            ++cursor;
        return cursor < m_touching.size() && m_touching[cursor] == pair;
    };
    for (const physics::Contact& c : world.contacts()) {
        if (!(c.normalImpulse[0] > 0 || c.normalImpulse[1] > 0)) {
            continue;
        }
        const physics::Body& a = world.body(c.a);
        const physics::Body& b = world.body(c.b);
        if (!countsForCollisions(a) || !countsForCollisions(b) ||
            (!a.isDynamic() && !b.isDynamic())) {
            continue;
        }
        if (touchedBefore(Pair(c.a, c.b))) {
            continue;
        }
        if (m_collisions.size() < kMaxCollisions)
            m_collisions.push_back(collisionEvent(world, c));
    }
    std::swap(m_touching, m_touchingNow);

    readState(world);
    recordTimed(world);
}

void Measurements::rewind(double t)
{
    const double limit = t + timeSlack(t);
    for (std::size_t i = 0; i < m_apexes.size(); ++i) {
        std::erase_if(m_apexes[i], [&](const ApexEvent& e) { return e.t > limit; });
        std::erase_if(m_bounces[i], [&](double b) { return b > limit; });
        m_bounceY[i].resize(m_bounces[i].size());
        // Rising again from the rewound state: the peak is found anew.
        const bool rising = m_bounces[i].size() > m_apexes[i].size();
        m_peaks[i] = {rising, t, -std::numeric_limits<double>::infinity(),
                      rising ? m_bounceY[i].back() : 0.0};
    }
    std::erase_if(m_collisions, [&](const CollisionEvent& e) { return e.t > limit; });
    for (Timed& timed : m_timed) {
        if (timed.value && timed.recordedAt > limit) {
            timed.value.reset();
        }
    }
    m_resync = true;
}

void Measurements::rewind(const physics::World& world)
{
    rewind(world.time());
    observe(world); // reads the state only
}

const std::vector<ApexEvent>& Measurements::apexes(BodyId body) const
{
    const auto i = static_cast<std::size_t>(body);
    return i < m_apexes.size() ? m_apexes[i] : kNoApexes;
}

const std::vector<double>& Measurements::bounces(BodyId body) const
{
    const auto i = static_cast<std::size_t>(body);
    return i < m_bounces.size() ? m_bounces[i] : kNoBounces;
}

std::optional<double> Measurements::value(const Measure& m, const Scene& scene) const
{
    if (m.kind == Measure::Kind::Apex) {
        const auto body = scene.bodyIndex(m.body);
        if (!body || m.n < 1) {
            return std::nullopt;
        }
        const std::vector<ApexEvent>& list = apexes(*body);
        if (static_cast<std::size_t>(m.n) > list.size()) {
            return std::nullopt;
        }
        return list[static_cast<std::size_t>(m.n - 1)].y - m.above;
    }
    for (const Timed& timed : m_timed) {
        if (sameMeasure(timed.measure, m)) {
            return timed.value;
        }
    }
    return std::nullopt;
}

} // namespace rigidlab::lessons
