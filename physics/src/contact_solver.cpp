// Stage 5 of a step: collision response by impulses.
//
// The seed's impulse (its equations 1.1-1.6): with n from A to B and the relative normal
// velocity vn = (vB + wB x rB - vA - wA x rA) . n < 0, the impulse
//     j = -(1 + e) vn / (1/mA + 1/mB + (rA x n)^2 / IA + (rB x n)^2 / IB)
// changes vA by -j n / mA, vB by +j n / mB, wA by -(rA x j n) / IA and wB by +(rB x j n) / IB.
// The paper prints the denominator without its rotational terms; without them an off-centre
// hit does not conserve energy at e = 1.
//
// Sequential impulses (Catto, "Iterative Dynamics with Temporal Coherence", GDC 2005): the
// same impulse, applied repeatedly to every contact, accumulated and clamped so that the
// total stays pushing (>= 0) and friction stays inside its cone, warm started from the last
// step so that resting stacks converge. Two points of one manifold are solved together as a
// 2x2 linear complementarity problem by trying its four cases (as in Box2D 2.x).
//
// Targets: a contact approaching faster than the restitution threshold bounces with
// vn' = -e vn; a contact with a gap (separation > 0) may close it within the step,
// vn' >= -separation / dt (a speculative contact), so that nothing bounces before touching.

#include "contact_solver.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>

