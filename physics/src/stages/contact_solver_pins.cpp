// SPDX-License-Identifier: GPL-3.0-or-later
// Pin joints inside the sequential contact solver (contact_solver.h).
//
// A body that rests on a pinned body (a box lying on the welcome scene's springboard) is held
// up by the contact and the pin together. Solved one after the other they fight: the contacts
// alone share the box's weight with the board as if the board were free, so the two sink
// together; the pin's projection afterwards (joints.cpp) stops the board, and the box is left
// moving into it. The position correction lifts it out again every step, without a change of
// velocity: work that nothing accounts for, which the contacts then take out as "friction"
// (the welcome scene gained 6 % of its energy in ten minutes). Solving each touched pin in
// the same Gauss-Seidel iterations as the contacts finds the impulses that satisfy both, so a
// box resting on a pinned board comes to rest; the same in the position passes.
//
// A pin between pA = xA + rA and pB = xB + rB: its velocity error is
//   C' = vA + wA x rA - vB - wB x rB,
// and an impulse P on A (-P on B) changes it by K P, with
//   K = (1/mA + 1/mB) I + perp(rA) perp(rA)^T / IA + perp(rB) perp(rB)^T / IB.

#include "contact_solver.h"

namespace rigidlab::physics {

namespace {

Eigen::Matrix2d pinMatrix(double invMassA, double invIA, const Vec2& rA, double invMassB,
                          double invIB, const Vec2& rB)
{
    Eigen::Matrix2d k = (invMassA + invMassB) * Eigen::Matrix2d::Identity();
    k += invIA * perp(rA) * perp(rA).transpose();
    k += invIB * perp(rB) * perp(rB).transpose();
    return k;
}

} // namespace

void ContactSolver::setPins(const std::vector<PinJointDef>& pins)
{
    const std::vector<Body>& bodies = *m_bodies;
    m_pins.clear();
    for (const PinJointDef& j : pins) {
        Pin& p = m_pins.emplace_back();
        auto end = [&](BodyId id, const Vec2& anchor, int& index, Vec2& local, double& invMass,
                       double& invI) {
            if (id == kWorld) {
                local = anchor; // a point of the world
                return;
            }
            const Body& b = bodies[static_cast<size_t>(id)];
            index = static_cast<int>(id);
            local = anchor - b.localCenter;
            invMass = b.isActive() ? b.invMass : 0.0;
            invI = b.isActive() ? b.invInertia : 0.0;
        };
        end(j.a, j.anchorA, p.a, p.anchorA, p.invMassA, p.invIA);
        end(j.b, j.anchorB, p.b, p.anchorB, p.invMassB, p.invIB);
        if (p.invMassA + p.invMassB + p.invIA + p.invIB == 0.0)
            m_pins.pop_back(); // nothing the solver may move
    }
    preparePins();
}

void ContactSolver::preparePins()
{
    const std::vector<Body>& bodies = *m_bodies;
    for (Pin& p : m_pins) {
        p.rA = p.a < 0 ? Vec2::Zero()
                       : Rotation(bodies[static_cast<size_t>(p.a)].angle).apply(p.anchorA);
        p.rB = p.b < 0 ? Vec2::Zero()
                       : Rotation(bodies[static_cast<size_t>(p.b)].angle).apply(p.anchorB);
        p.mass = pinMatrix(p.invMassA, p.invIA, p.rA, p.invMassB, p.invIB, p.rB).inverse();
        p.impulse = Vec2::Zero();
    }
}

void ContactSolver::solvePins()
{
    Velocity none;
    for (Pin& p : m_pins) {
        Velocity& a = p.a < 0 ? none : m_velocity[static_cast<size_t>(p.a)];
        Velocity& b = p.b < 0 ? none : m_velocity[static_cast<size_t>(p.b)];
        const Vec2 error = a.v + cross(a.w, p.rA) - b.v - cross(b.w, p.rB);
        const Vec2 P = -(p.mass * error);
        p.impulse += P;
        a.v += p.invMassA * P;
        a.w += p.invIA * cross(p.rA, P);
        b.v -= p.invMassB * P;
        b.w -= p.invIB * cross(p.rB, P);
        none = Velocity{};
    }
}

void ContactSolver::solvePinPositions()
{
    std::vector<Body>& bodies = *m_bodies;
    Body ground; // stands for the world: never moved (its inverse masses are 0)
    for (Pin& p : m_pins) {
        Body& a = p.a < 0 ? ground : bodies[static_cast<size_t>(p.a)];
        Body& b = p.b < 0 ? ground : bodies[static_cast<size_t>(p.b)];
        const Vec2 rA = p.a < 0 ? Vec2::Zero() : Rotation(a.angle).apply(p.anchorA);
        const Vec2 rB = p.b < 0 ? Vec2::Zero() : Rotation(b.angle).apply(p.anchorB);
        const Vec2 pA = p.a < 0 ? p.anchorA : Vec2(a.position + rA);
        const Vec2 pB = p.b < 0 ? p.anchorB : Vec2(b.position + rB);
        const Eigen::Matrix2d k = pinMatrix(p.invMassA, p.invIA, rA, p.invMassB, p.invIB, rB);
        const Vec2 P = -k.inverse() * (pA - pB);
        a.position += p.invMassA * P;
        a.angle += p.invIA * cross(rA, P);
        b.position -= p.invMassB * P;
        b.angle -= p.invIB * cross(rB, P);
        if (p.a >= 0)
            m_rotationStamp[static_cast<size_t>(p.a)] = 0;
        if (p.b >= 0)
            m_rotationStamp[static_cast<size_t>(p.b)] = 0;
    }
}

} // namespace rigidlab::physics
