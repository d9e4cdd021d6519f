// SPDX-License-Identifier: GPL-3.0-or-later
// Stage::ContactSolve (profile.h) with SolverKind::SequentialImpulse: sequential impulses
// (Catto, "Iterative Dynamics with Temporal Coherence", GDC 2005). The paper's impulse
// (paper_impulse.cpp), applied repeatedly to every contact, accumulated and clamped so that the
// total stays pushing (>= 0) and friction stays inside its cone, warm started from the last
// step so that resting stacks converge. Two points of one manifold are solved together as a
// 2x2 linear complementarity problem by trying its four cases (as in Box2D 2.x). The bounces
// come first, in the collision phase (contact_collisions.cpp).

#include "contact_solver.h"

#include <algorithm>
#include <cstddef>

namespace rigidlab::physics {

void ContactSolver::warmStart()
{
    for (const Constraint& c : m_constraints) {
        Velocity& a = m_velocity[static_cast<size_t>(c.a)];
        Velocity& b = m_velocity[static_cast<size_t>(c.b)];
        for (int i = 0; i < c.count; ++i) {
            const Point& p = c.p[i];
            const Vec2 P = p.warmNormal * c.normal + p.warmTangent * c.tangent;
            a.v -= c.invMassA * P;
            a.w -= c.invIA * (p.warmNormal * p.rnA + p.warmTangent * p.rtA);
            b.v += c.invMassB * P;
            b.w += c.invIB * (p.warmNormal * p.rnB + p.warmTangent * p.rtB);
        }
    }
}

[[gnu::always_inline]] inline void ContactSolver::solveNormalBlock(Constraint& c, Velocity& a,
                                                                   Velocity& b)
{
    // Find accumulated impulses x >= 0 with vn = K (x - x_old) + vn_now and, per point,
    // either x_i = 0 and vn_i >= bias_i, or x_i > 0 and vn_i = bias_i. With
    // b = vn_now - bias - K x_old the conditions read  w = K x + b,  x >= 0, w >= 0, x.w = 0.
    const Point &p1 = c.p[0], &p2 = c.p[1];
    const double old1 = p1.normalImpulse, old2 = p2.normalImpulse;
    const double vn = (b.v - a.v).dot(c.normal);
    const double vn1 = vn + b.w * p1.rnB - a.w * p1.rnA;
    const double vn2 = vn + b.w * p2.rnB - a.w * p2.rnA;
    const double b1 = vn1 - p1.bias - (c.k11 * old1 + c.k12 * old2);
    const double b2 = vn2 - p2.bias - (c.k12 * old1 + c.k22 * old2);

    double x1 = 0, x2 = 0;
    bool found = false;
    // Case 1: both points pushing.
    x1 = -(c.m11 * b1 + c.m12 * b2);
    x2 = -(c.m12 * b1 + c.m22 * b2);
    found = x1 >= 0 && x2 >= 0;
    // Case 2: only the first point pushing.
    if (!found) {
        x1 = -c.p[0].normalMass * b1;
        x2 = 0.0;
        found = x1 >= 0 && c.k12 * x1 + b2 >= 0;
    }
    // Case 3: only the second point pushing.
    if (!found) {
        x1 = 0.0;
        x2 = -c.p[1].normalMass * b2;
        found = x2 >= 0 && c.k12 * x2 + b1 >= 0;
    }
    // Case 4: neither pushing.
    if (!found) {
        x1 = x2 = 0.0;
        found = b1 >= 0 && b2 >= 0;
    }
    if (!found) {
        // Round-off left no exact case: fall back to point by point.
        solveNormalPoint(c, 0, a, b);
        solveNormalPoint(c, 1, a, b);
        return;
    }
    const double d1 = x1 - old1, d2 = x2 - old2;
    a.v -= (c.invMassA * (d1 + d2)) * c.normal;
    a.w -= c.invIA * (d1 * p1.rnA + d2 * p2.rnA);
    b.v += (c.invMassB * (d1 + d2)) * c.normal;
    b.w += c.invIB * (d1 * p1.rnB + d2 * p2.rnB);
    c.p[0].normalImpulse = x1;
    c.p[1].normalImpulse = x2;
}

void ContactSolver::solveSequential(int iterations, bool warm, double threshold)
{
    m_paperImpulse = false;
    prepare(threshold, m_settings->restitutionThreshold);
    // The collision phase: bounces, each from the approach it has when it is met. Last step's
    // impulses wait: they are the contact phase's starting guess.
    for (Constraint& c : m_constraints)
        for (Point& p : c.p) {
            p.warmNormal = warm ? p.normalImpulse : 0.0;
            p.warmTangent = warm ? p.tangentImpulse : 0.0;
            p.normalImpulse = p.tangentImpulse = 0.0;
        }
    solveCollisions(std::max(iterations, 1));
    // The contact phase with e = 0: a gap may close within the step, touching points may
    // not approach (position correction removes the overlap).
    for (Constraint& c : m_constraints)
        for (Point& p : c.p) {
            p.bias = p.speculative;
            p.normalImpulse = p.warmNormal;
            p.tangentImpulse += p.warmTangent;
        }
    if (warm)
        warmStart();
    const int count = static_cast<int>(m_constraints.size());
    for (int it = 0; it < iterations; ++it) {
        const bool backward = (it % 2 == 0);
        for (int k = 0; k < count; ++k) {
            Constraint& c = m_constraints[static_cast<size_t>(backward ? count - 1 - k : k)];
            // The two bodies' velocities stay in registers for the whole constraint.
            Velocity a = m_velocity[static_cast<size_t>(c.a)];
            Velocity b = m_velocity[static_cast<size_t>(c.b)];
            // Friction first: its limit uses the normal impulse, and normal wins the last word.
            // A point that has never pushed has no friction to give (the limit and the
            // accumulated impulse are both 0): skipping it changes nothing.
            for (int i = 0; i < c.count; ++i)
                if (c.p[i].normalImpulse != 0.0 || c.p[i].tangentImpulse != 0.0 ||
                    c.p[i].bounceImpulse != 0.0)
                    solveFrictionPoint(c, i, a, b);
            if (c.block)
                solveNormalBlock(c, a, b);
            else
                for (int i = 0; i < c.count; ++i)
                    solveNormalPoint(c, i, a, b);
            m_velocity[static_cast<size_t>(c.a)] = a;
            m_velocity[static_cast<size_t>(c.b)] = b;
        }
        solvePins();
    }
    store();
}

} // namespace rigidlab::physics
