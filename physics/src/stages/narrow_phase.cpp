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

#include "stages.h"

#include "rigidlab/physics/work_budget.h"

#include <algorithm>
#include <cmath>

namespace rigidlab::physics {

void mixMaterials(const Body& a, const Body& b, Contact& c)
{
    c.restitution = std::max(a.restitution, b.restitution);
    c.friction = std::sqrt(a.friction * b.friction);
}

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

void narrowPhase(const std::vector<Body>& bodies, const std::vector<Transform>& xf,
                 const std::vector<std::pair<int, int>>& pairs, double margin,
                 const std::vector<double>& sweep, const std::vector<Contact>& previous,
                 std::vector<Contact>& contacts)
{
    PreviousPairs<Contact> before(previous);
    for (const auto& [ia, ib] : pairs) {
        const Body& a = bodies[static_cast<size_t>(ia)];
        const Body& b = bodies[static_cast<size_t>(ib)];
        // Two resting bodies keep last step's contact.
        if (rests(a) && rests(b)) {
            if (const Contact* kept = before.find(ia, ib)) {
                contacts.push_back(*kept);
                continue;
            }
        }
        Contact c;
        c.a = ia;
        c.b = ib;
        c.manifold = collideShapes(a.shape, xf[static_cast<size_t>(ia)], b.shape,
                                   xf[static_cast<size_t>(ib)],
                                   margin + sweptMargin(sweep, ia) + sweptMargin(sweep, ib));
        if (c.manifold.pointCount == 0)
            continue; // farther apart than the margin
        finishContact(a, b, before, c);
        contacts.push_back(c);
    }
}

void findContacts(StepContext& ctx)
{
    StepScratch& s = ctx.scratch;
    std::swap(s.previous, ctx.contacts);
    ctx.contacts.clear();
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
    if (ctx.plain) {
        s.narrow.clear();
        narrowPhase(ctx.bodies, s.xf, s.pairs, margin, ctx.sweep, s.previous, ctx.contacts);
    } else {
        s.narrow.reuseFaces = ctx.contactSettings.reuseFaces;
        narrowPhaseFast(ctx.bodies, s.xf, s.pairs, margin, ctx.sweep, s.previous, s.narrow,
                        ctx.contacts);
    }
    ctx.profile.contacts = static_cast<int>(ctx.contacts.size());
    ctx.profile.reusedFaces = s.narrow.reused;
}

} // namespace rigidlab::physics
