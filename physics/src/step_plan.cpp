// A step built from what the world holds: the stages a scene does not need are left out.
//
//   - Contacts (broad and narrow phase, the contact solver) only when some two bodies can
//     collide: one of them dynamic, neither with collide == false, not the two ends of a pin.
//     A pendulum never looks for contacts.
//   - Springs and gravitation are passes of the force evaluation that run only when the
//     world has springs, or G != 0 (forces.cpp).
//   - Static bodies are never integrated; bodies asleep are neither integrated nor solved.
//   - Symplectic Euler with nothing but contacts coupling the bodies (no springs, joints or
//     gravitation) is done straight on the bodies: the same arithmetic as the integrator over
//     the ODE system, without gathering the state into vectors and scattering it back.

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

void World::integrateDirect()
{
    const double h = m_def.dt;
    const Vec2 g = m_def.gravity;
    const double drag = m_def.drag;
    Scratch& s = *m_scratch;
    const size_t n = m_bodies.size();

    // Forces: a = (m g + F) / m and alpha = M / I, with drag -drag m v and -drag I w, in the
    // order Dynamics::appliedAccelerations adds them up (so that the bits are the same).
    StageTimer forces(m_profile, Stage::Forces);
    s.acceleration.resize(n);
    s.angularAcceleration.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const Body& b = m_bodies[i];
        if (!b.isActive())
            continue;
        Vec2 f = b.mass * g + b.force;
        double torque = b.torque;
        if (drag != 0.0) {
            f -= drag * b.mass * b.velocity;
            torque -= drag * b.inertia * b.angularVelocity;
        }
        s.acceleration[i] = Vec2(0.0 + f.x(), 0.0 + f.y()) * b.invMass;
        s.angularAcceleration[i] = (0.0 + torque) * b.invInertia;
    }
    forces.stop();

    // Integration: v1 = v0 + h a, then x1 = x0 + h v1. Kinematic bodies keep their velocity.
    // Drag's share of the change in kinetic energy, h F_drag . (v0 + v1) / 2, is what it took
    // (dissipation.cpp).
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
        b.velocity = b.velocity + h * a;
        b.angularVelocity = b.angularVelocity + h * alpha;
        if (drag != 0.0 && b.isDynamic())
            dragLoss += drag * (b.mass * v0.dot(0.5 * (v0 + b.velocity)) +
                                b.inertia * w0 * 0.5 * (w0 + b.angularVelocity));
        b.position = b.position + h * b.velocity;
        b.angle = b.angle + h * b.angularVelocity;
    }
    m_dragLoss += h * dragLoss;
}

void World::setGravity(const Vec2& g)
{
    m_def.gravity = g;
    wakeAll();
}

void World::setGravitation(double G)
{
    m_def.gravitation = G;
    wakeAll();
}

void World::setDrag(double drag)
{
    m_def.drag = drag;
    wakeAll();
}

} // namespace rigidlab::physics
