// SPDX-License-Identifier: GPL-3.0-or-later
// Stage::Forces, Stage::Integration and Stage::ContactSolve of the soft step
// (SolverKind::SoftStep, World::Plan::soft): the forces once, at the start of the step, then
// substeps of integration and contact solve (soft_solver.cpp), then restitution.
//
//   for each substep h = dt / substeps:
//       v += h a                  integrate velocities
//       warm start                the contacts' impulses so far
//       solve, with soft bias     pushes overlaps apart, softly
//       x += h v                  integrate positions
//       relax, without bias       takes the push's velocity out again
//   restitution                   bounces from the normal velocities before the step
//
// The energy the contacts took is the kinetic energy their passes removed, measured as the
// sequential-impulse solver measures a resting contact's (dissipation.cpp): from the mean of
// the velocities before and after the substep's forces, so that a box at rest, which the
// forces push down by g h and the contact back up, loses nothing. For a velocity change dv
// against the forces' change h a that is the kinetic energy removed less (h / 2) m a.dv.

#include "rigidlab/physics/world.h"

#include "dynamics.h"
#include "world_scratch.h"

namespace rigidlab::physics {

void World::softStep()
{
    const double h = m_def.dt;
    Scratch& s = *m_scratch;
    const size_t n = m_bodies.size();

    // Forces: each body's applied load (appliedLoad, forces.cpp) over its mass and inertia,
    // held over the substeps as symplectic Euler holds it over the step.
    StageTimer forces(m_profile, Stage::Forces);
    s.acceleration.resize(n);
    s.angularAcceleration.resize(n);
    double dragPower = 0.0; // at the start of the step [W]
    for (size_t i = 0; i < n; ++i) {
        const Body& b = m_bodies[i];
        if (!b.isActive())
            continue;
        const AppliedLoad load = appliedLoad(m_def, b, b.velocity, b.angularVelocity);
        s.acceleration[i] = load.force * b.invMass;
        s.angularAcceleration[i] = load.torque * b.invInertia;
        if (m_def.drag != 0.0)
            dragPower += m_def.drag * (b.mass * b.velocity.squaredNorm() +
                                       b.inertia * b.angularVelocity * b.angularVelocity);
    }
    ++m_evaluations;
    m_profile.directIntegration = true;
    forces.stop();

    SoftSolver& solver = s.softSolver;
    const SoftStepSettings& settings = m_contactSettings.soft;
    {
        StageTimer timer(m_profile, Stage::ContactSolve);
        solver.begin(m_contacts, m_bodies, s.acceleration, s.angularAcceleration, h, settings,
                     restitutionThreshold(m_def, m_contactSettings));
    }
    const bool contacts = solver.constraintCount() > 0;
    double loss = 0.0;
    const double sub = h / settings.substeps; // [s]
    for (int k = 0; k < settings.substeps; ++k) {
        {
            StageTimer timer(m_profile, Stage::Integration);
            solver.integrateVelocities();
        }
        if (contacts) {
            StageTimer timer(m_profile, Stage::ContactSolve);
            loss += solver.kineticEnergy() - 0.5 * sub * solver.loadPower();
            solver.warmStart();
            solver.solve(true);
        }
        {
            StageTimer timer(m_profile, Stage::Integration);
            solver.integratePositions();
        }
        if (contacts) {
            StageTimer timer(m_profile, Stage::ContactSolve);
            solver.solve(false);
            loss -= solver.kineticEnergy() - 0.5 * sub * solver.loadPower();
        }
    }
    {
        StageTimer timer(m_profile, Stage::ContactSolve);
        if (contacts) {
            loss += solver.kineticEnergy();
            solver.applyRestitution();
            loss -= solver.kineticEnergy();
        }
        solver.end(m_bodies);
    }
    m_collisionLoss += loss;
    m_dragLoss += h * dragPower;
    m_profile.solved = solver.constraintCount();
    m_profile.positionPasses = 0;
}

} // namespace rigidlab::physics
