// SPDX-License-Identifier: GPL-3.0-or-later
// Stage::ContactSolve (profile.h): collision response by impulses, what the paper's impulse
// (paper_impulse.cpp) and sequential impulses (sequential_impulses.cpp) share: the
// constraints prepared from the contacts, their targets, the velocities stored back, the
// moments of the bounces and the position correction.
//
// Targets: a contact approaching faster than the restitution threshold bounces with
// vn' = -e vn; a contact with a gap (separation > 0) may close it within the step,
// vn' >= -separation / dt (a speculative contact), so that nothing bounces before touching.
//
// The sequential solver bounces in a collision phase of its own before the contact phase
// (Guendelman, Bridson and Fedkiw, "Nonconvex rigid bodies with stacking", SIGGRAPH 2003):
// each contact that closes within the step bounces from the approach it has when the sweep
// meets it, a pair's own impulse that at e = 1 keeps the energy and below takes some; then
// the contact phase solves with e = 0. With the restitution targets inside the iterations
// instead, a ball that bounced off a wall into a neighbour a few millimetres behind it was
// stopped by their speculative contact without a bounce (an elastic gas lost 5 % a minute),
// and simultaneous contacts gained energy (Newton's cradle, +0.19 % in a step). The targets
// and the lever arms of a bounce timed within the step are in restitution.h.

#include "contact_solver.h"

#include "restitution.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>

