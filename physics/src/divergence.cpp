// After a step: is the world still a simulation? A non-finite position, angle or velocity,
// or a total energy grown past its bound (DivergenceSettings), stops it with a diagnosis.
// Explicit Euler on a stiff spring grows its energy by (1 + (w h)^2) per step: the bound
// catches it long before the numbers overflow, at the step that crossed it.

#include "rigidlab/physics/world.h"

#include <charconv>
#include <cmath>

namespace rigidlab::physics {

namespace {

std::string number(double value)
{
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value, std::chars_format::general, 6);
    return std::string(text, end.ptr);
}

} // namespace

std::string Divergence::message() const
{
    std::string where = "diverged at t = " + number(time) + " s (step " + std::to_string(step) +
                        ", dt = " + number(dt) + " s, " + std::string(integratorName(integrator)) +
                        "): ";
    if (kind == Kind::NonFinite)
        return where + "body \"" + bodyName + "\": " + quantity + " is no longer finite";
    std::string line = where + "the " + quantity + " grew to " + number(value) +
                       " J, past the bound of " + number(bound) + " J";
    if (body != kWorld)
        line += " (body \"" + bodyName + "\" holds the most kinetic energy)";
    return line;
}

void World::rememberStartEnergy()
{
    updateDiagnostics();
    const Diagnostics& d = m_diagnostics;
    m_energyStart = d.total;
    double mass = 0;
    for (const Body& b : m_bodies)
        mass += b.mass;
    const double parts = d.kinetic + std::abs(d.gravityPotential) + d.springPotential +
                         std::abs(d.gravitationPotential);
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
    for (size_t i = 0; i < m_bodies.size(); ++i) {
        const Body& b = m_bodies[i];
        const char* quantity = !isFinite(b.position)               ? "position"
                               : !std::isfinite(b.angle)           ? "angle"
                               : !isFinite(b.velocity)             ? "velocity"
                               : !std::isfinite(b.angularVelocity) ? "angular velocity"
                                                                   : nullptr;
        if (quantity) {
            d.kind = Divergence::Kind::NonFinite;
            d.body = static_cast<BodyId>(i);
            d.bodyName = b.name;
            d.quantity = quantity;
            m_divergence = d;
            return;
        }
    }
    const double energy = m_diagnostics.total;
    const double bound =
        m_energyStart.value_or(energy) + m_divergenceSettings.energyGrowth * m_energyScale;
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
        d.quantity = "total energy";
        d.value = energy;
        d.bound = bound;
        m_divergence = d;
    }
}

} // namespace rigidlab::physics
