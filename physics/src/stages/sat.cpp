// SPDX-License-Identifier: GPL-3.0-or-later
// Stage::NarrowPhase (profile.h), its test for polygons: the separating axis theorem (the
// paper's method). The manifolds it leads to are built in manifold.cpp.
//
// SAT: two convex polygons are disjoint exactly when some line separates them, and it is
// enough to try the normals of their edges (Ericson, Real-Time Collision Detection, 5.2.1).
// Each axis is projected on both polygons; the first axis with a gap ends the test. When no
// axis separates, the axis with the least overlap gives the normal and the depth, and the
// reference face for the manifold (manifold.cpp) is chosen here.
//
//          A's interval             B's interval
//     |--------------------|   |-------------------|     axis n: pushB = maxA - minB < 0,
//    minA                 maxA minB               maxB   a gap: n separates A and B
//
// This is the plain SAT, the one the lessons draw (record = true) and the plain path of the
// narrow phase runs. Its acceleration, the same arithmetic for less work, is
// fast/sat_fast.cpp.

#include "manifold.h"

#include <algorithm>
#include <cmath>

namespace rigidlab::physics {

namespace {

/// The interval [lo, hi] of p's vertices projected on axis [m].
void project(const WorldPolygon& p, const Vec2& axis, double& lo, double& hi)
{
    lo = hi = axis.dot(p.v[0]);
    for (int i = 1; i < p.count; ++i) {
        const double d = axis.dot(p.v[static_cast<size_t>(i)]);
        lo = std::min(lo, d);
        hi = std::max(hi, d);
    }
}

/// What the loop over the axes keeps besides the SatResult: the least overlap over all axes
/// (the depth), and each polygon's least one-sided overlap along its own normals, with that
/// edge (to pick the reference face).
struct LeastOverlaps {
    double least = 0.0;
    int leastIndex = -1;
    double own[2] = {0.0, 0.0};
    int edge[2] = {-1, -1};
};

} // namespace

void toWorld(const Polygon& p, const Transform& xf, PlacedPolygon& out)
{
    out.count = static_cast<int>(std::min<size_t>(p.vertices.size(), kMaxPolygonVertices));
    for (size_t i = 0; i < static_cast<size_t>(out.count); ++i) {
        out.v[i] = xf.apply(p.vertices[i]);
        out.n[i] = xf.q.apply(p.normals[i]);
    }
}

SatResult satPolygons(const Polygon& a, const Transform& xfA, const Polygon& b,
                      const Transform& xfB, double margin, bool record)
{
    SatResult r;
    PlacedPolygon pa, pb;
    toWorld(a, xfA, pa);
    toWorld(b, xfB, pb);
    const WorldPolygon wa = pa.view(), wb = pb.view();
    LeastOverlaps lo;
    int index = 0; // of the axis, in the order tested: A's normals, then B's
    for (int owner = 0; owner < 2; ++owner) {
        const WorldPolygon& p = owner == 0 ? wa : wb;
        for (int e = 0; e < p.count; ++e, ++index) {
            SatAxis ax{.owner = owner, .edge = e, .axis = p.n[static_cast<size_t>(e)]};
            project(wa, ax.axis, ax.minA, ax.maxA);
            project(wb, ax.axis, ax.minB, ax.maxB);
            const double pushB = ax.maxA - ax.minB; // move B along +axis by this
            const double pushA = ax.maxB - ax.minA; // or along -axis by this
            ax.overlap = std::min(pushB, pushA);
            if (record)
                r.axes.push_back(ax);
            if (ax.overlap < -margin) { // a gap: the first separating axis ends the test
                r.axesTested = index + 1;
                r.separatingAxis = record ? index : -1;
                return r;
            }
            if (lo.leastIndex < 0 || ax.overlap < lo.least) {
                lo.least = ax.overlap;
                lo.leastIndex = index;
                r.normal = pushB <= pushA ? ax.axis : Vec2(-ax.axis);
            }
            // One-sided overlap along this polygon's outward normal, towards the other one.
            const double own = owner == 0 ? pushB : pushA;
            if (lo.edge[owner] < 0 || own < lo.own[owner]) {
                lo.own[owner] = own;
                lo.edge[owner] = e;
            }
        }
    }
    r.axesTested = index;
    r.intersects = lo.least >= 0.0;
    r.leastAxis = record ? lo.leastIndex : -1;
    r.depth = lo.least;
    if (!r.intersects && margin <= 0.0)
        return r;
    // Reference face: A's unless B's one-sided overlap is clearly smaller; the incident edge
    // of the other polygon is clipped against it (manifold.cpp).
    const int owner = lo.own[1] < lo.own[0] - kReferenceHysteresis ? 1 : 0;
    const WorldPolygon& ref = owner == 0 ? wa : wb;
    const WorldPolygon& inc = owner == 0 ? wb : wa;
    const Faces faces{owner, lo.edge[owner], incidentEdge(ref, lo.edge[owner], inc)};
    clipPolygonManifold(ref, owner == 0 ? xfA : xfB, inc, owner == 0 ? xfB : xfA, faces, margin,
                        r.intersects, r.manifold);
    return r;
}

} // namespace rigidlab::physics
