// SPDX-License-Identifier: GPL-3.0-or-later
// The acceleration of the narrow phase (stages/narrow_phase.cpp): the same contacts, bit for
// bit, for less work.
//   - Each polygon is placed in the world once per step (WorldPolygons), with its own
//     projection on each of its edge normals, however many pairs it is in.
//   - A pair the SAT found apart last step tries that separating axis first
//     (collidePlacedPolygons, fast/sat_fast.cpp): one axis settles a pair still apart.
//   - Kept faces: a touching pair that has moved too little since the SAT chose its faces to
//     change that choice (FaceChoice's bounds) is clipped from the same faces without the SAT.

#include "narrow_phase.h"

#include "contact_rewrite.h"

#include <algorithm>
#include <cmath>

namespace rigidlab::physics {

namespace {

/// The farthest vertex of `p` from its origin [m].
double radius(const Polygon& p)
{
    double r = 0.0;
    for (const Vec2& v : p.vertices)
        r = std::max(r, v.norm());
    return r;
}

/// Where two polygons are now, each in the other's frame, to compare with a TouchingPair.
struct RelativePlacement {
    Vec2 bInA, aInB;
    double turn;
    RelativePlacement(const Body& a, const Transform& xfA, const Body& b, const Transform& xfB)
        : bInA(xfA.q.applyInverse(xfB.p - xfA.p)), aInB(xfB.q.applyInverse(xfA.p - xfB.p)),
          turn(b.angle - a.angle)
    {
    }
};

/// Whether the SAT would choose the same faces for `kept` now, and find the pair no farther
/// apart than margin (FaceChoice). A vertex of B moves in A's frame by at most B's shift in
/// it plus the turn times its distance from B's origin, and the other way round; the slack
/// covers the round-off of the overlaps the SAT compared, which grows with the coordinates.
/// (|x| + |y| bounds the length of a vector from above, without a square root.)
bool facesStand(const TouchingPair& kept, const RelativePlacement& now, const Transform& xfA,
                const Transform& xfB, const Body& a, const Body& b, double margin)
{
    const FaceChoice& choice = kept.choice;
    const double turn = std::abs(now.turn - kept.turn) + 1e-12 +
                        1e-14 * (std::abs(a.angle) + std::abs(b.angle)); // [rad], with slack
    if (!(turn < choice.turnRoom))
        return false;
    const double slack =
        1e-12 + 1e-13 * (xfA.p.lpNorm<Eigen::Infinity>() + xfB.p.lpNorm<Eigen::Infinity>() +
                         kept.radiusA + kept.radiusB);
    const double shift = (now.bInA - kept.bInA).lpNorm<1>(); // [m]
    const double moved = std::max(shift + turn * kept.radiusB,
                                  (now.aInB - kept.aInB).lpNorm<1>() + turn * kept.radiusA) +
                         slack;
    const double ownerChange =
        choice.tilt * shift + turn * (kept.radiusA + kept.radiusB + now.bInA.lpNorm<1>()) + slack;
    return moved < choice.edgeRoom && ownerChange < choice.ownerRoom &&
           choice.least - moved >= -margin;
}

/// Clips a pair from the faces the SAT chose before (kept.choice.faces). Returns whether a
/// point was kept.
bool clipKeptFaces(const TouchingPair& kept, const Polygon& pa, const Transform& xfA,
                   const Polygon& pb, const Transform& xfB, double margin, Manifold& manifold)
{
    const Faces& faces = kept.choice.faces;
    const bool ownerA = faces.owner == 0;
    const Transform& xfRef = ownerA ? xfA : xfB;
    const Transform& xfInc = ownerA ? xfB : xfA;
    return clipFaces(facePoints(ownerA ? pa : pb, xfRef, ownerA ? pb : pa, xfInc, faces), xfRef,
                     xfInc, faces, margin, false, manifold);
}

/// The SAT on the polygons placed for this step, without recording, trying last step's
/// separating axis first (`apart`); a pair found apart is remembered with its axis, a
/// touching pair with the faces it chose.
void satOnPlaced(int ia, const Polygon& pa, const Transform& xfA, int ib, const Polygon& pb,
                 const Transform& xfB, double margin, const RelativePlacement& now,
                 const SeparatedPair* apart, NarrowPhaseCache& cache, Manifold& manifold)
{
    WorldPolygons& placed = cache.placed;
    placed.place(ia, pa, xfA);
    placed.place(ib, pb, xfB);
    const WorldPolygon wa = placed.view(ia), wb = placed.view(ib);
    int axis = apart ? apart->axis : -1;
    FaceChoice choice;
    collidePlacedPolygons(wa, xfA, wb, xfB, margin, axis, manifold, &choice);
    if (axis >= 0)
        cache.separated.push_back({ia, ib, axis});
    else if (choice.kept && choice.edgeRoom > 0.0 && choice.ownerRoom > 0.0 &&
             choice.turnRoom > 0.0)
        cache.touching.push_back({.a = ia,
                                  .b = ib,
                                  .choice = choice,
                                  .bInA = now.bInA,
                                  .aInB = now.aInB,
                                  .turn = now.turn,
                                  .radiusA = radius(pa),
                                  .radiusB = radius(pb)});
}

/// A recycled manifold's point carried to where the bodies are now (recycledPoints,
/// narrow_phase.cpp): its place [m] and separation [m].
struct CarriedPoint {
    double x = 0, y = 0, separation = 0;
};

/// How a pair moved since its anchors were kept (mayRecycle's AnchorMotion, as numbers).
struct Motion {
    double cA, sA, cB, sB; ///< each body's turn since then, cosine and sine
    double sx, sy;         ///< the shift of B's centre of mass less A's [m]
};

/// Point p of `last`'s manifold carried by `m` (recycledPoints' arithmetic in its order).
[[gnu::always_inline]] inline CarriedPoint carryPoint(const Manifold& last, const ContactAnchors& k,
                                                      const Motion& m, const Body& a, const Body& b,
                                                      size_t p)
{
    const double nx = last.normal.x(), ny = last.normal.y();
    const double ax = k.anchorA[p].x(), ay = k.anchorA[p].y();
    const double bx = k.anchorB[p].x(), by = k.anchorB[p].y();
    const double rAx = m.cA * ax - m.sA * ay, rAy = m.sA * ax + m.cA * ay;
    const double rBx = m.cB * bx - m.sB * by, rBy = m.sB * bx + m.cB * by;
    const double dx = (m.sx + (rBx - bx)) - (rAx - ax);
    const double dy = (m.sy + (rBy - by)) - (rAy - ay);
    return {.x = 0.5 * ((a.position.x() + rAx) + (b.position.x() + rBx)),
            .y = 0.5 * ((a.position.y() + rAy) + (b.position.y() + rBy)),
            .separation = k.separation[p] + (nx * dx + ny * dy)};
}

/// The soft step's recycled manifold (narrow_phase.cpp), as the plain path makes it, from
/// `last` (last step's contact of the pair a, b, just found in `contacts`) and its anchors,
/// kept in `contacts` with its anchors; false when the pair is not to be recycled. Its faces
/// are not kept: when it moves on, the pair gets the whole SAT.
///
/// recycleManifold's test and points (mayRecycle, then recycledPoints) with the same
/// arithmetic in the same order, so the same numbers, bit for bit, written out coordinate by
/// coordinate with no array between the test and the contact: the plain form passes the motion
/// and the points through memory, and GCC builds its two-number vectors from halves stored one
/// by one and loads them whole, a load that waits for the stores (a tenth of the base-100
/// pyramid's step went there once, and a fifth of this function's samples on base 40 later).
///
/// The recycled contact is then made what recycleManifold and finishContact make of a new one:
/// the mixed material, no bounce, and the impulses carryImpulses would give. Those are its own:
/// a point takes the impulses of last step's point with its id, which is itself, or the later
/// of two with one id; a point the manifold lacks has none.
bool recycleFound(const Contact& last, const Body& a, const Transform& xfA, const Body& b,
                  const Transform& xfB, double recycle, double margin, ContactRewrite& contacts)
{
    const ContactAnchors& k = contacts.anchorsOfFound();
    const int count = last.manifold.pointCount;
    if (!k.valid || count == 0)
        return false;
    // Each body's turn since the anchors were kept (turnSince), and the centres' shift.
    const Motion m{.cA = xfA.q.c * k.qA.c + xfA.q.s * k.qA.s,
                   .sA = xfA.q.s * k.qA.c - xfA.q.c * k.qA.s,
                   .cB = xfB.q.c * k.qB.c + xfB.q.s * k.qB.s,
                   .sB = xfB.q.s * k.qB.c - xfB.q.c * k.qB.s,
                   .sx = (b.position.x() - a.position.x()) - k.centres.x(),
                   .sy = (b.position.y() - a.position.y()) - k.centres.y()};
    const double turns = std::abs(m.sA) + (1.0 - m.cA) + std::abs(m.sB) + (1.0 - m.cB);
    if (!(std::abs(m.sx) + std::abs(m.sy) + (k.extentA + k.extentB) * turns < recycle))
        return false;
    const CarriedPoint p0 = carryPoint(last.manifold, k, m, a, b, 0);
    if (p0.separation > margin)
        return false; // let the full test say whether the point is still there
    CarriedPoint p1;
    if (count == 2) {
        p1 = carryPoint(last.manifold, k, m, a, b, 1);
        if (p1.separation > margin)
            return false;
    }
    Contact& c = contacts.keepFound();
    std::array<ContactPoint, 2>& points = c.manifold.points;
    points[0].point = Vec2(p0.x, p0.y);
    points[0].separation = p0.separation;
    if (count == 2) {
        points[1].point = Vec2(p1.x, p1.y);
        points[1].separation = p1.separation;
    }
    mixMaterials(a, b, c);
    c.bounceImpulse = {0.0, 0.0};
    if (count == 2 && points[0].id == points[1].id) {
        c.normalImpulse[0] = c.normalImpulse[1];
        c.tangentImpulse[0] = c.tangentImpulse[1];
    }
    for (auto i = static_cast<size_t>(count); i < 2; ++i)
        c.normalImpulse[i] = c.tangentImpulse[i] = 0.0;
    return true;
}

} // namespace

void narrowPhaseFast(const std::vector<Body>& bodies, const std::vector<Transform>& xf,
                     const std::vector<std::pair<int, int>>& pairs, double margin,
                     const std::vector<double>& sweep, double recycle, NarrowPhaseCache& cache,
                     ContactRewrite& contacts, bool& bounceKept)
{
    std::swap(cache.separated, cache.previousSeparated);
    cache.separated.clear();
    PreviousPairs<SeparatedPair> apartBefore(cache.previousSeparated);
    std::swap(cache.touching, cache.previousTouching);
    cache.touching.clear();
    PreviousPairs<TouchingPair> touchingBefore(cache.previousTouching);
    cache.reused = 0;
    cache.placed.reset(bodies.size());
    // The arrays through local pointers: a store into a contact may alias a vector's own
    // pointers as far as the compiler knows, and it loaded them again for every pair.
    const Body* const body = bodies.data();
    const Transform* const place = xf.data();
    const double* const swept = sweep.empty() ? nullptr : sweep.data(); // sweptMargin's
    for (const auto& [ia, ib] : pairs) {
        const Body& a = body[static_cast<size_t>(ia)];
        const Body& b = body[static_cast<size_t>(ib)];
        // Last step's contact of the pair: valid until `contacts` is written.
        const Contact* last = contacts.find(ia, ib);
        if (last && rests(a) && rests(b)) {
            const Contact& kept = contacts.keepFound();
            bounceKept = bounceKept || kept.bounceImpulse[0] > 0 || kept.bounceImpulse[1] > 0;
            continue;
        }
        const double pairMargin =
            swept ? margin + swept[static_cast<size_t>(ia)] + swept[static_cast<size_t>(ib)]
                  : margin;
        const Transform& xfA = place[static_cast<size_t>(ia)];
        const Transform& xfB = place[static_cast<size_t>(ib)];
        const Polygon* pa = a.shape.asPolygon();
        const Polygon* pb = b.shape.asPolygon();
        if (last && pa && pb && recycle > 0.0 && pairMargin == margin &&
            recycleFound(*last, a, xfA, b, xfB, recycle, margin, contacts))
            continue;
        Contact c;
        ContactAnchors k;
        c.a = ia;
        c.b = ib;
        if (pa && pb) {
            const TouchingPair* kept = cache.reuseFaces ? touchingBefore.find(ia, ib) : nullptr;
            // Two polygons. A pair that barely moved since the SAT chose its faces is clipped
            // from the same faces, placing only their points (FaceChoice).
            const RelativePlacement now(a, xfA, b, xfB);
            bool clipped = false;
            if (kept && facesStand(*kept, now, xfA, xfB, a, b, pairMargin)) {
                clipped = clipKeptFaces(*kept, *pa, xfA, *pb, xfB, pairMargin, c.manifold);
                if (clipped) {
                    cache.touching.push_back(*kept);
                    ++cache.reused;
                } else {
                    c.manifold = Manifold{};
                }
            }
            if (!clipped)
                satOnPlaced(ia, *pa, xfA, ib, *pb, xfB, pairMargin, now, apartBefore.find(ia, ib),
                            cache, c.manifold);
            if (recycle > 0.0 && c.manifold.pointCount > 0)
                keepAnchors(a, *pa, xfA, b, *pb, xfB, c.manifold, k);
        } else {
            c.manifold = collideShapes(a.shape, xfA, b.shape, xfB, pairMargin);
        }
        if (c.manifold.pointCount == 0)
            continue; // farther apart than the margin: last step's contact, if any, is dropped
        mixMaterials(a, b, c);
        if (last)
            carryImpulses(*last, c);
        contacts.put(c, k);
    }
    contacts.finish();
}

} // namespace rigidlab::physics
