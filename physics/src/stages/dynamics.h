// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private: the world's bodies and force elements seen as one ODE system over the state
// (q, v) of the moving bodies. forces.cpp gives the applied forces, joints.cpp the exact
// constraint forces of the pin joints and the projections that remove drift after a step,
// dissipation.cpp what drag and the dampers take.

#include "rigidlab/physics/body.h"
#include "rigidlab/physics/forces.h"
#include "rigidlab/physics/integrator.h"
#include "rigidlab/physics/world.h"

#include <Eigen/Core>

#include <vector>

namespace rigidlab::physics {

/// Pose and velocity of one body, read from a state vector (or from the body when static).
struct BodyState {
    Vec2 x = Vec2::Zero(); ///< centre of mass [m]
    Rotation q;
    Vec2 v = Vec2::Zero(); ///< [m/s]
    double w = 0.0;        ///< [rad/s]
};

/// What the dissipative forces take from the bodies: a power [W], or over a step an energy
/// [J] (dissipation.cpp).
struct Dissipation {
    double drag = 0;    ///< linear drag
    double damping = 0; ///< dampers of springs
};

/// What the force sum reads of the world's settings: its applied fields, taken once per step
/// into the step's context (step_context.h).
struct ForceField {
    Vec2 gravity = Vec2::Zero(); ///< uniform acceleration [m/s^2]
    double drag = 0.0;           ///< linear drag rate [1/s] (WorldDef::drag)
    double gravitation = 0.0;    ///< Newton's constant G between bodies [m^3/(kg s^2)]
};
inline ForceField forceField(const WorldDef& def)
{
    return {def.gravity, def.drag, def.gravitation};
}

/// The applied force and torque on a dynamic body moving at (v, w): gravity, the user's
/// accumulators and linear drag. The ODE system's force sum (forces.cpp) and the direct
/// integration (integration.cpp) both take a body's load from here.
struct AppliedLoad {
    Vec2 force = Vec2::Zero(); ///< [N]
    double torque = 0.0;       ///< [N m]
};
inline AppliedLoad appliedLoad(const ForceField& field, const Body& b, const Vec2& v, double w)
{
    AppliedLoad load{b.mass * field.gravity + b.force, b.torque};
    if (field.drag != 0.0) {
        load.force -= field.drag * b.mass * v;
        load.torque -= field.drag * b.inertia * w;
    }
    return load;
}

/// The power linear drag takes from body b [W] when the drag acts at its velocities (v, w) and
/// the body moves at (u, uw): -(F . u + M uw) with F = -drag m v and M = -drag I w. The force
/// sum's accounting (dissipation.cpp), the direct integration and the soft step all count
/// drag through this one function, so that they take the same bits from the same motion.
inline double dragPower(double drag, const Body& b, const Vec2& v, double w, const Vec2& u,
                        double uw)
{
    return drag * (b.mass * (v.x() * u.x() + v.y() * u.y()) + b.inertia * w * uw);
}

/// The moving bodies' state as the ODE vectors: (x, y, angle) and (vx, vy, w) of each body of
/// `moving`, in that order. World::getState and the stages' withState (step_context.h) both
/// gather it here.
inline void gatherState(const std::vector<Body>& bodies, const std::vector<BodyId>& moving,
                        Eigen::VectorXd& q, Eigen::VectorXd& v)
{
    const Eigen::Index n = 3 * static_cast<Eigen::Index>(moving.size());
    q.resize(n);
    v.resize(n);
    for (size_t s = 0; s < moving.size(); ++s) {
        const Body& b = bodies[static_cast<size_t>(moving[s])];
        const Eigen::Index i = 3 * static_cast<Eigen::Index>(s);
        q.segment<3>(i) << b.position.x(), b.position.y(), b.angle;
        v.segment<3>(i) << b.velocity.x(), b.velocity.y(), b.angularVelocity;
    }
}

/// Whether scatterState writes the state of a dynamic body asleep too.
enum class Sleepers { Write, Keep };
/// Writes the ODE vectors back onto the bodies of `moving` (gatherState's inverse). A step
/// keeps a sleeper's state (Sleepers::Keep): it does not move, whatever the integrator made
/// of it; World::setState writes every body.
inline void scatterState(const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                         const std::vector<BodyId>& moving, Sleepers sleepers,
                         std::vector<Body>& bodies)
{
    for (size_t s = 0; s < moving.size(); ++s) {
        Body& b = bodies[static_cast<size_t>(moving[s])];
        if (sleepers == Sleepers::Keep && b.isDynamic() && !b.awake)
            continue;
        const Eigen::Index i = 3 * static_cast<Eigen::Index>(s);
        b.position = Vec2(q[i], q[i + 1]);
        b.angle = q[i + 2];
        b.velocity = Vec2(v[i], v[i + 1]);
        b.angularVelocity = v[i + 2];
    }
}

/// A body's acceleration from its applied load at its own velocities: (0 + F) / m [m/s^2] and
/// (0 + M) / I [rad/s^2], the sum Dynamics::appliedAccelerations starts from 0 (so -0 becomes
/// +0). The direct integration and the soft step take it from here, so that their symplectic
/// Euler and the integrator's over the state give the same bits.
struct BodyAcceleration {
    Vec2 linear = Vec2::Zero();
    double angular = 0.0;
};
inline BodyAcceleration appliedAcceleration(const ForceField& field, const Body& b)
{
    const AppliedLoad load = appliedLoad(field, b, b.velocity, b.angularVelocity);
    return {Vec2(0.0 + load.force.x(), 0.0 + load.force.y()) * b.invMass,
            (0.0 + load.torque) * b.invInertia};
}

class Dynamics final : public OdeSystem {
public:
    Dynamics(const ForceField& field, const std::vector<Body>& bodies, const std::vector<int>& slot,
             const std::vector<SpringDef>& springs, const std::vector<PinJointDef>& joints)
        : m_field(field), m_bodies(bodies), m_slot(slot), m_springs(springs), m_joints(joints)
    {
    }

