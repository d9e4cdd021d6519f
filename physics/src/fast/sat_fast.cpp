// SPDX-License-Identifier: GPL-3.0-or-later
// The acceleration of the SAT (stages/sat.cpp) for the narrow phase (fast/kept_faces.cpp):
// the same arithmetic in the same order, so the same manifold bit for bit, for less work.
//   - Each polygon is placed once per step, with its own projection on each of its edge
//     normals (placePolygon, WorldPolygons): a pair projects only the other polygon.
//   - Two boxes (the common case) run with their vertex count known at compile time, the
//     loops unrolled.
//   - A hint (last step's separating axis of the pair) is tried first: it settles a pair
//     still apart with one axis, and cannot change the result (see collidePlacedPolygons).
//   - The faces chosen come with how far that choice was from changing (FaceChoice), for the
//     kept faces of the narrow phase.

#include "manifold.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rigidlab::physics {

namespace {

// No next overlap yet [m].
constexpr double kNone = std::numeric_limits<double>::infinity();

/// kCount: the vertex count when known at compile time (4, a box: the loops unroll), else 0.
template <int kCount = 0>
[[gnu::always_inline]] inline void project(const WorldPolygon& p, const Vec2& axis, double& lo,
                                           double& hi)
{
    const int count = kCount > 0 ? kCount : p.count;
    lo = hi = axis.dot(p.v[0]);
    for (int i = 1; i < count; ++i) {
        const double d = axis.dot(p.v[static_cast<size_t>(i)]);
        lo = std::min(lo, d);
        hi = std::max(hi, d);
    }
}

/// Places `p` by `xf` into the arrays (room for its vertex count), with its own projection
/// interval on each edge normal; returns the vertex count. The vertices and normals are
/// placePolygon's of stages/sat.cpp, the same arithmetic.
int placePolygon(const Polygon& p, const Transform& xf, Vec2* v, Vec2* n, double* ownMin,
                 double* ownMax)
{
    const int count = static_cast<int>(std::min<size_t>(p.vertices.size(), kMaxPolygonVertices));
    for (int i = 0; i < count; ++i) {
        v[i] = xf.apply(p.vertices[static_cast<size_t>(i)]);
        n[i] = xf.q.apply(p.normals[static_cast<size_t>(i)]);
    }
    const WorldPolygon placed{v, n, nullptr, nullptr, count};
    if (count == 4) // a box: the loops unrolled, the same arithmetic
        for (int i = 0; i < 4; ++i)
            project<4>(placed, n[i], ownMin[i], ownMax[i]);
    else
        for (int i = 0; i < count; ++i)
            project(placed, n[i], ownMin[i], ownMax[i]);
    return count;
}

/// Both polygons projected on the normal `e` of polygon `owner` (0: A, 1: B). The axis' own
/// polygon was projected on it when it was placed.
template <int kCount = 0>
[[gnu::always_inline]] inline void projectOn(const WorldPolygon& wa, const WorldPolygon& wb,
                                             int owner, int e, double& minA, double& maxA,
                                             double& minB, double& maxB)
{
    if (owner == 0) {
        minA = wa.ownMin[e];
        maxA = wa.ownMax[e];
        project<kCount>(wb, wa.n[e], minB, maxB);
    } else {
        project<kCount>(wa, wb.n[e], minA, maxA);
        minB = wb.ownMin[e];
        maxB = wb.ownMax[e];
    }
}

/// What satImpl finds; the manifold goes straight to the contact.
struct EngineVerdict {
    int axesTested = 0;
    bool intersects = false;
    Vec2 normal = Vec2::Zero();
    double depth = 0;
    Manifold& manifold;
    FaceChoice* choice = nullptr; ///< when given, how far the choice of faces was from changing
};

/// Reference face, incident edge, clipping and the choice's margins (FaceChoice), once no
/// axis separated the polygons by more than margin. leastOwn, nextOwn and leastEdge: per
/// polygon, its least one-sided overlap, the next one, and that least edge.
void clipChosenFaces(const WorldPolygon& wa, const Transform& xfA, const WorldPolygon& wb,
                     const Transform& xfB, double margin, const double (&leastOwn)[2],
                     const double (&nextOwn)[2], const int (&leastEdge)[2], double least,
                     EngineVerdict& r)
{
    // Reference face: A's unless B's one-sided overlap is clearly smaller.
    const int owner = leastOwn[1] < leastOwn[0] - kReferenceHysteresis ? 1 : 0;
    const WorldPolygon& ref = owner == 0 ? wa : wb;
    const WorldPolygon& inc = owner == 0 ? wb : wa;
    const Transform& xfRef = owner == 0 ? xfA : xfB;
    const Transform& xfInc = owner == 0 ? xfB : xfA;
    // The choice's margins (FaceChoice), when asked: every overlap changes by at most as much
    // as the other polygon's vertices move in this polygon's frame, so each polygon keeps its
    // least edge while that is less than half of the edge's lead over the next.
    FaceChoice* choice = r.choice;
    double lead = 0.0;
    const Faces faces{owner, leastEdge[owner],
                      incidentEdge(ref, leastEdge[owner], inc, choice ? &lead : nullptr)};
    const bool kept =
        clipPolygonManifold(ref, xfRef, inc, xfInc, faces, margin, r.intersects, r.manifold);
    if (choice)
        *choice = {.faces = faces,
                   .least = least,
                   .edgeRoom = 0.5 * std::min(nextOwn[0] - leastOwn[0], nextOwn[1] - leastOwn[1]),
                   .ownerRoom = std::abs(leastOwn[1] - (leastOwn[0] - kReferenceHysteresis)),
                   .tilt = (wa.n[static_cast<size_t>(leastEdge[0])] +
                            wb.n[static_cast<size_t>(leastEdge[1])])
                               .norm(),
                   .turnRoom = 0.5 * lead,
                   .kept = kept};
}

/// The SAT of stages/sat.cpp, the same arithmetic in the same order, on polygons placed once
/// per step. `hint`: an axis (index in the order tested) to try first. Returns the index of
/// the axis that separated the polygons by more than margin, or -1.
///
/// The hint cannot change the result: the polygons are farther apart than margin when any
/// axis shows it, and then there is no manifold whichever axis it was; when the hinted axis
/// does not show it, the test runs as without a hint.
/// kCount: both polygons' vertex count when known at compile time (4: two boxes, the
/// narrow phase's common case, its loops unrolled), else 0.
template <int kCount = 0>
int satImpl(const WorldPolygon& wa, const Transform& xfA, const WorldPolygon& wb,
            const Transform& xfB, double margin, int hint, EngineVerdict& r)
{
    const int countA = kCount > 0 ? kCount : wa.count;
    const int countB = kCount > 0 ? kCount : wb.count;
    if (hint >= 0 && hint < countA + countB) {
        const int owner = hint < countA ? 0 : 1;
        double minA, maxA, minB, maxB;
        projectOn<kCount>(wa, wb, owner, owner == 0 ? hint : hint - countA, minA, maxA, minB, maxB);
        if (std::min(maxA - minB, maxB - minA) < -margin) {
            r.axesTested = 1;
            r.intersects = false;
            return hint;
        }
    }
    double least = 0.0, leastOwn[2] = {0.0, 0.0};
    double nextOwn[2] = {kNone, kNone};
    int leastIndex = -1, leastEdge[2] = {-1, -1};
    int index = 0;
    for (int owner = 0; owner < 2; ++owner) {
        const WorldPolygon& p = owner == 0 ? wa : wb;
        const int count = owner == 0 ? countA : countB;
        for (int e = 0; e < count; ++e, ++index) {
            const Vec2& axis = p.n[static_cast<size_t>(e)];
            double minA, maxA, minB, maxB;
            projectOn<kCount>(wa, wb, owner, e, minA, maxA, minB, maxB);
            const double pushB = maxA - minB; // move B along +axis by this
            const double pushA = maxB - minA; // or along -axis by this
            const double overlap = std::min(pushB, pushA);
            if (overlap < -margin) {
                r.axesTested = index + 1;
                r.intersects = false;
                return index;
            }
            if (leastIndex < 0 || overlap < least) {
                least = overlap;
                leastIndex = index;
                r.normal = pushB <= pushA ? axis : Vec2(-axis);
            }
            // The next one-sided overlap of each polygon: how far its least edge is from
            // another (FaceChoice::edgeRoom).
            const double own = owner == 0 ? pushB : pushA;
            if (leastEdge[owner] < 0 || own < leastOwn[owner]) {
                if (leastEdge[owner] >= 0)
                    nextOwn[owner] = leastOwn[owner];
                leastOwn[owner] = own;
                leastEdge[owner] = e;
            } else {
                nextOwn[owner] = std::min(nextOwn[owner], own);
            }
        }
    }
    r.axesTested = index;
    r.intersects = least >= 0.0;
    r.depth = least;
    if (!r.intersects && margin <= 0.0)
        return -1;
    clipChosenFaces(wa, xfA, wb, xfB, margin, leastOwn, nextOwn, leastEdge, least, r);
    return -1;
}

} // namespace

