// SPDX-License-Identifier: GPL-3.0-or-later
// The soft step's isolated impacts (soft_step.cpp): two bodies, one contact, no other contact
// on either moving body. Such an impact is the textbook's, and gets its exact impulse.
//
// The collision phase shared with the sequential solver (contact_collisions.cpp) bounces a
// contact with the normal and points the narrow phase found at the start of the step, a few
// millimetres before the bodies touch: a cut shot of two billiard balls then pushes along a
// line a little off the line of centres at the impact, and the balls leave at 89.9995°. Here
// the moment of impact is found from the shapes themselves, and the impulse is taken there:
//
//     f         the gap s(f) of the bodies flown freely to the fraction f of the step (the
//               soft step's substeps: on the parabola through their end points, Flight; the
//               other solvers, to where the integrator put them: on a straight line), closed
//               from s by the root of s + vn t + an t^2 / 2 (vn the approach at f, an the
//               forces' pull along the normal; Newton's step on a line), until s is round-off.
//     impulse   the manifold at f: its normal, its touching points and lever arms from the
//               centres at f. The velocities at f (Flight::impactVelocity()) get the impulses
//               that turn each approach vn into -e vn, with Coulomb friction, solved to
//               convergence (one contact: a handful of passes).
//
// The impulse's velocity change is added to the end-of-step velocities (the forces act on
// after the impact as before it), and soft_step.cpp moves each body as if it had flown on
// until f, as for the collision phase's bounces. One impulse at one point both bodies share,
// about the centres where they are at the impact, conserves linear and angular momentum to
// round-off; at e = 1 without friction, kinetic energy too.

#include "rigidlab/physics/world.h"

#include "restitution.h"
#include "stages.h"

#include <algorithm>
#include <cmath>

namespace rigidlab::physics {

namespace {

/// A body's pose and velocities over the step, free flight: by the soft step's substeps
/// (Flown::ByForces) on the parabola through their end points, otherwise on a straight line.
///
/// Symplectic Euler with the substep h under a constant acceleration a puts the body after k
/// substeps at x0 + k h v0 + a h^2 k (k + 1) / 2: exactly on the parabola
///     x(t) = x0 + (v0 + a h / 2) t + a t^2 / 2,
/// whose velocity x'(t) runs h / 2 ahead of the substeps' velocity. An impulse at t turns that
/// parabola at t into another one, and the substeps then move the bodies on the turned one to
/// round-off (soft_step.cpp takes the velocity change back over t). So the impact is timed on
/// this parabola and the bounce turns its velocity x'(t): at e = 1 the parabola's apex stays
/// where it was, the height a ball was dropped from plus |g| h^2 / 8.
struct Flight {
    Vec2 x0 = Vec2::Zero();     ///< centre of mass at the start [m]
    double angle0 = 0;          ///< [rad]
    Vec2 v = Vec2::Zero();      ///< the path's velocity at the start [m/s]
    double w = 0;               ///< [rad/s]
    Vec2 vStart = Vec2::Zero(); ///< at the start of the step [m/s]
    double wStart = 0;          ///< [rad/s]
    Vec2 a = Vec2::Zero();      ///< applied load over mass [m/s^2]
    double alpha = 0;           ///< [rad/s^2]
    double invMass = 0, invInertia = 0;
    bool curved = false; ///< on the substeps' parabola (see above), else on a straight line

