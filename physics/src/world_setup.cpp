// SPDX-License-Identifier: GPL-3.0-or-later
// Building a world and changing it between steps: bodies, springs and joints, the settings,
// and a body's pose, velocity and mass. Each setter asserts its own preconditions: the ranges
// of limits.h, which the callers (a scene file, a typed value) check before with a message.

#include "rigidlab/physics/limits.h"
#include "rigidlab/physics/world.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace rigidlab::physics {

bool withinLimits(const WorldDef& def)
{
    return limits::kGravity.contains(def.gravity.x()) &&
           limits::kGravity.contains(def.gravity.y()) && limits::kDt.contains(def.dt) &&
           limits::kIterations.contains(def.iterations) &&
           limits::kRestitution.contains(def.restitution) &&
           limits::kFriction.contains(def.friction) &&
           limits::kGravitation.contains(def.gravitation) && limits::kDrag.contains(def.drag);
}

BodyId World::addBody(const BodyDef& def)
{
    Body b;
    b.name = def.name;
    b.type = def.type;
    b.shape = def.shape;
    b.collide = def.collide;
    b.restitution = resolvedMaterial(def.restitution, m_def.restitution);
    b.friction = resolvedMaterial(def.friction, m_def.friction);

    const MassProperties mp = computeMass(def.shape, def.mass > 0 ? 1.0 : def.density);
    b.localCenter = mp.centroid;
    if (def.type == BodyType::Dynamic) {
        // A given mass keeps the shape's distribution: inertia scales with it.
        const double scale = def.mass > 0 ? def.mass / mp.mass : 1.0;
        b.mass = mp.mass * scale;
        b.inertia = mp.inertia * scale;
        b.invMass = b.mass > 0 ? 1.0 / b.mass : 0.0;
        b.invInertia = b.inertia > 0 ? 1.0 / b.inertia : 0.0;
    }
    const BodyId id = static_cast<BodyId>(m_bodies.size());
    m_bodies.push_back(std::move(b));
    setBodyOrigin(id, def.position, def.angle);
    setBodyVelocity(id, def.velocity, def.angularVelocity);

    m_slot.push_back(-1);
    if (def.type != BodyType::Static) {
        m_slot.back() = static_cast<int>(m_moving.size());
        m_moving.push_back(id);
    }
    return id;
}

void World::addSpring(const SpringDef& spring)
{
    m_springs.push_back(spring);
}

void World::addPinJoint(const PinJointDef& joint)
{
    m_joints.push_back(joint);
    if (joint.a != kWorld && joint.b != kWorld) {
        m_jointPairs.push_back(std::minmax(joint.a, joint.b));
        std::sort(m_jointPairs.begin(), m_jointPairs.end());
    }
}

void World::setDt(double dt)
{
    assert(limits::kDt.contains(dt));
    m_def.dt = dt;
}

void World::setIntegrator(IntegratorKind kind)
{
    m_def.integrator = kind;
    m_integrator = ClonePtr<Integrator>(makeIntegrator(kind, m_def.tolerances));
}

void World::setIterations(int n)
{
    assert(limits::kIterations.contains(n));
    m_def.iterations = n;
}

void World::setTolerances(const Tolerances& tolerances)
{
    // Positive and finite: the error's scale is absolute + relative |y|. Files and fields
    // accept limits::kTolerance only, but a test of the method may want looser ones.
    assert(tolerances.absolute > 0 && tolerances.relative > 0 &&
           std::isfinite(tolerances.absolute) && std::isfinite(tolerances.relative));
    m_def.tolerances = tolerances;
    m_integrator->setTolerances(tolerances);
}

void World::setGravity(const Vec2& g)
{
    assert(limits::kGravity.contains(g.x()) && limits::kGravity.contains(g.y()));
    m_def.gravity = g;
    wakeAll();
}

void World::setRestitution(double e)
{
    assert(limits::kRestitution.contains(e));
    m_def.restitution = e;
    for (Body& b : m_bodies)
        b.restitution = e;
    wakeAll();
}

void World::setFriction(double mu)
{
    assert(limits::kFriction.contains(mu));
    m_def.friction = mu;
    for (Body& b : m_bodies)
        b.friction = mu;
    wakeAll();
}

void World::setBodyOrigin(BodyId id, const Vec2& origin, double angle)
{
    assert(limits::kCoordinate.contains(origin.x()) && limits::kCoordinate.contains(origin.y()) &&
           limits::kAngle.contains(angle));
    Body& b = mutableBody(id);
    b.angle = angle;
    b.position = origin + Rotation(angle).apply(b.localCenter);
    wakeBody(id);
}

void World::setBodyVelocity(BodyId id, const Vec2& originVelocity, double angularVelocity)
{
    assert(limits::kVelocity.contains(originVelocity.x()) &&
           limits::kVelocity.contains(originVelocity.y()) &&
           limits::kAngularVelocity.contains(angularVelocity));
    Body& b = mutableBody(id);
    b.angularVelocity = angularVelocity;
    b.velocity = originVelocity + cross(angularVelocity, Vec2(b.position - b.origin()));
    wakeBody(id);
}

bool World::setBodyMass(BodyId id, double mass)
{
    if (id < 0 || id >= static_cast<BodyId>(m_bodies.size()) || !(mass > 0) || !std::isfinite(mass))
        return false;
    Body& b = mutableBody(id);
    if (!b.isDynamic() || !(b.mass > 0))
        return false;
    // I = m k² for a fixed shape: the radius of gyration k does not depend on the mass.
    const double scale = mass / b.mass;
    b.mass = mass;
    b.invMass = 1.0 / mass;
    b.inertia *= scale;
    b.invInertia = b.inertia > 0 ? 1.0 / b.inertia : 0.0;
    // The energy changed by hand, not by the integrator: the divergence check measures growth
    // from the energy the next step starts with.
    m_energyStart.reset();
    wakeBody(id);
    return true;
}

void World::setBodyMaterial(BodyId id, double restitution, double friction)
{
    assert(limits::kRestitution.contains(restitution) && limits::kFriction.contains(friction));
    Body& b = mutableBody(id);
    b.restitution = restitution;
    b.friction = friction;
    wakeBody(id);
}

void World::setBodyAngle(BodyId id, double angle)
{
    assert(limits::kAngle.contains(angle));
    mutableBody(id).angle = angle; // the state is held at the centre of mass: it stays
    wakeBody(id);
}

void World::applyForce(BodyId id, const Vec2& force, double torque)
{
    assert(std::isfinite(force.x()) && std::isfinite(force.y()) && std::isfinite(torque));
    Body& b = mutableBody(id);
    b.force += force;
    b.torque += torque;
    wakeBody(id);
}

Vec2 World::originVelocity(BodyId id) const
{
    const Body& b = body(id);
    return b.pointVelocity(b.origin());
}

// Sleeping (islands.cpp does the islands).

bool World::sleepEnabled() const
{
    if (m_def.sleep)
        return *m_def.sleep;
    const auto dynamic = std::count_if(m_bodies.begin(), m_bodies.end(),
                                       [](const Body& b) { return b.isDynamic(); });
    return dynamic >= kLargeSceneBodies;
}

void World::setSleep(std::optional<bool> on)
{
    m_def.sleep = on;
    if (!sleepEnabled())
        wakeAll();
}

void World::wakeBody(BodyId id)
{
    Body& b = mutableBody(id);
    b.awake = true;
    b.sleepTime = 0.0;
}

void World::wakeAll()
{
    for (Body& b : m_bodies) {
        b.awake = true;
        b.sleepTime = 0.0;
    }
}

} // namespace rigidlab::physics
