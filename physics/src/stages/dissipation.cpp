// SPDX-License-Identifier: GPL-3.0-or-later
// The energy that drag, the dampers of springs (inside integration) and contacts (after the
// contact solver) take out in a step, so that the diagnostics can tell it from the
// integrator's error.
//
// A step changes the velocities by h times the forces' accelerations, and the kinetic energy
// by exactly the work of those impulses at the mean velocity u = (v0 + v1) / 2:
//   K1 - K0 = (v1 - v0)^T M u = h F^T u,   F the generalised force of the step.
// Each force's share h F_i^T u is what that force did to the kinetic energy, so a
// dissipative force's loss in the step is -h F_d^T u, with F_d weighted as the integrator
// weighted its evaluations: at the start for the two Euler methods, at the midpoint for the
// implicit midpoint rule (all three exact shares), and the trapezoid of the start and the
// end for Verlet, RK4 and dopri5 (an error of order h^2 in the loss per unit time).

#include "diagnostics_compute.h"
#include "dynamics.h"

namespace rigidlab::physics {

namespace {

/// u's velocity of the point at lever r of body id, zero where the body is not moved by the
/// step's forces (the world, static, kinematic or asleep bodies: no energy counted there).
Vec2 movingPointVelocity(const std::vector<Body>& bodies, const std::vector<int>& slot, BodyId id,
                         const Vec2& r, const Eigen::VectorXd& u)
{
    if (id == kWorld || !bodies[static_cast<size_t>(id)].isActive())
        return Vec2::Zero();
    const Eigen::Index i = 3 * static_cast<Eigen::Index>(slot[static_cast<size_t>(id)]);
    return Vec2(u[i], u[i + 1]) + cross(u[i + 2], r);
}

} // namespace

bool Dynamics::dissipates() const
{
    if (m_field.drag != 0.0)
        return true;
    for (const SpringDef& s : m_springs)
        if (s.damping != 0.0)
            return true;
    return false;
}

// Contacts. The solver's impulse P on a body changes its velocity from v' (after integration)
// to v1 = v' + dv. Its loss is the impulse's work over the velocities just before and just
// after it acted, -P . (before + after) / 2, placed in the step as the solver places it:
//   - resting (no bounce, or a contact already touching): at the start of the step, from v0
//     (the velocity at the start) to v1. Over the whole step, with a the applied
//     acceleration, the energy changes by P . (v0 + v1) / 2 - (m h^2 |a|^2 + h P . a) / 2, the
//     rest being the integrator's error. Where a body rests (P = -m a h) that error cancels
//     and the contact takes nothing, as it should: the floor does no work on a box that
//     stands on it. (The kinetic energy the solver removes, P . (v' + v1) / 2, would count
//     m |a|^2 h^2 / 2 a step for every resting body as lost.)
//   - a bounce timed at the fraction f of the step (every contact that pushed the body
//     bounced, f > 0): at the impact, from w = v0 + f (v' - v0) to w + dv, the forces acting on
//     for the rest of the step; the solver reverses w's normal part times e, so an elastic
//     bounce (e = 1) takes nothing.
// For bodies without applied forces all three are the kinetic energy the solver removed. A
// kinematic body that pushes gives energy: a negative loss.
double contactLoss(const std::vector<Body>& bodies, const std::vector<Vec2>& velocityAtStart,
                   const std::vector<double>& angularVelocityAtStart,
                   const std::vector<Vec2>& velocityBefore,
                   const std::vector<double>& angularVelocityBefore,
                   const std::vector<double>& impact)
{
    double loss = 0.0;
    for (size_t i = 0; i < bodies.size(); ++i) {
        const Body& b = bodies[i];
        if (!b.isActive())
            continue;
        const double f = impact[i];
        const Vec2 dv = b.velocity - velocityBefore[i];
        const double dw = b.angularVelocity - angularVelocityBefore[i];
        // Before the impulse: at the start of the step (f = 0) or at the impact.
        const Vec2 applied = velocityBefore[i] - velocityAtStart[i];
        const double appliedAngular = angularVelocityBefore[i] - angularVelocityAtStart[i];
        const Vec2 before = velocityAtStart[i] + f * applied;
        const double beforeAngular = angularVelocityAtStart[i] + f * appliedAngular;
        loss -= b.mass * dv.dot(before + 0.5 * dv) + b.inertia * dw * (beforeAngular + 0.5 * dw);
        if (f == 0.0) // resting: the impulse before the step's forces, so they come after it
            loss -= 0.5 * (b.mass * dv.dot(applied) + b.inertia * dw * appliedAngular);
    }
    return loss;
}

Dissipation stepDissipation(const Dynamics& dynamics, IntegratorKind kind, double h,
                            const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
                            const Eigen::VectorXd& q1, const Eigen::VectorXd& v1,
                            Eigen::VectorXd& u, Eigen::VectorXd& qm)
{
    u = 0.5 * (v0 + v1);
    Dissipation p;
    double weight = h;
    switch (integratorInfo(kind).dissipation) {
    case DissipationRule::StartOfStep:
        p = dynamics.dissipation(q0, v0, u);
        break;
    case DissipationRule::Midpoint:
        qm = 0.5 * (q0 + q1);
        p = dynamics.dissipation(qm, u, u);
        break;
    case DissipationRule::Trapezoid: {
        p = dynamics.dissipation(q0, v0, u);
        const Dissipation end = dynamics.dissipation(q1, v1, u);
        p.drag += end.drag;
        p.damping += end.damping;
        weight = 0.5 * h;
        break;
    }
    }
    p.drag *= weight;
    p.damping *= weight;
    return p;
}

Dissipation Dynamics::dissipation(const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                  const Eigen::VectorXd& u) const
{
    Dissipation p;
    // Drag: F = -drag m v, M = -drag I w on every active body.
    if (m_field.drag != 0.0) {
        for (size_t id = 0; id < m_bodies.size(); ++id) {
            const Body& b = m_bodies[id];
            if (!b.isActive())
                continue;
            const Eigen::Index i = 3 * static_cast<Eigen::Index>(m_slot[id]);
            p.drag += dragPower(m_field.drag, b, Vec2(v[i], v[i + 1]), v[i + 2],
                                Vec2(u[i], u[i + 1]), u[i + 2]);
        }
    }
    // Dampers: c dL/dt along n, the force on A being +c dL/dt n (see forces.cpp); its power on
    // the two ends is -c dL/dt (n . (uB - uA)).
    for (const SpringDef& s : m_springs) {
        if (s.damping == 0.0)
            continue;
        const SpringEnds e = springEnds(s, q, v);
        const Vec2 d = e.pB - e.pA;
        const double length = d.norm();
        if (length <= 1e-12)
            continue; // no force there either (forces.cpp)
        const Vec2 n = d / length;
        const double rate = (e.vB - e.vA).dot(n); // dL/dt [m/s]
        const Vec2 uA = movingPointVelocity(m_bodies, m_slot, s.a, e.rA, u);
        const Vec2 uB = movingPointVelocity(m_bodies, m_slot, s.b, e.rB, u);
        p.damping += s.damping * rate * (uB - uA).dot(n);
    }
    return p;
}

} // namespace rigidlab::physics