    Vec2 centre(double f, double dt) const
    {
        const double t = f * dt;
        return curved ? Vec2(x0 + t * v + (0.5 * t * t) * a) : Vec2(x0 + t * v);
    }
    Transform transform(const Body& b, double f, double dt) const
    {
        const double t = f * dt;
        Transform xf;
        xf.q = Rotation(angle0 + t * w + (curved ? 0.5 * t * t * alpha : 0.0));
        xf.p = centre(f, dt) - xf.q.apply(b.localCenter);
        return xf;
    }
    /// The velocity the path has at the fraction f [m/s], [rad/s].
    Vec2 pathVelocity(double f, double dt) const { return curved ? Vec2(v + (f * dt) * a) : v; }
    double pathSpin(double f, double dt) const { return curved ? w + f * dt * alpha : w; }
    /// The velocity that meets the impact at f: the path's on the parabola; on a line, the
    /// forces' share of the step so far on the velocity at the start.
    Vec2 impactVelocity(double f, double dt) const
    {
        return curved ? pathVelocity(f, dt) : Vec2(vStart + (f * dt) * a);
    }
    double impactSpin(double f, double dt) const
    {
        return curved ? pathSpin(f, dt) : wStart + f * dt * alpha;
    }
};

Flight flightOf(const StepContext& ctx, int id, Flown flown)
{
    const auto i = static_cast<size_t>(id);
    const Body& b = ctx.bodies[i];
    const StepScratch& s = ctx.scratch;
    Flight fl;
    fl.x0 = s.xfPosition[i];
    fl.angle0 = s.xfAngle[i];
    if (flown != Flown::ByForces) {
        // The integrator's motion in the step taken as a straight line at the mean velocity,
        // the velocity as changing evenly.
        const BodyPose end = flown == Flown::ToSmoothEnd
                                 ? s.smoothEnd[i]
                                 : BodyPose{b.position, b.angle, b.velocity, b.angularVelocity};
        fl.vStart = s.velocityAtStart[i];
        fl.wStart = s.angularVelocityAtStart[i];
        fl.v = end.velocity;
        fl.w = end.angularVelocity;
        if (b.isActive()) {
            const double invDt = ctx.invDt;
            fl.a = invDt * (end.velocity - fl.vStart);
            fl.alpha = invDt * (end.angularVelocity - fl.wStart);
            fl.v = invDt * (end.position - fl.x0);
            fl.w = invDt * (end.angle - fl.angle0);
            fl.invMass = b.invMass;
            fl.invInertia = b.invInertia;
        }
        return fl;
    }
    fl.vStart = b.velocity;
    fl.wStart = b.angularVelocity;
    fl.v = b.velocity;
    fl.w = b.angularVelocity;
    fl.curved = true;
    if (b.isActive()) {
        fl.a = s.acceleration[i];
        fl.alpha = s.angularAcceleration[i];
        fl.v += (0.5 * ctx.h) * fl.a;
        fl.w += 0.5 * ctx.h * fl.alpha;
        fl.invMass = b.invMass;
        fl.invInertia = b.invInertia;
    }
    return fl;
}

struct Velocity {
    Vec2 v = Vec2::Zero(); ///< [m/s]
    double w = 0;          ///< [rad/s]
};

/// The deepest point of a manifold: its index.
int deepest(const Manifold& m)
{
    return m.pointCount > 1 && m.points[1].separation < m.points[0].separation ? 1 : 0;
}

/// Relative normal velocity of B against A at the world point p [m/s].
double approach(const Velocity& a, const Velocity& b, const Vec2& p, const Vec2& cA, const Vec2& cB,
                const Vec2& n)
{
    return (b.v + cross(b.w, Vec2(p - cB)) - a.v - cross(a.w, Vec2(p - cA))).dot(n);
}

/// The fraction of the step at which the two bodies touch, flown freely, and their manifold
/// then; false when they do not touch within the step or the iteration does not settle.
bool timeOfImpact(const StepContext& ctx, const Contact& ct, const Flight& A, const Flight& B,
                  double& f, Manifold& m)
{
    const Body& a = ctx.bodies[static_cast<size_t>(ct.a)];
    const Body& b = ctx.bodies[static_cast<size_t>(ct.b)];
    const double dt = ctx.dt;
    double start = INFINITY;
    for (int i = 0; i < ct.manifold.pointCount; ++i)
        start = std::min(start, ct.manifold.points[static_cast<size_t>(i)].separation);
    const double margin = std::max(ctx.contactSettings.margin, 2.0 * std::abs(start)) + 1e-3;
    constexpr double kTouching = 1e-12; // [m]
    // On the parabola a step of the iteration may land past the root: there it steps back
    // from an overlap deeper than this [m]. (On a straight line the gap of convex shapes
    // approaching is convex in f, and each step lands short of the root.)
    constexpr double kOvershot = 1e-10;
    constexpr int kIterations = 50;
    f = 0.0;
    for (int k = 0; k < kIterations; ++k) {
        const Transform xfA = A.transform(a, f, dt), xfB = B.transform(b, f, dt);
        m = collideShapes(a.shape, xfA, b.shape, xfB, margin);
        if (m.pointCount == 0)
            return false;
        const ContactPoint& cp = m.points[static_cast<size_t>(deepest(m))];
        const double s = cp.separation;
        if (s <= kTouching && (k == 0 || !A.curved || s >= -kOvershot))
            return true; // touching (or overlapping already at the start, f = 0)
        const double vn = approach({A.pathVelocity(f, dt), A.pathSpin(f, dt)},
                                   {B.pathVelocity(f, dt), B.pathSpin(f, dt)}, cp.point,
                                   A.centre(f, dt), B.centre(f, dt), m.normal);
        // The gap's next root, the forces' pull along the normal taken as constant:
        // s + vn t + an t^2 / 2 = 0, in the form that keeps its digits (t = 2 s / (-vn + root)).
        // On a straight line (an = 0) and from below this is Newton's step.
        const double an = A.curved ? (B.a - A.a).dot(m.normal) : 0.0;
        const double d = vn * vn - 2.0 * an * s;
        const double denominator = d >= 0.0 ? std::sqrt(d) - vn : 0.0;
        if (!(denominator > 0.0))
            return false; // the gap does not close
        f += 2.0 * s / (denominator * dt);
        if (!(f <= 1.0) || f < 0.0)
            return false;
    }
    return false;
}

/// A touching point of an isolated impact: lever arms from the centres at the impact, its
/// effective masses, its target normal velocity and its accumulated impulses.
struct Arm {
    Vec2 rA = Vec2::Zero(), rB = Vec2::Zero(); ///< [m]
    double normalMass = 0, tangentMass = 0;    ///< [kg]
    double target = 0;                         ///< normal velocity after the impact [m/s]
    double normal = 0, tangent = 0;            ///< [N s]
};

/// Sequential impulses on this one contact, to convergence: normal impulses to their targets
/// (accumulated, never pulling), friction within its cone. Changes va and vb.
void solveImpact(Arm* arm, int count, const Vec2& n, double friction, const Flight& A,
                 const Flight& B, Velocity& va, Velocity& vb)
{
    const Vec2 t(n.y(), -n.x());
    auto apply = [&](const Arm& r, const Vec2& dir, double lambda) {
        va.v -= (A.invMass * lambda) * dir;
        va.w -= A.invInertia * lambda * cross(r.rA, dir);
        vb.v += (B.invMass * lambda) * dir;
        vb.w += B.invInertia * lambda * cross(r.rB, dir);
    };
    constexpr int kPasses = 500;
    for (int pass = 0; pass < kPasses; ++pass) {
        double change = 0.0, scale = 0.0;
        for (int i = 0; i < count; ++i) {
            Arm& r = arm[i];
            const double vn = (vb.v + cross(vb.w, r.rB) - va.v - cross(va.w, r.rA)).dot(n);
            const double next = std::max(r.normal + r.normalMass * (r.target - vn), 0.0);
            apply(r, n, next - r.normal);
            change = std::max(change, std::abs(next - r.normal));
            r.normal = next;
            const double vt = (vb.v + cross(vb.w, r.rB) - va.v - cross(va.w, r.rA)).dot(t);
            const double limit = friction * r.normal;
            const double nextT = std::clamp(r.tangent - r.tangentMass * vt, -limit, limit);
            apply(r, t, nextT - r.tangent);
            change = std::max(change, std::abs(nextT - r.tangent));
            r.tangent = nextT;
            scale = std::max(scale, r.normal);
        }
        if (change <= 1e-15 * scale)
            return;
    }
}

} // namespace

bool isolatedImpact(StepContext& ctx, const Contact& ct, double threshold, Flown flown,
                    IsolatedImpact& out)
{
    for (int i = 0; i < ct.manifold.pointCount; ++i)
        if (ct.normalImpulse[static_cast<size_t>(i)] != 0.0)
            return false; // a resting contact, carried from the step before
    const Flight A = flightOf(ctx, ct.a, flown), B = flightOf(ctx, ct.b, flown);
    if (A.invMass == 0.0 && B.invMass == 0.0)
        return false;
    double f = 0;
    Manifold m;
    if (!timeOfImpact(ctx, ct, A, B, f, m))
        return false;
    const double dt = ctx.dt;
    const Vec2 cA = A.centre(f, dt), cB = B.centre(f, dt);
    // The velocities at the impact (Flight::impactVelocity()).
    Velocity va{A.impactVelocity(f, dt), A.impactSpin(f, dt)};
    Velocity vb{B.impactVelocity(f, dt), B.impactSpin(f, dt)};
    if (A.invMass == 0.0) // a kinematic or static body keeps its velocity
        va = {A.v, A.w};
    if (B.invMass == 0.0)
        vb = {B.v, B.w};
    const Vec2 n = m.normal, t(n.y(), -n.x());
    const double least = m.points[static_cast<size_t>(deepest(m))].separation;
    constexpr double kFlat = 1e-9; // [m]: a second point this close touches too
    Arm arm[2];
    int count = 0;
    for (int i = 0; i < m.pointCount; ++i) {
        const ContactPoint& cp = m.points[static_cast<size_t>(i)];
        if (cp.separation > least + kFlat)
            continue;
        Arm& r = arm[count++];
        r.rA = cp.point - cA;
        r.rB = cp.point - cB;
        const double rnA = cross(r.rA, n), rnB = cross(r.rB, n);
        const double rtA = cross(r.rA, t), rtB = cross(r.rB, t);
        r.normalMass =
            1.0 / (A.invMass + B.invMass + A.invInertia * rnA * rnA + B.invInertia * rnB * rnB);
        r.tangentMass =
            1.0 / (A.invMass + B.invMass + A.invInertia * rtA * rtA + B.invInertia * rtB * rtB);
        const double vn = approach(va, vb, cp.point, cA, cB, n);
        r.target = vn < 0.0 ? rebound(vn, ct.restitution) : 0.0;
        if (i == deepest(m) && !(vn < -threshold))
            return false; // too slow to be an impact: the substeps' contact rests it
    }
    const Velocity before[2] = {va, vb};
    solveImpact(arm, count, n, ct.friction, A, B, va, vb);
    out = IsolatedImpact{};
    out.fraction = f;
    out.dvA = va.v - before[0].v;
    out.dwA = va.w - before[0].w;
    out.dvB = vb.v - before[1].v;
    out.dwB = vb.w - before[1].w;
    // The contact's points at the start of the step take the impulses of the points that
    // touched, by their order (a manifold found apart has its points in the same order).
    for (int i = 0; i < count && i < ct.manifold.pointCount; ++i)
        out.impulse[static_cast<size_t>(i)] = arm[i].normal;
    return true;
}

void countContactsOf(StepContext& ctx, std::vector<std::pair<int, int>>* pairs)
{
    StepScratch& s = ctx.scratch;
    s.contactsOf.assign(ctx.bodies.size(), 0);
    if (pairs)
        pairs->resize(ctx.contacts.size());
    for (size_t k = 0; k < ctx.contacts.size(); ++k) {
        const Contact& ct = ctx.contacts[k];
        ++s.contactsOf[static_cast<size_t>(ct.a)];
        ++s.contactsOf[static_cast<size_t>(ct.b)];
        if (pairs)
            (*pairs)[k] = {ct.a, ct.b};
    }
    // A pinned body is not free: its impact is the contact's and the pin's together, which
    // the solvers solve with the pins.
    for (const PinJointDef& j : ctx.joints)
        for (const BodyId id : {j.a, j.b})
            if (id != kWorld)
                s.contactsOf[static_cast<size_t>(id)] += 2;
}

bool findIsolatedImpacts(StepContext& ctx, double threshold, Flown flown)
{
    if (!ctx.plain)
        return findIsolatedImpactsFast(ctx, threshold, flown);
    StepScratch& s = ctx.scratch;
    s.impacts.clear();
    s.isolated.clear();
    countContactsOf(ctx, nullptr);
    const auto alone = [&](int id) {
        const auto i = static_cast<size_t>(id);
        return !ctx.bodies[i].isActive() || s.contactsOf[i] == 1;
    };
    for (size_t k = 0; k < ctx.contacts.size(); ++k) {
        const Contact& ct = ctx.contacts[k];
        IsolatedImpact impact;
        if (!alone(ct.a) || !alone(ct.b) || !isolatedImpact(ctx, ct, threshold, flown, impact))
            continue;
        if (s.isolated.empty())
            s.isolated.assign(ctx.contacts.size(), 0);
        s.isolated[k] = 1;
        s.impacts.emplace_back(static_cast<int>(k), impact);
    }
    return !s.impacts.empty();
}

} // namespace rigidlab::physics
