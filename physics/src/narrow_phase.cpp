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
            // Two polygons: the SAT on their placements of this step, without recording,
            // trying last step's separating axis first.
            placed.place(ia, *pa, xfA);
            placed.place(ib, *pb, xfB);
            const SeparatedPair* apart = apartBefore.find(ia, ib);
            int axis = apart ? apart->axis : -1;
            collidePlacedPolygons(placed.view(ia), xfA, placed.view(ib), xfB, pairMargin, axis,
                                  c.manifold);
            if (axis >= 0)
                cache.separated.push_back({ia, ib, axis});
        } else {
            c.manifold = collideShapes(a.shape, xfA, b.shape, xfB, pairMargin);
        }
        if (c.manifold.pointCount == 0) {
            contacts.pop_back();
            continue;
        }
        mixMaterials(a, b, c);
        if (const Contact* p = before.find(ia, ib))
            carryImpulses(*p, c);
    }
}

} // namespace rigidlab::physics
