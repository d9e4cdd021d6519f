// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Shapes and the mass properties they give a body.

#include "rigidlab/physics/math.h"
#include "rigidlab/physics/overloaded.h"
#include "rigidlab/physics/result.h"

#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace rigidlab::physics {

/// The most vertices a polygon may have (a convex polygon with more is better as a circle).
inline constexpr int kMaxPolygonVertices = 64;

struct Circle {
    Vec2 center = Vec2::Zero(); ///< centre in body coordinates [m]
    double radius = 0.0;        ///< [m]
};

/// A convex polygon, counter-clockwise, in body coordinates.
struct Polygon {
    std::vector<Vec2> vertices; ///< [m]
    std::vector<Vec2> normals;  ///< outward unit normal of edge i (vertex i to i+1)
};

/// A body's shape: one of a closed set of alternatives. Code that depends on the kind of shape
/// goes through visit() with a visitor for every alternative (see overloaded.h), so a new
/// alternative is a compile error at each place that must learn about it.
struct Shape {
    using Geometry = std::variant<Circle, Polygon>;
    Geometry geometry; ///< a zero circle by default

    /// The circle, or nullptr when the shape is another kind.
    const Circle* asCircle() const { return std::get_if<Circle>(&geometry); }
    /// The polygon, or nullptr when the shape is another kind.
    const Polygon* asPolygon() const { return std::get_if<Polygon>(&geometry); }

    /// Calls the visitor with the alternative the shape holds.
    template <class Visitor> decltype(auto) visit(Visitor&& visitor) const
    {
        return std::visit(std::forward<Visitor>(visitor), geometry);
    }
};

struct MassProperties {
    double mass = 0.0;            ///< [kg]
    Vec2 centroid = Vec2::Zero(); ///< centre of mass in body coordinates [m]
    double inertia = 0.0;         ///< about the centre of mass [kg m^2]
    double area = 0.0;            ///< [m^2]
};

/// A convex polygon made from a vertex list, with what had to change to make it one.
struct PolygonBuild {
    Polygon polygon;
    std::string warning; ///< empty, or why the input was replaced (for example by its convex hull)
};

/// Builds a convex polygon: 3 to kMaxPolygonVertices distinct vertices and a positive area are
/// required; clockwise input is reversed; a non-convex list is replaced by its convex hull (with a
/// warning, as in the paper: detection is then exact only for the hull).
Result<PolygonBuild> makePolygon(const std::vector<Vec2>& vertices);

/// The convex hull, counter-clockwise, collinear points dropped (Andrew's monotone chain).
std::vector<Vec2> convexHull(std::vector<Vec2> points);

/// An axis-aligned box centred on the body origin.
Polygon makeBox(double width, double height);

Shape makeCircleShape(double radius, const Vec2& center = Vec2::Zero());
Shape makePolygonShape(Polygon polygon);

/// Mass, centroid and rotational inertia about the centroid for a uniform density [kg/m^2].
MassProperties computeMass(const Shape& shape, double density);

/// Signed area of a closed vertex loop (positive when counter-clockwise) [m^2].
double signedArea(const std::vector<Vec2>& vertices);

} // namespace rigidlab::physics