namespace rigidlab::physics {

namespace {

struct NamedSolver {
    SolverKind kind;
    std::string_view name;
};
constexpr std::array<NamedSolver, 2> kSolvers{{
    {SolverKind::SeedImpulse, "seed-impulse"},
    {SolverKind::SequentialImpulse, "sequential-impulse"},
}};

} // namespace

std::string_view solverName(SolverKind kind)
{
    for (const auto& s : kSolvers)
        if (s.kind == kind)
            return s.name;
    return "?";
}

std::optional<SolverKind> solverFromName(std::string_view name)
{
    for (const auto& s : kSolvers)
        if (s.name == name)
            return s.kind;
    return std::nullopt;
}

ContactSolver::ContactSolver(std::vector<Contact>& contacts, std::vector<Body>& bodies,
                             const ContactSettings& settings, double dt,
                             const std::vector<Vec2>& startVelocity,
                             const std::vector<double>& startAngularVelocity)
    : m_contacts(contacts), m_bodies(bodies), m_settings(settings), m_dt(dt),
      m_startVelocity(startVelocity), m_startAngularVelocity(startAngularVelocity)
{
}

double ContactSolver::normalVelocity(const Constraint& c, int i) const
{
    const Contact& ct = m_contacts[static_cast<size_t>(c.contact)];
    const Body& a = m_bodies[static_cast<size_t>(ct.a)];
    const Body& b = m_bodies[static_cast<size_t>(ct.b)];
    const Point& p = c.p[i];
    const Vec2 dv =
        b.velocity + cross(b.angularVelocity, p.rB) - a.velocity - cross(a.angularVelocity, p.rA);
    return dv.dot(c.normal);
}

void ContactSolver::prepare(double threshold)
{
    m_constraints.clear();
    m_constraints.reserve(m_contacts.size());
    for (size_t ci = 0; ci < m_contacts.size(); ++ci) {
        const Contact& ct = m_contacts[ci];
        const Body& a = m_bodies[static_cast<size_t>(ct.a)];
        const Body& b = m_bodies[static_cast<size_t>(ct.b)];
        Constraint c;
        c.contact = static_cast<int>(ci);
        c.count = ct.manifold.pointCount;
        // The manifold was found where the bodies stood at the start of the step; they have
        // moved since. Its points and normal are placed again on the bodies as they are now,
        // so that the lever arms belong to the same instant as the centres (else a
        // frictionless ball would pick up spin). The separations stay those of the start,
        // which time the contact within the step.
        const Transform xfA = a.transform(), xfB = b.transform();
        std::array<Vec2, 2> points{};
        for (int i = 0; i < c.count; ++i) {
            double sepNow;
            evaluateManifoldPoint(ct.manifold, i, xfA, xfB, c.normal,
                                  points[static_cast<size_t>(i)], sepNow);
        }
        c.tangent = Vec2(c.normal.y(), -c.normal.x());
        for (int i = 0; i < c.count; ++i) {
            const ContactPoint& cp = ct.manifold.points[static_cast<size_t>(i)];
            Point& p = c.p[i];
            p.rA = points[static_cast<size_t>(i)] - a.position;
            p.rB = points[static_cast<size_t>(i)] - b.position;
            const double rnA = cross(p.rA, c.normal), rnB = cross(p.rB, c.normal);
            const double kn =
                a.invMass + b.invMass + a.invInertia * rnA * rnA + b.invInertia * rnB * rnB;
            p.normalMass = kn > 0 ? 1.0 / kn : 0.0;
            const double rtA = cross(p.rA, c.tangent), rtB = cross(p.rB, c.tangent);
            const double kt =
                a.invMass + b.invMass + a.invInertia * rtA * rtA + b.invInertia * rtB * rtB;
            p.tangentMass = kt > 0 ? 1.0 / kt : 0.0;

            // Target normal velocity, from the velocity before any impulse of this step.
            const double vn = normalVelocity(c, i);
            const double sep = cp.separation;
            const double speculative = sep > 0 ? -sep / m_dt : 0.0;
            p.closes = sep <= 0 || -vn * m_dt > sep;
            p.bias = speculative;
            p.impact = 0.0;
            if (p.closes && vn < -threshold) {
                double bounce = -ct.restitution * vn;
                double fraction = 0.0;
                if (sep > 0) {
                    // The gap closes within this step: time the impact. At the start of the
                    // step the normal velocity was vn0; the gap closes after the fraction f
                    // of the step, at about vn0 + f (vn - vn0). The bounce reverses that,
                    // and the forces act on for the rest of the step.
                    const size_t ia = static_cast<size_t>(ct.a), ib = static_cast<size_t>(ct.b);
                    const double vn0 =
                        (m_startVelocity[ib] + cross(m_startAngularVelocity[ib], p.rB) -
                         m_startVelocity[ia] - cross(m_startAngularVelocity[ia], p.rA))
                            .dot(c.normal);
                    fraction = vn0 < 0 ? std::clamp(sep / (-vn0 * m_dt), 0.0, 1.0) : 1.0;
                    const double atImpact = vn0 + fraction * (vn - vn0);
                    bounce = -ct.restitution * atImpact + (1.0 - fraction) * (vn - vn0);
                }
                if (bounce > speculative && bounce >= 0) {
                    p.bias = bounce;
                    p.impact = fraction;
                }
            }
        }
        if (c.count == 2) {
            const Point &p1 = c.p[0], &p2 = c.p[1];
            const double rn1A = cross(p1.rA, c.normal), rn1B = cross(p1.rB, c.normal);
            const double rn2A = cross(p2.rA, c.normal), rn2B = cross(p2.rB, c.normal);
            const double k11 =
                a.invMass + b.invMass + a.invInertia * rn1A * rn1A + b.invInertia * rn1B * rn1B;
            const double k22 =
                a.invMass + b.invMass + a.invInertia * rn2A * rn2A + b.invInertia * rn2B * rn2B;
            const double k12 =
                a.invMass + b.invMass + a.invInertia * rn1A * rn2A + b.invInertia * rn1B * rn2B;
            // Solve the pair together only while K is well conditioned.
            constexpr double kMaxCondition = 1000.0;
            if (k11 * k11 < kMaxCondition * (k11 * k22 - k12 * k12)) {
                c.block = true;
                c.k << k11, k12, k12, k22;
                c.normalMassBlock = c.k.inverse();
            }
        }
        m_constraints.push_back(c);
    }
}

void ContactSolver::warmStart()
{
    for (Constraint& c : m_constraints) {
        Contact& ct = m_contacts[static_cast<size_t>(c.contact)];
        Body& a = m_bodies[static_cast<size_t>(ct.a)];
        Body& b = m_bodies[static_cast<size_t>(ct.b)];
        for (int i = 0; i < c.count; ++i) {
            const Vec2 P = ct.normalImpulse[static_cast<size_t>(i)] * c.normal +
                           ct.tangentImpulse[static_cast<size_t>(i)] * c.tangent;
            a.velocity -= a.invMass * P;
            a.angularVelocity -= a.invInertia * cross(c.p[i].rA, P);
            b.velocity += b.invMass * P;
            b.angularVelocity += b.invInertia * cross(c.p[i].rB, P);
        }
    }
}

void ContactSolver::solveFriction(Constraint& c)
{
    for (int i = 0; i < c.count; ++i)
        solveFrictionPoint(c, i);
}

void ContactSolver::solveFrictionPoint(Constraint& c, int i)
{
    Contact& ct = m_contacts[static_cast<size_t>(c.contact)];
    Body& a = m_bodies[static_cast<size_t>(ct.a)];
    Body& b = m_bodies[static_cast<size_t>(ct.b)];
    Point& p = c.p[i];
    const Vec2 dv =
        b.velocity + cross(b.angularVelocity, p.rB) - a.velocity - cross(a.angularVelocity, p.rA);
    const double vt = dv.dot(c.tangent);
    double& acc = ct.tangentImpulse[static_cast<size_t>(i)];
    const double limit = ct.friction * ct.normalImpulse[static_cast<size_t>(i)];
    const double next = std::clamp(acc - p.tangentMass * vt, -limit, limit);
    const double lambda = next - acc;
    acc = next;
    const Vec2 P = lambda * c.tangent;
    a.velocity -= a.invMass * P;
    a.angularVelocity -= a.invInertia * cross(p.rA, P);
    b.velocity += b.invMass * P;
    b.angularVelocity += b.invInertia * cross(p.rB, P);
}

void ContactSolver::solveNormalPoint(Constraint& c, int i)
{
    Contact& ct = m_contacts[static_cast<size_t>(c.contact)];
    Body& a = m_bodies[static_cast<size_t>(ct.a)];
    Body& b = m_bodies[static_cast<size_t>(ct.b)];
    Point& p = c.p[i];
    const double vn = normalVelocity(c, i);
    double& acc = ct.normalImpulse[static_cast<size_t>(i)];
    const double next = std::max(acc - p.normalMass * (vn - p.bias), 0.0);
    const double lambda = next - acc;
    acc = next;
    const Vec2 P = lambda * c.normal;
    a.velocity -= a.invMass * P;
    a.angularVelocity -= a.invInertia * cross(p.rA, P);
    b.velocity += b.invMass * P;
    b.angularVelocity += b.invInertia * cross(p.rB, P);
}

void ContactSolver::solveNormalBlock(Constraint& c)
{
    // Find accumulated impulses x >= 0 with vn = K (x - x_old) + vn_now and, per point,
    // either x_i = 0 and vn_i >= bias_i, or x_i > 0 and vn_i = bias_i. With
    // b = vn_now - bias - K x_old the conditions read  w = K x + b,  x >= 0, w >= 0, x.w = 0.
    Contact& ct = m_contacts[static_cast<size_t>(c.contact)];
    Body& a = m_bodies[static_cast<size_t>(ct.a)];
    Body& b = m_bodies[static_cast<size_t>(ct.b)];
    const Eigen::Vector2d old(ct.normalImpulse[0], ct.normalImpulse[1]);
    Eigen::Vector2d rhs(normalVelocity(c, 0) - c.p[0].bias, normalVelocity(c, 1) - c.p[1].bias);
    rhs -= c.k * old;

    Eigen::Vector2d x;
    auto accept = [&](const Eigen::Vector2d& cand) {
        x = cand;
        return true;
    };
    bool found = false;
    // Case 1: both points pushing.
    {
        const Eigen::Vector2d cand = -(c.normalMassBlock * rhs);
        if (cand.x() >= 0 && cand.y() >= 0)
            found = accept(cand);
    }
    // Case 2: only the first point pushing.
    if (!found) {
        const Eigen::Vector2d cand(-c.p[0].normalMass * rhs.x(), 0.0);
        const double w2 = c.k(1, 0) * cand.x() + rhs.y();
        if (cand.x() >= 0 && w2 >= 0)
            found = accept(cand);
    }
    // Case 3: only the second point pushing.
    if (!found) {
        const Eigen::Vector2d cand(0.0, -c.p[1].normalMass * rhs.y());
        const double w1 = c.k(0, 1) * cand.y() + rhs.x();
        if (cand.y() >= 0 && w1 >= 0)
            found = accept(cand);
    }
    // Case 4: neither pushing.
    if (!found) {
        if (rhs.x() >= 0 && rhs.y() >= 0)
            found = accept(Eigen::Vector2d::Zero());
    }
    if (!found) {
        // Round-off left no exact case: fall back to point by point.
        solveNormalPoint(c, 0);
        solveNormalPoint(c, 1);
        return;
    }
    const Eigen::Vector2d d = x - old;
    const Vec2 P1 = d.x() * c.normal, P2 = d.y() * c.normal;
    a.velocity -= a.invMass * (P1 + P2);
    a.angularVelocity -= a.invInertia * (cross(c.p[0].rA, P1) + cross(c.p[1].rA, P2));
    b.velocity += b.invMass * (P1 + P2);
    b.angularVelocity += b.invInertia * (cross(c.p[0].rB, P1) + cross(c.p[1].rB, P2));
    ct.normalImpulse = {x.x(), x.y()};
}

void ContactSolver::solveSequential(int iterations, bool warm)
{
    prepare(m_settings.restitutionThreshold);
    if (warm)
        warmStart();
    else
        for (Contact& ct : m_contacts)
            ct.normalImpulse = ct.tangentImpulse = {0.0, 0.0};
    for (int it = 0; it < iterations; ++it) {
        for (Constraint& c : m_constraints) {
            // Friction first: its limit uses the normal impulse, and normal wins the last word.
            solveFriction(c);
            if (c.block)
                solveNormalBlock(c);
            else
                for (int i = 0; i < c.count; ++i)
                    solveNormalPoint(c, i);
        }
    }
}

void ContactSolver::solveSeed()
{
    for (Contact& ct : m_contacts)
        ct.normalImpulse = ct.tangentImpulse = {0.0, 0.0};
    // The seed has no threshold: every approaching contact gets its impulse, once, in order.
    prepare(0.0);
    for (Constraint& c : m_constraints) {
        for (int i = 0; i < c.count; ++i) {
            if (!c.p[i].closes || normalVelocity(c, i) >= 0)
                continue; // separating, or will not reach the other body this step
            solveNormalPoint(c, i);
            solveFrictionPoint(c, i);
        }
    }
}

bool ContactSolver::appliedImpulse() const
{
    for (const Contact& ct : m_contacts)
        if (ct.normalImpulse[0] > 0 || ct.normalImpulse[1] > 0)
            return true;
    return false;
}

std::vector<double> ContactSolver::impactFractions() const
{
    // A body bounced by every contact that pushed it moved freely until its earliest impact;
    // any contact that pushed it without a bounce (resting) makes it 0.
    std::vector<double> fraction(m_bodies.size(), 1.0);
    for (const Constraint& c : m_constraints) {
        const Contact& ct = m_contacts[static_cast<size_t>(c.contact)];
        for (int i = 0; i < c.count; ++i) {
            if (ct.normalImpulse[static_cast<size_t>(i)] <= 0)
                continue;
            for (BodyId id : {ct.a, ct.b}) {
                double& f = fraction[static_cast<size_t>(id)];
                f = std::min(f, c.p[i].impact);
            }
        }
    }
    for (double& f : fraction)
        if (f == 1.0)
            f = 0.0; // untouched: no velocity change to place
    return fraction;
}

bool ContactSolver::solvePositions()
{
    double worst = 0.0;
    for (Contact& ct : m_contacts) {
        Body& a = m_bodies[static_cast<size_t>(ct.a)];
        Body& b = m_bodies[static_cast<size_t>(ct.b)];
        for (int i = 0; i < ct.manifold.pointCount; ++i) {
            Vec2 n, point;
            double sep;
            evaluateManifoldPoint(ct.manifold, i, a.transform(), b.transform(), n, point, sep);
            const Vec2 rA = point - a.position, rB = point - b.position;
            worst = std::min(worst, sep);
            // Remove a fraction of the penetration beyond the slop, never more than the cap.
            const double C = std::clamp(m_settings.baumgarte * (sep + m_settings.linearSlop),
                                        -m_settings.maxCorrection, 0.0);
            const double rnA = cross(rA, n), rnB = cross(rB, n);
            const double k =
                a.invMass + b.invMass + a.invInertia * rnA * rnA + b.invInertia * rnB * rnB;
            if (k <= 0 || C == 0.0)
                continue;
            const Vec2 P = (-C / k) * n;
            a.position -= a.invMass * P;
            a.angle -= a.invInertia * cross(rA, P);
            b.position += b.invMass * P;
            b.angle += b.invInertia * cross(rB, P);
        }
    }
    return worst >= -3.0 * m_settings.linearSlop;
}

} // namespace rigidlab::physics
