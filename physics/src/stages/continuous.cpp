// SPDX-License-Identifier: GPL-3.0-or-later
// Continuous collision by speculative contacts (Catto, "Continuous Collision", GDC 2013;
// Box2D v3's speculative margin). The contact solver already lets a contact with a gap close
// by at most that gap within the step (its target vn >= -separation / dt) and times a bounce
// inside the step. What a fast body lacks is the contact itself: found where it stands at the
// start of the step with the fixed margin (ContactSettings::margin, 1 cm), a bullet that moves
// 1.5 m per step is never near enough to the wall to get one, and jumps over it.
//
// So a body that moves more than its own size in a step (the soft step: more than the margin)
// gets a margin as large as its motion
// bound, |v| dt + |w| R dt + |g| dt^2 (R its farthest point from the centre of mass), both in
// the broad phase (its box grown by that) and in the narrow phase (the pair's margin):
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

namespace {

/// The pairs from `before` on (none of them among the sorted ones before it) sorted, made
/// distinct and merged in: the same sorted list of distinct pairs as sorting the whole.
void mergeNewPairs(std::vector<std::pair<int, int>>& pairs, size_t before)
{
    if (pairs.size() == before)
        return;
    const auto found = pairs.begin() + static_cast<std::ptrdiff_t>(before);
    std::sort(found, pairs.end());
    pairs.erase(std::unique(found, pairs.end()), pairs.end());
    std::inplace_merge(pairs.begin(), pairs.begin() + static_cast<std::ptrdiff_t>(before),
                       pairs.end());
}

} // namespace

void addSweptPairs(StepContext& ctx, std::vector<std::pair<int, int>>& pairs)
{
    ctx.sweep.clear();
    if (!ctx.def.continuous)
        return;
    const double h = ctx.def.dt;
    std::vector<int> fast;
    for (size_t i = 0; i < ctx.bodies.size(); ++i) {
        const Body& b = ctx.bodies[i];
        if (!b.moves() || !b.collide)
            continue;
        const double reach = outerRadius(b);
        const double motion = (b.velocity.norm() + std::abs(b.angularVelocity) * reach) * h +
                              (b.isDynamic() ? ctx.def.gravity.norm() * h * h : 0.0);
        // The soft step times each impact from the contact's gap at the start of the step
        // (soft_impacts.cpp), so it wants the contact of every body that moves more than the
        // margin in a step, before the two overlap; the impulse solvers only the bullets'.
        const double fastAbove = ctx.plan.soft ? ctx.contactSettings.margin : ownSize(b);
        if (!(motion > fastAbove) || !std::isfinite(motion))
            continue;
        if (ctx.sweep.empty())
            ctx.sweep.assign(ctx.bodies.size(), 0.0);
        ctx.sweep[i] = motion;
        fast.push_back(static_cast<int>(i));
    }
    if (fast.empty())
        return;
    // Each fast body's grown box against the boxes near it (the broad phase's tree holds every
    // body's box), then the fast bodies' grown boxes against each other, swept along x (the
    // soft step makes every body faster than the margin a fast one: a falling pile of
    // thousands, which a test of every two would make quadratic).
    const size_t before = pairs.size();
    const double margin = ctx.contactSettings.margin;
    const StepScratch& s = ctx.scratch;
    std::vector<std::pair<Aabb, int>> grown;
    grown.reserve(fast.size());
    for (int f : fast)
        grown.emplace_back(computeAabb(ctx.bodies[static_cast<size_t>(f)].shape,
                                       s.xf[static_cast<size_t>(f)],
                                       margin + ctx.sweep[static_cast<size_t>(f)]),
                           f);
    const auto add = [&](int f, int j) {
        const Body& a = ctx.bodies[static_cast<size_t>(f)];
        const Body& b = ctx.bodies[static_cast<size_t>(j)];
        if (j == f || !b.collide || (!a.isDynamic() && !b.isDynamic()))
            return;
        const std::pair<int, int> p = std::minmax(f, j);
        if (std::binary_search(ctx.jointPairs.begin(), ctx.jointPairs.end(), p))
            return;
        // Most are pairs the broad phase found already (its list is sorted): only the new
        // ones are added, so that the list is not sorted whole again every step.
        const auto found = pairs.begin() + static_cast<std::ptrdiff_t>(before);
        if (!std::binary_search(pairs.begin(), found, p))
            pairs.push_back(p);
    };
    for (const auto& entry : grown) {
        // Named, not a structured binding: clang before 16 (the fuzz build's) cannot capture
        // one in a lambda.
        const auto& box = entry.first;
        const int f = entry.second;
        s.broadPhase.query(box, [&](int j) {
            if (ctx.sweep[static_cast<size_t>(j)] > 0)
                return; // another fast body: its grown box, below
            if (box.overlaps(s.broadPhase.box(j)))
                add(f, j);
        });
    }
    std::sort(grown.begin(), grown.end(),
              [](const auto& x, const auto& y) { return x.first.lo.x() < y.first.lo.x(); });
    for (size_t i = 0; i < grown.size(); ++i)
        for (size_t k = i + 1; k < grown.size() && grown[k].first.lo.x() <= grown[i].first.hi.x();
             ++k)
            if (grown[i].first.overlaps(grown[k].first))
                add(grown[i].second, grown[k].second);
    mergeNewPairs(pairs, before);
}

} // namespace rigidlab::physics
