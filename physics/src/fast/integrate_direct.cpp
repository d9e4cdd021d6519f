// SPDX-License-Identifier: GPL-3.0-or-later
// The acceleration of Stage::Forces and Stage::Integration (stages/integration.cpp) for
// symplectic Euler with nothing but contacts coupling the bodies (StepPlan::direct): the
// update straight on the bodies, without gathering the state into the ODE vectors and
// scattering it back. The same update (symplectic_euler.h) on the same forces (appliedLoad,
// forces.cpp) as the integrator over the state, so the same bits; the plain path is the
// integrator's (EngineSettings::plainPaths, test_golden).

#include "dynamics.h"
#include "stages.h"
#include "symplectic_euler.h"

namespace rigidlab::physics {

void integrateDirect(StepContext& ctx)
{
    const double h = ctx.dt;
    const double drag = ctx.field.drag;
    StepScratch& s = ctx.scratch;
    const size_t n = ctx.bodies.size();

    // Forces: each body's applied load (appliedLoad, the same function the ODE system sums)
    // over its mass and inertia (appliedAcceleration, dynamics.h).
    StageTimer forces(ctx.profile, Stage::Forces);
    s.acceleration.resize(n);
    s.angularAcceleration.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const Body& b = ctx.bodies[i];
        if (!b.isActive())
            continue;
        const BodyAcceleration a = appliedAcceleration(ctx.field, b);
        s.acceleration[i] = a.linear;
        s.angularAcceleration[i] = a.angular;
    }
    forces.stop();

    // Integration: symplectic Euler's update (symplectic_euler.h). Kinematic bodies keep their
    // velocity. Drag's share of the change in kinetic energy, h F_drag . (v0 + v1) / 2, is what it
    // took (dissipation.cpp).
    StageTimer integration(ctx.profile, Stage::Integration);
    double dragLoss = 0.0;
    ++ctx.evaluations;
    ctx.profile.directIntegration = true;
    for (size_t i = 0; i < n; ++i) {
        Body& b = ctx.bodies[i];
        if (b.type == BodyType::Static || (b.isDynamic() && !b.awake))
            continue;
        const Vec2 a = b.isDynamic() ? s.acceleration[i] : Vec2::Zero();
        const double alpha = b.isDynamic() ? s.angularAcceleration[i] : 0.0;
        const Vec2 v0 = b.velocity;
        const double w0 = b.angularVelocity;
        symplecticEulerUpdate(h, a, b.velocity, b.position);
        symplecticEulerUpdate(h, alpha, b.angularVelocity, b.angle);
        if (drag != 0.0 && b.isDynamic())
            dragLoss +=
                dragPower(drag, b, v0, w0, 0.5 * (v0 + b.velocity), 0.5 * (w0 + b.angularVelocity));
    }
    ctx.dragLoss += h * dragLoss;
}

} // namespace rigidlab::physics