    void acceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                      Eigen::VectorXd& a) override;

    /// Applied forces only (gravity, springs, gravitation, drag, accumulators) as
    /// accelerations of the moving bodies.
    void appliedAccelerations(const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                              Eigen::VectorXd& a) const;
    /// Adds the pin joints' constraint forces so that the joints' relative acceleration is 0.
    void addJointAccelerations(const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                               Eigen::VectorXd& a);

    /// After a step: moves positions back onto the joints (Newton iterations on C(q) = 0).
    void projectJointPositions(Eigen::VectorXd& q);
    /// After a step: removes joint-violating velocity (exact, mass-weighted projection).
    void projectJointVelocities(const Eigen::VectorXd& q, Eigen::VectorXd& v);
    /// After the integrator `kind` stepped (q, v) over h: back onto the joints, SHAKE for
    /// symplectic Euler and RATTLE for the others (joints.cpp). `before` is scratch space.
    void projectAfterStep(IntegratorKind kind, double h, Eigen::VectorXd& q, Eigen::VectorXd& v,
                          Eigen::VectorXd& before);

    /// Whether anything dissipates: drag, or a spring with a damper (dissipation.cpp).
    bool dissipates() const;
    /// The power that drag and the dampers, evaluated at (q, v), take from the bodies when
    /// they move at u (dissipation.cpp). Only active (dynamic, awake) bodies count.
    Dissipation dissipation(const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                            const Eigen::VectorXd& u) const;

    BodyState state(BodyId id, const Eigen::VectorXd& q, const Eigen::VectorXd& v) const;
    /// A spring's two ends at (q, v): lever arms, world points and their velocities (an end
    /// on the world stays at its anchor, at rest). The force sum and the damper's accounting
    /// both read the spring through this.
    struct SpringEnds {
        Vec2 rA = Vec2::Zero(), rB = Vec2::Zero(); ///< lever arms [m]
        Vec2 pA = Vec2::Zero(), pB = Vec2::Zero(); ///< world points [m]
        Vec2 vA = Vec2::Zero(), vB = Vec2::Zero(); ///< their velocities [m/s]
    };
    SpringEnds springEnds(const SpringDef& s, const Eigen::VectorXd& q,
                          const Eigen::VectorXd& v) const;
    /// A body-local anchor (origin frame) as a lever arm from the centre of mass, in the world.
    Vec2 lever(BodyId id, const Rotation& rot, const Vec2& localAnchor) const;

    long long evaluations = 0;
    double forceMilliseconds = 0; ///< wall time spent in acceleration() [ms]

private:
    /// Joint j's lever arms and world anchor points at positions q.
    struct JointFrame {
        Vec2 rA = Vec2::Zero(), rB = Vec2::Zero(); ///< lever arms [m]
        Vec2 pA = Vec2::Zero(), pB = Vec2::Zero(); ///< world points [m]
    };
    JointFrame jointFrame(const PinJointDef& j, const Eigen::VectorXd& q) const;
    /// Velocity of the point at lever r of body id (zero for the world and static bodies).
    Vec2 pointVelocity(BodyId id, const Vec2& r, const Eigen::VectorXd& v) const;
    /// Assembles K = J M^-1 J^T for the joints at positions q into m_k and factors it.
    void factorJointMatrix(const std::vector<JointFrame>& frames);
    /// Applies the joint impulses (or forces) lambda to a velocity-like vector.
    void applyJointVector(const std::vector<JointFrame>& frames, const Eigen::VectorXd& lambda,
                          Eigen::VectorXd& out) const;

    ForceField m_field;
    const std::vector<Body>& m_bodies;
    const std::vector<int>& m_slot; ///< state slot of each body, -1 if static
    const std::vector<SpringDef>& m_springs;
    const std::vector<PinJointDef>& m_joints;

    std::vector<JointFrame> m_frames;
    Eigen::MatrixXd m_k;
    Eigen::VectorXd m_rhs, m_lambda;
};

/// The energy drag and the dampers took in one step of the integrator `kind` from (q0, v0)
/// to (q1, v1) [J], their forces weighted as the integrator weighted them (dissipation.cpp).
/// u and qm are scratch space.
Dissipation stepDissipation(const Dynamics& dynamics, IntegratorKind kind, double h,
                            const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
                            const Eigen::VectorXd& q1, const Eigen::VectorXd& v1,
                            Eigen::VectorXd& u, Eigen::VectorXd& qm);

} // namespace rigidlab::physics
