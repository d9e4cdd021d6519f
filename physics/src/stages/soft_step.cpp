// SPDX-License-Identifier: GPL-3.0-or-later
// Stage::Forces, Stage::Integration and Stage::ContactSolve of the soft step
// (SolverKind::SoftStep, StepPlan::soft): the forces once, at the start of the step, then
// the collision phase, then substeps of integration and contact solve (soft_solver.cpp).
//
//   collisions                    isolated impacts exactly at their moment (soft_impacts.cpp),
//                                 the other bounces as the sequential solver's collision phase
//   for each substep h = dt / substeps:
//       v += h a                  integrate velocities
//       warm start                the contacts' impulses so far
//       solve, with soft bias     pushes overlaps apart, softly
//       x += h v                  integrate positions
//       relax, without bias       takes the push's velocity out again
//   sweep back                    a bullet to where it first touches a wall (soft_continuous.cpp)
//
// Bounces come first, from the sequential solver's collision phase (contact_collisions.cpp,
// restitution.h), on the bodies as they would end the step without contacts: each contact
// that closes within the step bounces from the approach it has when a sweep meets it, with
// the lever arms at the moment of impact. The substeps then move the bodies on with the
// bounced velocities, and each bounced body is moved back by f dt times its change, as if it
// had flown on until the impact at the fraction f of the step. The last relax pass leaves
// gaps alone: a pair that closes its gap only in the next step bounces then, in that step's
// collision phase, instead of being stopped short of touching. (With a restitution pass
// after the substeps from the normal velocities before the step, Box2D v3's, a ball that
// bounced off a wall into a neighbour a few millimetres behind it did not bounce off that
// one, and an elastic gas of 300 balls lost 7 % of its energy in 10 s.)
//
// The energy the contacts took is the kinetic energy their passes removed, measured as the
// sequential-impulse solver measures a resting contact's (dissipation.cpp): from the mean of
// the velocities before and after the substep's forces, so that a box at rest, which the
// forces push down by g h and the contact back up, loses nothing. For a velocity change dv
// against the forces' change h a that is the kinetic energy removed less (h / 2) m a.dv.
// A bounce's is measured at the velocities of its moment.

#include "rigidlab/physics/world.h"

#include "dynamics.h"
#include "restitution.h"
#include "stages.h"

#include <tuple>

