// SPDX-License-Identifier: GPL-3.0-or-later
// Continuous collision by speculative contacts (Catto, "Continuous Collision", GDC 2013;
// Box2D v3's speculative margin). The contact solver already lets a contact with a gap close
// by at most that gap within the step (its target vn >= -separation / dt) and times a bounce
// inside the step. What a fast body lacks is the contact itself: found where it stands at the
// start of the step with the fixed margin (ContactSettings::margin, 1 cm), a bullet that moves
// 1.5 m per step is never near enough to the wall to get one, and jumps over it.
//
// So a body that moves more than the margin in a step gets a margin as large as its motion
// bound, |v| dt + |w| R dt + |g| dt^2 (R its farthest point from the centre of mass), both in
// the broad phase (its box grown by that, broad_phase.cpp) and in the narrow phase (the pair's
// margin):
//
//     start         end of step (without contact)
//      (o)--------------------------->(o)
//               |wall|
//      |<-gap->|       the contact is made at the start with separation = gap, and the
//                      solver stops the bullet at the wall within this step.

#include "rigidlab/physics/world.h"

#include "broad_phase.h"
#include "stages.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace rigidlab::physics {

/// Distance from the centre of mass to the shape's farthest point [m].
double outerRadius(const Body& b)
{
    return b.shape.visit(
        Overloaded{[&](const Circle& c) { return (c.center - b.localCenter).norm() + c.radius; },
                   [&](const Polygon& p) {
                       // One square root of the largest square: the same number as the
                       // largest root (the square root is monotonic and correctly rounded),
                       // for every body in every step.
                       double r2 = 0;
                       for (const Vec2& v : p.vertices)
                           r2 = std::max(r2, (v - b.localCenter).squaredNorm());
                       return std::sqrt(r2);
                   }});
}

/// The body's smallest width: what it must not jump past [m].
double ownSize(const Body& b)
{
    return b.shape.visit(Overloaded{[](const Circle& c) { return 2.0 * c.radius; },
                                    [&](const Polygon& p) {
                                        // Twice the smallest distance from the centroid to an
                                        // edge's line.
                                        double d = INFINITY;
                                        for (size_t i = 0; i < p.vertices.size(); ++i)
                                            d = std::min(
                                                d, p.normals[i].dot(p.vertices[i] - b.localCenter));
                                        return 2.0 * std::max(d, 0.0);
                                    }});
}

const std::vector<BodyExtent>& bodyExtents(StepContext& ctx)
{
    // A body's shape and centre of mass do not change after World::addBody, and a world has
    // no way to remove a body: the extents of the bodies seen before stay (a copied world
    // starts with an empty scratch and computes them all). The sanitizer build's asserts check
    // that each extent is still its body's.
    std::vector<BodyExtent>& extent = ctx.scratch.extent;
    if (extent.size() > ctx.bodies.size())
        extent.clear();
    for (size_t i = extent.size(); i < ctx.bodies.size(); ++i)
        extent.push_back({outerRadius(ctx.bodies[i]), ownSize(ctx.bodies[i])});
    return extent;
}

void findSweeps(StepContext& ctx)
{
    ctx.sweep.clear();
    if (!ctx.continuous)
        return;
    const double h = ctx.dt;
    const std::vector<BodyExtent>& extent = bodyExtents(ctx);
    // The fall in a step, once (the stores below kept the compiler from taking it out of the
    // loop): the same number for every dynamic body.
    const double fall = ctx.field.gravity.norm() * h * h;
    // Every solver times an isolated impact from the contact's gap at the start of the step
    // (soft_impacts.cpp), so it wants the contact of every body that moves more than the
    // margin in a step, before the two overlap (found only once they overlap, a cut shot at
    // 1/60 s left 6 mrad off the line of centres).
    const double fastAbove = ctx.contactSettings.margin;
    const size_t n = ctx.bodies.size();
    const Body* const bodies = ctx.bodies.data();
    int fast = 0;
    for (size_t i = 0; i < n; ++i) {
        const Body& b = bodies[i];
        if (!b.moves() || !b.collide)
            continue;
        const double reach = extent[i].outerRadius;
        assert(reach == outerRadius(b));
        const double motion = (b.velocity.norm() + std::abs(b.angularVelocity) * reach) * h +
                              (b.isDynamic() ? fall : 0.0);
        if (!(motion > fastAbove) || !std::isfinite(motion))
            continue;
        if (ctx.sweep.empty())
            ctx.sweep.assign(n, 0.0);
        ctx.sweep[i] = motion;
        ++fast;
    }
    ctx.profile.fast += fast;
}

} // namespace rigidlab::physics
