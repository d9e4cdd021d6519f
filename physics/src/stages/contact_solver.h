// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private: stage 5 of a step, collision response on the contacts found this step.
//
// The solver works on packed copies of what it needs (velocities, inverse masses, positions)
// and on constraints that hold body indices, not on the bodies themselves: a body is a large
// struct, and the iterations touch every contact ten times a step. The buffers live as long
// as the world's scratch space, so that a step allocates nothing once the scene has settled.

#include "rigidlab/physics/body.h"
#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/world.h"

#include <Eigen/Dense>

#include <algorithm>
#include <vector>

namespace rigidlab::physics {

class ContactSolver {
public:
    /// Takes this step's contacts (and last step's, for what bounced then: not warm started).
    /// Only contacts with an awake dynamic body are solved.
    /// startPosition: each body's centre of mass where the narrow phase found the contacts;
    /// startVelocity / startAngularVelocity: its velocities then, before forces, so that a
    /// bounce can be timed within the step.
    void begin(std::vector<Contact>& contacts, const std::vector<Contact>& previous,
               std::vector<Body>& bodies, const ContactSettings& settings, double dt,
               const std::vector<Vec2>& startPosition, const std::vector<Vec2>& startVelocity,
               const std::vector<double>& startAngularVelocity);

    /// The paper's impulse: one impulse per contact point, in order, with the full denominator
    /// 1/mA + 1/mB + (rA x n)^2/IA + (rB x n)^2/IB and Coulomb friction.
    void solveSeed();

    /// Sequential impulse in two phases (Guendelman, Bridson and Fedkiw, "Nonconvex rigid
    /// bodies with stacking", SIGGRAPH 2003): first the collisions, every contact that closes
    /// within the step and approaches faster than the threshold bouncing from its approach
    /// as it is then, in sweeps until none approaches (solveCollisions()); then the contacts,
    /// warm started with last step's impulses and iterated with e = 0, accumulating and
    /// clamping normal (>= 0) and friction (|t| <= mu n) impulses.
    /// threshold: a new contact approaching slower than this rests instead of bouncing [m/s];
    /// one that pushed in the step before rests below the settings' restitutionThreshold.
    void solveSequential(int iterations, bool warmStart, double threshold);

    /// The collision phase alone, on the velocities as they are (after prepare()): at most
    /// `sweeps` sweeps over the contacts. Each bounce is a pair's own impulse to the target
    /// -e vn from its approach vn at that moment (two points of a manifold together), so that
    /// none adds energy: at e = 1 each keeps it, below 1 each takes some. Returns the sweeps
    /// made. Another solver gets the same targets from restitution.h (closesWithinStep,
    /// impactFraction, bounceVelocity, centreAt, leverArmsAt).
    int solveCollisions(int sweeps);

    /// The collision phase for a solver of its own (the soft step, soft_step.cpp), on bodies
    /// placed where they would end the step without contacts: prepare() as for the sequential
    /// solver, then solveCollisions(sweeps). Writes the velocities to the bodies, each
    /// contact's bounces to Contact::bounceImpulse and what remains of its carried impulses
    /// (prepare(): none where it separates, less last step's bounce) to normalImpulse and
    /// tangentImpulse, the other solver's warm start. Returns whether anything bounced;
    /// impactFractions() then tells when. exempt: per contact, non-zero for a contact solved
    /// elsewhere (the soft step's isolated impacts), which does not bounce here. substep: the
    /// soft step's substep [s]; each bounce is timed on the parabola its substeps move the
    /// bodies on (restitution.h, substepImpactFraction()).
    bool solveCollisionPhase(double threshold, int sweeps, double substep,
                             const std::vector<char>* exempt = nullptr);

    /// Both solvers end by writing the velocities back to the bodies and the accumulated
    /// impulses to the contacts.

    /// Whether any impulse was applied this step.
    bool appliedImpulse() const;
    /// For each body, the fraction of the step that passed before its first bounce (0 when it
    /// rests or was already touching). A velocity change at that moment moves the body by
    /// (1 - fraction) dt times the change by the end of the step.
    const std::vector<double>& impactFractions();

    /// Position correction (non-linear Gauss-Seidel on the separations): at most `passes`
    /// passes, fewer once every contact is within the allowed penetration. Moves the bodies.
    /// Returns the passes made.
    int solvePositions(int passes);

    /// The pin joints that share a body with this step's contacts, solved with them: in every
    /// velocity iteration after the contacts, and in every position pass
    /// (contact_solver_pins.cpp). Set after begin(), before the solve; none by default.
    void setPins(const std::vector<PinJointDef>& pins);

    /// Contacts solved elsewhere this step (non-zero per contact: the isolated impacts solved
    /// exactly, soft_impacts.cpp), left out of the solve and of the position correction. Set
    /// after begin(), before the solve; none by default.
    void leaveOut(const std::vector<char>* contacts) { m_leftOut = contacts; }

