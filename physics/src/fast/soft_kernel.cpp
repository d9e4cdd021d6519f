// SPDX-License-Identifier: GPL-3.0-or-later
// The soft step's contact passes over blocks of lanes (soft_kernel.h), written once with the
// compiler's vector types (GCC and Clang) for RIGIDLAB_SOFT_WIDTH lanes of RIGIDLAB_SOFT_REAL
// (double unless said). Compiled as it is for two lanes of doubles, by soft_kernel_avx2.cpp for
// four lanes with AVX2, and by soft_kernel_single*.cpp for four and eight lanes of floats.
//
// Per lane and point, with the normal n from A to B, the tangent t = (n.y, -n.x), the lever
// arms rA, rB and the relative velocity dv = vB + wB x rB - vA - wA x rA (Catto, "Solver2D",
// 2024, and Box2D v3's soft step):
//   separation  s = n . (dpB + qB rB - dpA - qA rA) + base   (base: see PointLanes; single
//               precision: q less the identity, base the separation at the step's start)
//   s > 0       speculative: the gap may close within the substep, bias = s / h, rigid
//   s <= 0      with bias: soft, bias = max(biasRate s, -maxPush), the mass and the accumulated
//               impulse scaled by massScale and impulseScale; relaxing: rigid, no bias
//   normal      dj = -normalMass massScale (dv.n + bias) - impulseScale j, j stays >= 0
//   friction    dj = -tangentMass dv.t, |j_t| <= friction j_n
// (single precision: dv is the change since the step began plus each point's relative velocity
// then, and j the impulse at the start of the step, rounded, plus the passes' change since:
// only the change is accumulated and applied, SingleLanesOf)
// Bounces are not the kernel's: the collision phase gives them before the substeps
// (soft_step.cpp, contact_collisions.cpp).

#include "soft_kernel.h"

