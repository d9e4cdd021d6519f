// SPDX-License-Identifier: GPL-3.0-or-later
// Part of soft_kernel.cpp, included by it in its namespace when it is compiled in single
// precision (RIGIDLAB_SOFT_SINGLE): not a header of its own. It uses the kernel's vectors and
// its textbook formulas (load, store, relative, apply) on vectors of doubles.
//
// Single precision's last relax pass in double (KernelOf::relaxDouble): on the double bodies,
// from the float block's rows widened exactly, each impulse its start plus its change (both
// floats, exact in double); the change stored back as next - start, rounded. One block after
// the other: a lane's result does not depend on its neighbours, so both widths give the same
// bits.

using VD = double __attribute__((vector_size(W * sizeof(double))));
using DoubleState = BodyStateOf<double>;

inline VD widen(const Real* p)
{
    return __builtin_convertvector(load(p), VD);
}

struct DoubleSide {
    VD vx, vy, w, m;
};

inline DoubleSide gatherDouble(const int* index, const DoubleState* bodies)
{
    DoubleSide s;
    for (int i = 0; i < W; ++i) {
        const DoubleState& b = bodies[index[i]];
        s.vx[i] = b.vx;
        s.vy[i] = b.vy;
        s.w[i] = b.w;
        s.m[i] = b.invMass;
    }
    return s;
}

inline void scatterDouble(const int* index, DoubleState* bodies, const DoubleSide& s)
{
    // As scatter(): a body that does not move writes back what it read.
    for (int i = 0; i < W; ++i) {
        DoubleState& b = bodies[index[i]];
        b.vx = s.vx[i];
        b.vy = s.vy[i];
        b.w = s.w[i];
    }
}

void relaxDoubleBlocks(Block* blocks, int count, DoubleState* bodies, const PassSettings& s)
{
    // The relax pass of solveLanes(): rigid, a gap closing by s / t over the look-ahead time.
    const VD zero{}, inverseSubstep = VD{} + s.inverseSubstep;
    for (int k = 0; k < count; ++k) {
        Block& c = blocks[k];
        DoubleSide A = gatherDouble(c.a, bodies), B = gatherDouble(c.b, bodies);
        // The displacements and the rotations less the identity, in double.
        VD dpx, dpy, qcA, qsA, qcB, qsB;
        for (int i = 0; i < W; ++i) {
            const DoubleState& a = bodies[c.a[i]];
            const DoubleState& b = bodies[c.b[i]];
            dpx[i] = b.dpx - a.dpx;
            dpy[i] = b.dpy - a.dpy;
            qcA[i] = a.qc - 1.0;
            qsA[i] = a.qs;
            qcB[i] = b.qc - 1.0;
            qsB[i] = b.qs;
        }
        const VD iA = widen(c.invIA), iB = widen(c.invIB), nx = widen(c.nx), ny = widen(c.ny);
        VD jn[2];
        for (int i = 0; i < 2; ++i) {
            PointLanes& p = c.p[i];
            const VD start = widen(p.normalImpulse);
            const VD old = start + widen(p.single.normalChange);
            const VD rAx = widen(p.rAx), rAy = widen(p.rAy), rBx = widen(p.rBx), rBy = widen(p.rBy);
            const VD dx = dpx + (qcB * rBx - qsB * rBy) - (qcA * rAx - qsA * rAy);
            const VD dy = dpy + (qsB * rBx + qcB * rBy) - (qsA * rAx + qcA * rAy);
            const VD sep = dx * nx + dy * ny + widen(p.base);
            const VD bias = sep > zero ? sep * inverseSubstep : zero;
            const VD vn = relative(A, B, nx, ny, rAx, rAy, rBx, rBy);
            const VD sum = old - widen(p.normalMass) * (vn + bias);
            const VD next = sum > zero ? sum : zero;
            // 0 gives -start exactly, so that end() reads a released impulse as 0.
            store(p.single.normalChange, __builtin_convertvector(next - start, V));
            jn[i] = next;
            apply(A, B, A.m, iA, B.m, iB, next - old, nx, ny, rAx, rAy, rBx, rBy);
        }
        if (s.friction) {
            const VD friction = widen(c.friction);
            const VD tx = ny, ty = -nx;
            for (int i = 0; i < 2; ++i) {
                PointLanes& p = c.p[i];
                const VD start = widen(p.tangentImpulse);
                const VD old = start + widen(p.single.tangentChange);
                const VD rAx = widen(p.rAx), rAy = widen(p.rAy), rBx = widen(p.rBx),
                         rBy = widen(p.rBy);
                const VD limit = friction * jn[i];
                const VD vt = relative(A, B, tx, ty, rAx, rAy, rBx, rBy);
                const VD unclamped = old - widen(p.tangentMass) * vt;
                const VD capped = unclamped < limit ? unclamped : limit;
                const VD next = capped > -limit ? capped : -limit;
                store(p.single.tangentChange, __builtin_convertvector(next - start, V));
                apply(A, B, A.m, iA, B.m, iB, next - old, tx, ty, rAx, rAy, rBx, rBy);
            }
        }
        scatterDouble(c.a, bodies, A);
        scatterDouble(c.b, bodies, B);
    }
}
