// SPDX-License-Identifier: GPL-3.0-or-later
// Stage::Forces and Stage::Integration (profile.h): the chosen integrator over the moving
// bodies' state, the forces evaluated at each of its stages (forces.cpp, joints.cpp), the
// joints projected back after the step (joints.cpp), and what drag and dampers took
// (dissipation.cpp).
//
// Symplectic Euler with nothing but contacts coupling the bodies (no springs, joints or
// gravitation: World::Plan::direct) runs straight on the bodies instead, without gathering
// the state into vectors and scattering it back. It is not a second integrator: the same
// update (symplectic_euler.h) on the same forces (appliedLoad), so the same bits.

#include "rigidlab/physics/world.h"

#include "dynamics.h"
#include "symplectic_euler.h"
#include "world_scratch.h"

namespace rigidlab::physics {

void World::integrate()
{
    if (m_moving.empty())
        return;
    if (m_plan.direct) {
        integrateDirect();
        return;
    }
    StageTimer timer(m_profile, Stage::Integration);
    const double t = m_time, h = m_def.dt;
    withState([&](Dynamics& dynamics, Eigen::VectorXd& q, Eigen::VectorXd& v) {
        Scratch& s = *m_scratch;
        const bool dissipates = dynamics.dissipates();
        if (dissipates) {
            s.q0 = q;
            s.v0 = v;
        }
        m_integrator->step(dynamics, t, h, q, v);
        // What drag and dampers took, before the joints move anything (dissipation.cpp).
        if (dissipates) {
            const Dissipation loss = stepDissipation(dynamics, m_def.integrator, h, s.q0, s.v0, q,
                                                     v, s.meanVelocity, s.midpoint);
            m_dragLoss += loss.drag;
            m_dampingLoss += loss.damping;
        }
        // The force evaluations inside count as the forces stage, not as integration.
        m_profile.ran[static_cast<int>(Stage::Forces)] = true;
        m_profile.ms[static_cast<int>(Stage::Forces)] += dynamics.forceMilliseconds;
        m_profile.ms[static_cast<int>(Stage::Integration)] -= dynamics.forceMilliseconds;
        // Back onto the joints (joints.cpp): SHAKE for symplectic Euler, RATTLE for the others.
        dynamics.projectAfterStep(m_def.integrator, h, q, v, s.shake);
    });
}

void World::integrateDirect()
{
    const double h = m_def.dt;
    const double drag = m_def.drag;
    Scratch& s = *m_scratch;
    const size_t n = m_bodies.size();

    // Forces: each body's applied load (appliedLoad, forces.cpp, the same function the ODE
    // system sums) over its mass and inertia.
    StageTimer forces(m_profile, Stage::Forces);
    s.acceleration.resize(n);
    s.angularAcceleration.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const Body& b = m_bodies[i];
        if (!b.isActive())
            continue;
        const AppliedLoad load = appliedLoad(m_def, b, b.velocity, b.angularVelocity);
        // 0 + F: the sum Dynamics::appliedAccelerations starts from 0 (-0 becomes +0).
        s.acceleration[i] = Vec2(0.0 + load.force.x(), 0.0 + load.force.y()) * b.invMass;
        s.angularAcceleration[i] = (0.0 + load.torque) * b.invInertia;
    }
    forces.stop();

    // Integration: symplectic Euler's update (symplectic_euler.h). Kinematic bodies keep their
    // velocity. Drag's share of the change in kinetic energy, h F_drag . (v0 + v1) / 2, is what it
    // took (dissipation.cpp).
    StageTimer integration(m_profile, Stage::Integration);
    double dragLoss = 0.0;
    ++m_evaluations;
    m_profile.directIntegration = true;
    for (size_t i = 0; i < n; ++i) {
        Body& b = m_bodies[i];
        if (b.type == BodyType::Static || (b.isDynamic() && !b.awake))
            continue;
        const Vec2 a = b.isDynamic() ? s.acceleration[i] : Vec2::Zero();
        const double alpha = b.isDynamic() ? s.angularAcceleration[i] : 0.0;
        const Vec2 v0 = b.velocity;
        const double w0 = b.angularVelocity;
        symplecticEulerUpdate(h, a, b.velocity, b.position);
        symplecticEulerUpdate(h, alpha, b.angularVelocity, b.angle);
        if (drag != 0.0 && b.isDynamic())
            dragLoss += drag * (b.mass * v0.dot(0.5 * (v0 + b.velocity)) +
                                b.inertia * w0 * 0.5 * (w0 + b.angularVelocity));
    }
    m_dragLoss += h * dragLoss;
}

} // namespace rigidlab::physics
