// SPDX-License-Identifier: GPL-3.0-or-later
// The pin joints of the soft step's substeps (soft_solver.h, SoftSolver::setPins()): the
// joints a contact touches, solved with the contacts in every pass, as Box2D v3 solves its
// revolute joint's point constraint.
//
// The constraint C = pB - pA = 0 of the two anchor points, its velocity
//     Cdot = vB + wB x rB - vA - wA x rA,
// and its 2x2 effective mass K = (mA + mB) I + iA perp(rA) perp(rA)^T + iB perp(rB) perp(rB)^T
// (m, i the inverse masses and inertias). The biased pass is soft (soft_solver.cpp's
// coefficients against a body that does not move, a rigid joint's stiffness):
//     impulse = -massScale K^-1 (Cdot + biasRate C) - impulseScale accumulated;
// the relax pass rigid, impulse = -K^-1 Cdot, so that the push back onto the pin leaves no
// velocity behind. The lever arms turn with the bodies from substep to substep.

#include "soft_solver.h"

namespace rigidlab::physics {

void SoftSolver::setPins(const std::vector<PinJointDef>& pins, const std::vector<Body>& bodies)
{
    m_pins.clear();
    for (const PinJointDef& j : pins) {
        Pin pin;
        auto local = [&](BodyId id, const Vec2& anchor, int& index, Vec2& out) {
            if (id == kWorld) {
                index = -1;
                out = anchor;
                return;
            }
            index = static_cast<int>(id);
            out = anchor - bodies[static_cast<size_t>(id)].localCenter;
        };
        local(j.a, j.anchorA, pin.a, pin.localA);
        local(j.b, j.anchorB, pin.b, pin.localB);
        m_pins.push_back(pin);
    }
}

SoftSolver::PinEnd SoftSolver::pinEnd(int body, const Vec2& local)
{
    PinEnd end;
    if (body < 0) {
        end.p = local;
        end.state = &m_state.back(); // the spare body: inverse mass 0, never read back
        return end;
    }
    const auto i = static_cast<size_t>(body);
    end.r = Rotation(m_angle[i]).apply(local);
    end.p = m_position[i] + end.r;
    end.state = &m_state[i];
    end.invMass = end.state->invMass;
    end.invInertia = m_invInertia[i];
    return end;
}

namespace {

/// Applies `impulse` on B at its lever arm, and its opposite on A.
void applyPin(const Vec2& impulse, double mA, double iA, const Vec2& rA, soft::BodyState& a,
              double mB, double iB, const Vec2& rB, soft::BodyState& b)
{
    a.vx -= mA * impulse.x();
    a.vy -= mA * impulse.y();
    a.w -= iA * cross(rA, impulse);
    b.vx += mB * impulse.x();
    b.vy += mB * impulse.y();
    b.w += iB * cross(rB, impulse);
}

} // namespace

void SoftSolver::warmStartPins()
{
    for (const Pin& pin : m_pins) {
        const PinEnd a = pinEnd(pin.a, pin.localA), b = pinEnd(pin.b, pin.localB);
        applyPin(pin.impulse, a.invMass, a.invInertia, a.r, *a.state, b.invMass, b.invInertia, b.r,
                 *b.state);
    }
}

void SoftSolver::solvePins(bool useBias)
{
    const Softness& soft = m_pass.softness[1];
    for (Pin& pin : m_pins) {
        const PinEnd a = pinEnd(pin.a, pin.localA), b = pinEnd(pin.b, pin.localB);
        const soft::BodyState &sa = *a.state, &sb = *b.state;
        const Vec2 cdot =
            Vec2(sb.vx, sb.vy) + cross(sb.w, b.r) - Vec2(sa.vx, sa.vy) - cross(sa.w, a.r);
        const double m = a.invMass + b.invMass, iA = a.invInertia, iB = b.invInertia;
        const double k11 = m + iA * a.r.y() * a.r.y() + iB * b.r.y() * b.r.y();
        const double k12 = -iA * a.r.x() * a.r.y() - iB * b.r.x() * b.r.y();
        const double k22 = m + iA * a.r.x() * a.r.x() + iB * b.r.x() * b.r.x();
        const double det = k11 * k22 - k12 * k12;
        if (!(det > 0))
            continue; // both ends fixed
        Vec2 bias = Vec2::Zero();
        double massScale = 1.0, impulseScale = 0.0;
        if (useBias) {
            bias = soft.biasRate * (b.p - a.p);
            massScale = soft.massScale;
            impulseScale = soft.impulseScale;
        }
        const Vec2 rhs = cdot + bias;
        const Vec2 solved =
            Vec2(k22 * rhs.x() - k12 * rhs.y(), k11 * rhs.y() - k12 * rhs.x()) / det;
        const Vec2 impulse = -massScale * solved - impulseScale * pin.impulse;
        pin.impulse += impulse;
        applyPin(impulse, a.invMass, iA, a.r, *a.state, b.invMass, iB, b.r, *b.state);
    }
}

} // namespace rigidlab::physics
