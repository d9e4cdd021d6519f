// SPDX-License-Identifier: GPL-3.0-or-later
// Stage::ContactSolve (profile.h): the contact solver (contact_solver.cpp) on this step's
// contacts, then what its impulses mean for the rest of the step: the positions moved by the
// change of velocity, the joints' velocities and positions projected back (joints.cpp), and
// the energy the contacts took (dissipation.cpp).

#include "rigidlab/physics/world.h"

#include "diagnostics_compute.h"
#include "dynamics.h"
#include "world_scratch.h"

#include <algorithm>

namespace rigidlab::physics {

void World::rememberStartVelocities()
{
    Scratch& s = *m_scratch;
    s.velocityAtStart.resize(m_bodies.size());
    s.angularVelocityAtStart.resize(m_bodies.size());
    for (size_t i = 0; i < m_bodies.size(); ++i) {
        s.velocityAtStart[i] = m_bodies[i].velocity;
        s.angularVelocityAtStart[i] = m_bodies[i].angularVelocity;
    }
}

double restitutionThreshold(const WorldDef& def, const ContactSettings& settings)
{
    constexpr double kFloor = 0.01; // [m/s]
    return std::min(settings.restitutionThreshold,
                    std::max(kFloor, 2.0 * def.gravity.norm() * def.dt));
}

void World::solveContacts()
{
    if (m_contacts.empty())
        return;
    StageTimer timer(m_profile, Stage::ContactSolve);
    Scratch& s = *m_scratch;
    const double h = m_def.dt;
    s.velocityBefore.resize(m_bodies.size());
    s.angularVelocityBefore.resize(m_bodies.size());
    for (size_t i = 0; i < m_bodies.size(); ++i) {
        s.velocityBefore[i] = m_bodies[i].velocity;
        s.angularVelocityBefore[i] = m_bodies[i].angularVelocity;
    }
    ContactSolver& solver = s.solver;
    solver.begin(m_contacts, s.previous, m_bodies, m_contactSettings, h, s.xfPosition,
                 s.velocityAtStart, s.angularVelocityAtStart);
    if (m_def.solver == SolverKind::SeedImpulse)
        solver.solveSeed();
    else
        solver.solveSequential(m_def.iterations, true,
                               restitutionThreshold(m_def, m_contactSettings));

    // A resting contact's impulse changes the velocity for the whole step, so the position
    // moves by dt times the change (for symplectic Euler exactly Box2D's order: solve the
    // velocities, then integrate the positions). A bounce timed at the fraction f of the step
    // moves it by (1 - f) dt times the change.
    const std::vector<double>& impact = solver.impactFractions();
    for (size_t i = 0; i < m_bodies.size(); ++i) {
        Body& b = m_bodies[i];
        if (!b.isActive())
            continue;
        const double after = (1.0 - impact[i]) * h;
        b.position += after * (b.velocity - s.velocityBefore[i]);
        b.angle += after * (b.angularVelocity - s.angularVelocityBefore[i]);
    }
    // Impulses on jointed bodies may push along a joint: take that velocity out again.
    if (!m_joints.empty() && solver.appliedImpulse())
        withState([](Dynamics& d, Eigen::VectorXd& q, Eigen::VectorXd& v) {
            d.projectJointVelocities(q, v);
        });
    // What the contacts took (dissipation.cpp): friction and inelastic bounces.
    m_collisionLoss += contactLoss(m_bodies, s.velocityAtStart, s.angularVelocityAtStart,
                                   s.velocityBefore, s.angularVelocityBefore, impact);

    m_profile.solved = solver.constraintCount();
    m_profile.positionPasses = solver.solvePositions(m_contactSettings.positionIterations);
    if (!m_joints.empty())
        withState(
            [](Dynamics& d, Eigen::VectorXd& q, Eigen::VectorXd&) { d.projectJointPositions(q); });
}

} // namespace rigidlab::physics
