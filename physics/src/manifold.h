// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private: what the SAT (sat.cpp) hands to the manifold builder (manifold.cpp): the two
// polygons placed in the world, and the reference face it chose.

#include "rigidlab/physics/sat.h"

#include <array>

namespace rigidlab::physics {

/// A polygon's vertices and outward edge normals, placed in the world.
struct WorldPolygon {
    std::array<Vec2, kMaxPolygonVertices> v; ///< vertices [m]
    std::array<Vec2, kMaxPolygonVertices> n; ///< unit normal of the edge from v[i] to v[i + 1]
    int count = 0;
};

/// Places `p` by `xf` (sat.cpp).
void toWorld(const Polygon& p, const Transform& xf, WorldPolygon& out);

/// Builds the manifold of two polygons with `ref` as the reference polygon (owner 0 is A,
/// 1 is B) and its edge `refEdge` as the reference face (manifold.cpp). `intersecting`: the
/// SAT found no separating axis, so a contact is kept even when clipping keeps nothing.
void buildPolygonManifold(const WorldPolygon& ref, const Transform& xfRef, const WorldPolygon& inc,
                          const Transform& xfInc, int owner, int refEdge, double margin,
                          bool intersecting, Manifold& m);

} // namespace rigidlab::physics
