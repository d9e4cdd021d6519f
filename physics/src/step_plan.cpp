// SPDX-License-Identifier: GPL-3.0-or-later
// A step built from what the world holds: the stages a scene does not need are left out.
//
//   - Contacts (broad and narrow phase, the contact solver) only when some two bodies can
//     collide: one of them dynamic, neither with collide == false, not the two ends of a pin.
//     A pendulum never looks for contacts.
//   - Springs and gravitation are passes of the force evaluation that run only when the
//     world has springs, or G != 0 (forces.cpp).
//   - Static bodies are never integrated; bodies asleep are neither integrated nor solved.
//   - Symplectic Euler with nothing but contacts coupling the bodies (no springs, joints or
//     gravitation) is done straight on the bodies (integration.cpp): the same update on the
//     same forces as the integrator over the ODE system, without gathering the state into
//     vectors and scattering it back.
// Also here: each body's placement for the step, the plain path (every body anew); the fast
// one recomputes only the bodies that moved (fast/body_placement.cpp).

#include "rigidlab/physics/world.h"

#include "stages.h"

#include <algorithm>

namespace rigidlab::physics {

const char* stageName(Stage s)
{
    switch (s) {
    case Stage::BroadPhase:
        return "broad phase";
    case Stage::NarrowPhase:
        return "narrow phase";
    case Stage::Islands:
        return "islands";
    case Stage::Forces:
        return "forces";
    case Stage::Integration:
        return "integration";
    case Stage::ContactSolve:
        return "contact solve";
    case Stage::Sleep:
        return "sleep";
    case Stage::Diagnostics:
        return "diagnostics";
    }
    return "?";
}

StepPlan planStep(const WorldDef& def, const std::vector<Body>& bodies,
                  const std::vector<SpringDef>& springs, const std::vector<PinJointDef>& joints,
                  const std::vector<std::pair<int, int>>& jointPairs, bool plain)
{
    StepPlan plan;
    int collidable = 0, collidableDynamic = 0, dynamic = 0;
    BodyId first = -1, second = -1;
    for (size_t i = 0; i < bodies.size(); ++i) {
        const Body& b = bodies[i];
        dynamic += b.isDynamic() ? 1 : 0;
        if (!b.collide)
            continue;
        ++collidable;
        collidableDynamic += b.isDynamic() ? 1 : 0;
        (first < 0 ? first : second) = static_cast<BodyId>(i);
    }
    plan.collide = collidableDynamic >= 1 && collidable >= 2;
    if (plan.collide && collidable == 2 &&
        std::binary_search(jointPairs.begin(), jointPairs.end(), std::pair(first, second)))
        plan.collide = false; // the only two are pinned together
    // Symplectic Euler with only contacts coupling the bodies: it can run straight on the
    // bodies (fast/integrate_direct.cpp; the plain path takes the integrator), and the soft
    // step's substeps are all of its motion. Otherwise the soft step lets the integrator move
    // the bodies first (StepPlan::smooth).
    const bool contactsOnly = def.integrator == IntegratorKind::SymplecticEuler &&
                              springs.empty() && joints.empty() && def.gravitation == 0.0;
    plan.soft = def.solver == SolverKind::SoftStep;
    plan.smooth = !contactsOnly;
    plan.direct = contactsOnly && !plain;
    plan.sleep = def.sleep.value_or(dynamic >= kLargeSceneBodies);
    plan.dynamic = dynamic;
    return plan;
}

void placeBodies(StepContext& ctx)
{
    StepScratch& s = ctx.scratch;
    const size_t n = ctx.bodies.size();
    s.xf.resize(n);
    s.xfPosition.resize(n);
    s.xfAngle.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const Body& b = ctx.bodies[i];
        s.xf[i] = b.transform();
        s.xfAngle[i] = b.angle;
        s.xfPosition[i] = b.position;
    }
}

} // namespace rigidlab::physics
