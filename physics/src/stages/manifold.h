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

/// Places `p` by `xf`: its vertices and edge normals in the world (sat.cpp; ownMin and ownMax
/// are left for the fast path's placement, fast/sat_fast.cpp).
void toWorld(const Polygon& p, const Transform& xf, PlacedPolygon& out);

/// The reference face changes from A to B only when B's axis is better by this much [m],
/// so that two nearly parallel faces do not swap roles from one step to the next.
inline constexpr double kReferenceHysteresis = 0.0005;

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

/// The faces a polygon manifold is clipped from: the reference polygon (0: A, 1: B), its
/// reference edge, and the other polygon's incident edge.
struct Faces {
    int owner = 0, refEdge = 0, incEdge = 0;
};

/// The faces the SAT chose for a pair that it found closer than margin, and how far that
/// choice was from changing (narrow_phase.cpp tells from them whether a pair that has moved
/// would get the same faces):
/// - each polygon's edge of least one-sided overlap stays the same while every vertex of the
///   other polygon has moved less than edgeRoom in its frame;
/// - the reference polygon stays the same while the difference of the two least one-sided
///   overlaps changes by less than ownerRoom. A shift t of B in A's frame changes it by at
///   most tilt |t| (tilt: the length of the sum of the two edges' unit normals, 0 for
///   opposite faces), a turn by at most the turn times both radii and the distance;
/// - the incident edge stays the same while the pair has turned less than turnRoom;
/// - the pair stays no farther apart than margin while least stays above -margin.
struct FaceChoice {
    Faces faces;
    double least = 0;     ///< the least overlap over all axes [m] (negative: a gap)
    double edgeRoom = 0;  ///< [m]
    double ownerRoom = 0; ///< [m]
    double tilt = 0;      ///< [1]
    double turnRoom = 0;  ///< [rad]
    bool kept = false;    ///< clipping kept a point (clipPolygonManifold)
};

/// The SAT's verdict and manifold for two placed polygons, without recording the axes (the
/// engine's path; sat.cpp), written into `manifold`, which must be a default Manifold.
/// pointCount stays 0 when farther apart than margin.
/// `separatingAxis`: in, an axis to try first (last step's separating axis of the pair, or
/// -1); out, the axis that showed them farther apart than margin, or -1. The axis tried first
/// saves the rest of the test for a pair still apart, and never changes the result.
/// `choice`, when given: filled for a pair not found apart (separatingAxis -1).
void collidePlacedPolygons(const WorldPolygon& a, const Transform& xfA, const WorldPolygon& b,
                           const Transform& xfB, double margin, int& separatingAxis,
                           Manifold& manifold, FaceChoice* choice = nullptr);

/// The incident edge of `inc` for the reference face `refEdge` of `ref`: the edge whose normal
/// is most nearly opposite. `lead`, when given: by how much that normal's cosine beats the
/// next edge's, less the tie tolerance; a relative turn smaller than half of it cannot change
/// the choice (the cosines change by at most the turn).
int incidentEdge(const WorldPolygon& ref, int refEdge, const WorldPolygon& inc,
                 double* lead = nullptr);

/// The points a polygon manifold is clipped from, placed in the world: the reference face's
/// normal and ends, and the incident edge's ends.
struct FacePoints {
    Vec2 normal, r1, r2, i1, i2;
};

/// The face points of two polygons placed by their transforms, with the arithmetic of the
/// polygons' placement (WorldPolygons), so that clipping them gives the bits that clipping
/// the placed polygons gives: a pair clipped from kept faces places only these.
FacePoints facePoints(const Polygon& ref, const Transform& xfRef, const Polygon& inc,
                      const Transform& xfInc, const Faces& faces);

/// Clips the incident edge to the reference face (clipPolygonManifold without its fallback).
/// Returns true when a point was kept; false leaves `m` to be reset or completed.
bool clipFaces(const FacePoints& f, const Transform& xfRef, const Transform& xfInc,
               const Faces& faces, double margin, bool intersecting, Manifold& m);

/// The manifold of two placed polygons from the given faces: the incident edge clipped to
/// the reference face (the reference polygon `ref` is A for faces.owner 0, B for 1).
/// `intersecting`: the SAT found no separating axis, so a contact is kept even when clipping
/// keeps nothing (the incident polygon's deepest vertex). Returns true when clipping kept a
/// point, so that the manifold does not depend on `intersecting`.
bool clipPolygonManifold(const WorldPolygon& ref, const Transform& xfRef, const WorldPolygon& inc,
                         const Transform& xfInc, const Faces& faces, double margin,
                         bool intersecting, Manifold& m);

} // namespace rigidlab::physics
