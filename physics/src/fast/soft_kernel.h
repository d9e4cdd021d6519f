// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private: the soft step's contact solve in structure-of-arrays form (soft_lanes.cpp fills
// the blocks, soft_kernel.cpp solves them).
//
// The contacts are coloured so that no two of one colour share a moving body; a block holds
// up to kBlockWidth contacts of one colour, each field an array with one lane per contact.
// The kernel then solves the lanes of a block side by side, in SIMD registers of doubles:
// two lanes (SSE2, every x86-64) or four (AVX2, chosen at run time where the processor has
// it). Since the lanes of a block touch distinct moving bodies, the result of a lane does not
// depend on its neighbours: both widths give the same bits. With
// SoftStepSettings::singlePrecision the solve and relax passes run on floats (Box2D v3's
// choice), but the step's last relax in double (KernelOf::relaxDouble): four lanes (SSE2) or
// eight (AVX2), again the same bits at either width, but not the bits of double precision. The
// floats hold changes, not whole values: each body's velocity less its velocity at the start of the
// step (each point's relative velocity then is in SingleLanesOf, from double), its rotation less
// the identity, the separation at the start of the step as the base, and the passes' change of the
// accumulated impulses since the start of the step (the impulses are applied in double by the warm
// start: SoftSolver::warmStart); so a float's rounding is relative to what the step changed, not to
// the speed, the lever arm or the impulse that holds a weight.
//
// This header and soft_kernel.cpp include nothing but plain C++ types: soft_kernel.cpp is
// compiled four times (soft_kernel_avx2.cpp with -mavx2, soft_kernel_single.cpp and
// again soft_kernel_avx2.cpp in single precision), and an inline function shared with the
// rest of the engine (Eigen's, the standard library's) could otherwise be taken by the linker
// from the AVX2 copy and run on a processor without it.