    /// Contacts solved this step (those with an awake dynamic body).
    int constraintCount() const { return static_cast<int>(m_constraints.size()); }

private:
    /// What the velocity iterations read and write for one body.
    struct Velocity {
        Vec2 v = Vec2::Zero(); ///< [m/s]
        double w = 0;          ///< [rad/s]
    };
    struct Point {
        Vec2 rA = Vec2::Zero(), rB = Vec2::Zero(); ///< lever arms [m]
        /// The lever arms crossed with the normal and the tangent [m]: the relative normal
        /// velocity is (vB - vA).n + wB rnB - wA rnA, and an impulse j n turns A by
        /// -j rnA / IA. Computed once per step, they make an iteration three times cheaper.
        double rnA = 0, rnB = 0, rtA = 0, rtB = 0;
        double normalMass = 0;     ///< 1 / K along the normal [kg]
        double tangentMass = 0;    ///< 1 / K along the tangent [kg]
        double bias = 0;           ///< target normal velocity [m/s]
        double normalImpulse = 0;  ///< accumulated [N s]
        double tangentImpulse = 0; ///< accumulated [N s]
        double impact = 0;         ///< fraction of the step before a bounce, 0 if no bounce
        bool closes = false;       ///< touching, or the gap closes within this step
        bool bounces = false;      ///< bias is a bounce (restitution) target
        double vnPrepared = 0;     ///< normal velocity the bias was computed from [m/s]
        double speculative = 0;    ///< the least target a gap allows: -separation / dt [m/s]
        double separation = 0;     ///< at the start of the step [m]
        double threshold = 0;      ///< approaches slower than this do not bounce [m/s]
        /// What the forces of the step add to the normal velocity (vn - vn at the start)
        /// [m/s]: a bounce at the fraction f keeps (1 - f) of it after the impact.
        double forcing = 0;
        double bounceImpulse = 0;  ///< of the collision phase, accumulated [N s]
        double warmNormal = 0;     ///< last step's normal impulse, the warm start [N s]
        double warmTangent = 0;    ///< last step's tangent impulse, the warm start [N s]
        bool timed = false;        ///< lever arms placed at the moment of impact
        Vec2 point = Vec2::Zero(); ///< the manifold's point at the start of the step [m]
    };
    struct Constraint {
        int contact = 0;
        int a = 0, b = 0; ///< body indices
        double invMassA = 0, invIA = 0, invMassB = 0, invIB = 0;
        double friction = 0;
        double restitution = 0;
        Vec2 normal = Vec2::Zero();
        Vec2 tangent = Vec2::Zero();
        int count = 0;
        bool block = false; ///< two points solved together
        Point p[2];
        /// The 2x2 normal mass matrix K and its inverse (block solver).
        double k11 = 0, k12 = 0, k22 = 0, m11 = 0, m12 = 0, m22 = 0;
    };
    /// Approaches slower than `impact` do not bounce [m/s], nor, at a point that pushed in the
    /// step before (a resting contact), slower than `resting`.
    void prepare(double impact, double resting);
    /// Point i of constraint c from the contact's point: lever arms, masses, the target
    /// normal velocity, whether it closes within the step and may bounce.
    void preparePoint(Constraint& c, int i, const Contact& ct, double impact, double resting);
    /// The bouncing points' lever arms at the moment of impact and their bounce velocity.
    void prepareBounces(Constraint& c, const Contact& ct);
    /// The collision phase's share of what point `id` of `ct` carried from last step [N s]
    /// (last step's contacts walked with m_previousCursor, in pair order).
    double lastBounce(const Contact& ct, std::uint32_t id);
    /// Applies the warm start impulses (warmNormal, warmTangent).
    void warmStart();
    /// Lever arms of point i from the centres at the fraction f of the step, about one point
    /// both bodies share then (see placeAt in the .cpp), and what depends on them.
    void placeAt(Constraint& c, int i, double f);
    /// The 2x2 normal mass matrix of a two-point manifold, and whether it is solved as a block.
    static void prepareBlock(Constraint& c);
    /// Whether point i bounces now, at the velocities a and b: it closes within the step and
    /// approaches faster than its threshold. Sets its target normal velocity [m/s]; times the
    /// impact (and places the lever arms there) when the gap closes within the step.
    bool bounceTarget(Constraint& c, int i, const Velocity& a, const Velocity& b, double& target);
    /// The 2x2 complementarity problem of a block: x >= 0, w = K x + b >= 0, x.w = 0.
    static bool solveBlock(const Constraint& c, double b1, double b2, double x[2]);
    /// The normal velocity of point i at the start of the step, before forces [m/s].
    double startNormalVelocity(const Constraint& c, int i) const;
    /// Lever arms crossed with the normal and tangent, and the effective masses, of point i.
    static void setMasses(Constraint& c, int i);
    static void applyNormal(Constraint& c, int i, double lambda, Velocity& a, Velocity& b);
    static void solveFrictionPoint(Constraint& c, int i, Velocity& a, Velocity& b);
    static void solveNormalPoint(Constraint& c, int i, Velocity& a, Velocity& b);
    static void solveNormalBlock(Constraint& c, Velocity& a, Velocity& b);
    static double normalVelocity(const Constraint& c, int i, const Velocity& a, const Velocity& b);
    /// A pin joint as the solver sees it: body indices (-1 for the world), lever arms and
    /// the inverse of its 2x2 mass matrix, and its accumulated impulse (on A; -impulse on B).
    struct Pin {
        int a = -1, b = -1;
        Vec2 anchorA = Vec2::Zero(), anchorB = Vec2::Zero(); ///< from the centres, body frame
        double invMassA = 0, invIA = 0, invMassB = 0, invIB = 0;
        Vec2 rA = Vec2::Zero(), rB = Vec2::Zero(); ///< lever arms in the world [m]
        Eigen::Matrix2d mass = Eigen::Matrix2d::Zero();
        Vec2 impulse = Vec2::Zero(); ///< accumulated this step [N s]
    };
    /// Lever arms and mass matrix of each pin at the bodies' present angles.
    void preparePins();
    /// One Gauss-Seidel pass over the pins' velocity constraints.
    void solvePins();
    /// One pass of position corrections onto the pins (the bodies move).
    void solvePinPositions();
    /// Velocities and impulses back to the bodies and contacts.
    void store();
    /// The solver's velocities back to the bodies (the first half of store()).
    void storeVelocities();
    /// The body's rotation, computed once per epoch (see newRotationEpoch()).
    const Rotation& rotation(int body);
    /// Forgets every rotation computed so far (the bodies have turned).
    void newRotationEpoch();