namespace rigidlab::physics {

namespace {

struct NamedSolver {
    SolverKind kind;
    std::string_view name;
};
constexpr std::array<NamedSolver, 3> kSolvers{{
    {SolverKind::PaperImpulse, "seed-impulse"},
    {SolverKind::SequentialImpulse, "sequential-impulse"},
    {SolverKind::SoftStep, "soft-step"},
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

void ContactSolver::begin(std::vector<Contact>& contacts, const std::vector<Contact>& previous,
                          std::vector<Body>& bodies, const ContactSettings& settings, double dt,
                          const std::vector<Vec2>& startPosition,
                          const std::vector<Vec2>& startVelocity,
                          const std::vector<double>& startAngularVelocity)
{
    m_contacts = &contacts;
    m_previous = &previous;
    m_bodies = &bodies;
    m_settings = &settings;
    m_dt = dt;
    m_startPosition = &startPosition;
    m_startVelocity = &startVelocity;
    m_startAngularVelocity = &startAngularVelocity;
    m_softPhase = false;
    m_leftOut = nullptr;
    m_constraints.clear();
    m_pins.clear();
    const size_t n = bodies.size();
    m_velocity.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const Body& b = bodies[i];
        m_velocity[i] = {b.velocity, b.angularVelocity};
    }
    if (m_rotationStamp.size() != n) {
        m_rotationStamp.assign(n, 0);
        m_rotation.resize(n);
    }
    newRotationEpoch();
}

void ContactSolver::newRotationEpoch()
{
    if (++m_stamp == 0) { // wrapped round: forget every stamp
        std::fill(m_rotationStamp.begin(), m_rotationStamp.end(), 0u);
        m_stamp = 1;
    }
}

const Rotation& ContactSolver::rotation(int body)
{
    const size_t i = static_cast<size_t>(body);
    if (m_rotationStamp[i] != m_stamp) {
        m_rotation[i] = Rotation((*m_bodies)[i].angle);
        m_rotationStamp[i] = m_stamp;
    }
    return m_rotation[i];
}

double ContactSolver::lastBounce(const Contact& ct, std::uint32_t id)
{
    const std::vector<Contact>& before = *m_previous;
    size_t& next = m_previousCursor;
    while (next < before.size() &&
           std::pair(before[next].a, before[next].b) < std::pair(ct.a, ct.b))
        ++next;
    if (next == before.size() || before[next].a != ct.a || before[next].b != ct.b)
        return 0.0;
    const Contact& last = before[next];
    for (int k = 0; k < last.manifold.pointCount; ++k)
        if (last.manifold.points[static_cast<size_t>(k)].id == id)
            return last.bounceImpulse[static_cast<size_t>(k)];
    return 0.0;
}

void ContactSolver::prepare(double impact, double resting)
{
    std::vector<Contact>& contacts = *m_contacts;
    const std::vector<Body>& bodies = *m_bodies;
    m_constraints.reserve(contacts.size());
    // Last step's contacts, walked with one cursor: both lists are sorted by pair.
    m_previousCursor = 0;
    for (size_t ci = 0; ci < contacts.size(); ++ci) {
        const Contact& ct = contacts[ci];
        const Body& a = bodies[static_cast<size_t>(ct.a)];
        const Body& b = bodies[static_cast<size_t>(ct.b)];
        if (!a.isActive() && !b.isActive())
            continue; // both asleep (or one asleep on a static body): nothing to solve
        if (m_leftOut && !m_leftOut->empty() && (*m_leftOut)[ci])
            continue; // solved exactly elsewhere
        Constraint& c = m_constraints.emplace_back();
        c.contact = static_cast<int>(ci);
        c.a = ct.a;
        c.b = ct.b;
        c.invMassA = a.isActive() ? a.invMass : 0.0;
        c.invIA = a.isActive() ? a.invInertia : 0.0;
        c.invMassB = b.isActive() ? b.invMass : 0.0;
        c.invIB = b.isActive() ? b.invInertia : 0.0;
        c.friction = ct.friction;
        c.count = ct.manifold.pointCount;
        // The velocities are solved on the geometry the narrow phase found at the start of
        // the step: its normal and points, with lever arms from the centres of mass of that
        // instant (as Box2D does). Placed again on the bodies as they stand after the
        // integration, a fast pair's normal would turn within the step, and a contact that was
        // barely separating could look as if it separated fast: pushing on it hands out
        // energy (an elastic gas heated up).
        c.normal = ct.manifold.normal;
        c.tangent = Vec2(c.normal.y(), -c.normal.x());
        c.restitution = ct.restitution;
        for (int i = 0; i < c.count; ++i)
            preparePoint(c, i, ct, impact, resting);
        prepareBounces(c, ct);
        if (c.count == 2)
            prepareBlock(c);
    }
}

void ContactSolver::preparePoint(Constraint& c, int i, const Contact& ct, double impact,
                                 double resting)
{
    const std::vector<Vec2>& x0 = *m_startPosition;
    const size_t ia = static_cast<size_t>(ct.a), ib = static_cast<size_t>(ct.b);
    const ContactPoint& cp = ct.manifold.points[static_cast<size_t>(i)];
    Point& p = c.p[i];
    p.normalImpulse = ct.normalImpulse[static_cast<size_t>(i)];
    p.tangentImpulse = ct.tangentImpulse[static_cast<size_t>(i)];
    p.bounceImpulse = 0.0;
    p.point = cp.point;
    p.timed = false;
    p.rA = cp.point - x0[ia];
    p.rB = cp.point - x0[ib];
    setMasses(c, i);

    // Target normal velocity, from the velocity before any impulse of this step.
    const double vn = normalVelocity(c, i, m_velocity[ia], m_velocity[ib]);
    const double sep = cp.separation;
    const double speculative = sep > 0 ? -sep / m_dt : 0.0;
    p.separation = sep;
    p.closes = closesWithinStep(sep, vn, m_dt, m_softPhase);
    p.bias = speculative;
    p.speculative = speculative;
    p.vnPrepared = vn;
    p.bounces = false;
    p.impact = 0.0;
    p.forcing = 0.0;
    // A point that pushed in the step before is resting (its impulse was carried over):
    // it keeps the larger threshold, so that a stack does not hop on the solver's
    // leftovers; a new contact bounces from the small one. What it carried from a
    // bounce (the collision phase's part, Contact::bounceImpulse) is neither warm
    // started nor a reason to stop bouncing: only the rest, and friction in proportion.
    if (p.normalImpulse > 0) {
        if (vn > std::max(impact, resting)) {
            // Separating faster than a resting contact may bounce: not resting.
            p.normalImpulse = p.tangentImpulse = 0.0;
        } else if (const double bounced = lastBounce(ct, cp.id); bounced > 0) {
            const double rest = std::max(p.normalImpulse - bounced, 0.0);
            p.tangentImpulse *= rest / p.normalImpulse;
            p.normalImpulse = rest;
        }
    }
    p.threshold = p.normalImpulse > 0 ? std::max(impact, resting) : impact;
    if (m_softPhase) {
        // Timed on the substeps' parabola, touching already or not (restitution.h).
        p.forcing = vn - startNormalVelocity(c, i);
        p.impact = substepImpactFraction(sep, vn - p.forcing, p.forcing, m_dt, m_substep);
        p.closes = p.impact <= 1.0;
    } else if (sep > 0) {
        const double vn0 = startNormalVelocity(c, i);
        p.forcing = vn - vn0;
        p.impact = impactFraction(sep, vn0, m_dt);
    }
    p.bounces = p.closes && vn < -p.threshold;
}

void ContactSolver::prepareBounces(Constraint& c, const Contact& ct)
{
    const size_t ia = static_cast<size_t>(ct.a), ib = static_cast<size_t>(ct.b);
    // Bounces within the step: the lever arms at the moment of impact, the earliest of the
    // manifold's points (the body's velocity change is placed there, impactFractions()).
    double first = 1.0;
    for (int i = 0; i < c.count; ++i)
        if (c.p[i].bounces && c.p[i].separation > 0)
            first = std::min(first, c.p[i].impact);
    for (int i = 0; i < c.count; ++i) {
        Point& p = c.p[i];
        if (!p.bounces)
            continue;
        p.bounces = false;
        if (p.separation > 0) {
            placeAt(c, i, first);
            p.impact = first;
            p.vnPrepared = normalVelocity(c, i, m_velocity[ia], m_velocity[ib]);
            p.forcing = p.vnPrepared - startNormalVelocity(c, i);
        }
        const double bounce = bounceVelocity(p.vnPrepared, ct.restitution,
                                             p.separation > 0 ? p.impact : 0.0, p.forcing);
        if (bounce > p.speculative && bounce >= 0) {
            p.bias = bounce;
            p.bounces = true;
        }
    }
    for (Point& p : c.p)
        if (!p.bounces)
            p.impact = 0.0;
}

double ContactSolver::startNormalVelocity(const Constraint& c, int i) const
{
    const Point& p = c.p[i];
    const size_t ia = static_cast<size_t>(c.a), ib = static_cast<size_t>(c.b);
    const std::vector<Vec2>& v0 = *m_startVelocity;
    const std::vector<double>& w0 = *m_startAngularVelocity;
    return (v0[ib] + cross(w0[ib], p.rB) - v0[ia] - cross(w0[ia], p.rA)).dot(c.normal);
}

void ContactSolver::setMasses(Constraint& c, int i)
{
    Point& p = c.p[i];
    const double mA = c.invMassA, iA = c.invIA, mB = c.invMassB, iB = c.invIB;
    p.rnA = cross(p.rA, c.normal);
    p.rnB = cross(p.rB, c.normal);
    const double kn = mA + mB + iA * p.rnA * p.rnA + iB * p.rnB * p.rnB;
    p.normalMass = kn > 0 ? 1.0 / kn : 0.0;
    p.rtA = cross(p.rA, c.tangent);
    p.rtB = cross(p.rB, c.tangent);
    const double kt = mA + mB + iA * p.rtA * p.rtA + iB * p.rtB * p.rtB;
    p.tangentMass = kt > 0 ? 1.0 / kt : 0.0;
}

void ContactSolver::prepareBlock(Constraint& c)
{
    const Point &p1 = c.p[0], &p2 = c.p[1];
    const double mA = c.invMassA, iA = c.invIA, mB = c.invMassB, iB = c.invIB;
    const double rn1A = p1.rnA, rn1B = p1.rnB, rn2A = p2.rnA, rn2B = p2.rnB;
    const double k11 = mA + mB + iA * rn1A * rn1A + iB * rn1B * rn1B;
    const double k22 = mA + mB + iA * rn2A * rn2A + iB * rn2B * rn2B;
    const double k12 = mA + mB + iA * rn1A * rn2A + iB * rn1B * rn2B;
    // Solve the pair together only while K is well conditioned.
    constexpr double kMaxCondition = 1000.0;
    const double det = k11 * k22 - k12 * k12;
    c.block = k11 * k11 < kMaxCondition * det;
    if (c.block) {
        c.k11 = k11;
        c.k12 = k12;
        c.k22 = k22;
        const double inv = 1.0 / det;
        c.m11 = inv * k22;
        c.m12 = -inv * k12;
        c.m22 = inv * k11;
    }
}

void ContactSolver::storeVelocities()
{
    std::vector<Body>& bodies = *m_bodies;
    for (size_t i = 0; i < bodies.size(); ++i) {
        Body& b = bodies[i];
        if (!b.isActive())
            continue;
        b.velocity = m_velocity[i].v;
        b.angularVelocity = m_velocity[i].w;
    }
}

void ContactSolver::store()
{
    storeVelocities();
    for (const Constraint& c : m_constraints) {
        Contact& ct = (*m_contacts)[static_cast<size_t>(c.contact)];
        for (int i = 0; i < c.count; ++i) {
            // Bounce and contact together: what the lessons measure, and what warm starts the
            // next step if the point then rests (prepare() drops it if it separates).
            ct.normalImpulse[static_cast<size_t>(i)] = c.p[i].normalImpulse + c.p[i].bounceImpulse;
            ct.bounceImpulse[static_cast<size_t>(i)] = c.p[i].bounceImpulse;
            ct.tangentImpulse[static_cast<size_t>(i)] = c.p[i].tangentImpulse;
        }
    }
}

bool ContactSolver::appliedImpulse() const
{
    for (const Constraint& c : m_constraints)
        if (c.p[0].normalImpulse > 0 || c.p[1].normalImpulse > 0 || c.p[0].bounceImpulse > 0 ||
            c.p[1].bounceImpulse > 0)
            return true;
    return false;
}

const std::vector<double>& ContactSolver::impactFractions()
{
    // A body bounced by every contact that pushed it moved freely until its earliest impact;
    // any contact that pushed it without a bounce (resting) makes it 0. The paper's impulses
    // are its bounces; the sequential solver's bounces are its collision phase's.
    // In the soft step's collision phase a bounce may come at the very end of the step
    // (f = 1): placed there, not taken for "untouched" (which moved the body by a whole step
    // of its rebound from where it started: at dt = 0.2 s a dropped ball rose to 6 m). The
    // other solvers keep their bits (their golden runs).
    const double untouched = m_softPhase ? kNeverCloses : 1.0;
    m_impact.assign(m_bodies->size(), untouched);
    for (const Constraint& c : m_constraints) {
        for (int i = 0; i < c.count; ++i) {
            const Point& p = c.p[i];
            if (m_softPhase && !(p.bounceImpulse > 0) && !(p.normalImpulse > 0))
                continue;
            double at = 1.0;
            if (p.bounceImpulse > 0)
                at = p.impact;
            if (p.normalImpulse > 0)
                at = std::min(at, m_paperImpulse ? p.impact : 0.0);
            if (at == 1.0 && !m_softPhase)
                continue;
            for (int id : {c.a, c.b}) {
                double& f = m_impact[static_cast<size_t>(id)];
                f = std::min(f, at);
            }
        }
    }
    for (double& f : m_impact)
        if (f == untouched)
            f = 0.0; // untouched: no velocity change to place
    return m_impact;
}

int ContactSolver::solvePositions(int passes)
{
    std::vector<Body>& bodies = *m_bodies;
    const ContactSettings& s = *m_settings;
    // The bodies have moved since prepare(): rotations anew. Each is computed again only
    // after a correction turned its body; most points need none (within the slop), and a
    // static body never turns, so most sines and cosines are saved.
    newRotationEpoch();
    auto transform = [&](int id, const Body& body) {
        Transform xf;
        xf.q = rotation(id);
        xf.p = body.position - xf.q.apply(body.localCenter);
        return xf;
    };
    int made = 0;
    while (made < passes) {
        ++made;
        double worst = 0.0;
        for (const Constraint& c : m_constraints) {
            const Contact& ct = (*m_contacts)[static_cast<size_t>(c.contact)];
            Body& a = bodies[static_cast<size_t>(c.a)];
            Body& b = bodies[static_cast<size_t>(c.b)];
            for (int i = 0; i < c.count; ++i) {
                Vec2 n, point;
                double sep;
                evaluateManifoldPoint(ct.manifold, i, transform(c.a, a), transform(c.b, b), n,
                                      point, sep);
                const Vec2 rA = point - a.position, rB = point - b.position;
                worst = std::min(worst, sep);
                // Remove a fraction of the penetration beyond the slop, never more than the cap.
                const double C =
                    std::clamp(s.baumgarte * (sep + s.linearSlop), -s.maxCorrection, 0.0);
                const double rnA = cross(rA, n), rnB = cross(rB, n);
                const double k =
                    c.invMassA + c.invMassB + c.invIA * rnA * rnA + c.invIB * rnB * rnB;
                if (k <= 0 || C == 0.0)
                    continue;
                const Vec2 P = (-C / k) * n;
                a.position -= c.invMassA * P;
                a.angle -= c.invIA * cross(rA, P);
                b.position += c.invMassB * P;
                b.angle += c.invIB * cross(rB, P);
                if (c.invIA != 0.0)
                    m_rotationStamp[static_cast<size_t>(c.a)] = 0;
                if (c.invIB != 0.0)
                    m_rotationStamp[static_cast<size_t>(c.b)] = 0;
            }
        }
        solvePinPositions();
        if (worst >= -3.0 * s.linearSlop)
            break;
    }
    return made;
}

} // namespace rigidlab::physics
