// SPDX-License-Identifier: GPL-3.0-or-later
// Stage::NarrowPhase (profile.h): from the broad phase's pairs to contacts. The geometry is
// manifold.cpp's (and, for two polygons, sat.cpp's); this file adds what a contact carries
// from step to step and from its bodies: the warm-start impulses and the mixed material.

#include "narrow_phase.h"

#include <algorithm>
#include <cmath>

namespace rigidlab::physics {

namespace {

/// Last step's records of pairs (contacts, separated pairs), looked up pair by pair in
/// increasing order: both lists are sorted, so one cursor walks through them once.
template <typename Record> class PreviousPairs {
public:
    explicit PreviousPairs(const std::vector<Record>& records) : m_records(records) {}
    /// Last step's record of the pair (a, b), or null. Calls come in increasing (a, b).
    const Record* find(int a, int b)
    {
        while (m_next < m_records.size() &&
               std::pair(m_records[m_next].a, m_records[m_next].b) < std::pair(a, b))
            ++m_next;
        if (m_next < m_records.size() && m_records[m_next].a == a && m_records[m_next].b == b)
            return &m_records[m_next];
        return nullptr;
    }

private:
    const std::vector<Record>& m_records;
    size_t m_next = 0;
};

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

/// Static, or dynamic and asleep: it does not move this step.
bool rests(const Body& body)
{
    return body.type == BodyType::Static || (body.isDynamic() && !body.awake);
}

} // namespace

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

namespace {

/// A contact with its manifold made: its mixed material and last step's impulses.
void finishContact(const Body& a, const Body& b, PreviousPairs<Contact>& before, Contact& c)
{
    mixMaterials(a, b, c);
    if (const Contact* p = before.find(c.a, c.b))
        carryImpulses(*p, c);
}

} // namespace

void narrowPhase(const std::vector<Body>& bodies, const std::vector<Transform>& xf,
                 const std::vector<std::pair<int, int>>& pairs, double margin,
                 const std::vector<double>& sweep, const std::vector<Contact>& previous,
                 NarrowPhaseCache& cache, std::vector<Contact>& contacts)
{
    const auto swept = [&sweep](int body) {
        return sweep.empty() ? 0.0 : sweep[static_cast<size_t>(body)];
    };
    PreviousPairs<Contact> before(previous);
    std::swap(cache.separated, cache.previousSeparated);
    cache.separated.clear();
    PreviousPairs<SeparatedPair> apartBefore(cache.previousSeparated);
    std::swap(cache.touching, cache.previousTouching);
    cache.touching.clear();
    PreviousPairs<TouchingPair> touchingBefore(cache.previousTouching);
    cache.reused = 0;
    WorldPolygons& placed = cache.placed;
    placed.reset(bodies.size());
    for (const auto& [ia, ib] : pairs) {
        const Body& a = bodies[static_cast<size_t>(ia)];
        const Body& b = bodies[static_cast<size_t>(ib)];
        if (rests(a) && rests(b)) {
            if (const Contact* kept = before.find(ia, ib)) {
                contacts.push_back(*kept);
                continue;
            }
        }
        // Built in place; taken back when the shapes are too far apart.
        Contact& c = contacts.emplace_back();
        c.a = ia;
        c.b = ib;
        const double pairMargin = margin + swept(ia) + swept(ib);
        const Transform& xfA = xf[static_cast<size_t>(ia)];
        const Transform& xfB = xf[static_cast<size_t>(ib)];
        const Polygon* pa = a.shape.asPolygon();
        const Polygon* pb = b.shape.asPolygon();
        if (pa && pb) {
            // Two polygons. A pair that barely moved since the SAT chose its faces is clipped
            // from the same faces, placing only their points (FaceChoice).
            const RelativePlacement now(a, xfA, b, xfB);
            const TouchingPair* kept = cache.reuseFaces ? touchingBefore.find(ia, ib) : nullptr;
            if (kept && facesStand(*kept, now, xfA, xfB, a, b, pairMargin)) {
                const Faces& faces = kept->choice.faces;
                const bool ownerA = faces.owner == 0;
                const Transform& xfRef = ownerA ? xfA : xfB;
                const Transform& xfInc = ownerA ? xfB : xfA;
                if (clipFaces(
                        facePoints(ownerA ? *pa : *pb, xfRef, ownerA ? *pb : *pa, xfInc, faces),
                        xfRef, xfInc, faces, pairMargin, false, c.manifold)) {
                    cache.touching.push_back(*kept);
                    ++cache.reused;
                    finishContact(a, b, before, c);
                    continue;
                }
                c.manifold = Manifold{};
            }
            // Else the SAT on the polygons placed for this step, without recording, trying
            // last step's separating axis first; a touching pair keeps the faces it chose.
            placed.place(ia, *pa, xfA);
            placed.place(ib, *pb, xfB);
            const WorldPolygon wa = placed.view(ia), wb = placed.view(ib);
            const SeparatedPair* apart = apartBefore.find(ia, ib);
            int axis = apart ? apart->axis : -1;
            FaceChoice choice;
            collidePlacedPolygons(wa, xfA, wb, xfB, pairMargin, axis, c.manifold, &choice);
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
                                          .radiusA = radius(*pa),
                                          .radiusB = radius(*pb)});
        } else {
            c.manifold = collideShapes(a.shape, xfA, b.shape, xfB, pairMargin);
        }
        if (c.manifold.pointCount == 0) {
            contacts.pop_back();
            continue;
        }
        finishContact(a, b, before, c);
    }
}

} // namespace rigidlab::physics
