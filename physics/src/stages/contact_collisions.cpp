// SPDX-License-Identifier: GPL-3.0-or-later
// Stage::ContactSolve (profile.h): the sequential solver's collision phase (contact_solver.h,
// solveCollisions()), before its contact phase (sequential_impulses.cpp).
//
// Guendelman, Bridson and Fedkiw, "Nonconvex rigid bodies with stacking" (SIGGRAPH 2003):
// sweep over the contacts; each one that closes within the step and approaches faster than
// its threshold gets the impulse that turns its approach vn, as it is at that moment, into
// the bounce -e vn (restitution.h); repeat until a sweep finds none. An impulse between two
// bodies alone changes their kinetic energy by (1 - e)/2 j vn <= 0 (j >= 0, vn < 0), and two
// points of one manifold solved as a 2x2 complementarity problem with these targets do the
// same, so no sweep adds energy: an elastic gas keeps it, a row of touching balls passes the
// striker's velocity to the last one.
//
//     sweep 1:  |wall| (A)<-  (B)<-     A bounces off the wall, then off B (B was 3 mm behind
//     sweep 2:  |wall| (A)<-  ->(B)     and approached slowly at the start of the step); A
//     sweep 3:  |wall| ->(A)  ->(B)     bounces off the wall again; nothing approaches.

#include "contact_solver.h"

#include "restitution.h"

#include <algorithm>

