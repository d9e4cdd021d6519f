// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private: what every stage of a step reads and writes, computed once at the start of
// World::step() (after Box2D v3's b2StepContext): the step and the substep with their
// inverses, the soft contact's coefficients, the plan of the step, the settings the stages
// read, the world's parts, the buffers reused from step to step, and the profile. No stage
// reads the world's settings on its own (tests/tools/check_code_shape.py checks that no stage
// file reaches for them through the context). The stages are free functions of this context
// (stages.h).
//
// Nothing in StepScratch is state: a copied world starts with empty buffers (FreshOnCopy)
// and steps exactly as the original (the golden test checks it).

#include "rigidlab/physics/world.h"

#include "broad_phase.h"
#include "contact_solver.h"
#include "dynamics.h"
#include "narrow_phase.h"
#include "soft_solver.h"

#include <Eigen/Core>

#include <chrono>
#include <utility>
#include <vector>

namespace rigidlab::physics {

/// What a step needs, from what the world holds (step_plan.cpp): the stages a scene does not
/// need are left out.
struct StepPlan {
    bool collide = false; ///< some two bodies can collide: broad and narrow phase
    bool direct = false;  ///< symplectic Euler on the bodies, without the ODE state
    bool sleep = false;   ///< islands and sleeping
    bool anyAwake = true; ///< some dynamic body is awake (after wakeIslands())
    /// The soft step (SolverKind::SoftStep).
    bool soft = false;
    /// Springs, pins, gravitation or an integrator other than symplectic Euler: the soft step
    /// lets the integrator carry the smooth motion (soft_step.cpp).
    bool smooth = false;
    int dynamic = 0; ///< dynamic bodies
};

/// An isolated impact of the soft step (soft_impacts.cpp): when, and the exact impulse's
/// velocity changes of the contact's two bodies.
struct IsolatedImpact {
    double fraction = 0;                         ///< of the step before the impact
    Vec2 dvA = Vec2::Zero(), dvB = Vec2::Zero(); ///< [m/s]
    double dwA = 0, dwB = 0;                     ///< [rad/s]
    double impulse[2] = {0, 0};                  ///< normal, per manifold point [N s]
};
/// A body's position, angle and velocities.
struct BodyPose {
    Vec2 position = Vec2::Zero();
    double angle = 0;
    Vec2 velocity = Vec2::Zero();
    double angularVelocity = 0;
};

/// A body's extent about its centre of mass, from its shape (continuous.cpp).
struct BodyExtent {
    double outerRadius = 0; ///< outerRadius(): to its farthest point [m]
    double ownSize = 0;     ///< ownSize(): its smallest width [m]
};

/// The world's buffers reused from step to step.
struct StepScratch {
    BroadPhase broadPhase;
    std::vector<std::pair<int, int>> pairs;
    std::vector<Contact> previous;
    std::vector<ContactAnchors> previousAnchors; ///< previous's, at the same index
    NarrowPhaseCache narrow; ///< saves the narrow phase work, changes no result (narrow_phase.h)
    Eigen::VectorXd q, v;
    Eigen::VectorXd shake; ///< positions before the joint projection (symplectic Euler)
    /// The state at the start of the step, the mean velocity and the midpoint, for the
    /// energy that drag and dampers take (dissipation.cpp).
    Eigen::VectorXd q0, v0, meanVelocity, midpoint;
    std::vector<Vec2> velocityBefore, velocityAtStart;
    std::vector<double> angularVelocityBefore, angularVelocityAtStart;
    ContactSolver solver;
    SoftSolver softSolver;
    /// The soft step's collision phase: each body's velocities at the start of the step, and
    /// how far its bounce moves it back, -f dt dv and -f dt dw (empty: nothing bounced).
    std::vector<Vec2> softVelocity, impactShift;
    std::vector<double> softAngularVelocity, impactTurn;
    /// The soft step's isolated impacts (soft_impacts.cpp): per body, how many contacts it
    /// has; per contact, whether it is solved as one; the impacts, by contact.
    std::vector<int> contactsOf;
    std::vector<char> isolated;
    /// The fast path's search (fast/isolated_pairs.cpp): per contact its two bodies, per body
    /// whether it is alone (does not move, or has one contact and no pin).
    std::vector<std::pair<int, int>> contactPairs;
    std::vector<char> alone;
    std::vector<std::pair<int, IsolatedImpact>> impacts;
    /// The joints whose bodies a contact touched this step, with every joint that shares a
    /// body with them (contact_response.cpp).
    std::vector<PinJointDef> touchedJoints;
    /// Per body, the fraction of the step before its velocity changed in the collision phase.
    std::vector<double> impactFraction;
    /// Some body has restitution this step (else no contact has, and none can bounce).
    bool anyRestitution = true;
    /// Whether some contact may hold a bounce (Contact::bounceImpulse > 0); false only when
    /// none does. Kept where bounces are written or carried (the narrow phase's kept contacts,
    /// the collision phases, the isolated impacts), so that the soft step's collision phase
    /// does not read every contact of the step before for it (soft_step.cpp). True in a fresh
    /// scratch: a copied world's contacts may hold one.
    bool bounceHeld = true;
    bool bounceHeldBefore = true; ///< bounceHeld at the end of the step before (findContacts())
    /// Each body's applied load over its mass and inertia [m/s^2] and [rad/s^2] (the direct
    /// integration's and the soft step's).
    std::vector<Vec2> acceleration;
    std::vector<double> angularAcceleration;
    /// The soft step's smooth motion (StepPlan::smooth, soft_step.cpp): per body, what the
    /// integrator's displacement adds to the substeps' [m/s] and [rad/s], and where the
    /// integrator ended the step (kept by a body no contact touches).
    std::vector<Vec2> drift;
    std::vector<double> angularDrift;
    std::vector<BodyPose> smoothEnd;
    std::vector<char> touched; ///< per body: in a contact, or on a pin a contact touches
    /// Each body's placement at the start of the step, and the pose it was computed for.
    std::vector<Transform> xf;
    std::vector<Vec2> xfPosition;
    std::vector<double> xfAngle;
    /// Per body, its extent (bodyExtents(), continuous.cpp): a body's shape and centre of mass
    /// are set when it is added (World::addBody) and stay, so each body's is computed once,
    /// when the step first sees it, instead of in every step.
    std::vector<BodyExtent> extent;
    /// Islands (islands.cpp): union-find parents and the bodies of each island.
    std::vector<int> islandParent;
    std::vector<int> islandOrder, islandStart;
    std::vector<double> islandRest;
};

/// The step's numbers, the world's parts and the buffers, handed to every stage.
struct StepContext {
    // Computed once per step.
    double dt = 0;    ///< the step [s]
    double invDt = 0; ///< 1 / dt [1/s]
    int substeps = 1; ///< the soft step's substeps (1 for the other solvers)
    double h = 0;     ///< the substep dt / substeps [s]
    double invH = 0;  ///< 1 / h [1/s]
    /// What the integrator makes of a constant acceleration over a step, as a share of dt
    /// times the change of velocity (IntegratorInfo::steadyPush).
    double steadyPush = 1;
    /// The soft contact's coefficients at the substep (soft step only): between two moving
    /// bodies [0], against a body that does not move [1] (twice the frequency).
    Softness softness[2];
    /// Below this approach speed a new contact rests instead of bouncing [m/s]
    /// (restitutionThreshold(), settings.h).
    double restitutionThreshold = 0;
    bool plain = false; ///< EngineSettings::plainPaths: the plain paths of every stage
    StepPlan plan;
    // The world's settings that the stages read, taken once.
    IntegratorKind integratorKind = IntegratorKind::SymplecticEuler;
    SolverKind solver = SolverKind::SoftStep;
    int iterations = 1;      ///< the impulse solvers' and the soft step's bounce sweeps
    bool continuous = false; ///< continuous collision (WorldDef::continuous)
    ForceField field;        ///< gravity, drag and gravitation

