// SPDX-License-Identifier: GPL-3.0-or-later
// The soft step's constraint rows (SoftSolver, soft_solver.h): each contact point as the kernel
// solves it, filled into its block's lane once a step (fast/soft_colouring.cpp chooses the
// block and lane). For a point with lever arms rA, rB from the centres of mass and unit normal
// n (tangent t = (n.y, -n.x)):
//     effective mass along n:  1 / (1/mA + 1/mB + (rA x n)^2 / IA + (rB x n)^2 / IB)
//     the same along t with t in place of n,
// and the separation with the lever arms' share taken off, so that the kernel can follow it
// through the substeps from the bodies' displacements alone (fast/soft_kernel.h).

#include "soft_solver.h"

#include <array>
#include <cstddef>
#include <type_traits>

namespace rigidlab::physics {

void SoftSolver::resetBlocks(int count)
{
    // Resized, not assigned anew: the blocks of a large pile are megabytes, and every lane is
    // written again, by fillLaneOf() or emptyLanes().
    if (m_single)
        m_singleBlocks.resize(static_cast<size_t>(count));
    else
        m_blocks.resize(static_cast<size_t>(count));
}

void SoftSolver::emptyLanes(int block, int from, int spare)
{
    const auto empty = [&](auto& k) {
        using BlockType = std::remove_reference_t<decltype(k)>;
        for (auto l = static_cast<size_t>(from); l < size_t{BlockType::kWidth}; ++l) {
            k.a[l] = k.b[l] = spare;
            for (auto* field : {k.invIA, k.invIB, k.nx, k.ny, k.friction})
                field[l] = 0;
            for (auto& p : k.p) {
                for (auto* field : {p.rAx, p.rAy, p.rBx, p.rBy, p.base, p.normalMass, p.tangentMass,
                                    p.normalImpulse, p.tangentImpulse})
                    field[l] = 0;
                if constexpr (requires { p.single.normalVelocity; })
                    p.single.normalVelocity[l] = p.single.tangentVelocity[l] =
                        p.single.normalChange[l] = p.single.tangentChange[l] = 0;
            }
        }
    };
    if (m_single)
        empty(m_singleBlocks[static_cast<size_t>(block)]);
    else
        empty(m_blocks[static_cast<size_t>(block)]);
}

void SoftSolver::addSingleWarm(const Contact& ct, int point, const Vec2& rA, const Vec2& rB)
{
    // The velocity that the point's impulse at the start of the step gives each body in a warm
    // start, in double: P = jn n + jt t, with the substep's share of the step's impulse.
    const auto ia = static_cast<size_t>(ct.a), ib = static_cast<size_t>(ct.b);
    const auto i = static_cast<size_t>(point);
    const double substeps = m_substeps.count;
    const Vec2 n = ct.manifold.normal, t(n.y(), -n.x());
    const Vec2 impulse =
        (ct.normalImpulse[i] / substeps) * n + (ct.tangentImpulse[i] / substeps) * t;
    const double mA = m_state[ia].invMass, mB = m_state[ib].invMass;
    std::array<double, 3>& warmA = m_singleWarm[ia];
    std::array<double, 3>& warmB = m_singleWarm[ib];
    warmA[0] -= mA * impulse.x();
    warmA[1] -= mA * impulse.y();
    warmA[2] -= m_invInertia[ia] * cross(rA, impulse);
    warmB[0] += mB * impulse.x();
    warmB[1] += mB * impulse.y();
    warmB[2] += m_invInertia[ib] * cross(rB, impulse);
}

template <typename BlockType> void SoftSolver::fillLaneOf(const Contact& ct, BlockType& k, int lane)
{
    // The bodies as begin() took them (inverse masses and inertias, 0 for a body the step does
    // not move; centres of mass), without reaching into the bodies again: the lanes are filled
    // in the colours' order, and the bodies' large records would be read out of order.
    const auto ia = static_cast<size_t>(ct.a), ib = static_cast<size_t>(ct.b);
    const double mA = m_state[ia].invMass, mB = m_state[ib].invMass;
    const double iA = m_invInertia[ia], iB = m_invInertia[ib];
    const Vec2& centreA = m_position[ia];
    const Vec2& centreB = m_position[ib];
    const auto l = static_cast<size_t>(lane);
    k.a[l] = ct.a;
    k.b[l] = ct.b;
    k.invIA[l] = iA;
    k.invIB[l] = iB;
    const Vec2 n = ct.manifold.normal, t(n.y(), -n.x());
    k.nx[l] = n.x();
    k.ny[l] = n.y();
    k.friction[l] = ct.friction;

    const double substeps = m_substeps.count;
    for (int i = 0; i < ct.manifold.pointCount; ++i) {
        const ContactPoint& cp = ct.manifold.points[static_cast<size_t>(i)];
        auto& p = k.p[i];
        // Lever arms from the centres of mass where the narrow phase found the contact.
        const Vec2 rA = cp.point - centreA, rB = cp.point - centreB;
        p.rAx[l] = rA.x();
        p.rAy[l] = rA.y();
        p.rBx[l] = rB.x();
        p.rBy[l] = rB.y();
        p.base[l] = cp.separation - n.dot(rB - rA);
        const double rnA = cross(rA, n), rnB = cross(rB, n);
        const double kn = mA + mB + iA * rnA * rnA + iB * rnB * rnB;
        p.normalMass[l] = kn > 0 ? 1.0 / kn : 0.0;
        const double rtA = cross(rA, t), rtB = cross(rB, t);
        const double kt = mA + mB + iA * rtA * rtA + iB * rtB * rtB;
        p.tangentMass[l] = kt > 0 ? 1.0 / kt : 0.0;
        // Warm start: the contact keeps the impulse of a whole step; a substep applies its
        // share.
        p.normalImpulse[l] = ct.normalImpulse[static_cast<size_t>(i)] / substeps;
        p.tangentImpulse[l] = ct.tangentImpulse[static_cast<size_t>(i)] / substeps;
        if constexpr (requires { p.single.normalVelocity; }) {
            // Single precision: the point's relative velocity at the start of the step, in
            // double, which the bodies' floats leave out (SingleLanesOf); and the separation
            // itself as the base, since the kernel turns the lever arms by the rotation less
            // the identity (soft_kernel.h). With the lever arms whole in floats, a box 5 m from
            // the centre of its slope had its separation to half a micrometre, and the soft push
            // made that a creep of 1.4e-4 m/s.
            const auto& oA = m_singleOrigin[ia];
            const auto& oB = m_singleOrigin[ib];
            const Vec2 dv =
                Vec2(oB[0], oB[1]) + cross(oB[2], rB) - Vec2(oA[0], oA[1]) - cross(oA[2], rA);
            p.single.normalVelocity[l] = static_cast<float>(dv.dot(n));
            p.single.tangentVelocity[l] = static_cast<float>(dv.dot(t));
            p.base[l] = static_cast<float>(cp.separation);
            // No change of the impulses yet; their warm start, in double, to the bodies'
            // (SoftSolver::warmStart).
            p.single.normalChange[l] = p.single.tangentChange[l] = 0.0f;
            addSingleWarm(ct, i, rA, rB);
        }
    }
    // A point the manifold lacks: zero masses, so zero impulses (a block filled again may
    // hold last step's second point here).
    for (int i = ct.manifold.pointCount; i < 2; ++i) {
        auto& p = k.p[i];
        for (auto* field : {p.rAx, p.rAy, p.rBx, p.rBy, p.base, p.normalMass, p.tangentMass,
                            p.normalImpulse, p.tangentImpulse})
            field[l] = 0.0;
        if constexpr (requires { p.single.normalVelocity; })
            p.single.normalVelocity[l] = p.single.tangentVelocity[l] = p.single.normalChange[l] =
                p.single.tangentChange[l] = 0.0f;
    }
}

// Both precisions' lanes are filled from fast/soft_colouring.cpp.
template void SoftSolver::fillLaneOf<soft::Block>(const Contact&, soft::Block&, int);
template void SoftSolver::fillLaneOf<soft::SingleBlock>(const Contact&, soft::SingleBlock&, int);

} // namespace rigidlab::physics
