// SPDX-License-Identifier: GPL-3.0-or-later
// Stage::Diagnostics (profile.h): the measured quantities.

#include "diagnostics_compute.h"

#include "rigidlab/physics/touching.h"

#include <cmath>

namespace rigidlab::physics {

Diagnostics computeDiagnostics(const WorldDef& def, const std::vector<Body>& bodies,
                               const std::vector<SpringDef>& springs)
{
    Diagnostics d;
    for (const Body& b : bodies) {
        if (!b.isDynamic())
            continue;
        d.translationalKinetic += 0.5 * b.mass * b.velocity.squaredNorm();
        d.rotationalKinetic += 0.5 * b.inertia * b.angularVelocity * b.angularVelocity;
        d.gravityPotential -= b.mass * def.gravity.dot(b.position);
        d.momentum += b.mass * b.velocity;
        d.angularMomentum += b.mass * cross(b.position, b.velocity) + b.inertia * b.angularVelocity;
    }
    for (const SpringDef& s : springs) {
        auto point = [&](BodyId id, const Vec2& anchor) -> Vec2 {
            if (id == kWorld)
                return anchor;
            const Body& b = bodies[static_cast<size_t>(id)];
            return b.transform().apply(anchor);
        };
        const double stretch =
            (point(s.b, s.anchorB) - point(s.a, s.anchorA)).norm() - s.restLength;
        d.springPotential += 0.5 * s.stiffness * stretch * stretch;
    }
    if (def.gravitation != 0.0) {
        for (size_t i = 0; i < bodies.size(); ++i) {
            if (!bodies[i].isDynamic())
                continue;
            for (size_t j = i + 1; j < bodies.size(); ++j) {
                if (!bodies[j].isDynamic())
                    continue;
                const double r = (bodies[j].position - bodies[i].position).norm();
                if (r > 1e-12)
                    d.gravitationPotential -= def.gravitation * bodies[i].mass * bodies[j].mass / r;
            }
        }
    }
    d.kinetic = d.translationalKinetic + d.rotationalKinetic;
    d.potential = d.gravityPotential + d.springPotential + d.gravitationPotential;
    d.total = d.kinetic + d.potential;
    return d;
}

void World::updateDiagnostics()
{
    m_diagnostics = computeDiagnostics(m_def, m_bodies, m_springs);
    m_diagnostics.collisionLoss = m_collisionLoss;
    m_diagnostics.dragLoss = m_dragLoss;
    m_diagnostics.dampingLoss = m_dampingLoss;
    m_diagnostics.dissipated = m_collisionLoss + m_dragLoss + m_dampingLoss;
    m_touchingCounted = false;
}

const Diagnostics& World::diagnostics() const
{
    if (!m_touchingCounted) {
        m_diagnostics.contacts = touchingPoints(m_contacts);
        m_touchingCounted = true;
    }
    return m_diagnostics;
}

} // namespace rigidlab::physics