namespace rigidlab::physics::soft {

/// Lanes stored per block: the widest kernel's (four doubles or eight floats in AVX2).
inline constexpr int kBlockWidth = 4;
inline constexpr int kSingleBlockWidth = 8;

/// One body as the kernel sees it, in double precision (BodyState) or single
/// (SingleBodyState, SoftStepSettings::singlePrecision). Velocities change in the kernel; the
/// displacement and rotation are written by the substep's integration of positions
/// (soft_solver.cpp).
template <typename Real> struct alignas(8 * sizeof(Real)) BodyStateOf {
    /// Velocity of the centre of mass [m/s], and angular velocity [rad/s]; in single precision
    /// their change since the start of the step.
    Real vx = 0, vy = 0;
    Real w = 0;
    /// 1 / mass [1/kg], 0 for a body the step does not move: loaded with the velocity as one
    /// vector, so that the blocks need not carry it per lane.
    Real invMass = 0;
    Real dpx = 0, dpy = 0; ///< displacement of the centre of mass since the step began [m]
    /// cos and sin of the rotation since the step began; in single precision cos - 1 and sin
    /// (the rotation less the identity).
    Real qc = 1, qs = 0;
};

/// Single precision only, per point: its relative velocity at the start of the step, along
/// the normal and the tangent [m/s], computed in double when the lane is filled (the float
/// bodies carry only their velocity's change since then, SoftSolver::toSingle, so a float's
/// rounding is relative to that change, not to the speed); and the change the float passes
/// made to its accumulated impulses since the start of the step [N s]. The lanes'
/// normalImpulse and tangentImpulse hold the impulses at the start of the step, rounded, for
/// the clamps only: the passes accumulate and apply only the change, rounded to its own size,
/// not to the impulse's, and the warm start applies the impulses in double
/// (SoftSolver::warmStart). Double precision has no such lanes.
template <typename Real, int Width> struct SingleLanesOf {
};
template <int Width> struct SingleLanesOf<float, Width> {
    float normalVelocity[Width]{};
    float tangentVelocity[Width]{};
    float normalChange[Width]{};
    float tangentChange[Width]{};
};

/// One point of each lane's manifold. A manifold with one point leaves the second's masses 0,
/// which makes its impulses 0.
template <typename Real, int Width> struct alignas(32) PointLanesOf {
    Real rAx[Width]{}, rAy[Width]{}; ///< lever arm from A's centre [m]
    Real rBx[Width]{}, rBy[Width]{}; ///< lever arm from B's centre [m]
    /// The separation with the lever arms' share taken off: the separation now is
    /// n . (dpB + qB rB - dpA - qA rA) + base [m]. In single precision, whose q is the
    /// rotation less the identity, the separation at the start of the step itself.
    Real base[Width]{};
    Real normalMass[Width]{};  ///< 1 / K along the normal [kg]
    Real tangentMass[Width]{}; ///< 1 / K along the tangent [kg]
    /// Accumulated within a substep [N s]; in single precision as it was at the start of the
    /// step, rounded (SingleLanesOf holds the change since).
    Real normalImpulse[Width]{};
    Real tangentImpulse[Width]{};
    [[no_unique_address]] SingleLanesOf<Real, Width> single;
};

/// A block's lanes. The inverse masses are the bodies' (BodyStateOf::invMass), and the soft
/// coefficients the pass's (PassSettings): the blocks are streamed through memory in every
/// pass, and on a large pile they no longer fit in the cache.
template <typename Real, int Width> struct alignas(32) BlockOf {
    using State = BodyStateOf<Real>;
    static constexpr int kWidth = Width;
    int a[Width]{}, b[Width]{};          ///< body indices; empty lanes use the spare body
    Real invIA[Width]{}, invIB[Width]{}; ///< 0 for a body the step does not move
    Real nx[Width]{}, ny[Width]{};       ///< unit normal from A to B
    Real friction[Width]{};
    PointLanesOf<Real, Width> p[2];
};

using BodyState = BodyStateOf<double>;
using Block = BlockOf<double, kBlockWidth>;
/// Single precision: half the bytes per lane, twice the lanes per register.
using SingleBodyState = BodyStateOf<float>;
using SingleBlock = BlockOf<float, kSingleBlockWidth>;
static_assert(sizeof(PointLanesOf<double, kBlockWidth>) == 9 * sizeof(double[kBlockWidth]),
              "double precision's lanes carry no origin");

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

/// The kernel's passes over blocks [0, count) of one colour: no two of the blocks share a
/// moving body (the kernel takes two at a time). The overflow's blocks, which may, are given
/// one per call.
template <typename BlockType> struct KernelOf {
    using State = typename BlockType::State;
    /// Applies the accumulated impulses (warm start); nullptr in single precision, whose
    /// warm start is double (SoftSolver::warmStart).
    void (*warmStart)(BlockType* blocks, int count, State* bodies);
    /// One pass of normal and friction impulses, soft with bias or rigid without (relax).
    void (*solve)(BlockType* blocks, int count, State* bodies, const PassSettings& s);
    int width; ///< lanes solved together
    const char* name;
    /// Single precision only (nullptr in double): the step's last relax pass (without bias or
    /// look-ahead) in double on the double bodies, from the float blocks' rows; over blocks
    /// [0, count) one after the other, the overflow's too.
    void (*relaxDouble)(BlockType* blocks, int count, BodyStateOf<double>* bodies,
                        const PassSettings& s) = nullptr;
};
using Kernel = KernelOf<Block>;
using SingleKernel = KernelOf<SingleBlock>;

/// The two-lane kernel (SSE2 on x86-64, the compiler's vectors elsewhere).
Kernel kernel2();
/// The four-lane kernel compiled for AVX2 (x86-64 only; nullptr elsewhere).
Kernel kernel4Avx2();
/// The same passes in single precision: four lanes (SSE2), and eight compiled for AVX2
/// (x86-64 only; nullptr elsewhere).
SingleKernel singleKernel4();
SingleKernel singleKernel8Avx2();
/// Whether the four-lane AVX2 kernel can run here.
bool haveAvx2();

} // namespace rigidlab::physics::soft
