// SPDX-License-Identifier: GPL-3.0-or-later
// After a step: is the world still a simulation? A non-finite position, angle or velocity,
// or a total energy grown past its bound (DivergenceSettings; a far lower one once contacts
// made energy), stops it with a diagnosis.
// Explicit Euler on a stiff spring grows its energy by (1 + (w h)^2) per step: the bound
// catches it long before the numbers overflow, at the step that crossed it.

#include "rigidlab/physics/world.h"

#include <algorithm>
#include <cmath>

namespace rigidlab::physics {

namespace {

/// Energy contacts may add to the bodies, as a share of the energy scale, before the world's
/// total energy is held to the start plus that share. Their solver's error stays below it for
/// a long time (sequential impulses bounce an elastic ball a few per cent higher each time at
/// dt = 1/120 s: the step's gravity is reflected too); overlapping bodies thrown apart pass it
/// in one step (a heap of 1,000 balls: five times the energy in play).
constexpr double kContactGain = 1.0;

/// The first part of a body's state that is no longer finite, if any.
std::optional<Divergence::Quantity> nonFinitePart(const Body& b)
{
    using Q = Divergence::Quantity;
    if (!isFinite(b.position))
        return Q::Position;
    if (!std::isfinite(b.angle))
        return Q::Angle;
    if (!isFinite(b.velocity))
        return Q::Velocity;
    if (!std::isfinite(b.angularVelocity))
        return Q::AngularVelocity;
    return std::nullopt;
}

} // namespace

void World::rememberStartEnergy()
{
    updateDiagnostics();
    const Diagnostics& d = m_diagnostics;
    m_energyStart = d.total;
    double mass = 0;
    for (const Body& b : m_bodies)
        mass += b.mass;
    const double parts = energyParts(d);
    m_energyScale = std::max(parts, m_divergenceSettings.energyFloorPerKg * mass);
}

void World::checkDivergence()
{
    if (!m_divergenceSettings.enabled || m_divergence)
        return;
    Divergence d;
    d.time = m_time;
    d.step = m_steps;
    d.dt = m_def.dt;
    d.integrator = m_def.integrator;
    // One pass over the bodies for both questions: whether some part of a state is not finite
    // (x - x is 0 for a finite x, NaN for an infinite one or NaN, and a sum of zeros stays 0),
    // and whether some body is kinematic. Only then the bodies one by one, for the first.
    double probe = 0.0;
    bool kinematic = false;
    for (const Body& b : m_bodies) {
        probe += (b.position.x() - b.position.x()) + (b.position.y() - b.position.y()) +
                 (b.angle - b.angle) + (b.velocity.x() - b.velocity.x()) +
                 (b.velocity.y() - b.velocity.y()) + (b.angularVelocity - b.angularVelocity);
        kinematic = kinematic || b.type == BodyType::Kinematic;
    }
    for (size_t i = 0; probe != 0.0 && i < m_bodies.size(); ++i) {
        const Body& b = m_bodies[i];
        if (const auto quantity = nonFinitePart(b)) {
            d.kind = Divergence::Kind::NonFinite;
            d.body = static_cast<BodyId>(i);
            d.bodyName = b.name;
            d.quantity = *quantity;
            m_divergence = d;
            return;
        }
    }
    const double energy = m_diagnostics.total;
    // Contacts between bodies none of which is kinematic never make energy: when their books
    // (collisionLoss, what they took so far) went negative past kContactGain of the scale, the
    // energy they made is the growth to judge, long before the general bound (overlapping
    // bodies thrown apart). A kinematic body may push energy in; then only the general bound.
    const double contactBound = kContactGain * m_energyScale;
    const bool contactsMade = !kinematic && -m_diagnostics.collisionLoss > contactBound;
    const double bound =
        m_energyStart.value_or(energy) +
        (contactsMade ? contactBound : m_divergenceSettings.energyGrowth * m_energyScale);
    if (!std::isfinite(energy) || (m_energyStart && m_energyScale > 0 && energy > bound)) {
        d.kind =
            std::isfinite(energy) ? Divergence::Kind::EnergyGrowth : Divergence::Kind::NonFinite;
        // Name the body holding the most kinetic energy: the one running away.
        double most = -1;
        for (size_t i = 0; i < m_bodies.size(); ++i) {
            const Body& b = m_bodies[i];
            const double k = 0.5 * (b.mass * b.velocity.squaredNorm() +
                                    b.inertia * b.angularVelocity * b.angularVelocity);
            if (b.isDynamic() && k > most) {
                most = k;
                d.body = static_cast<BodyId>(i);
                d.bodyName = b.name;
            }
        }
        d.quantity = Divergence::Quantity::TotalEnergy;
        d.value = energy;
        d.bound = bound;
        d.start = m_energyStart.value_or(energy);
        m_divergence = d;
    }
}

} // namespace rigidlab::physics