void WorldPolygons::reset(size_t bodies)
{
    m_start.assign(bodies, -1);
    m_count.assign(bodies, 0);
    m_v.clear();
    m_n.clear();
    m_ownMin.clear();
    m_ownMax.clear();
}

void WorldPolygons::placeNew(int body, const Polygon& p, const Transform& xf)
{
    const auto b = static_cast<size_t>(body);
    const size_t start = m_v.size();
    const size_t count = std::min<size_t>(p.vertices.size(), kMaxPolygonVertices);
    m_v.resize(start + count);
    m_n.resize(start + count);
    m_ownMin.resize(start + count);
    m_ownMax.resize(start + count);
    m_start[b] = static_cast<int>(start);
    m_count[b] = placePolygon(p, xf, m_v.data() + start, m_n.data() + start,
                              m_ownMin.data() + start, m_ownMax.data() + start);
}

void collidePlacedPolygons(const WorldPolygon& a, const Transform& xfA, const WorldPolygon& b,
                           const Transform& xfB, double margin, int& separatingAxis,
                           Manifold& manifold, FaceChoice* choice)
{
    EngineVerdict r{.manifold = manifold, .choice = choice};
    separatingAxis = a.count == 4 && b.count == 4
                         ? satImpl<4>(a, xfA, b, xfB, margin, separatingAxis, r)
                         : satImpl(a, xfA, b, xfB, margin, separatingAxis, r);
}

} // namespace rigidlab::physics
