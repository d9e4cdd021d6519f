// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Rigid bodies: what a scene defines, and what the world keeps for each.

#include "rigidlab/physics/math.h"
#include "rigidlab/physics/shape.h"

#include <string>

namespace rigidlab::physics {

enum class BodyType {
    Static,    ///< never moves, infinite mass
    Kinematic, ///< moves with its given velocity, unaffected by forces and contacts
    Dynamic,   ///< moved by forces, joints and contacts
};

/// How a body is created. Every field has its default; units as marked.
struct BodyDef {
    std::string name; ///< the scene's id, for traces and messages
    BodyType type = BodyType::Dynamic;
    Shape shape;                  ///< in body coordinates about the body origin
    Vec2 position = Vec2::Zero(); ///< the body origin in the world [m]
    double angle = 0.0;           ///< [rad]
    Vec2 velocity = Vec2::Zero(); ///< of the body origin [m/s]
    double angularVelocity = 0.0; ///< [rad/s]
    double density = 1.0;         ///< [kg/m^2], used when mass <= 0
    double mass = 0.0;            ///< [kg]; > 0 overrides density (inertia scales with it)
    double restitution = -1.0;    ///< coefficient of restitution; < 0 takes the world's
    double friction = -1.0;       ///< Coulomb friction coefficient; < 0 takes the world's
    bool collide = true;          ///< false: passes through everything
};

/// A BodyDef's restitution or friction as the body gets it: its own, or the world's when it
/// has none (< 0). World::addBody and every reader of a scene that predicts the body's motion
/// resolve it here.
inline double resolvedMaterial(double own, double world)
{
    return own >= 0 ? own : world;
}

/// A body as the world keeps it. The state is held at the centre of mass.
///
/// Each step reads every body in several passes (placing it, its forces, the solver's begin
/// and end, the diagnostics, the divergence check), most of them for whether it moves, its
/// state and its mass: those fields come first, in the record's first two cache lines of
/// 64 bytes (the record is aligned to them), and the shape and the name, which fewer passes
/// read, after them. (In declaration order, a pass fetched three or four of the record's
/// five lines for a few bytes of each: 5,050 bodies are 1.45 MB.)
struct alignas(64) Body {
    BodyType type = BodyType::Dynamic;
    /// A dynamic body asleep (false) rests with its island: neither integrated nor solved until
    /// a contact, a force or World::wakeBody wakes it (islands.cpp). Static and kinematic
    /// bodies never sleep.
    bool awake = true;
    bool collide = true;

    double angle = 0.0;           ///< [rad]
    Vec2 position = Vec2::Zero(); ///< centre of mass in the world [m]
    Vec2 velocity = Vec2::Zero(); ///< of the centre of mass [m/s]
    double angularVelocity = 0.0; ///< [rad/s]

    double invMass = 0.0;     ///< [1/kg]
    double invInertia = 0.0;  ///< [1/(kg m^2)]
    double mass = 0.0;        ///< [kg], 0 for static and kinematic bodies
    double inertia = 0.0;     ///< about the centre of mass [kg m^2]
    double restitution = 0.0; ///< resolved against the world's default
    double friction = 0.0;    ///< resolved against the world's default

    /// The paper's accumulators: force and torque applied by the user for the next step,
    /// cleared after it. Force acts at the centre of mass [N], torque [N m].
    double torque = 0.0;
    Vec2 force = Vec2::Zero();

    Vec2 localCenter = Vec2::Zero(); ///< centre of mass in body coordinates [m]
    double sleepTime = 0.0;          ///< how long it has been nearly at rest [s]
    Shape shape;
    std::string name;

    bool isDynamic() const { return type == BodyType::Dynamic; }
    bool moves() const { return type != BodyType::Static; }
    /// Moved by this step's forces and contacts: dynamic and awake.
    bool isActive() const { return type == BodyType::Dynamic && awake; }

    /// Body-to-world placement of the body origin (the frame shape vertices live in).
    Transform transform() const
    {
        Rotation q(angle);
        Transform t;
        t.q = q;
        t.p = position - q.apply(localCenter);
        return t;
    }
    /// The body origin in the world [m].
    Vec2 origin() const { return transform().p; }
    /// Velocity of a world point moving with the body [m/s].
    Vec2 pointVelocity(const Vec2& worldPoint) const
    {
        return velocity + cross(angularVelocity, Vec2(worldPoint - position));
    }
};

} // namespace rigidlab::physics
