// SPDX-License-Identifier: GPL-3.0-or-later
// Stage::ContactSolve (profile.h): the contact solver (contact_solver.cpp) on this step's
// contacts, then what its impulses mean for the rest of the step: the positions moved by the
// change of velocity, the joints' velocities and positions projected back (joints.cpp), and
// the energy the contacts took (dissipation.cpp).

#include "rigidlab/physics/world.h"

#include "diagnostics_compute.h"
#include "dynamics.h"
#include "stages.h"

#include <algorithm>
#include <tuple>

namespace rigidlab::physics {

void rememberStartVelocities(StepContext& ctx)
{
    StepScratch& s = ctx.scratch;
    s.velocityAtStart.resize(ctx.bodies.size());
    s.angularVelocityAtStart.resize(ctx.bodies.size());
    for (size_t i = 0; i < ctx.bodies.size(); ++i) {
        s.velocityAtStart[i] = ctx.bodies[i].velocity;
        s.angularVelocityAtStart[i] = ctx.bodies[i].angularVelocity;
    }
}

double restitutionThreshold(const WorldDef& def, const ContactSettings& settings)
{
    constexpr double kFloor = 0.01; // [m/s]
    const double oneStep = def.gravity.norm() * def.dt;
    return std::max(std::min(settings.restitutionThreshold, std::max(kFloor, 2.0 * oneStep)),
                    oneStep);
}

bool touchedJoints(StepContext& ctx)
{
    std::vector<PinJointDef>& touched = ctx.scratch.touchedJoints;
    touched.clear();
    if (ctx.joints.empty())
        return false;
    std::vector<char> in(ctx.bodies.size(), 0), taken(ctx.joints.size(), 0);
    for (const Contact& ct : ctx.contacts)
        in[static_cast<size_t>(ct.a)] = in[static_cast<size_t>(ct.b)] = 1;
    const auto marked = [&](BodyId id) { return id != kWorld && in[static_cast<size_t>(id)]; };
    for (bool grew = true; grew;) {
        grew = false;
        for (size_t k = 0; k < ctx.joints.size(); ++k) {
            const PinJointDef& j = ctx.joints[k];
            if (taken[k] || (!marked(j.a) && !marked(j.b)))
                continue;
            taken[k] = 1;
            grew = true;
            for (BodyId id : {j.a, j.b})
                if (id != kWorld)
                    in[static_cast<size_t>(id)] = 1;
        }
    }
    for (size_t k = 0; k < ctx.joints.size(); ++k)
        if (taken[k])
            touched.push_back(ctx.joints[k]);
    return !touched.empty();
}

namespace {

/// The isolated impacts (soft_impacts.cpp) of the impulse solvers: two bodies, one contact,
/// no other contact or pin on either moving body. Each gets the textbook's impulse at its
/// moment of impact, found from the shapes flown as the integrator moved them, instead of the
/// solver's impulse on the normal and points of the start of the step (a cut shot then left
/// at 89.9992° instead of 90°). Its bodies are moved as if they had flown on from the impact
/// with their new velocities, and their velocities before the solver are set to the new ones,
/// so that what follows leaves them alone. Fills StepScratch::isolated (the contacts the solver
/// leaves out); returns the kinetic energy the impacts took [J], at the velocities of their
/// moments.
double solveIsolatedImpacts(StepContext& ctx)
{
    StepScratch& s = ctx.scratch;
    if (!findIsolatedImpacts(ctx, ctx.restitutionThreshold, Flown::ToBodies))
        return 0.0;
    double loss = 0.0;
    for (const auto& [k, impact] : s.impacts) {
        Contact& ct = ctx.contacts[static_cast<size_t>(k)];
        for (const auto& [id, dv, dw] :
             {std::tuple(ct.a, impact.dvA, impact.dwA), std::tuple(ct.b, impact.dvB, impact.dwB)}) {
            const auto i = static_cast<size_t>(id);
            Body& b = ctx.bodies[i];
            if (!b.isActive())
                continue;
            const double f = impact.fraction, after = (1.0 - f) * ctx.dt;
            const Vec2 v = s.velocityAtStart[i] + f * (b.velocity - s.velocityAtStart[i]);
            const double w =
                s.angularVelocityAtStart[i] + f * (b.angularVelocity - s.angularVelocityAtStart[i]);
            loss -= b.mass * (v.dot(dv) + 0.5 * dv.squaredNorm()) +
                    b.inertia * (w * dw + 0.5 * dw * dw);
            b.velocity += dv;
            b.angularVelocity += dw;
            b.position += after * dv;
            b.angle += after * dw;
            s.velocityBefore[i] = b.velocity;
            s.angularVelocityBefore[i] = b.angularVelocity;
        }
        // Reported as a bounce, which the next step does not warm start.
        for (size_t p = 0; p < 2; ++p) {
            ct.tangentImpulse[p] = 0.0;
            ct.normalImpulse[p] = ct.bounceImpulse[p] = impact.impulse[p];
        }
    }
    return loss;
}

} // namespace

void solveContacts(StepContext& ctx)
{
    if (ctx.contacts.empty())
        return;
    StageTimer timer(ctx.profile, Stage::ContactSolve);
    StepScratch& s = ctx.scratch;
    s.bounceHeld = true; // this solver's bounces are written contact by contact
    const double h = ctx.dt;
    s.velocityBefore.resize(ctx.bodies.size());
    s.angularVelocityBefore.resize(ctx.bodies.size());
    for (size_t i = 0; i < ctx.bodies.size(); ++i) {
        s.velocityBefore[i] = ctx.bodies[i].velocity;
        s.angularVelocityBefore[i] = ctx.bodies[i].angularVelocity;
    }
    const double exactLoss = solveIsolatedImpacts(ctx);
    ContactSolver& solver = s.solver;
    solver.begin(ctx.contacts, s.previous, ctx.bodies, ctx.contactSettings, h, s.xfPosition,
                 s.velocityAtStart, s.angularVelocityAtStart);
    solver.leaveOut(&s.isolated);
    // The pins a contact touches are solved with the contacts (contact_solver_pins.cpp); the
    // paper's impulse stays the paper's, one impulse per contact point.
    const bool jointed = touchedJoints(ctx);
    if (jointed && ctx.solver != SolverKind::PaperImpulse)
        solver.setPins(s.touchedJoints);
    if (ctx.solver == SolverKind::PaperImpulse)
        solver.solveSeed();
    else
        solver.solveSequential(ctx.iterations, true, ctx.restitutionThreshold);

    // A resting contact's impulse P is the constraint force P / dt held through the step,
    // beside gravity and the rest: the position moves by what the integrator makes of a
    // constant force, steadyPush dt times the change of velocity (integrator.h). For
    // symplectic Euler that is dt times the change, exactly Box2D's order (solve the
    // velocities, then integrate the positions with them); for Verlet, RK4 and the others,
    // exact on a constant force, half of it. Moving them by the whole dt times the change
    // lifted a resting body by g dt^2 / 2 every step, and the contacts' bookkeeping counted
    // the hopping as energy taken. A bounce, an impulse at the fraction f of the step, moves
    // the position by (1 - f) dt times the change, whatever the integrator.
    const double steady = ctx.steadyPush * h;
    const std::vector<double>& impact = solver.impactFractions();
    for (size_t i = 0; i < ctx.bodies.size(); ++i) {
        Body& b = ctx.bodies[i];
        if (!b.isActive())
            continue;
        const double after = impact[i] > 0.0 ? (1.0 - impact[i]) * h : steady;
        b.position += after * (b.velocity - s.velocityBefore[i]);
        b.angle += after * (b.angularVelocity - s.angularVelocityBefore[i]);
    }
    // Impulses on jointed bodies may push along a joint: take that velocity out again. Only
    // then: the integrator has already put the jointed bodies back onto their joints (SHAKE
    // for symplectic Euler, whose velocities are the chord's), and projecting a free swinging
    // pendulum's velocity again whenever some box elsewhere rests on the floor pumped energy
    // into it (the welcome scene's wrecking ball: 3 % in 2 minutes). The joints no contact
    // touches are left alone for the same reason.
    if (jointed && solver.appliedImpulse())
        withState(
            ctx,
            [](Dynamics& d, Eigen::VectorXd& q, Eigen::VectorXd& v) {
                d.projectJointVelocities(q, v);
            },
            &s.touchedJoints);
    // What the contacts took (dissipation.cpp): friction and inelastic bounces.
    ctx.collisionLoss += exactLoss;
    ctx.collisionLoss += contactLoss(ctx.bodies, s.velocityAtStart, s.angularVelocityAtStart,
                                     s.velocityBefore, s.angularVelocityBefore, impact);

    ctx.profile.solved = solver.constraintCount();
    ctx.profile.positionPasses = solver.solvePositions(ctx.contactSettings.positionIterations);
    if (jointed)
        withState(
            ctx,
            [](Dynamics& d, Eigen::VectorXd& q, Eigen::VectorXd&) { d.projectJointPositions(q); },
            &s.touchedJoints);
}

} // namespace rigidlab::physics
