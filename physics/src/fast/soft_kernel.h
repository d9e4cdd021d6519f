// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private: the soft step's contact solve in structure-of-arrays form (soft_solver.cpp builds
// the blocks, soft_kernel.cpp solves them).
//
// The contacts are coloured so that no two of one colour share a moving body; a block holds
// up to kBlockWidth contacts of one colour, each field an array with one lane per contact.
// The kernel then solves the lanes of a block side by side, in SIMD registers of doubles:
// two lanes (SSE2, every x86-64) or four (AVX2, chosen at run time where the processor has
// it). Since the lanes of a block touch distinct moving bodies, the result of a lane does not
// depend on its neighbours: both widths give the same bits.
//
// This header and soft_kernel.cpp include nothing but plain C++ types: soft_kernel.cpp is
// compiled twice (soft_kernel_avx2.cpp with -mavx2), and an inline function shared with the
// rest of the engine (Eigen's, the standard library's) could otherwise be taken by the linker
// from the AVX2 copy and run on a processor without it.

namespace rigidlab::physics::soft {

/// Lanes stored per block: the widest kernel's.
inline constexpr int kBlockWidth = 4;

/// One body as the kernel sees it. Velocities change in the kernel; the displacement and
/// rotation are written by the substep's integration of positions (soft_solver.cpp).
struct alignas(64) BodyState {
    double vx = 0, vy = 0; ///< velocity of the centre of mass [m/s]
    double w = 0;          ///< angular velocity [rad/s]
    /// 1 / mass [1/kg], 0 for a body the step does not move: loaded with the velocity as one
    /// vector, so that the blocks need not carry it per lane.
    double invMass = 0;
    double dpx = 0, dpy = 0; ///< displacement of the centre of mass since the step began [m]
    double qc = 1, qs = 0;   ///< cos and sin of the rotation since the step began
};

/// One point of each lane's manifold. A manifold with one point leaves the second's masses 0,
/// which makes its impulses 0.
struct alignas(32) PointLanes {
    double rAx[kBlockWidth]{}, rAy[kBlockWidth]{}; ///< lever arm from A's centre [m]
    double rBx[kBlockWidth]{}, rBy[kBlockWidth]{}; ///< lever arm from B's centre [m]
    /// The separation with the lever arms' share taken off: the separation now is
    /// n . (dpB + qB rB - dpA - qA rA) + base [m].
    double base[kBlockWidth]{};
    double normalMass[kBlockWidth]{};     ///< 1 / K along the normal [kg]
    double tangentMass[kBlockWidth]{};    ///< 1 / K along the tangent [kg]
    double normalImpulse[kBlockWidth]{};  ///< accumulated within a substep [N s]
    double tangentImpulse[kBlockWidth]{}; ///< accumulated within a substep [N s]
};

/// A block's lanes. The inverse masses are the bodies' (BodyState::invMass), and the soft
/// coefficients the pass's (PassSettings): the blocks are streamed through memory in every
/// pass, and on a large pile they no longer fit in the cache.
struct alignas(32) Block {
    int a[kBlockWidth]{}, b[kBlockWidth]{}; ///< body indices; empty lanes use the spare body
    double invIA[kBlockWidth]{}, invIB[kBlockWidth]{}; ///< 0 for a body the step does not move
    double nx[kBlockWidth]{}, ny[kBlockWidth]{};       ///< unit normal from A to B
    double friction[kBlockWidth]{};
    PointLanes p[2];
};

/// The soft constraint's coefficients for one substep (soft_solver.cpp).
struct Softness {
    double biasRate = 0;     ///< [1/s]
    double massScale = 1;    ///< of the effective mass, in (0, 1)
    double impulseScale = 0; ///< of the accumulated impulse, in (0, 1)
};

/// What a pass of the kernel needs besides the blocks and bodies.
struct PassSettings {
    double inverseSubstep = 0; ///< 1 / substep [1/s]
    double maxPushSpeed = 0;   ///< how fast the bias pushes overlapping bodies apart [m/s]
    bool useBias = true;       ///< solve (true) or relax (false)
    bool friction = true;      ///< friction impulses in this pass
    /// Between two moving bodies [0], and against one that does not move [1] (a lane whose
    /// A or B has inverse mass 0).
    Softness softness[2];
};

/// The kernel's passes over blocks [0, count), in order.
struct Kernel {
    /// Applies the accumulated impulses (warm start).
    void (*warmStart)(Block* blocks, int count, BodyState* bodies);
    /// One pass of normal and friction impulses, soft with bias or rigid without (relax).
    void (*solve)(Block* blocks, int count, BodyState* bodies, const PassSettings& s);
    int width; ///< lanes solved together
    const char* name;
};

/// The two-lane kernel (SSE2 on x86-64, the compiler's vectors elsewhere).
Kernel kernel2();
/// The four-lane kernel compiled for AVX2 (x86-64 only; nullptr elsewhere).
Kernel kernel4Avx2();
/// Whether the four-lane AVX2 kernel can run here.
bool haveAvx2();

} // namespace rigidlab::physics::soft