namespace rigidlab::physics {

void ContactSolver::placeAt(Constraint& c, int i, double f)
{
    // A bounce at the fraction f of the step: the bodies stand where they were then. Their
    // velocity change from this impulse moves them by (1 - f) dt times it (impactFractions()),
    // so the centres at f are where they end minus (1 - f) dt times the velocity before the
    // solve (restitution.h); with these arms angular momentum about any point is conserved.
    Point& p = c.p[i];
    const std::vector<Body>& bodies = *m_bodies;
    const std::vector<Vec2>& x0 = *m_startPosition;
    const Body& a = bodies[static_cast<size_t>(c.a)];
    const Body& b = bodies[static_cast<size_t>(c.b)];
    const double turn = f * m_dt;
    const Vec2 cA = a.moves() ? centreAt(a.position, a.velocity, f, m_dt) : a.position;
    const Vec2 cB = b.moves() ? centreAt(b.position, b.velocity, f, m_dt) : b.position;
    const LeverArms arms =
        leverArmsAt(p.point, x0[static_cast<size_t>(c.a)], cA, turn * a.angularVelocity,
                    x0[static_cast<size_t>(c.b)], cB, turn * b.angularVelocity);
    p.rA = arms.rA;
    p.rB = arms.rB;
    p.timed = true;
    setMasses(c, i);
    if (c.count == 2)
        prepareBlock(c);
}

[[gnu::always_inline]] inline void ContactSolver::applyNormal(Constraint& c, int i, double lambda,
                                                              Velocity& a, Velocity& b)
{
    const Point& p = c.p[i];
    a.v -= (c.invMassA * lambda) * c.normal;
    a.w -= c.invIA * lambda * p.rnA;
    b.v += (c.invMassB * lambda) * c.normal;
    b.w += c.invIB * lambda * p.rnB;
}

bool ContactSolver::bounceTarget(Constraint& c, int i, const Velocity& a, const Velocity& b,
                                 double& target)
{
    if (m_exempt && (*m_exempt)[static_cast<size_t>(c.contact)])
        return false;
    Point& p = c.p[i];
    double vn = normalVelocity(c, i, a, b);
    // A point already timed closes within the step: its lever arms at the impact may make its
    // approach a little slower than the one that timed it (a spinning ball whose gap closes
    // at 0.99 of the step), and the bounce must not be left to the contacts for that (the
    // soft step's stopped it short of touching: an elastic gas lost 0.4 % in 5 s). Only for
    // the soft step (m_softPhase): the sequential solver keeps its bits (its golden runs).
    // The soft step times it on its substeps' parabola (restitution.h), from the approach it
    // has now less what the forces add over the step.
    const double soft = m_softPhase ? substepImpactFraction(p.separation, vn - p.forcing, p.forcing,
                                                            m_dt, m_substep)
                                    : kNeverCloses;
    const bool closes =
        m_softPhase ? p.timed || soft <= 1.0 : closesWithinStep(p.separation, vn, m_dt);
    if (!closes || !(vn < -p.threshold))
        return false;
    if (p.separation > 0 && !p.timed) {
        // It closes only now, after other impulses of this step (a ball that bounced off a
        // wall into a neighbour): time it from the approach it has now.
        p.impact = m_softPhase ? soft : impactFraction(p.separation, vn, m_dt);
        placeAt(c, i, p.impact);
        vn = normalVelocity(c, i, a, b);
    }
    // On the soft step's parabola the approach at f is that of f + h / (2 dt) on the line.
    const double f = p.separation > 0 || m_softPhase ? p.impact : 0.0;
    target =
        bounceVelocity(vn, c.restitution, m_softPhase ? f + 0.5 * m_substep / m_dt : f, p.forcing);
    return target >= 0 && target > vn;
}

int ContactSolver::solveCollisions(int sweeps)
{
    int made = 0;
    while (made < sweeps) {
        ++made;
        bool bounced = false;
        for (Constraint& c : m_constraints) {
            Velocity& a = m_velocity[static_cast<size_t>(c.a)];
            Velocity& b = m_velocity[static_cast<size_t>(c.b)];
            double target[2] = {0, 0};
            bool bounce[2] = {false, false};
            for (int i = 0; i < c.count; ++i)
                bounce[i] = bounceTarget(c, i, a, b, target[i]);
            if (!bounce[0] && !bounce[1])
                continue;
            bounced = true;
            if (c.count == 2 && bounce[0] && bounce[1] && c.block) {
                // Both points at once: the 2x2 problem with the bounce targets, from no
                // impulse (each bounce is its own collision).
                double x[2];
                if (solveBlock(c, normalVelocity(c, 0, a, b) - target[0],
                               normalVelocity(c, 1, a, b) - target[1], x)) {
                    for (int i = 0; i < 2; ++i) {
                        c.p[i].bounceImpulse += x[i];
                        applyNormal(c, i, x[i], a, b);
                    }
                } else {
                    bounce[1] = false; // round-off left no exact case: the first alone
                    const double lambda =
                        c.p[0].normalMass * (target[0] - normalVelocity(c, 0, a, b));
                    c.p[0].bounceImpulse += lambda;
                    applyNormal(c, 0, lambda, a, b);
                }
            } else {
                for (int i = 0; i < c.count; ++i) {
                    if (!bounce[i])
                        continue;
                    // Recomputed: the other point's bounce may have changed this one's approach.
                    const double vn = normalVelocity(c, i, a, b);
                    if (!(vn < target[i]))
                        continue;
                    const double lambda = c.p[i].normalMass * (target[i] - vn);
                    c.p[i].bounceImpulse += lambda;
                    applyNormal(c, i, lambda, a, b);
                }
            }
            // Friction during the bounce, within the cone of the impulse so far.
            for (int i = 0; i < c.count; ++i)
                if (bounce[i])
                    solveFrictionPoint(c, i, a, b);
        }
        if (!bounced)
            break;
    }
    return made;
}

bool ContactSolver::solveCollisionPhase(double threshold, int sweeps, double substep,
                                        const std::vector<char>* exempt)
{
    m_paperImpulse = false;
    m_softPhase = true;
    m_substep = substep;
    m_exempt = exempt;
    prepare(threshold, m_settings->restitutionThreshold);
    for (Constraint& c : m_constraints)
        for (Point& p : c.p) {
            p.warmNormal = p.normalImpulse;
            p.warmTangent = p.tangentImpulse;
            p.normalImpulse = p.tangentImpulse = 0.0;
        }
    solveCollisions(std::max(sweeps, 1));
    m_exempt = nullptr;
    storeVelocities();
    bool bounced = false;
    for (Constraint& c : m_constraints) {
        Contact& ct = (*m_contacts)[static_cast<size_t>(c.contact)];
        for (int i = 0; i < c.count; ++i) {
            Point& p = c.p[i];
            const auto k = static_cast<size_t>(i);
            ct.normalImpulse[k] = p.warmNormal;
            ct.tangentImpulse[k] = p.warmTangent;
            ct.bounceImpulse[k] = p.bounceImpulse;
            bounced = bounced || p.bounceImpulse > 0;
            // A point that carries an impulse rests: its bodies were not in free flight
            // before a bounce (impactFractions()).
            p.normalImpulse = p.warmNormal;
        }
    }
    return bounced;
}

bool ContactSolver::solveBlock(const Constraint& c, double b1, double b2, double x[2])
{
    // Find x >= 0 with w = K x + b >= 0 and x.w = 0 by trying the four cases.
    x[0] = -(c.m11 * b1 + c.m12 * b2);
    x[1] = -(c.m12 * b1 + c.m22 * b2);
    if (x[0] >= 0 && x[1] >= 0)
        return true;
    x[0] = -c.p[0].normalMass * b1;
    x[1] = 0.0;
    if (x[0] >= 0 && c.k12 * x[0] + b2 >= 0)
        return true;
    x[0] = 0.0;
    x[1] = -c.p[1].normalMass * b2;
    if (x[1] >= 0 && c.k12 * x[1] + b1 >= 0)
        return true;
    x[0] = x[1] = 0.0;
    return b1 >= 0 && b2 >= 0;
}

} // namespace rigidlab::physics
