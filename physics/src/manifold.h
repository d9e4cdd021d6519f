// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private: what the SAT (sat.cpp) hands to the manifold builder (manifold.cpp): the two
// polygons placed in the world, and the reference face it chose.

#include "rigidlab/physics/sat.h"

#include <array>
#include <vector>

namespace rigidlab::physics {

/// A polygon placed in the world, as the SAT and the manifold builder read it: views into a
/// PlacedPolygon (one pair, the lesson's path) or into the narrow phase's per-body store
/// (WorldPolygons, each body placed once per step however many pairs it is in).
struct WorldPolygon {
    const Vec2* v = nullptr; ///< vertices [m]
    const Vec2* n = nullptr; ///< unit normal of the edge from v[i] to v[i + 1]
    /// The polygon's own projection interval on each of its edge normals n[i] [m]: it depends
    /// on this polygon alone, so it is computed once with the placement, not once per pair.
    const double* ownMin = nullptr;
    const double* ownMax = nullptr;
    int count = 0;
};

/// The storage of one placed polygon.
struct PlacedPolygon {
    std::array<Vec2, kMaxPolygonVertices> v;
    std::array<Vec2, kMaxPolygonVertices> n;
    std::array<double, kMaxPolygonVertices> ownMin, ownMax;
    int count = 0;
    WorldPolygon view() const { return {v.data(), n.data(), ownMin.data(), ownMax.data(), count}; }
};

/// Places `p` by `xf` (sat.cpp).
void toWorld(const Polygon& p, const Transform& xf, PlacedPolygon& out);

/// The polygons of a step's bodies placed in the world, each computed on first use with the
/// same arithmetic as toWorld (so that a pair's SAT gives the same bits either way).
class WorldPolygons {
public:
    /// Forgets the last step's placements; `bodies` is how many bodies there are.
    void reset(size_t bodies);
    /// Places body `body`'s polygon by `xf` unless already placed this step. Views taken
    /// before a call to place() may be invalidated by it.
    void place(int body, const Polygon& p, const Transform& xf)
    {
        if (m_start[static_cast<size_t>(body)] < 0)
            placeNew(body, p, xf);
    }
    /// The placed polygon of `body` (place() called this step).
    WorldPolygon view(int body) const
    {
        const auto b = static_cast<size_t>(body);
        const auto start = static_cast<size_t>(m_start[b]);
        return {m_v.data() + start, m_n.data() + start, m_ownMin.data() + start,
                m_ownMax.data() + start, m_count[b]};
    }

private:
    void placeNew(int body, const Polygon& p, const Transform& xf);

    std::vector<int> m_start; ///< per body: its first vertex in the arrays, or -1
    std::vector<int> m_count; ///< per body: its vertex count
    std::vector<Vec2> m_v, m_n;
    std::vector<double> m_ownMin, m_ownMax;
};

/// The SAT's verdict and manifold for two placed polygons, without recording the axes (the
/// engine's path; sat.cpp), written into `manifold`, which must be a default Manifold.
/// pointCount stays 0 when farther apart than margin.
/// `separatingAxis`: in, an axis to try first (last step's separating axis of the pair, or
/// -1); out, the axis that showed them farther apart than margin, or -1. The axis tried first
/// saves the rest of the test for a pair still apart, and never changes the result.
void collidePlacedPolygons(const WorldPolygon& a, const Transform& xfA, const WorldPolygon& b,
                           const Transform& xfB, double margin, int& separatingAxis,
                           Manifold& manifold);

/// Builds the manifold of two polygons with `ref` as the reference polygon (owner 0 is A,
/// 1 is B) and its edge `refEdge` as the reference face (manifold.cpp). `intersecting`: the
/// SAT found no separating axis, so a contact is kept even when clipping keeps nothing.
void buildPolygonManifold(const WorldPolygon& ref, const Transform& xfRef, const WorldPolygon& inc,
                          const Transform& xfInc, int owner, int refEdge, double margin,
                          bool intersecting, Manifold& m);

} // namespace rigidlab::physics
