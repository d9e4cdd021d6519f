// SPDX-License-Identifier: GPL-3.0-or-later
// Stage::BroadPhase and Stage::NarrowPhase (profile.h): from the bodies to this step's
// contacts. The broad phase's pairs (broad_phase.cpp, continuous.cpp), then for each pair
// its manifold (manifold.cpp; for two polygons the SAT, sat.cpp) with what a contact carries
// from step to step and from its bodies: the warm-start impulses and the mixed material.
//
// This is the plain narrow phase: every pair gets the whole test. Its acceleration
// (fast/kept_faces.cpp) places each polygon once per step, tries last step's separating axis
// first and clips a pair that barely moved from the faces the SAT chose before: the same
// contacts, bit for bit (EngineSettings::plainPaths, test_golden).

#include "narrow_phase.h"

#include "contact_rewrite.h"

#include "stages.h"

#include "rigidlab/physics/work_budget.h"

#include <algorithm>
#include <cmath>

namespace rigidlab::physics {

void carryImpulses(const Contact& previous, Contact& c)
{
    for (int i = 0; i < c.manifold.pointCount; ++i)
        for (int k = 0; k < previous.manifold.pointCount; ++k)
            if (previous.manifold.points[static_cast<size_t>(k)].id ==
                c.manifold.points[static_cast<size_t>(i)].id) {
                c.normalImpulse[static_cast<size_t>(i)] =
                    previous.normalImpulse[static_cast<size_t>(k)];
                c.tangentImpulse[static_cast<size_t>(i)] =
                    previous.tangentImpulse[static_cast<size_t>(k)];
            }
}

/// A contact with its manifold made: its mixed material and last step's impulses.
void finishContact(const Body& a, const Body& b, PreviousPairs<Contact>& before, Contact& c)
{
    mixMaterials(a, b, c);
    if (const Contact* p = before.find(c.a, c.b))
        carryImpulses(*p, c);
}

namespace {

/// The farthest vertex of p from the body's centre of mass (at localCenter) [m], from above.
double extent(const Polygon& p, const Vec2& localCenter)
{
    double r = 0.0;
    for (const Vec2& v : p.vertices)
        r = std::max(r, (v - localCenter).norm());
    return r;
}

/// The turn from `then` to `now` (now times then's inverse).
Rotation turnSince(const Rotation& now, const Rotation& then)
{
    Rotation q;
    q.c = now.c * then.c + now.s * then.s;
    q.s = now.s * then.c - now.c * then.s;
    return q;
}

} // namespace

void keepAnchors(const Body& a, const Polygon& pa, const Transform& xfA, const Body& b,
                 const Polygon& pb, const Transform& xfB, const Manifold& manifold,
                 ContactAnchors& k)
{
    k.valid = true;
    k.centres = b.position - a.position;
    k.qA = xfA.q;
    k.qB = xfB.q;
    k.extentA = extent(pa, a.localCenter);
    k.extentB = extent(pb, b.localCenter);
    for (int i = 0; i < manifold.pointCount; ++i) {
        const ContactPoint& cp = manifold.points[static_cast<size_t>(i)];
        k.anchorA[static_cast<size_t>(i)] = cp.point - a.position;
        k.anchorB[static_cast<size_t>(i)] = cp.point - b.position;
        k.separation[static_cast<size_t>(i)] = cp.separation;
    }
}

bool mayRecycle(const Contact& previous, const ContactAnchors& k, const Body& a,
                const Transform& xfA, const Body& b, const Transform& xfB, double recycle,
                AnchorMotion& motion)
{
    // After Box2D v3.2 (physics_world.c, b2Collide's contact recycling): the points stay on
    // the bodies, the normal stays, and each separation follows the anchors as the soft
    // step's substeps follow them (soft_kernel.cpp). A vertex moves by at most the shift of the
    // centres plus each body's turn times its extent, so the faces a full test would clip
    // differ from the kept ones by no more than `recycle`.
    if (!k.valid || previous.manifold.pointCount == 0)
        return false;
    motion.dqA = turnSince(xfA.q, k.qA);
    motion.dqB = turnSince(xfB.q, k.qB);
    motion.shift = (b.position - a.position) - k.centres;
    const Rotation& dqA = motion.dqA;
    const Rotation& dqB = motion.dqB;
    // |sin| of each turn, from above by |s| + (1 - c) (a turn past 90 degrees fails anyway).
    const double turns = std::abs(dqA.s) + (1.0 - dqA.c) + std::abs(dqB.s) + (1.0 - dqB.c);
    return motion.shift.lpNorm<1>() + (k.extentA + k.extentB) * turns < recycle;
}

bool recycledPoints(const Contact& previous, const ContactAnchors& k, const Body& a,
                    const Transform& xfA, const Body& b, const Transform& xfB, double recycle,
                    double margin, std::array<ContactPoint, 2>& points)
{
    AnchorMotion m;
    if (!mayRecycle(previous, k, a, xfA, b, xfB, recycle, m))
        return false;
    const Manifold& last = previous.manifold;
    points = last.points;
    for (int i = 0; i < last.pointCount; ++i) {
        const auto p = static_cast<size_t>(i);
        const Vec2 rA = m.dqA.apply(k.anchorA[p]), rB = m.dqB.apply(k.anchorB[p]);
        const double s =
            k.separation[p] + last.normal.dot(m.shift + (rB - k.anchorB[p]) - (rA - k.anchorA[p]));
        if (s > margin)
            return false; // let the full test say whether the point is still there
        points[p].point = 0.5 * ((a.position + rA) + (b.position + rB));
        points[p].separation = s;
    }
    return true;
}

bool recycleManifold(const Contact& previous, const ContactAnchors& kept, const Body& a,
                     const Transform& xfA, const Body& b, const Transform& xfB, double recycle,
                     double margin, Contact& c, ContactAnchors& anchors)
{
    std::array<ContactPoint, 2> points;
    if (!recycledPoints(previous, kept, a, xfA, b, xfB, recycle, margin, points))
        return false;
    c.manifold = previous.manifold;
    c.manifold.points = points;
    anchors = kept;
    return true;
}

void narrowPhase(const std::vector<Body>& bodies, const std::vector<Transform>& xf,
                 const std::vector<std::pair<int, int>>& pairs, double margin,
                 const std::vector<double>& sweep, double recycle, ContactLists lists)
{
    PreviousPairs<Contact> before(lists.previous);
    for (const auto& [ia, ib] : pairs) {
        const Body& a = bodies[static_cast<size_t>(ia)];
        const Body& b = bodies[static_cast<size_t>(ib)];
        // Two resting bodies keep last step's contact.
        if (rests(a) && rests(b)) {
            if (const Contact* kept = before.find(ia, ib)) {
                lists.keep(*kept);
                continue;
            }
        }
        Contact c;
        ContactAnchors anchors;
        c.a = ia;
        c.b = ib;
        const Transform& xfA = xf[static_cast<size_t>(ia)];
        const Transform& xfB = xf[static_cast<size_t>(ib)];
        const double pairMargin = margin + sweptMargin(sweep, ia) + sweptMargin(sweep, ib);
        const Polygon* pa = a.shape.asPolygon();
        const Polygon* pb = b.shape.asPolygon();
        const bool polygons = recycle > 0.0 && pa && pb;
        const Contact* last = polygons && pairMargin == margin ? before.find(ia, ib) : nullptr;
        if (!(last && recycleManifold(*last, lists.anchorsOf(*last), a, xfA, b, xfB, recycle,
                                      margin, c, anchors))) {
            c.manifold = collideShapes(a.shape, xfA, b.shape, xfB, pairMargin);
            if (c.manifold.pointCount == 0)
                continue; // farther apart than the margin
            if (polygons)
                keepAnchors(a, *pa, xfA, b, *pb, xfB, c.manifold, anchors);
        }
        finishContact(a, b, before, c);
        lists.contacts.push_back(c);
        lists.anchors.push_back(anchors);
    }
}

void findContacts(StepContext& ctx)
{
    StepScratch& s = ctx.scratch;
    if (ctx.plain) {
        std::swap(s.previous, ctx.contacts);
        std::swap(s.previousAnchors, ctx.contactAnchors);
        ctx.contacts.clear();
        ctx.contactAnchors.clear();
    }
    s.bounceHeldBefore = s.bounceHeld;
    s.bounceHeld = false;
    const double margin = ctx.contactSettings.margin;

    StageTimer broad(ctx.profile, Stage::BroadPhase);
    if (ctx.plain)
        placeBodies(ctx);
    else
        placeMovedBodies(ctx);
    // Fast bodies: boxes and margins over their motion in this step (continuous collision).
    findSweeps(ctx);
    s.broadPhase.findPairs(ctx.bodies, s.xf, margin, ctx.sweep, ctx.dt, ctx.jointPairs,
                           pairBudget(ctx.bodies.size()), s.pairs);
    broad.stop();
    ctx.profile.pairs = static_cast<int>(s.pairs.size());
    ctx.profile.refitted = s.broadPhase.refitted();

    StageTimer narrow(ctx.profile, Stage::NarrowPhase);
    // Only the soft step recycles manifolds: its substeps already carry each point on its
    // bodies; the impulse solvers' position correction re-evaluates the manifold's faces.
    const double recycle =
        ctx.solver == SolverKind::SoftStep ? ctx.contactSettings.soft.recycleDistance : 0.0;
    if (ctx.plain) {
        const ContactLists lists{.previous = s.previous,
                                 .previousAnchors = s.previousAnchors,
                                 .contacts = ctx.contacts,
                                 .anchors = ctx.contactAnchors,
                                 .bounceKept = s.bounceHeld};
        s.narrow.clear();
        narrowPhase(ctx.bodies, s.xf, s.pairs, margin, ctx.sweep, recycle, lists);
    } else {
        s.narrow.reuseFaces = ctx.contactSettings.reuseFaces;
        // Last step's contacts are read after the narrow phase only for their bounces
        // (ContactSolver::lastBounce, when one holds a bounce) and, in a world stopped as
        // crowded, for the touching points it started with (World::stopWhenCrowded). Else
        // this step's are written over them (fast/contact_rewrite.h) and none is left to read:
        // no bounce to find.
        if (s.bounceHeldBefore || s.broadPhase.crowding()) {
            std::swap(s.previous, ctx.contacts);
            std::swap(s.previousAnchors, ctx.contactAnchors);
            ContactRewrite rewrite(s.previous, s.previousAnchors, ctx.contacts, ctx.contactAnchors,
                                   s.narrow);
            narrowPhaseFast(ctx.bodies, s.xf, s.pairs, margin, ctx.sweep, recycle, s.narrow,
                            rewrite, s.bounceHeld);
        } else {
            s.previous.clear();
            s.previousAnchors.clear();
            ContactRewrite rewrite(ctx.contacts, ctx.contactAnchors, s.narrow);
            narrowPhaseFast(ctx.bodies, s.xf, s.pairs, margin, ctx.sweep, recycle, s.narrow,
                            rewrite, s.bounceHeld);
        }
    }
    ctx.profile.contacts = static_cast<int>(ctx.contacts.size());
    ctx.profile.reusedFaces = s.narrow.reused;
}

} // namespace rigidlab::physics
