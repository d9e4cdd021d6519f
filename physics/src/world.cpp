// SPDX-License-Identifier: GPL-3.0-or-later
// World::step(): the stages in the order of physics::Stage (profile.h), which names each
// stage's file. This file only computes the step's context (stages/step_context.h) and calls
// the stages (stages/stages.h); the world is built and changed in world_setup.cpp.

#include "rigidlab/physics/world.h"

#include "cpu_state.h"
#include "stages.h"

#include <cassert>
#include <utility>

namespace rigidlab::physics {

World::World(const WorldDef& def)
    : m_def(def), m_integrator(makeIntegrator(def.integrator, def.tolerances))
{
    assert(withinLimits(def));
}

World::~World() = default;
World::World(const World&) = default;
World& World::operator=(const World&) = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

void World::step()
{
    assert(m_integrator);
    if (m_divergence)
        return; // stopped with a diagnosis; see divergence()
    if (!m_energyStart)
        rememberStartEnergy();
    clearUpperVectorState();
    const auto start = StageTimer::Clock::now();
    m_profile = StepProfile{};
    StepContext ctx = context();
    if (!ctx.plan.sleep)
        m_profile.awake = ctx.plan.dynamic;

    // Stage::BroadPhase, Stage::NarrowPhase: the contacts where the shapes stand now.
    if (ctx.plan.collide) {
        rememberStartVelocities(ctx);
        findContacts(ctx);
        // More pairs than the step's work budget: stopped before anything moves.
        if (stopWhenCrowded())
            return;
    } else {
        m_contacts.clear();
        m_contactAnchors.clear();
    }
    // Stage::Islands: a body touched by an awake one wakes, with everything touching it.
    if (ctx.plan.sleep)
        wakeIslands(ctx);
    if (ctx.plan.soft && ctx.plan.anyAwake) {
        // Stage::Forces, Stage::Integration, Stage::ContactSolve in substeps: the soft step.
        softStep(ctx);
    } else {
        // Stage::Forces, Stage::Integration.
        integrate(ctx);
        // Stage::ContactSolve: impulses on the new velocities, then position correction. (The
        // soft step with every body asleep comes here too: only kinematic bodies move.)
        if (!m_contacts.empty() && ctx.plan.anyAwake)
            solveContacts(ctx);
        // Continuous collision: a bullet whose corner the contacts missed goes back to where
        // it first touches a wall.
        if (ctx.plan.collide && ctx.plan.anyAwake) {
            StageTimer timer(m_profile, Stage::ContactSolve);
            sweepBackBullets(ctx);
        }
    }
    // Stage::Sleep: islands that have rested long enough.
    if (ctx.plan.sleep)
        sleepIslands(ctx);

    for (Body& b : m_bodies) {
        b.force = Vec2::Zero();
        b.torque = 0.0;
    }
    m_time += m_def.dt;
    ++m_steps;
    // Stage::Diagnostics.
    {
        StageTimer timer(m_profile, Stage::Diagnostics);
        updateDiagnostics();
    }
    // After the stages: a non-finite state or runaway energy stops the world.
    checkDivergence();
    m_profile.total =
        std::chrono::duration<double, std::milli>(StageTimer::Clock::now() - start).count();
}

StepContext World::context()
{
    // The plan (step_plan.cpp): contacts only if some two bodies can collide, the direct
    // integration when only contacts couple the bodies, islands when sleeping.
    const bool plain = m_engineSettings.plainPaths;
    const StepPlan plan = planStep(m_def, m_bodies, m_springs, m_joints, m_jointPairs, plain);
    const SoftStepSettings& soft = m_contactSettings.soft;
    const double dt = m_def.dt;
    const int substeps = plan.soft ? soft.substeps : 1;
    const double h = dt / substeps;
    StepContext ctx{.dt = dt,
                    .invDt = 1.0 / dt,
                    .substeps = substeps,
                    .h = h,
                    .invH = 1.0 / h,
                    .steadyPush = integratorInfo(m_def.integrator).steadyPush,
                    .softness = {},
                    .restitutionThreshold = restitutionThreshold(m_def, m_contactSettings),
                    .plain = plain,
                    .plan = plan,
                    .integratorKind = m_def.integrator,
                    .solver = m_def.solver,
                    .iterations = m_def.iterations,
                    .continuous = m_def.continuous,
                    .field = forceField(m_def),
                    .contactSettings = m_contactSettings,
                    .bodies = m_bodies,
                    .springs = m_springs,
                    .joints = m_joints,
                    .contacts = m_contacts,
                    .contactAnchors = m_contactAnchors,
                    .moving = m_moving,
                    .slot = m_slot,
                    .jointPairs = m_jointPairs,
                    .sweep = m_sweep,
                    .integrator = *m_integrator,
                    .time = m_time,
                    .evaluations = m_evaluations,
                    .collisionLoss = m_collisionLoss,
                    .dragLoss = m_dragLoss,
                    .dampingLoss = m_dampingLoss,
                    .scratch = *m_scratch,
                    .profile = m_profile};
    if (plan.soft)
        softContactCoefficients(soft, h, ctx.softness);
    return ctx;
}

} // namespace rigidlab::physics
