// SPDX-License-Identifier: GPL-3.0-or-later
// World::step(): the stages in the order of physics::Stage (profile.h), which names each
// stage's file. This file only calls them; the world is built and changed in world_setup.cpp.

#include "rigidlab/physics/world.h"

#include "cpu_state.h"
#include "narrow_phase.h"
#include "world_scratch.h"

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
    // The plan (step_plan.cpp): contacts only if some two bodies can collide, the direct
    // integration when only contacts couple the bodies, islands when sleeping.
    m_plan = planStep();
    if (!m_plan.sleep)
        m_profile.awake = m_plan.dynamic;

    // Stage::BroadPhase, Stage::NarrowPhase: the contacts where the shapes stand now.
    if (m_plan.collide) {
        rememberStartVelocities();
        findContacts();
    } else {
        m_contacts.clear();
    }
    // Stage::Islands: a body touched by an awake one wakes, with everything touching it.
    if (m_plan.sleep)
        wakeIslands();
    if (m_plan.soft) {
        // Stage::Forces, Stage::Integration, Stage::ContactSolve in substeps: the soft step.
        softStep();
    } else {
        // Stage::Forces, Stage::Integration.
        integrate();
        // Stage::ContactSolve: impulses on the new velocities, then position correction.
        if (!m_contacts.empty() && m_plan.anyAwake)
            solveContacts();
    }
    // Stage::Sleep: islands that have rested long enough.
    if (m_plan.sleep)
        sleepIslands();

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

void World::findContacts()
{
    Scratch& s = *m_scratch;
    std::swap(s.previous, m_contacts);
    m_contacts.clear();
    const double margin = m_contactSettings.margin;

    StageTimer broad(m_profile, Stage::BroadPhase);
    updateTransforms();
    s.broadPhase.findPairs(m_bodies, s.xf, margin, m_def.dt, m_jointPairs, s.pairs);
    // Fast bodies: pairs and margins over their motion in this step (continuous collision).
    addSweptPairs(s.pairs);
    broad.stop();
    m_profile.pairs = static_cast<int>(s.pairs.size());

    StageTimer narrow(m_profile, Stage::NarrowPhase);
    s.narrow.reuseFaces = m_contactSettings.reuseFaces;
    narrowPhase(m_bodies, s.xf, s.pairs, margin, m_sweep, s.previous, s.narrow, m_contacts);
    m_profile.contacts = static_cast<int>(m_contacts.size());
    m_profile.reusedFaces = s.narrow.reused;
}

} // namespace rigidlab::physics
