// SPDX-License-Identifier: GPL-3.0-or-later
// Stage::ContactSolve (profile.h) with SolverKind::PaperImpulse: the paper's impulse (its
// equations 1.1-1.6). With n from A to B and the relative normal velocity
// vn = (vB + wB x rB - vA - wA x rA) . n < 0, the impulse
//     j = -(1 + e) vn / (1/mA + 1/mB + (rA x n)^2 / IA + (rB x n)^2 / IB)
// changes vA by -j n / mA, vB by +j n / mB, wA by -(rA x j n) / IA and wB by +(rB x j n) / IB.
// The paper prints the denominator without its rotational terms; without them an off-centre
// hit does not conserve energy at e = 1. Each contact gets it once, in order.

#include "contact_solver.h"

#include "restitution.h"

#include <algorithm>

namespace rigidlab::physics {

void ContactSolver::solveSeed()
{
    // The paper has no threshold: every approaching contact gets its impulse, once, in order.
    m_paperImpulse = true;
    prepare(0.0, 0.0);
    for (Constraint& c : m_constraints) {
        for (Point& p : c.p)
            p.normalImpulse = p.tangentImpulse = 0.0;
        Velocity& a = m_velocity[static_cast<size_t>(c.a)];
        Velocity& b = m_velocity[static_cast<size_t>(c.b)];
        for (int i = 0; i < c.count; ++i) {
            const double vn = normalVelocity(c, i, a, b);
            Point& p = c.p[i];
            if (vn >= 0)
                continue; // separating
            // Contacts handled before this one in the pass may have changed how fast these
            // two approach: bounce from the approach as it is now, not as it was when the
            // target was set (that would hand out energy in a break of many balls). One that
            // approaches only now (a ball struck into its touching neighbour) bounces too.
            double target = 0.0;
            if (p.bounces) {
                p.bias =
                    std::max(p.bias + rebound(vn - p.vnPrepared, c.restitution), p.speculative);
            } else if (bounceTarget(c, i, a, b, target)) {
                p.bias = target;
                p.bounces = true;
            } else if (!closesWithinStep(p.separation, vn, m_dt)) {
                continue; // will not reach the other body this step
            }
            solveNormalPoint(c, i, a, b);
            solveFrictionPoint(c, i, a, b);
        }
    }
    store();
}

} // namespace rigidlab::physics
