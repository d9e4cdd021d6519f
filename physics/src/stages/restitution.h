// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private: the restitution targets of impacts, shared by every solver that bounces contacts
// (contact_solver.cpp; a new solver gets the same bounces by calling these).
//
// A contact point with a gap s > 0 at the start of the step, whose bodies approach at vn0 < 0
// then, touches after the fraction f = s / (-vn0 dt) of the step. Its bounce reverses the
// approach it has at that moment, and the forces act on for the rest of the step:
//
//     vn at the start  vn0                      gap s
//     forces over the whole step add  F = vn - vn0   (vn: the velocity before the solve)
//     at the impact      vn(f) = vn0 + f F
//     after the step     vn' = -e vn(f) + (1 - f) F = -e vn + (1 + e)(1 - f) F
//
// The target depends on the approach only through -e vn, so a solver that meets the contact
// again after other impulses changed vn bounces it from the approach it has then: a ball that
// bounces off a wall into a neighbour a few millimetres behind it bounces off that one too,
// however slowly the two approached at the start of the step.
//
// The impulse of a bounce at f acts on the bodies as they stand at f: its lever arms are
// taken from the centres there (c(f) = x(end) - (1 - f) dt v, since the solver's velocity
// change moves a body by (1 - f) dt times it), about one point both bodies share. Then the
// impulse P changes the angular momentum about any point O by
//     (c_B(f) + r_B - O) x P - (c_A(f) + r_A - O) x P = 0,
// and moving the bodies on from f keeps it: angular momentum is conserved to round-off.

#include "rigidlab/physics/math.h"

#include <algorithm>
#include <cmath>

namespace rigidlab::physics {

/// Whether a point with the gap `separation` [m] at the start of the step touches within it
/// at the normal velocity vn [m/s] (negative: approaching): touching already, or the gap
/// closes within dt [s].
/// atEnd: also a gap that closes at the end of the step, to a relative 1e-9 (the soft step's
/// collision phase: its substeps bring such a gap to touching, give or take round-off, and
/// their last relax pass would stop it without a bounce).
inline bool closesWithinStep(double separation, double vn, double dt, bool atEnd = false)
{
    constexpr double kEnd = 1.0 - 1e-9;
    return separation <= 0 || -vn * dt > separation || (atEnd && -vn * dt >= kEnd * separation);
}

/// The fraction of the step before a gap of `separation` [m] closes at the approach vn [m/s]
/// (0 when touching already, 1 when it does not close at that speed).
inline double impactFraction(double separation, double vn, double dt)
{
    if (separation <= 0)
        return 0.0;
    if (!(vn < 0))
        return 1.0;
    const double f = separation / (-vn * dt);
    return f < 1.0 ? f : 1.0;
}

/// The soft step's substeps of h [s] move a body under constant forces on the parabola
/// through their end points (soft_impacts.cpp, Flight): a gap closes along it as
///     s(t) = s + (vn0 + F h / (2 dt)) t + (F / dt) t^2 / 2,
/// vn0 the approach at the start [m/s] and F what the forces add to it over the step [m/s].
/// The fraction of the step at which a gap of `separation` [m] closes so: 0 when touching
/// already, more than 1 (kNeverCloses) when it does not close within the step. The
/// approach at that moment is vn0 + F (f + h / (2 dt)): the bounce's fraction in
/// bounceVelocity() is f + h / (2 dt).
inline constexpr double kNeverCloses = 2.0;
inline double substepImpactFraction(double separation, double vn0, double forcing, double dt,
                                    double h)
{
    if (separation <= 0)
        return 0.0;
    const double pull = forcing / dt; // [m/s^2]
    const double v = vn0 + 0.5 * h * pull;
    const double d = v * v - 2.0 * pull * separation;
    const double denominator = d >= 0 ? std::sqrt(d) - v : 0.0;
    if (!(denominator > 0))
        return kNeverCloses;
    // t = 2 s / (sqrt(d) - v). A gap that closes at the end of the step, to a relative 1e-9,
    // closes (the substeps bring it to touching, give or take round-off, and their last relax
    // pass would stop it without a bounce).
    constexpr double kEnd = 1.0 + 1e-9;
    const double f = 2.0 * separation / (denominator * dt);
    return f <= kEnd ? std::min(f, 1.0) : kNeverCloses;
}

/// The bounce itself: the normal velocity [m/s] that an approach vn [m/s] leaves with at the
/// impact, for the restitution e (Newton's law of restitution). Every solver's bounce is
/// this one expression: the impulse solvers' target (bounceVelocity), its update when other
/// impulses changed the approach (paper_impulse.cpp), and the soft step's isolated impact
/// (soft_impacts.cpp).
inline double rebound(double vn, double e)
{
    return -e * vn;
}

/// The normal velocity after a bounce [m/s] (see above): vn the approach now, e the
/// restitution, f the fraction of the step at the impact, forcing what the forces of the
/// whole step added to vn (0 for a contact touching at the start).
inline double bounceVelocity(double vn, double e, double f, double forcing)
{
    return rebound(vn, e) + (1.0 + e) * (1.0 - f) * forcing;
}

/// Where a body's centre of mass was at the fraction f of the step [m], from where it ends
/// (before the contact impulses) and its velocity then.
inline Vec2 centreAt(const Vec2& end, const Vec2& velocity, double f, double dt)
{
    return end - (1.0 - f) * dt * velocity;
}

/// The lever arms of a contact at the moment f of the step [m]: the manifold's point p0 at the
/// start, carried by each body (turned by f dt w, moved with its centre from c0 to c(f)),
/// and the midpoint of the two carried points taken as the one point both share.
struct LeverArms {
    Vec2 rA = Vec2::Zero(), rB = Vec2::Zero();
};
inline LeverArms leverArmsAt(const Vec2& p0, const Vec2& c0A, const Vec2& cA, double turnA,
                             const Vec2& c0B, const Vec2& cB, double turnB)
{
    const Vec2 pA = cA + Rotation(turnA).apply(p0 - c0A);
    const Vec2 pB = cB + Rotation(turnB).apply(p0 - c0B);
    const Vec2 p = 0.5 * (pA + pB);
    return {p - cA, p - cB};
}

} // namespace rigidlab::physics
