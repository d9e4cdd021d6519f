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
// The forces' work in a substep is h m a.v at the velocities that moved the bodies, those of
// the soft solve (the relax pass comes after the positions): the difference to the relaxed
// velocities is the contacts' too. Then the books close: what they took is what the bodies'
// energy lost, to the integrator's bounded error. A bounce's is measured at the velocities
// of its moment.

#include "rigidlab/physics/world.h"

#include "dynamics.h"
#include "restitution.h"
#include "stages.h"

#include <cassert>
#include <tuple>

namespace rigidlab::physics {

namespace {

/// Whether some contact holds a bounce: the plain form of StepScratch::bounceHeld.
bool holdsBounce(const std::vector<Contact>& contacts)
{
    for (const Contact& ct : contacts)
        if (ct.bounceImpulse[0] > 0 || ct.bounceImpulse[1] > 0)
            return true;
    return false;
}

/// Whether the collision phase has work: a contact point with restitution that closes within
/// the step and approaches faster than `threshold` [m/s] at the velocities the forces give it
/// (only then can a sweep bounce anything), or a contact that bounced in the step before
/// (`bouncedBefore`: its carried impulse holds the bounce, which must not warm start the
/// substeps). A contact without restitution only stops its approach, as the substeps'
/// speculative contact does; in a pyramid of 5050 boxes one such contact somewhere made every
/// step pay for the phase.
bool collisionsToSolve(const std::vector<Contact>& contacts, bool bouncedBefore,
                       const std::vector<Body>& bodies, const std::vector<Vec2>& acceleration,
                       const std::vector<double>& angularAcceleration, double dt, double h,
                       double threshold, bool anyRestitution)
{
    if (bouncedBefore)
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
            if (!(vn < -threshold))
                continue;
            // Closing on the substeps' parabola (restitution.h) or on the line at the end
            // velocities.
            const double vn0 =
                (bodies[static_cast<size_t>(ct.b)].velocity +
                 cross(bodies[static_cast<size_t>(ct.b)].angularVelocity, cp.point - cB) -
                 bodies[static_cast<size_t>(ct.a)].velocity -
                 cross(bodies[static_cast<size_t>(ct.a)].angularVelocity, cp.point - cA))
                    .dot(ct.manifold.normal);
            if (closesWithinStep(cp.separation, vn, dt, true) ||
                substepImpactFraction(cp.separation, vn0, vn - vn0, dt, h) <= 1.0)
                return true;
        }
    }
    return false;
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

/// Each moving body where it would end the step without contacts (symplectic Euler, or where
/// the integrator put it in a smooth step): where the sequential solver's collision phase finds
/// it. Keeps the velocities at the start in StepScratch::softVelocity, those at the end in
/// StepScratch::velocityBefore.
void placeAtEndOfStep(StepContext& ctx)
{
    StepScratch& s = ctx.scratch;
    const double h = ctx.dt;
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
        if (ctx.plan.smooth)
            b.position = s.smoothEnd[i].position;
        else
            b.position += h * b.velocity;
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
    const double h = ctx.dt;
    if (ctx.contacts.empty())
        return 0.0;
    const bool exact =
        findIsolatedImpacts(ctx, threshold, ctx.plan.smooth ? Flown::ToSmoothEnd : Flown::ByForces);
    // Last step's bounces: the plain path reads every contact of the step before, the fast path
    // the flag kept as they were written.
    assert(s.bounceHeldBefore || !holdsBounce(s.previous));
    const bool bouncedBefore = ctx.plain ? holdsBounce(s.previous) : s.bounceHeldBefore;
    const bool general =
        collisionsToSolve(ctx.contacts, bouncedBefore, ctx.bodies, s.acceleration,
                          s.angularAcceleration, h, ctx.h, threshold, s.anyRestitution);
    if (!exact && !general)
        return 0.0;
    placeAtEndOfStep(ctx);
    const size_t n = ctx.bodies.size();
    bool bounced = false;
    if (general) {
        ContactSolver& solver = s.solver;
        solver.begin(ctx.contacts, s.previous, ctx.bodies, ctx.contactSettings, h, s.xfPosition,
                     s.velocityAtStart, s.angularVelocityAtStart);
        bounced = solver.solveCollisionPhase(threshold, ctx.iterations, ctx.h,
                                             exact ? &s.isolated : nullptr);
    }
    // When each body's velocity changed: the collision phase's moments, and the isolated
    // impacts' (their bodies have no other contact, so no bounce of the phase).
    if (bounced || exact)
        s.bounceHeld = true;
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
    const double lead = ctx.plan.smooth ? 0.0 : 0.5 * ctx.h; // [s]
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
        // The kinetic energy the bounce took, at the velocities of its moment: on the
        // substeps' parabola, which leads their velocity by half a substep (soft_impacts.cpp;
        // at the velocity of the step's line instead, the books of a ball bounced at dt = 0.2 s
        // were 1 J out per bounce).
        const double at = f * h + lead;
        const Vec2 v = s.softVelocity[i] + at * s.acceleration[i];
        const double w = s.softAngularVelocity[i] + at * s.angularAcceleration[i];
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
    double power = 0.0; // drag's, at the start of the step [W]
    s.anyRestitution = false;
    for (size_t i = 0; i < n; ++i) {
        const Body& b = ctx.bodies[i];
        s.anyRestitution = s.anyRestitution || b.restitution > 0.0;
        if (!b.isActive())
            continue;
        const BodyAcceleration a = appliedAcceleration(ctx.field, b);
        s.acceleration[i] = a.linear;
        s.angularAcceleration[i] = a.angular;
        if (ctx.field.drag != 0.0)
            power += dragPower(ctx.field.drag, b, b.velocity, b.angularVelocity, b.velocity,
                               b.angularVelocity);
    }
    ++ctx.evaluations;
    ctx.profile.directIntegration = true;
    return power;
}

/// Stage::Forces and Stage::Integration of the soft step with smooth forces the substeps do
/// not hold constant (StepPlan::smooth: springs, pins, gravitation, or another integrator):
/// the chosen integrator moves the bodies over the whole step as if there were no contacts
/// (integration.cpp: its forces at each of its stages, the pins as exact constraint forces,
/// what drag and dampers took), and each body goes back to the start of the step with what the
/// substeps need to repeat that motion: its mean acceleration a = (v1 - v0) / dt, held over
/// the substeps, and the drift u, the part of its displacement that no constant force makes:
///     x1 - x0 = dt v0 + c dt (v1 - v0) + dt u,
/// c the integrator's steady push (what it makes of a constant acceleration, integrator.h: 1/2
/// for Verlet and RK4, 0 for explicit Euler). The substeps make c' = (n + 1) / (2 n) of a
/// constant acceleration; a body no contact touches takes the integrator's end instead
/// (finishSmoothMotion()), so without contacts each integrator keeps its order and its bits.
void softSmoothMotion(StepContext& ctx)
{
    StepScratch& s = ctx.scratch;
    const size_t n = ctx.bodies.size();
    // Where the contacts were found: the start of the step (findContacts()).
    integrate(ctx);
    const double invDt = ctx.invDt;
    const double steady = ctx.steadyPush;
    s.acceleration.resize(n);
    s.angularAcceleration.resize(n);
    s.drift.assign(n, Vec2::Zero());
    s.angularDrift.assign(n, 0.0);
    s.smoothEnd.resize(n);
    s.anyRestitution = false;
    for (size_t i = 0; i < n; ++i) {
        Body& b = ctx.bodies[i];
        s.anyRestitution = s.anyRestitution || b.restitution > 0.0;
        if (!b.moves())
            continue;
        s.smoothEnd[i] = {b.position, b.angle, b.velocity, b.angularVelocity};
        const Vec2 x0 = s.xfPosition[i], v0 = s.velocityAtStart[i];
        const double angle0 = s.xfAngle[i], w0 = s.angularVelocityAtStart[i];
        if (b.isActive()) {
            const Vec2 dv = b.velocity - v0;
            const double dw = b.angularVelocity - w0;
            s.acceleration[i] = invDt * dv;
            s.angularAcceleration[i] = invDt * dw;
            s.drift[i] = invDt * (b.position - x0) - v0 - steady * dv;
            s.angularDrift[i] = invDt * (b.angle - angle0) - w0 - steady * dw;
        }
        b.position = x0;
        b.angle = angle0;
        b.velocity = v0;
        b.angularVelocity = w0;
    }
}

/// After the substeps of a smooth step: a body no contact touched (nor a pin a contact
/// touched) ends where the integrator put it, bit for bit. A body in contact keeps the
/// substeps' motion: its contacts hold it as the soft step holds any body (a resting body's
/// contact cancels its load within each substep), its drift adds the integrator's motion
/// beyond a constant force, and only the constant force's share differs from the integrator's
/// (c' instead of c, softSmoothMotion()): by (c' - c) dt^2 |a| in a step with a contact, 0.1 g
/// dt^2 for RK4. (Moving such a body by the integrator's share of its whole change of velocity
/// instead, the contacts' included, left explicit Euler's resting ball, c = 0, unable to move
/// off its contact within a step: it hovered at 2 cm/s, and its contact's bookkeeping took
/// 13 % of its energy in a minute.)
void finishSmoothMotion(StepContext& ctx)
{
    StepScratch& s = ctx.scratch;
    const size_t n = ctx.bodies.size();
    s.touched.assign(n, 0);
    for (const Contact& ct : ctx.contacts)
        s.touched[static_cast<size_t>(ct.a)] = s.touched[static_cast<size_t>(ct.b)] = 1;
    for (const PinJointDef& j : s.touchedJoints)
        for (const BodyId id : {j.a, j.b})
            if (id != kWorld)
                s.touched[static_cast<size_t>(id)] = 1;
    // A body whose contacts pushed nothing this step (a ball rising within the margin of the
    // floor it bounced off) ends where the substeps put it but for their share of the constant
    // force (c' - c) dt dv: then it takes the integrator's end too, so that a free flight
    // stays the integrator's in steps with a contact that does not act.
    const double shift = ((ctx.substeps + 1.0) / (2.0 * ctx.substeps) - ctx.steadyPush) * ctx.dt;
    constexpr double kRoundOff = 1e-11; // relative
    const auto near = [&](const Vec2& a, const Vec2& b) {
        return (a - b).norm() <= kRoundOff * (1.0 + b.norm());
    };
    for (size_t i = 0; i < n; ++i) {
        Body& b = ctx.bodies[i];
        if (!b.isActive())
            continue;
        const BodyPose& end = s.smoothEnd[i];
        const Vec2 dv = end.velocity - s.velocityAtStart[i];
        const double dw = end.angularVelocity - s.angularVelocityAtStart[i];
        const bool pushed = !near(b.velocity, end.velocity) ||
                            !near(Vec2(b.angularVelocity, b.angle),
                                  Vec2(end.angularVelocity, end.angle + shift * dw)) ||
                            !near(b.position, end.position + shift * dv);
        if (s.touched[i] && pushed)
            continue;
        b.position = end.position;
        b.angle = end.angle;
        b.velocity = end.velocity;
        b.angularVelocity = end.angularVelocity;
    }
}

/// Back onto the pins the contacts touched (the integrator's projection, joints.cpp), after
/// the substeps held them softly.
void projectTouchedPins(StepContext& ctx)
{
    withState(
        ctx,
        [](Dynamics& d, Eigen::VectorXd& q, Eigen::VectorXd& v) {
            d.projectJointPositions(q);
            d.projectJointVelocities(q, v);
        },
        &ctx.scratch.touchedJoints);
}

/// What a substep's relax pass leaves to subtract from the contacts' loss (softSubsteps()): the
/// kinetic energy and the loads' power after it (`relaxed`), against the loads' work at the
/// velocities that moved the bodies. The load moved the bodies at the solve's velocities, before
/// the relax pass: its work is h P there, not at the relaxed velocities (a rolling disc, pushed
/// up and relaxed down in every substep, counted 0.64 J/s taken that it kept).
double relaxedLoss(const SoftSolver& solver, std::pair<double, double> relaxed, double sub)
{
    return relaxed.first + 0.5 * sub * relaxed.second - sub * solver.movePower();
}

/// The substeps (soft_solver.cpp), each timed by stage: integrate velocities, warm start,
/// solve with the soft push, integrate positions, relax. contacts: whether there is anything
/// to solve. Returns the kinetic energy the contacts took [J] (see the top of this file).
double softSubsteps(StepContext& ctx, bool contacts)
{
    SoftSolver& solver = ctx.scratch.softSolver;
    const double sub = ctx.h; // [s]
    double loss = 0.0;
    for (int k = 0; k < ctx.substeps; ++k) {
        {
            StageTimer timer(ctx.profile, Stage::Integration);
            // After the first substep, the energy the relax pass before left is summed in the
            // same pass over the bodies (below).
            solver.integrateVelocities(contacts && k > 0);
        }
        if (contacts) {
            StageTimer timer(ctx.profile, Stage::ContactSolve);
            if (k > 0)
                loss -= relaxedLoss(solver, solver.energyBefore(), sub);
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
            if (k + 1 == ctx.substeps)
                loss -= relaxedLoss(solver, {solver.kineticEnergy(), solver.loadPower()}, sub);
        }
    }
    return loss;
}

} // namespace