    // The world's parts.
    const ContactSettings& contactSettings;
    std::vector<Body>& bodies;
    const std::vector<SpringDef>& springs;
    const std::vector<PinJointDef>& joints;
    std::vector<Contact>& contacts;
    std::vector<ContactAnchors>& contactAnchors; ///< contacts', at the same index (narrow_phase.h)
    const std::vector<BodyId>& moving;           ///< bodies in the ODE state, in id order
    const std::vector<int>& slot;                ///< each body's index in moving, or -1
    const std::vector<std::pair<int, int>>& jointPairs; ///< pinned body pairs, sorted
    std::vector<double>& sweep;                         ///< per body: extra contact margin [m]
    Integrator& integrator;
    double time; ///< at the start of the step [s]
    // What the step adds to the world's totals.
    long long& evaluations;
    double& collisionLoss; ///< [J]
    double& dragLoss;      ///< [J]
    double& dampingLoss;   ///< [J]

    StepScratch& scratch;
    StepProfile& profile;
};

/// Times a stage into the step's profile: the wall time from construction to stop().
class StageTimer {
public:
    using Clock = std::chrono::steady_clock;
    StageTimer(StepProfile& profile, Stage stage)
        : m_profile(profile), m_stage(static_cast<int>(stage)), m_start(Clock::now())
    {
    }
    ~StageTimer() { stop(); }
    StageTimer(const StageTimer&) = delete;
    StageTimer& operator=(const StageTimer&) = delete;
    void stop()
    {
        if (m_stopped)
            return;
        m_stopped = true;
        m_profile.ran[m_stage] = true;
        m_profile.ms[m_stage] +=
            std::chrono::duration<double, std::milli>(Clock::now() - m_start).count();
    }

private:
    StepProfile& m_profile;
    int m_stage;
    Clock::time_point m_start;
    bool m_stopped = false;
};

/// Gathers the moving bodies' state into the ODE vectors, lets `fn(dynamics, q, v)` change
/// it, scatters it back (a body asleep keeps its state). joints: the joints the dynamics
/// holds, when not all of the world's.
template <typename Fn>
inline void withState(StepContext& ctx, Fn&& fn, const std::vector<PinJointDef>* joints = nullptr)
{
    Eigen::VectorXd& q = ctx.scratch.q;
    Eigen::VectorXd& v = ctx.scratch.v;
    gatherState(ctx.bodies, ctx.moving, q, v);
    Dynamics dynamics(ctx.field, ctx.bodies, ctx.slot, ctx.springs, joints ? *joints : ctx.joints);
    fn(dynamics, q, v);
    ctx.evaluations += dynamics.evaluations;
    scatterState(q, v, ctx.moving, Sleepers::Keep, ctx.bodies);
}

} // namespace rigidlab::physics