    std::vector<Contact>* m_contacts = nullptr;
    const std::vector<Contact>* m_previous = nullptr;
    size_t m_previousCursor = 0; ///< in *m_previous, while prepare() walks the contacts
    std::vector<Body>* m_bodies = nullptr;
    const ContactSettings* m_settings = nullptr;
    double m_dt = 0;
    const std::vector<Vec2>* m_startPosition = nullptr;
    const std::vector<Vec2>* m_startVelocity = nullptr;
    const std::vector<double>* m_startAngularVelocity = nullptr;

    std::vector<Constraint> m_constraints;
    std::vector<Pin> m_pins;
    std::vector<Velocity> m_velocity; ///< per body
    std::vector<double> m_impact;     ///< per body, see impactFractions()
    std::vector<Rotation> m_rotation; ///< per body, valid where m_rotationStamp == m_stamp
    bool m_paperImpulse = false;      ///< this step's solver is the paper's impulse
    /// The soft step's collision phase (solveCollisionPhase()): a point timed within the step
    /// bounces even if its arms at the impact slow its approach below closing, and a gap
    /// that closes exactly at the end of the step bounces too (bounceTarget()).
    bool m_softPhase = false;
    double m_substep = 0; ///< the soft step's substep, in its collision phase [s]
    const std::vector<char>* m_exempt = nullptr;  ///< see solveCollisionPhase()
    const std::vector<char>* m_leftOut = nullptr; ///< see leaveOut()
    std::vector<unsigned> m_rotationStamp;
    unsigned m_stamp = 0;
};

// The iteration's helpers are inlined into the loop, so that the two bodies' velocities stay
// in registers for a whole constraint.
[[gnu::always_inline]] inline double
ContactSolver::normalVelocity(const Constraint& c, int i, const Velocity& a, const Velocity& b)
{
    const Point& p = c.p[i];
    return (b.v - a.v).dot(c.normal) + b.w * p.rnB - a.w * p.rnA;
}

[[gnu::always_inline]] inline void ContactSolver::solveFrictionPoint(Constraint& c, int i,
                                                                     Velocity& a, Velocity& b)
{
    Point& p = c.p[i];
    const double vt = (b.v - a.v).dot(c.tangent) + b.w * p.rtB - a.w * p.rtA;
    const double limit = c.friction * (p.normalImpulse + p.bounceImpulse);
    const double next = std::clamp(p.tangentImpulse - p.tangentMass * vt, -limit, limit);
    const double lambda = next - p.tangentImpulse;
    p.tangentImpulse = next;
    a.v -= (c.invMassA * lambda) * c.tangent;
    a.w -= c.invIA * lambda * p.rtA;
    b.v += (c.invMassB * lambda) * c.tangent;
    b.w += c.invIB * lambda * p.rtB;
}

[[gnu::always_inline]] inline void ContactSolver::solveNormalPoint(Constraint& c, int i,
                                                                   Velocity& a, Velocity& b)
{
    Point& p = c.p[i];
    const double vn = normalVelocity(c, i, a, b);
    const double next = std::max(p.normalImpulse - p.normalMass * (vn - p.bias), 0.0);
    const double lambda = next - p.normalImpulse;
    p.normalImpulse = next;
    a.v -= (c.invMassA * lambda) * c.normal;
    a.w -= c.invIA * lambda * p.rnA;
    b.v += (c.invMassB * lambda) * c.normal;
    b.w += c.invIB * lambda * p.rnB;
}

} // namespace rigidlab::physics