void softStep(StepContext& ctx)
{
    const double h = ctx.dt;
    StepScratch& s = ctx.scratch;
    const size_t n = ctx.bodies.size();

    if (ctx.plan.smooth && ctx.contacts.empty()) {
        // Nothing for the substeps to solve: the integrator's step, exactly.
        integrate(ctx);
        if (ctx.plan.collide) {
            StageTimer timer(ctx.profile, Stage::ContactSolve);
            sweepBackBullets(ctx);
        }
        return;
    }
    double dragAtStart = 0.0; // at the start of the step [W]; the integrator counts its own
    if (ctx.plan.smooth)
        softSmoothMotion(ctx);
    else
        dragAtStart = softForces(ctx);

    SoftSolver& solver = s.softSolver;
    const bool pinned = touchedJoints(ctx);
    SoftStepSettings settings = ctx.contactSettings.soft;
    settings.singlePrecision = settings.singlePrecision && !pinned; // the pins are in double
    double loss = 0.0;
    {
        StageTimer timer(ctx.profile, Stage::ContactSolve);
        loss += softCollisions(ctx, ctx.restitutionThreshold);
        solver.begin(ctx.contacts, ctx.bodies, s.acceleration, s.angularAcceleration,
                     {.count = ctx.substeps, .h = ctx.h, .invH = ctx.invH}, ctx.softness, settings,
                     ctx.plain);
        if (ctx.plan.smooth)
            solver.setDrift(s.drift, s.angularDrift);
    }
    if (pinned)
        solver.setPins(s.touchedJoints, ctx.bodies);
    loss += softSubsteps(ctx, solver.constraintCount() > 0 || pinned);
    {
        StageTimer timer(ctx.profile, Stage::ContactSolve);
        solver.end(ctx.bodies);
        if (ctx.plan.smooth)
            finishSmoothMotion(ctx);
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
        if (pinned)
            projectTouchedPins(ctx);
        sweepBackBullets(ctx);
    }
    ctx.collisionLoss += loss;
    ctx.dragLoss += h * dragAtStart;
    ctx.profile.solved = solver.constraintCount();
    ctx.profile.positionPasses = 0;
}

} // namespace rigidlab::physics