namespace rigidlab::physics {

namespace {

/// Whether the collision phase has work: a contact point with restitution that closes within
/// the step and approaches faster than `threshold` [m/s] at the velocities the forces give it
/// (only then can a sweep bounce anything), or a contact that bounced in the step before (its
/// carried impulse holds the bounce, which must not warm start the substeps). A contact
/// without restitution only stops its approach, as the substeps' speculative contact does;
/// in a pyramid of 5050 boxes one such contact somewhere made every step pay for the phase.
bool collisionsToSolve(const std::vector<Contact>& contacts, const std::vector<Contact>& previous,
                       const std::vector<Body>& bodies, const std::vector<Vec2>& acceleration,
                       const std::vector<double>& angularAcceleration, double dt, double threshold,
                       bool anyRestitution)
{
    for (const Contact& ct : previous)
        if (ct.bounceImpulse[0] > 0 || ct.bounceImpulse[1] > 0)
            return true;
    if (!anyRestitution) // a contact's restitution is the larger of its two bodies'
        return false;
    const auto velocity = [&](int id, Vec2& v, double& w) {
        const auto i = static_cast<size_t>(id);
        const Body& b = bodies[i];
        v = b.velocity;
        w = b.angularVelocity;
        if (b.isActive()) {
            v += dt * acceleration[i];
            w += dt * angularAcceleration[i];
        }
        return b.isActive();
    };
    for (const Contact& ct : contacts) {
        if (ct.restitution == 0.0)
            continue;
        Vec2 vA, vB;
        double wA = 0, wB = 0;
        const bool activeA = velocity(ct.a, vA, wA);
        const bool activeB = velocity(ct.b, vB, wB);
        if (!activeA && !activeB)
            continue;
        const Vec2& cA = bodies[static_cast<size_t>(ct.a)].position;
        const Vec2& cB = bodies[static_cast<size_t>(ct.b)].position;
        for (int i = 0; i < ct.manifold.pointCount; ++i) {
            const ContactPoint& cp = ct.manifold.points[static_cast<size_t>(i)];
            const double vn = (vB + cross(wB, cp.point - cB) - vA - cross(wA, cp.point - cA))
                                  .dot(ct.manifold.normal);
            if (vn < -threshold && closesWithinStep(cp.separation, vn, dt, true))
                return true;
        }
    }
    return false;
}

/// The isolated impacts of this step (soft_impacts.cpp): contacts whose moving bodies have no
/// other contact, each solved exactly at its moment of impact. Fills StepScratch::impacts and
/// StepScratch::isolated; returns whether there are any.
bool findIsolatedImpacts(StepContext& ctx, double threshold)
{
    StepScratch& s = ctx.scratch;
    s.impacts.clear();
    s.isolated.clear();
    s.contactsOf.assign(ctx.bodies.size(), 0);
    for (const Contact& ct : ctx.contacts) {
        ++s.contactsOf[static_cast<size_t>(ct.a)];
        ++s.contactsOf[static_cast<size_t>(ct.b)];
    }
    const auto alone = [&](int id) {
        const auto i = static_cast<size_t>(id);
        return !ctx.bodies[i].isActive() || s.contactsOf[i] == 1;
    };
    for (size_t k = 0; k < ctx.contacts.size(); ++k) {
        const Contact& ct = ctx.contacts[k];
        IsolatedImpact impact;
        if (!alone(ct.a) || !alone(ct.b) || !isolatedImpact(ctx, ct, threshold, impact))
            continue;
        if (s.isolated.empty())
            s.isolated.assign(ctx.contacts.size(), 0);
        s.isolated[k] = 1;
        s.impacts.emplace_back(static_cast<int>(k), impact);
    }
    return !s.impacts.empty();
}

/// The isolated impacts' velocity changes to their bodies (where they end the step without
/// contacts), their moments to StepScratch::impactFraction, their impulses to the contacts.
void applyIsolatedImpacts(StepContext& ctx)
{
    StepScratch& s = ctx.scratch;
    for (const auto& [k, impact] : s.impacts) {
        Contact& ct = ctx.contacts[static_cast<size_t>(k)];
        for (const auto& [id, dv, dw] :
             {std::tuple(ct.a, impact.dvA, impact.dwA), std::tuple(ct.b, impact.dvB, impact.dwB)}) {
            Body& b = ctx.bodies[static_cast<size_t>(id)];
            if (!b.isActive())
                continue;
            b.velocity += dv;
            b.angularVelocity += dw;
            s.impactFraction[static_cast<size_t>(id)] = impact.fraction;
        }
        // The impulse is reported as a bounce (added after the substeps); nothing to warm start.
        for (size_t p = 0; p < 2; ++p) {
            ct.normalImpulse[p] = ct.tangentImpulse[p] = 0.0;
            ct.bounceImpulse[p] = impact.impulse[p];
        }
    }
}

/// The soft step's collision phase, before its substeps: the isolated impacts' exact impulses,
/// and the bounces of the sequential solver's collision phase (contact_collisions.cpp) for the
/// rest. Returns the kinetic energy they took [J].
double softCollisions(StepContext& ctx, double threshold)
{
    StepScratch& s = ctx.scratch;
    s.impactShift.clear();
    s.impactTurn.clear();
    const double h = ctx.def.dt;
    if (ctx.contacts.empty())
        return 0.0;
    const bool exact = findIsolatedImpacts(ctx, threshold);
    const bool general = collisionsToSolve(ctx.contacts, s.previous, ctx.bodies, s.acceleration,
                                           s.angularAcceleration, h, threshold, s.anyRestitution);
    if (!exact && !general)
        return 0.0;
    // Each moving body where it would end the step without contacts (symplectic Euler): where
    // the sequential solver's collision phase finds it.
    const size_t n = ctx.bodies.size();
    s.softVelocity.resize(n);
    s.softAngularVelocity.resize(n);
    s.velocityBefore.resize(n);
    s.angularVelocityBefore.resize(n);
    for (size_t i = 0; i < n; ++i) {
        Body& b = ctx.bodies[i];
        if (!b.isActive())
            continue;
        s.softVelocity[i] = b.velocity;
        s.softAngularVelocity[i] = b.angularVelocity;
        b.velocity += h * s.acceleration[i];
        b.angularVelocity += h * s.angularAcceleration[i];
        s.velocityBefore[i] = b.velocity;
        s.angularVelocityBefore[i] = b.angularVelocity;
        b.position += h * b.velocity;
    }
    bool bounced = false;
    if (general) {
        ContactSolver& solver = s.solver;
        solver.begin(ctx.contacts, s.previous, ctx.bodies, ctx.contactSettings, h, s.xfPosition,
                     s.velocityAtStart, s.angularVelocityAtStart);
        bounced = solver.solveCollisionPhase(threshold, ctx.def.iterations,
                                             exact ? &s.isolated : nullptr);
    }
    // When each body's velocity changed: the collision phase's moments, and the isolated
    // impacts' (their bodies have no other contact, so no bounce of the phase).
    if (bounced)
        s.impactFraction = s.solver.impactFractions();
    else if (exact)
        s.impactFraction.assign(n, 0.0);
    applyIsolatedImpacts(ctx);
    // Back to the start of the step with the bounces' velocity changes; the substeps add the
    // forces. A change at the fraction f moves the body by (1 - f) dt times it by the end of
    // the step, the substeps by dt times it: the rest is taken back after them.
    const bool moved = bounced || exact;
    if (moved) {
        s.impactShift.assign(n, Vec2::Zero());
        s.impactTurn.assign(n, 0.0);
    }
    double loss = 0.0;
    for (size_t i = 0; i < n; ++i) {
        Body& b = ctx.bodies[i];
        if (!b.isActive())
            continue;
        const Vec2 dv = b.velocity - s.velocityBefore[i];
        const double dw = b.angularVelocity - s.angularVelocityBefore[i];
        b.position = s.xfPosition[i];
        b.velocity = s.softVelocity[i] + dv;
        b.angularVelocity = s.softAngularVelocity[i] + dw;
        if (!moved)
            continue;
        const double f = s.impactFraction[i];
        s.impactShift[i] = -(f * h) * dv;
        s.impactTurn[i] = -(f * h) * dw;
        // The kinetic energy the bounce took, at the velocities of its moment.
        const Vec2 v = s.softVelocity[i] + (f * h) * s.acceleration[i];
        const double w = s.softAngularVelocity[i] + (f * h) * s.angularAcceleration[i];
        loss -=
            b.mass * (v.dot(dv) + 0.5 * dv.squaredNorm()) + b.inertia * (w * dw + 0.5 * dw * dw);
    }
    return loss;
}

/// Stage::Forces of the soft step: each body's applied load over its mass and inertia
/// (appliedAcceleration, dynamics.h: the direct integration's), held over the substeps as
/// symplectic Euler holds it over the step.
/// Returns the drag's power at the start of the step [W].
double softForces(StepContext& ctx)
{
    StepScratch& s = ctx.scratch;
    const size_t n = ctx.bodies.size();
    StageTimer forces(ctx.profile, Stage::Forces);
    s.acceleration.resize(n);
    s.angularAcceleration.resize(n);
    double dragPower = 0.0; // at the start of the step [W]
    s.anyRestitution = false;
    for (size_t i = 0; i < n; ++i) {
        const Body& b = ctx.bodies[i];
        s.anyRestitution = s.anyRestitution || b.restitution > 0.0;
        if (!b.isActive())
            continue;
        const BodyAcceleration a = appliedAcceleration(ctx.def, b);
        s.acceleration[i] = a.linear;
        s.angularAcceleration[i] = a.angular;
        if (ctx.def.drag != 0.0)
            dragPower += ctx.def.drag * (b.mass * b.velocity.squaredNorm() +
                                         b.inertia * b.angularVelocity * b.angularVelocity);
    }
    ++ctx.evaluations;
    ctx.profile.directIntegration = true;
    return dragPower;
}

} // namespace

void softStep(StepContext& ctx)
{
    const double h = ctx.def.dt;
    StepScratch& s = ctx.scratch;
    const size_t n = ctx.bodies.size();

    const double dragPower = softForces(ctx); // at the start of the step [W]

    SoftSolver& solver = s.softSolver;
    const SoftStepSettings& settings = ctx.contactSettings.soft;
    double loss = 0.0;
    {
        StageTimer timer(ctx.profile, Stage::ContactSolve);
        loss += softCollisions(ctx, ctx.restitutionThreshold);
        solver.begin(ctx.contacts, ctx.bodies, s.acceleration, s.angularAcceleration, ctx.h,
                     ctx.softness, settings, ctx.plain);
    }
    const bool contacts = solver.constraintCount() > 0;
    const double sub = ctx.h; // [s]
    for (int k = 0; k < ctx.substeps; ++k) {
        {
            StageTimer timer(ctx.profile, Stage::Integration);
            solver.integrateVelocities();
        }
        if (contacts) {
            StageTimer timer(ctx.profile, Stage::ContactSolve);
            loss += solver.kineticEnergy() - 0.5 * sub * solver.loadPower();
            solver.warmStart();
            solver.solve(true);
        }
        {
            StageTimer timer(ctx.profile, Stage::Integration);
            solver.integratePositions();
        }
        if (contacts) {
            StageTimer timer(ctx.profile, Stage::ContactSolve);
            solver.solve(false, k + 1 < ctx.substeps);
            loss -= solver.kineticEnergy() - 0.5 * sub * solver.loadPower();
        }
    }
    {
        StageTimer timer(ctx.profile, Stage::ContactSolve);
        solver.end(ctx.bodies);
        if (!s.impactShift.empty()) {
            // Bounced bodies flew on until their impact (softCollisions()); the contacts
            // report the bounce with the rest of their impulse, as the sequential solver's.
            for (size_t i = 0; i < n; ++i) {
                ctx.bodies[i].position += s.impactShift[i];
                ctx.bodies[i].angle += s.impactTurn[i];
            }
            for (Contact& ct : ctx.contacts)
                for (size_t k = 0; k < 2; ++k)
                    ct.normalImpulse[k] += ct.bounceImpulse[k];
        }
    }
    {
        StageTimer timer(ctx.profile, Stage::ContactSolve);
        softSweepBack(ctx);
    }
    ctx.collisionLoss += loss;
    ctx.dragLoss += h * dragPower;
    ctx.profile.solved = solver.constraintCount();
    ctx.profile.positionPasses = 0;
}

} // namespace rigidlab::physics