#ifndef RIGIDLAB_SOFT_WIDTH
#define RIGIDLAB_SOFT_WIDTH 2
#define RIGIDLAB_SOFT_NAMESPACE lanes2
#endif
#ifndef RIGIDLAB_SOFT_REAL
#define RIGIDLAB_SOFT_REAL double
#endif
#if RIGIDLAB_SOFT_SINGLE
// Single precision's last relax in double uses vectors of twice the float lanes' bytes, wider
// than this compilation's registers may be: GCC notes that returning them changes the ABI, which
// does not matter for the functions of this file's anonymous namespace.
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace rigidlab::physics::soft {
namespace RIGIDLAB_SOFT_NAMESPACE {
namespace {

constexpr int W = RIGIDLAB_SOFT_WIDTH;
using Real = RIGIDLAB_SOFT_REAL;
using V = Real __attribute__((vector_size(W * sizeof(Real))));
/// The blocks and bodies of this precision (soft_kernel.h).
using Block = BlockOf<Real, sizeof(Real) == sizeof(double) ? kBlockWidth : kSingleBlockWidth>;
using BodyState = typename Block::State;
using PointLanes = PointLanesOf<Real, Block::kWidth>;
/// Single precision (SingleLanesOf): the bodies carry their velocity's change since the step
/// began instead of the velocity, and the passes accumulate only their change of the impulses.
constexpr bool kSingle = sizeof(SingleLanesOf<Real, Block::kWidth>) > 1;

// The kernel leans on no library (see soft_kernel.h): loads, stores and selections by hand.
inline V load(const Real* p)
{
    V v;
    __builtin_memcpy(&v, p, sizeof(V));
    return v;
}
inline void store(Real* p, const V& v)
{
    __builtin_memcpy(p, &v, sizeof(V));
}
inline V splat(double x)
{
    V v;
    for (int i = 0; i < W; ++i)
        v[i] = static_cast<Real>(x);
    return v;
}
inline V vmax(const V& a, const V& b)
{
    return a > b ? a : b;
}
inline V vmin(const V& a, const V& b)
{
    return a < b ? a : b;
}

/// The velocities of one side of the lanes, gathered from the bodies, with their inverse
/// masses (which the kernel only reads, and writes back as read).
struct Side {
    V vx, vy, w, m;
};

/// The displacement of both sides since the step began, gathered per lane.
struct Motion {
    V dpx, dpy; ///< dpB - dpA [m]
    V qcA, qsA, qcB, qsB;
};

/// Four doubles of each lane's body, from `offset` within its BodyState, turned into four
/// vectors of lanes: out[j][i] = body i's field offset + j. Loads and shuffles instead of a
/// scalar load per field and lane; it moves bits only. (__builtin_shufflevector: GCC from 12
/// and Clang both have it; GCC's own __builtin_shuffle broke the Clang-built fuzzers.)
inline void transpose(const int* index, const BodyState* bodies, int offset, V (&out)[4])
{
    const auto field = [&](int lane) {
        return reinterpret_cast<const Real*>(&bodies[index[lane]]) + offset;
    };
#if RIGIDLAB_SOFT_WIDTH == 8
    // Eight rows of four floats: rows i and i + 4 side by side in one register, then the
    // four-row transpose within each 128-bit half.
    using R = Real __attribute__((vector_size(4 * sizeof(Real))));
    const auto rows = [&](int i) {
        R lo, hi;
        __builtin_memcpy(&lo, field(i), sizeof(R));
        __builtin_memcpy(&hi, field(i + 4), sizeof(R));
        return V(__builtin_shufflevector(lo, hi, 0, 1, 2, 3, 4, 5, 6, 7));
    };
    const V c0 = rows(0), c1 = rows(1), c2 = rows(2), c3 = rows(3);
    const V t0 = __builtin_shufflevector(c0, c1, 0, 8, 1, 9, 4, 12, 5, 13);
    const V t1 = __builtin_shufflevector(c0, c1, 2, 10, 3, 11, 6, 14, 7, 15);
    const V t2 = __builtin_shufflevector(c2, c3, 0, 8, 1, 9, 4, 12, 5, 13);
    const V t3 = __builtin_shufflevector(c2, c3, 2, 10, 3, 11, 6, 14, 7, 15);
    out[0] = __builtin_shufflevector(t0, t2, 0, 1, 8, 9, 4, 5, 12, 13);
    out[1] = __builtin_shufflevector(t0, t2, 2, 3, 10, 11, 6, 7, 14, 15);
    out[2] = __builtin_shufflevector(t1, t3, 0, 1, 8, 9, 4, 5, 12, 13);
    out[3] = __builtin_shufflevector(t1, t3, 2, 3, 10, 11, 6, 7, 14, 15);
#elif RIGIDLAB_SOFT_WIDTH == 4
    // Rows r_i = body i's four fields; unpack pairs of rows, then swap the 128-bit halves.
    const V r0 = load(field(0)), r1 = load(field(1)), r2 = load(field(2)), r3 = load(field(3));
    const V t0 = __builtin_shufflevector(r0, r1, 0, 4, 2, 6);
    const V t1 = __builtin_shufflevector(r0, r1, 1, 5, 3, 7);
    const V t2 = __builtin_shufflevector(r2, r3, 0, 4, 2, 6);
    const V t3 = __builtin_shufflevector(r2, r3, 1, 5, 3, 7);
    out[0] = __builtin_shufflevector(t0, t2, 0, 1, 4, 5);
    out[1] = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
    out[2] = __builtin_shufflevector(t0, t2, 2, 3, 6, 7);
    out[3] = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
#elif RIGIDLAB_SOFT_WIDTH == 2 && !RIGIDLAB_SOFT_SINGLE
    const V a0 = load(field(0)), a1 = load(field(0) + 2);
    const V b0 = load(field(1)), b1 = load(field(1) + 2);
    out[0] = __builtin_shufflevector(a0, b0, 0, 2);
    out[1] = __builtin_shufflevector(a0, b0, 1, 3);
    out[2] = __builtin_shufflevector(a1, b1, 0, 2);
    out[3] = __builtin_shufflevector(a1, b1, 1, 3);
#else
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < W; ++i)
            out[j][i] = field(i)[j];
#endif
}

inline Side gather(const int* index, const BodyState* bodies)
{
    static_assert(__builtin_offsetof(BodyState, vx) == 0 &&
                  __builtin_offsetof(BodyState, vy) == sizeof(Real) &&
                  __builtin_offsetof(BodyState, w) == 2 * sizeof(Real) &&
                  __builtin_offsetof(BodyState, invMass) == 3 * sizeof(Real));
    V f[4];
    transpose(index, bodies, 0, f);
    return {f[0], f[1], f[2], f[3]};
}

inline void scatter(const int* index, BodyState* bodies, const Side& s)
{
    // Lanes of a block never share a moving body. A body that does not move (static, asleep,
    // or the spare body of an empty lane) may stand in several lanes: each writes back the
    // velocity it read, since its inverse mass is 0. The rows are the gather's transposed
    // back, the inverse mass with them as it was read.
    const auto row = [&](int lane) { return reinterpret_cast<Real*>(&bodies[index[lane]]); };
#if RIGIDLAB_SOFT_WIDTH == 8
    using R = Real __attribute__((vector_size(4 * sizeof(Real))));
    const auto put = [&](int lane, const R& r) { __builtin_memcpy(row(lane), &r, sizeof(R)); };
    const V u0 = __builtin_shufflevector(s.vx, s.vy, 0, 8, 1, 9, 4, 12, 5, 13);
    const V u1 = __builtin_shufflevector(s.vx, s.vy, 2, 10, 3, 11, 6, 14, 7, 15);
    const V u2 = __builtin_shufflevector(s.w, s.m, 0, 8, 1, 9, 4, 12, 5, 13);
    const V u3 = __builtin_shufflevector(s.w, s.m, 2, 10, 3, 11, 6, 14, 7, 15);
    put(0, __builtin_shufflevector(u0, u2, 0, 1, 8, 9));
    put(1, __builtin_shufflevector(u0, u2, 2, 3, 10, 11));
    put(2, __builtin_shufflevector(u1, u3, 0, 1, 8, 9));
    put(3, __builtin_shufflevector(u1, u3, 2, 3, 10, 11));
    put(4, __builtin_shufflevector(u0, u2, 4, 5, 12, 13));
    put(5, __builtin_shufflevector(u0, u2, 6, 7, 14, 15));
    put(6, __builtin_shufflevector(u1, u3, 4, 5, 12, 13));
    put(7, __builtin_shufflevector(u1, u3, 6, 7, 14, 15));
#elif RIGIDLAB_SOFT_WIDTH == 4
    const V t0 = __builtin_shufflevector(s.vx, s.vy, 0, 4, 2, 6);
    const V t1 = __builtin_shufflevector(s.vx, s.vy, 1, 5, 3, 7);
    const V t2 = __builtin_shufflevector(s.w, s.m, 0, 4, 2, 6);
    const V t3 = __builtin_shufflevector(s.w, s.m, 1, 5, 3, 7);
    store(row(0), __builtin_shufflevector(t0, t2, 0, 1, 4, 5));
    store(row(1), __builtin_shufflevector(t1, t3, 0, 1, 4, 5));
    store(row(2), __builtin_shufflevector(t0, t2, 2, 3, 6, 7));
    store(row(3), __builtin_shufflevector(t1, t3, 2, 3, 6, 7));
#elif RIGIDLAB_SOFT_WIDTH == 2 && !RIGIDLAB_SOFT_SINGLE
    store(row(0), __builtin_shufflevector(s.vx, s.vy, 0, 2));
    store(row(0) + 2, __builtin_shufflevector(s.w, s.m, 0, 2));
    store(row(1), __builtin_shufflevector(s.vx, s.vy, 1, 3));
    store(row(1) + 2, __builtin_shufflevector(s.w, s.m, 1, 3));
#else
    for (int i = 0; i < W; ++i) {
        Real* b = row(i);
        b[0] = s.vx[i];
        b[1] = s.vy[i];
        b[2] = s.w[i];
        b[3] = s.m[i];
    }
#endif
}

inline Motion gatherMotion(const Block& k, const BodyState* bodies)
{
    constexpr int kOffset = __builtin_offsetof(BodyState, dpx) / sizeof(Real);
    static_assert(
        __builtin_offsetof(BodyState, dpy) == __builtin_offsetof(BodyState, dpx) + sizeof(Real) &&
        __builtin_offsetof(BodyState, qc) ==
            __builtin_offsetof(BodyState, dpx) + 2 * sizeof(Real) &&
        __builtin_offsetof(BodyState, qs) == __builtin_offsetof(BodyState, dpx) + 3 * sizeof(Real));
    V a[4], b[4];
    transpose(k.a, bodies, kOffset, a);
    transpose(k.b, bodies, kOffset, b);
    return {b[0] - a[0], b[1] - a[1], a[2], a[3], b[2], b[3]};
}

/// Applies the impulse P = dj (dx, dy) at lever arms (rAx, rAy), (rBx, rBy). (S, T: the sides
/// and vectors of the kernel's precision, or of single precision's last relax in double.)
template <typename S, typename T>
inline void apply(S& A, S& B, const T& mA, const T& iA, const T& mB, const T& iB, const T& dj,
                  const T& dx, const T& dy, const T& rAx, const T& rAy, const T& rBx, const T& rBy)
{
    const T px = dj * dx, py = dj * dy;
    A.vx -= mA * px;
    A.vy -= mA * py;
    A.w -= iA * (rAx * py - rAy * px);
    B.vx += mB * px;
    B.vy += mB * py;
    B.w += iB * (rBx * py - rBy * px);
}

/// Relative velocity of the contact point along (dx, dy).
template <typename S, typename T>
inline T relative(const S& A, const S& B, const T& dx, const T& dy, const T& rAx, const T& rAy,
                  const T& rBx, const T& rBy)
{
    // v + w x r = (vx - w ry, vy + w rx)
    const T ux = (B.vx - B.w * rBy) - (A.vx - A.w * rAy);
    const T uy = (B.vy + B.w * rBx) - (A.vy + A.w * rAx);
    return ux * dx + uy * dy;
}

/// The relative velocity of point p's lanes along the normal (tangent: along the tangent) at
/// the start of the step, which single precision's bodies do not carry (SingleLanesOf); 0 in
/// double precision.
template <bool kTangent, typename Point> inline V origin(const Point& p)
{
    if constexpr (requires { p.single.normalVelocity; })
        return load(kTangent ? p.single.tangentVelocity : p.single.normalVelocity);
    else
        return V{};
}

/// The warm start of one block's lanes, on its sides as gathered.
inline void warmStartLanes(Block& c, Side& A, Side& B)
{
    const V mA = A.m, iA = load(c.invIA), mB = B.m, iB = load(c.invIB);
    const V nx = load(c.nx), ny = load(c.ny);
    for (PointLanes& p : c.p) {
        const V rAx = load(p.rAx), rAy = load(p.rAy), rBx = load(p.rBx), rBy = load(p.rBy);
        apply(A, B, mA, iA, mB, iB, load(p.normalImpulse), nx, ny, rAx, rAy, rBx, rBy);
        apply(A, B, mA, iA, mB, iB, load(p.tangentImpulse), ny, -nx, rAx, rAy, rBx, rBy);
    }
}

/// Runs lanes(block, A, B) on blocks [0, count), which are of one colour (KernelOf): no two
/// share a moving body. So two blocks are taken at a time, both gathered before either is
/// scattered: the processor can then run their long chains of dependent operations side by side,
/// where the stores of one block's bodies before the next block's loads held it to one chain
/// (the kernel's samples, base-40 pyramid: 5 % fewer). The same bits as one block after the
/// other: a body both blocks hold does not move, and both write back what they read.
template <typename Lanes>
inline void eachBlock(Block* blocks, int count, BodyState* bodies, const Lanes& lanes)
{
    int k = 0;
    for (; k + 1 < count; k += 2) {
        Block& c0 = blocks[k];
        Block& c1 = blocks[k + 1];
        Side A0 = gather(c0.a, bodies), B0 = gather(c0.b, bodies);
        Side A1 = gather(c1.a, bodies), B1 = gather(c1.b, bodies);
        lanes(c0, A0, B0);
        lanes(c1, A1, B1);
        scatter(c0.a, bodies, A0);
        scatter(c0.b, bodies, B0);
        scatter(c1.a, bodies, A1);
        scatter(c1.b, bodies, B1);
    }
    if (k < count) {
        Block& c = blocks[k];
        Side A = gather(c.a, bodies), B = gather(c.b, bodies);
        lanes(c, A, B);
        scatter(c.a, bodies, A);
        scatter(c.b, bodies, B);
    }
}

#if !RIGIDLAB_SOFT_SINGLE // single precision's warm start is double (SoftSolver::warmStart)
void warmStartBlocks(Block* blocks, int count, BodyState* bodies)
{
    eachBlock(blocks, count, bodies, [](Block& c, Side& A, Side& B) { warmStartLanes(c, A, B); });
}
#endif

/// What a pass splats once: its constants, and the two softnesses, [0] between moving bodies
/// and [1] against one that does not move.
struct PassConstants {
    V zero, inverseSubstep, maxPush;
    V biasRates[2], massScales[2], impulseScales[2];
    explicit PassConstants(const PassSettings& s)
        : zero(splat(0.0)), inverseSubstep(splat(s.inverseSubstep)),
          maxPush(splat(-s.maxPushSpeed)), biasRates{splat(s.softness[0].biasRate),
                                                     splat(s.softness[1].biasRate)},
          massScales{splat(s.softness[0].massScale), splat(s.softness[1].massScale)},
          impulseScales{splat(s.softness[0].impulseScale), splat(s.softness[1].impulseScale)}
    {
    }
};

/// The friction impulses of one block's lanes along the tangent (tx, ty), each within its cone
/// of this pass's normal impulse. (The block a parameter of the template: see solveLanes().)
template <typename BlockType>
inline void frictionLanes(BlockType& c, Side& A, Side& B, const V& mA, const V& iA, const V& mB,
                          const V& iB, const V& tx, const V& ty)
{
    const V friction = load(c.friction);
    for (auto& p : c.p) {
        const V rAx = load(p.rAx), rAy = load(p.rAy), rBx = load(p.rBx), rBy = load(p.rBy);
        V vt = relative(A, B, tx, ty, rAx, rAy, rBx, rBy);
        if constexpr (kSingle) {
            // The change, so that the impulse stays within the cone: start + change in
            // [-limit, limit].
            vt += origin<true>(p);
            const V limit = friction * (load(p.normalImpulse) + load(p.single.normalChange));
            const V start = load(p.tangentImpulse);
            const V old = load(p.single.tangentChange);
            const V next =
                vmax(vmin(old - load(p.tangentMass) * vt, limit - start), -limit - start);
            store(p.single.tangentChange, next);
            apply(A, B, mA, iA, mB, iB, next - old, tx, ty, rAx, rAy, rBx, rBy);
            continue;
        }
        const V limit = friction * load(p.normalImpulse);
        const V old = load(p.tangentImpulse);
        const V next = vmax(vmin(old - load(p.tangentMass) * vt, limit), -limit);
        store(p.tangentImpulse, next);
        apply(A, B, mA, iA, mB, iB, next - old, tx, ty, rAx, rAy, rBx, rBy);
    }
}

/// One pass over one block's lanes, on its sides and motion as gathered.
/// (Block as a parameter of the template, so that single precision's members are only
/// looked up in the kernels that have them.)
template <bool kBias, bool kFriction, typename BlockType>
inline void solveLanes(BlockType& c, Side& A, Side& B, const Motion& m, const PassConstants& k)
{
    const V zero = k.zero;
    const V mA = A.m, iA = load(c.invIA), mB = B.m, iB = load(c.invIB);
    const V nx = load(c.nx), ny = load(c.ny);
    // The softness of each lane: against a body that does not move, or between two that do.
    V biasRate = zero, massScale = zero, impulseScale = zero;
    if constexpr (kBias) {
        const auto oneSided = (mA == zero) | (mB == zero);
        biasRate = oneSided ? k.biasRates[1] : k.biasRates[0];
        massScale = oneSided ? k.massScales[1] : k.massScales[0];
        impulseScale = oneSided ? k.impulseScales[1] : k.impulseScales[0];
    }
    for (auto& p : c.p) {
        const V rAx = load(p.rAx), rAy = load(p.rAy), rBx = load(p.rBx), rBy = load(p.rBy);
        // The separation now: both lever arms turned by their body's rotation so far (in
        // single precision by the rotation less the identity, from the separation at the
        // start: the same sum, without the lever arms' whole length in it).
        const V dx = m.dpx + (m.qcB * rBx - m.qsB * rBy) - (m.qcA * rAx - m.qsA * rAy);
        const V dy = m.dpy + (m.qsB * rBx + m.qcB * rBy) - (m.qsA * rAx + m.qcA * rAy);
        const V sep = dx * nx + dy * ny + load(p.base);
        const auto gap = sep > zero;
        V vn = relative(A, B, nx, ny, rAx, rAy, rBx, rBy);
        if constexpr (kSingle)
            vn += origin<false>(p);
        if constexpr (kSingle) {
            // The change since the step began, clamped so that the impulse (the one at the
            // start, rounded, plus the change) stays >= 0: at most -start, which makes it 0.
            const V total = load(p.normalImpulse);
            const V old = load(p.single.normalChange);
            V next;
            if constexpr (kBias) {
                const V bias = gap ? sep * k.inverseSubstep : vmax(biasRate * sep, k.maxPush);
                const V ms = gap ? splat(1.0) : massScale;
                const V is = gap ? zero : impulseScale;
                next =
                    vmax(old - load(p.normalMass) * ms * (vn + bias) - is * (total + old), -total);
            } else {
                const V bias = gap ? sep * k.inverseSubstep : zero;
                next = vmax(old - load(p.normalMass) * (vn + bias), -total);
            }
            store(p.single.normalChange, next);
            apply(A, B, mA, iA, mB, iB, next - old, nx, ny, rAx, rAy, rBx, rBy);
            continue;
        }
        const V old = load(p.normalImpulse);
        V next;
        if constexpr (kBias) {
            const V bias = gap ? sep * k.inverseSubstep : vmax(biasRate * sep, k.maxPush);
            const V ms = gap ? splat(1.0) : massScale;
            const V is = gap ? zero : impulseScale;
            next = vmax(old - load(p.normalMass) * ms * (vn + bias) - is * old, zero);
        } else {
            // Rigid: the soft formula with ms = 1 and is = 0, whose products by 1 and
            // subtraction of +0 (j >= 0) are exact, so the same bits with fewer operations.
            const V bias = gap ? sep * k.inverseSubstep : zero;
            next = vmax(old - load(p.normalMass) * (vn + bias), zero);
        }
        store(p.normalImpulse, next);
        apply(A, B, mA, iA, mB, iB, next - old, nx, ny, rAx, rAy, rBx, rBy);
    }
    // Friction after the normal impulses, so that its cone is this pass's.
    if constexpr (kFriction)
        frictionLanes(c, A, B, mA, iA, mB, iB, ny, -nx);
}

/// One pass, compiled for each combination of PassSettings::useBias and ::friction.
template <bool kBias, bool kFriction>
void solvePass(Block* blocks, int count, BodyState* bodies, const PassSettings& s)
{
    const PassConstants constants(s);
    eachBlock(blocks, count, bodies, [&](Block& c, Side& A, Side& B) {
        solveLanes<kBias, kFriction>(c, A, B, gatherMotion(c, bodies), constants);
    });
}

void solveBlocks(Block* blocks, int count, BodyState* bodies, const PassSettings& s)
{
    if (s.useBias && s.friction)
        solvePass<true, true>(blocks, count, bodies, s);
    else if (s.useBias)
        solvePass<true, false>(blocks, count, bodies, s);
    else if (s.friction)
        solvePass<false, true>(blocks, count, bodies, s);
    else
        solvePass<false, false>(blocks, count, bodies, s);
}

#if RIGIDLAB_SOFT_SINGLE
// Single precision's last relax pass in double (KernelOf::relaxDouble).
#include "soft_kernel_relax_double.h"
#endif

} // namespace
} // namespace RIGIDLAB_SOFT_NAMESPACE

#if defined(RIGIDLAB_SOFT_KERNEL)
// The kernel's name and width, from the file that compiles this one again.
RIGIDLAB_SOFT_KERNEL
{
    // Single precision has no warm start of its own: its impulses are applied in double
    // (SoftSolver::warmStart).
    using namespace RIGIDLAB_SOFT_NAMESPACE;
#if RIGIDLAB_SOFT_SINGLE
    return {nullptr, solveBlocks, RIGIDLAB_SOFT_WIDTH, RIGIDLAB_SOFT_NAME, relaxDoubleBlocks};
#else
    return {warmStartBlocks, solveBlocks, RIGIDLAB_SOFT_WIDTH, RIGIDLAB_SOFT_NAME};
#endif
}
#else
Kernel kernel2()
{
    return {lanes2::warmStartBlocks, lanes2::solveBlocks, 2, "2 lanes"};
}
#endif

} // namespace rigidlab::physics::soft
