// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Collision detection: the separating axis theorem for convex polygons, and the contact
// manifold (up to two points) built by clipping the incident edge against the reference edge.
// The SAT result keeps every axis it tested, so that a lesson can draw it step by step.

#include "rigidlab/physics/math.h"
#include "rigidlab/physics/shape.h"

#include <array>
#include <cstdint>
#include <vector>

namespace rigidlab::physics {

/// One axis tested by the SAT.
struct SatAxis {
    int owner = 0;             ///< 0: the axis is the normal of an edge of A, 1: of B
    int edge = 0;              ///< that edge's index (vertex edge to edge + 1)
    Vec2 axis = Vec2::Zero();  ///< unit outward edge normal, in the world
    double minA = 0, maxA = 0; ///< projection interval of A on the axis [m]
    double minB = 0, maxB = 0; ///< projection interval of B on the axis [m]
    /// How far B must move along the axis, one way or the other, to separate:
    /// min(maxA - minB, maxB - minA). Negative: a gap, and the axis separates.
    double overlap = 0;
};

/// One contact point.
struct ContactPoint {
    Vec2 point = Vec2::Zero(); ///< world point halfway between the two surfaces [m]
    double separation = 0;     ///< along the normal, negative when penetrating [m]
    /// Identifies the features that made this point (for warm starting across steps).
    std::uint32_t id = 0;
};

/// How the manifold's geometry is defined, so that the position solver can re-evaluate it
/// as bodies move: two circles (centre to centre), or a reference face on A or on B.
enum class ManifoldType { Circles, FaceA, FaceB };

struct Manifold {
    ManifoldType type = ManifoldType::FaceA;
    Vec2 normal = Vec2::Zero(); ///< unit, world, from A to B
    int pointCount = 0;
    std::array<ContactPoint, 2> points{};
    // Local geometry (see ManifoldType), in the reference body's frame.
    Vec2 localNormal = Vec2::Zero(); ///< FaceA/FaceB: reference face normal
    Vec2 localPoint = Vec2::Zero();  ///< Circles: centre of A; Face: a point of the reference face
    /// Incident points in the incident body's frame (Circles: centre of B).
    std::array<Vec2, 2> localIncident{Vec2::Zero(), Vec2::Zero()};
    double radiusA = 0, radiusB = 0; ///< circle radii taken off the separation [m]
};

/// Everything the SAT found for a pair of polygons.
struct SatResult {
    bool intersects = false;
    std::vector<SatAxis> axes; ///< in the order tested: A's edges, then B's (empty if not recorded)
    int axesTested = 0;        ///< how many axes were projected before the verdict
    int separatingAxis = -1;   ///< index into axes of the first separating axis, or -1
    int leastAxis = -1;        ///< when intersecting: index of the axis of least penetration
    Vec2 normal = Vec2::Zero(); ///< when intersecting: from A to B
    double depth = 0;           ///< when intersecting: penetration depth [m]
    Manifold manifold;          ///< when intersecting (or within the margin)
};

/// The SAT on two convex polygons placed by xfA and xfB. It stops at the first axis whose
/// gap exceeds `margin` (0 gives the textbook verdict: touching counts as intersecting).
/// With a margin > 0 the manifold is built for shapes closer than margin, as speculative
/// contacts. With record = false, `axes` stays empty (the engine's fast path).
SatResult satPolygons(const Polygon& a, const Transform& xfA, const Polygon& b,
                      const Transform& xfB, double margin = 0.0, bool record = true);

/// Contacts between two circles, or a polygon and a circle, closer than margin.
/// pointCount == 0 when farther apart.
Manifold collideCircles(const Circle& a, const Transform& xfA, const Circle& b,
                        const Transform& xfB, double margin);
Manifold collidePolygonCircle(const Polygon& a, const Transform& xfA, const Circle& b,
                              const Transform& xfB, double margin);

/// Re-evaluates manifold point k for bodies placed at xfA and xfB (origin frames), as the
/// position solver needs while it moves them: the normal (A to B), the point halfway between
/// the surfaces and the separation.
void evaluateManifoldPoint(const Manifold& m, int k, const Transform& xfA, const Transform& xfB,
                           Vec2& normal, Vec2& point, double& separation);

/// Any pair of shapes; normal from A to B.
Manifold collideShapes(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB,
                       double margin);

} // namespace rigidlab::physics
