// SPDX-License-Identifier: GPL-3.0-or-later
// Stage::Forces and Stage::Integration (profile.h): the chosen integrator over the moving
// bodies' state, the forces evaluated at each of its stages (forces.cpp, joints.cpp), the
// joints projected back after the step (joints.cpp), and what drag and dampers took
// (dissipation.cpp). This is the plain path for every integrator, symplectic Euler included.
//
// Its acceleration: symplectic Euler with nothing but contacts coupling the bodies (no
// springs, joints or gravitation: StepPlan::direct) runs straight on the bodies
// (fast/integrate_direct.cpp), without gathering the state into vectors and scattering it
// back. It is not a second integrator: the same update (symplectic_euler.h) on the same
// forces (appliedLoad), so the same bits (test_golden's plain-path rows).

#include "rigidlab/physics/world.h"

#include "dynamics.h"
#include "stages.h"

namespace rigidlab::physics {

void integrate(StepContext& ctx)
{
    if (ctx.moving.empty())
        return;
    if (ctx.plan.direct) {
        integrateDirect(ctx);
        return;
    }
    StageTimer timer(ctx.profile, Stage::Integration);
    const double t = ctx.time, h = ctx.dt;
    withState(ctx, [&](Dynamics& dynamics, Eigen::VectorXd& q, Eigen::VectorXd& v) {
        StepScratch& s = ctx.scratch;
        const bool dissipates = dynamics.dissipates();
        if (dissipates) {
            s.q0 = q;
            s.v0 = v;
        }
        ctx.integrator.step(dynamics, t, h, q, v);
        // What drag and dampers took, before the joints move anything (dissipation.cpp).
        if (dissipates) {
            const Dissipation loss = stepDissipation(dynamics, ctx.integratorKind, h, s.q0, s.v0, q,
                                                     v, s.meanVelocity, s.midpoint);
            ctx.dragLoss += loss.drag;
            ctx.dampingLoss += loss.damping;
        }
        // The force evaluations inside count as the forces stage, not as integration.
        ctx.profile.ran[static_cast<int>(Stage::Forces)] = true;
        ctx.profile.ms[static_cast<int>(Stage::Forces)] += dynamics.forceMilliseconds;
        ctx.profile.ms[static_cast<int>(Stage::Integration)] -= dynamics.forceMilliseconds;
        // Back onto the joints (joints.cpp): SHAKE for symplectic Euler, RATTLE for the others.
        dynamics.projectAfterStep(ctx.integratorKind, h, q, v, s.shake);
    });
}

} // namespace rigidlab::physics
