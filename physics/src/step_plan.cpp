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
// Also here: each body's placement for the step, recomputed only for bodies that moved.

#include "rigidlab/physics/world.h"

#include "world_scratch.h"

#include <algorithm>
#include <limits>

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

World::Plan World::planStep() const
{
    Plan plan;
    int collidable = 0, collidableDynamic = 0, dynamic = 0;
    BodyId first = -1, second = -1;
    for (size_t i = 0; i < m_bodies.size(); ++i) {
        const Body& b = m_bodies[i];
        dynamic += b.isDynamic() ? 1 : 0;
        if (!b.collide)
            continue;
        ++collidable;
        collidableDynamic += b.isDynamic() ? 1 : 0;
        (first < 0 ? first : second) = static_cast<BodyId>(i);
    }
    plan.collide = collidableDynamic >= 1 && collidable >= 2;
    if (plan.collide && collidable == 2 &&
        std::binary_search(m_jointPairs.begin(), m_jointPairs.end(), std::pair(first, second)))
        plan.collide = false; // the only two are pinned together
    plan.direct = m_def.integrator == IntegratorKind::SymplecticEuler && m_springs.empty() &&
                  m_joints.empty() && m_def.gravitation == 0.0;
    plan.soft = plan.direct && m_def.solver == SolverKind::SoftStep;
    plan.sleep = m_def.sleep.value_or(dynamic >= kLargeSceneBodies);
    plan.dynamic = dynamic;
    return plan;
}

void World::updateTransforms()
{
    Scratch& s = *m_scratch;
    const size_t n = m_bodies.size();
    if (s.xf.size() != n) {
        s.xf.resize(n);
        // NaN never equals itself: every new entry is computed below.
        s.xfPosition.resize(n, Vec2::Constant(std::numeric_limits<double>::quiet_NaN()));
        s.xfAngle.resize(n, std::numeric_limits<double>::quiet_NaN());
    }
    for (size_t i = 0; i < n; ++i) {
        const Body& b = m_bodies[i];
        if (b.angle == s.xfAngle[i] && b.position == s.xfPosition[i])
            continue; // has not moved: the same transform, without a sine and a cosine
        s.xf[i] = b.transform();
        s.xfAngle[i] = b.angle;
        s.xfPosition[i] = b.position;
    }
}

} // namespace rigidlab::physics
