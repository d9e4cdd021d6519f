// SPDX-License-Identifier: GPL-3.0-or-later
// Continuous collision for fast bodies (a body that moves more than its own size in a step,
// continuous.cpp's bullet), after the soft step's substeps or the impulse solvers' solve.
//
// The speculative contact made at the start of the step (continuous.cpp) stops a body that
// flies straight at a wall: its closest features then are the ones that hit. A body that turns
// fast, or a sharp wedge that meets the wall obliquely, hits with a corner that was not in the
// start's manifold, and the substeps let it through. So each fast body's motion in the step,
// from its pose at the start to its pose at the end taken as linear in time, is swept against
// every body that does not move in the step (static and sleeping ones, the thin walls):
//
//     t = 0; repeat: s = the gap at t (the manifold's least separation, never more than the
//     distance); t += s / (how fast any point of the body can close in on the other: the
//     centre's displacement plus the turn times the farthest point's distance)
//
// Conservative advancement (Mirtich): no step of t passes the first touch. Where the gap falls
// below the linear slop before t = 1 (half the gap at the start, for a body within the slop
// then; half the gap at the end, for a body that ends short of the other), the body is put
// back to that pose with its velocities: the next step finds the
// contact touching, and its collision phase stops it (the soft step's, or the impulse
// solvers'). Box2D v3's continuous
// collision is the same idea, with its own time of impact.

#include "rigidlab/physics/world.h"

#include "broad_phase.h"
#include "stages.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace rigidlab::physics {

namespace {

/// A pose on the way from the start's to the end's.
Transform poseAt(const Body& b, const Vec2& x0, double angle0, double t)
{
    Transform xf;
    xf.q = Rotation(angle0 + t * (b.angle - angle0));
    xf.p = (x0 + t * (b.position - x0)) - xf.q.apply(b.localCenter);
    return xf;
}

/// The least separation of two shapes placed by xfA, xfB, at most `margin` [m].
double gap(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB,
           double margin)
{
    const Manifold m = collideShapes(a, xfA, b, xfB, margin);
    double s = margin;
    for (int i = 0; i < m.pointCount; ++i)
        s = std::min(s, m.points[static_cast<size_t>(i)].separation);
    return s;
}

/// The fraction of the step at which the fast body `fast` first comes within `target` of the
/// body `other` that does not move, or 1 when it does not.
double firstTouch(const StepContext& ctx, int fast, int other, double reach, double target)
{
    const Body& a = ctx.bodies[static_cast<size_t>(fast)];
    const Body& b = ctx.bodies[static_cast<size_t>(other)];
    const StepScratch& s = ctx.scratch;
    const Vec2& x0 = s.xfPosition[static_cast<size_t>(fast)];
    const double angle0 = s.xfAngle[static_cast<size_t>(fast)];
    const Transform xfB = b.transform();
    // How far any point of the body moves over the whole step, at most [m].
    const double bound = (a.position - x0).norm() + std::abs(a.angle - angle0) * reach;
    if (!(bound > 0))
        return 1.0;
    const double margin = bound + target + ctx.contactSettings.margin;
    // A body within the slop at the start comes no nearer than half its gap then (a box
    // spinning at the wall touches it with one corner and may swing another into it); one
    // overlapping already is the contact's.
    const double start = gap(a.shape, poseAt(a, x0, angle0, 0.0), b.shape, xfB, margin);
    if (!(start > 0.0))
        return 1.0;
    target = std::min(target, 0.5 * start);
    // A body that ends the step short of the other (a ball falling onto the floor, stopped by
    // nothing yet) is put back only if its path comes nearer than half its gap at the end: in
    // between, it passed through. Put back into the slop from where it ends, it rose without
    // losing speed, and gravity's work on it came back as energy (a bouncing ball climbed).
    const double end = gap(a.shape, poseAt(a, x0, angle0, 1.0), b.shape, xfB, margin);
    if (end > 0.0)
        target = std::min(target, 0.5 * end);
    constexpr int kIterations = 100;
    double t = 0.0;
    for (int k = 0; k < kIterations; ++k) {
        const double sep = gap(a.shape, poseAt(a, x0, angle0, t), b.shape, xfB, margin);
        if (sep <= target)
            return t;
        t += (sep - 0.5 * target) / bound;
        if (t >= 1.0)
            return 1.0;
    }
    return t; // still closing in after many steps: stop where it is, short of touching
}

} // namespace

void sweepBackBullets(StepContext& ctx)
{
    if (ctx.sweep.empty())
        return;
    const std::vector<BodyExtent>& extent = bodyExtents(ctx);
    const StepScratch& s = ctx.scratch;
    const double target = ctx.contactSettings.linearSlop;
    for (size_t i = 0; i < ctx.bodies.size(); ++i) {
        Body& a = ctx.bodies[i];
        const double size = extent[i].ownSize;
        assert(size == ownSize(a) && extent[i].outerRadius == outerRadius(a));
        // The bullets: a body that moves less than its own size in a step cannot pass a wall
        // its contact has not stopped (the soft step finds the contacts of every body faster
        // than the margin, continuous.cpp; sweeping them all cost a rain of 1000 bodies twice
        // its step).
        if (!(ctx.sweep[i] > 0) || !a.isActive() || !a.collide || !(ctx.sweep[i] > size))
            continue;
        const double reach = extent[i].outerRadius;
        const Vec2 x0 = s.xfPosition[i];
        const double angle0 = s.xfAngle[i];
        // Nor one that, stopped by its contacts, moved less than that in the end (a ball at
        // rest at dt = 0.2 s, whose bound g dt^2 is twice its size: put back to where it
        // touched at the start, it rose out of its soft contact, and the energy books, which
        // had counted the sink, were out by that much each step).
        const double moved = (a.position - x0).norm() + std::abs(a.angle - angle0) * reach;
        if (!(moved > size))
            continue;
        // Everything the motion could reach: the box of the start's pose grown by the sweep.
        const Aabb box = computeAabb(a.shape, s.xf[i], ctx.contactSettings.margin + ctx.sweep[i]);
        double first = 1.0;
        s.broadPhase.query(box, [&](int j) {
            const Body& b = ctx.bodies[static_cast<size_t>(j)];
            if (static_cast<size_t>(j) == i || !b.collide || b.isActive() ||
                b.type == BodyType::Kinematic)
                return;
            const std::pair<int, int> pair = std::minmax(static_cast<int>(i), j);
            if (std::binary_search(ctx.jointPairs.begin(), ctx.jointPairs.end(), pair))
                return;
            first = std::min(first, firstTouch(ctx, static_cast<int>(i), j, reach, target));
        });
        if (first < 1.0) {
            a.position = x0 + first * (a.position - x0);
            a.angle = angle0 + first * (a.angle - angle0);
        }
    }
}

} // namespace rigidlab::physics
