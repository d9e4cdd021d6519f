// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Shared helpers of the physics tests:
//  - RL_VERIFY_NEAR and the other comparisons of tests/near.h;
//  - builders for the scenes several tests share (a body on a spring, a pendulum, bodies);
//  - small independent geometry and statistics (a gift-wrapping hull, a least-squares slope),
//    so that no test checks the engine against the engine's own code.

#include <rigidlab/physics/body.h>
#include <rigidlab/physics/shape.h>
#include <rigidlab/physics/world.h>

#include "near.h"

#include <QByteArray>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <numbers>
#include <vector>

namespace rigidlab::test {

using physics::Vec2;

// ---------------------------------------------------------------------------------------------
// Body and world builders

/// A world with nothing but what the test asks for: no gravity, no drag, no default bounce.
inline physics::WorldDef quietWorldDef(physics::IntegratorKind integrator, double dt)
{
    physics::WorldDef def;
    def.gravity = Vec2::Zero();
    def.dt = dt;
    def.integrator = integrator;
    def.drag = 0.0;
    def.gravitation = 0.0;
    // The sequential-impulse solver, not the default soft step: these worlds test the
    // integrators and the step's stages on the path they were written for; a test of another
    // solver names it.
    def.solver = physics::SolverKind::SequentialImpulse;
    return def;
}

/// A world for exactness tests of one solver: symplectic Euler at dt, every body's default
/// restitution e and friction, no sleep (quietWorldDef's otherwise: no gravity, no drag).
inline physics::WorldDef exactWorld(physics::SolverKind solver, double dt, double e,
                                    double friction)
{
    physics::WorldDef def = quietWorldDef(physics::IntegratorKind::SymplecticEuler, dt);
    def.solver = solver;
    def.restitution = e;
    def.friction = friction;
    def.sleep = false;
    return def;
}

/// The solver's name in scene files, for the rows' names.
inline const char* solverLabel(physics::SolverKind solver)
{
    return physics::solverName(solver).data(); // the names are string literals
}

inline physics::BodyDef circleBody(double radius, const Vec2& origin,
                                   const Vec2& velocity = Vec2::Zero(), double density = 1.0)
{
    physics::BodyDef def;
    def.shape = physics::makeCircleShape(radius);
    def.position = origin;
    def.velocity = velocity;
    def.density = density;
    return def;
}

inline physics::BodyDef boxBody(double width, double height, const Vec2& origin, double angle = 0.0,
                                double density = 1.0)
{
    physics::BodyDef def;
    def.shape = physics::makePolygonShape(physics::makeBox(width, height));
    def.position = origin;
    def.angle = angle;
    def.density = density;
    return def;
}

/// A body of mass m on a spring of stiffness k to a world anchor, moving along x only.
///
///     anchor (-L0, 0) ~~~~~~~~ spring, rest length L0 ~~~~~~~~ body at (x, 0)
///
/// The spring force along x is -k ((x + L0) - L0) = -k x: a linear oscillator in x about
/// the origin, with omega = sqrt(k / m) and (damping c) m x'' = -k x - c x'. The anchor sits
/// L0 away so that the spring never passes through zero length, where its direction is
/// undefined. The body is a circle centred on its origin, so body position = centre of mass.
struct OscillatorSpec {
    double mass = 1.0;       ///< [kg]
    double stiffness = 4.0;  ///< [N/m]
    double damping = 0.0;    ///< [N s/m]
    double x0 = 0.5;         ///< initial displacement [m]
    double v0 = 0.0;         ///< initial velocity [m/s]
    double restLength = 2.0; ///< [m], larger than any displacement
    double radius = 0.1;     ///< of the circle body [m]
};

inline physics::World makeOscillator(physics::IntegratorKind integrator, double dt,
                                     const OscillatorSpec& spec = {})
{
    physics::World world(quietWorldDef(integrator, dt));
    physics::BodyDef body = circleBody(spec.radius, Vec2(spec.x0, 0.0), Vec2(spec.v0, 0.0));
    body.mass = spec.mass;
    const physics::BodyId id = world.addBody(body);
    physics::SpringDef spring;
    spring.a = id;
    spring.anchorA = Vec2::Zero();
    spring.b = physics::kWorld;
    spring.anchorB = Vec2(-spec.restLength, 0.0);
    spring.stiffness = spec.stiffness;
    spring.damping = spec.damping;
    spring.restLength = spec.restLength;
    world.addSpring(spring);
    return world;
}

/// A pendulum: a circular bob of radius r and mass m whose body-local point (0, L) is pinned
/// to the world point `pivot`. The bob swings as a rigid body (it turns with the rod), so it
/// is a physical pendulum:
///
///         pivot o
///               |\   L (rod)
///               | \  (L from pivot to bob centre)
///               |  (bob)   theta: the angle from straight down = the body's angle
///
/// I_pivot = m r^2 / 2 + m L^2, and theta'' = -(m g L / I_pivot) sin(theta): the point-mass
/// equation for the equivalent length L_eq = I_pivot / (m L) = L + r^2 / (2 L).
struct PendulumSpec {
    double length = 1.0;     ///< pivot to bob centre [m]
    double bobRadius = 0.05; ///< [m]
    double mass = 1.0;       ///< [kg]
    double theta0 = 1.0;     ///< initial angle from straight down [rad]
    double gravity = 9.81;   ///< [m/s^2], acting along -y
    Vec2 pivot = Vec2::Zero();
};

inline double pendulumEquivalentLength(const PendulumSpec& p)
{
    return p.length + p.bobRadius * p.bobRadius / (2.0 * p.length);
}

inline physics::World makePendulum(physics::IntegratorKind integrator, double dt,
                                   const PendulumSpec& spec = {})
{
    physics::WorldDef def = quietWorldDef(integrator, dt);
    def.gravity = Vec2(0.0, -spec.gravity);
    physics::World world(def);
    const double s = std::sin(spec.theta0);
    const double c = std::cos(spec.theta0);
    physics::BodyDef bob =
        circleBody(spec.bobRadius, spec.pivot + Vec2(spec.length * s, -spec.length * c));
    bob.angle = spec.theta0;
    bob.mass = spec.mass;
    const physics::BodyId id = world.addBody(bob);
    physics::PinJointDef pin;
    pin.a = id;
    pin.anchorA = Vec2(0.0, spec.length); // body-local: L "above" the bob centre
    pin.b = physics::kWorld;
    pin.anchorB = spec.pivot;
    world.addPinJoint(pin);
    return world;
}

/// Kinetic energy of every body, from its state (independent of diagnostics()).
inline double kineticEnergy(const physics::World& world)
{
    double e = 0.0;
    for (const physics::Body& b : world.bodies()) {
        e += 0.5 * b.mass * b.velocity.squaredNorm() +
             0.5 * b.inertia * b.angularVelocity * b.angularVelocity;
    }
    return e;
}

/// Linear momentum of every body, from its state.
inline Vec2 momentum(const physics::World& world)
{
    Vec2 p = Vec2::Zero();
    for (const physics::Body& b : world.bodies()) {
        p += b.mass * b.velocity;
    }
    return p;
}

// ---------------------------------------------------------------------------------------------
// Independent geometry

inline double cross2(const Vec2& a, const Vec2& b)
{
    return a.x() * b.y() - a.y() * b.x();
}

/// Convex hull by gift wrapping (Jarvis march), counter-clockwise, collinear points dropped.
/// Written for the tests on purpose: a different algorithm from the engine's convexHull.
/// Returns an empty list if the wrap does not close (it would mean inconsistent rounding).
inline std::vector<Vec2> giftWrapHull(const std::vector<Vec2>& pts)
{
    if (pts.size() < 3) {
        return {};
    }
    // Start at the lowest point (leftmost among the lowest): surely a hull vertex.
    std::size_t start = 0;
    for (std::size_t i = 1; i < pts.size(); ++i) {
        if (pts[i].y() < pts[start].y() ||
            (pts[i].y() == pts[start].y() && pts[i].x() < pts[start].x())) {
            start = i;
        }
    }
    std::vector<Vec2> hull;
    std::size_t current = start;
    for (std::size_t guard = 0; guard <= pts.size(); ++guard) {
        hull.push_back(pts[current]);
        // The next vertex is the point with every other point on its left (or on the line,
        // farther away: that drops collinear points).
        std::size_t next = (current + 1) % pts.size();
        for (std::size_t i = 0; i < pts.size(); ++i) {
            if (i == current) {
                continue;
            }
            const Vec2 a = pts[next] - pts[current];
            const Vec2 b = pts[i] - pts[current];
            const double turn = cross2(a, b);
            if (turn < 0.0 || (turn == 0.0 && b.squaredNorm() > a.squaredNorm())) {
                next = i;
            }
        }
        if ((pts[next] - pts[current]).squaredNorm() == 0.0) {
            return {}; // only duplicates left: degenerate
        }
        current = next;
        if (current == start) {
            return hull.size() >= 3 ? hull : std::vector<Vec2>{};
        }
    }
    return {};
}

/// True when b is a with its starting vertex moved (the same loop, same direction).
inline bool sameLoop(const std::vector<Vec2>& a, const std::vector<Vec2>& b)
{
    if (a.size() != b.size()) {
        return false;
    }
    for (std::size_t k = 0; k < a.size(); ++k) {
        bool same = true;
        for (std::size_t i = 0; i < a.size() && same; ++i) {
            same = a[(i + k) % a.size()] == b[i];
        }
        if (same) {
            return true;
        }
    }
    return a.empty();
}

/// True when the closed loop is a convex polygon as given: every turn strictly the same way
/// and the turns adding up to one full turn (a star turns the same way but twice round).
inline bool isConvexLoop(const std::vector<Vec2>& v)
{
    if (v.size() < 3) {
        return false;
    }
    double total = 0.0;
    int sign = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const Vec2 a = v[(i + 1) % v.size()] - v[i];
        const Vec2 b = v[(i + 2) % v.size()] - v[(i + 1) % v.size()];
        const double c = cross2(a, b);
        const int s = c > 0.0 ? 1 : (c < 0.0 ? -1 : 0);
        if (s == 0 || (sign != 0 && s != sign)) {
            return false;
        }
        sign = s;
        total += std::atan2(c, a.dot(b));
    }
    return std::abs(std::abs(total) - 2.0 * std::numbers::pi) < 1e-6;
}

/// Shortest distance from p to the segment [a, b].
inline double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b)
{
    const Vec2 ab = b - a;
    const double len2 = ab.squaredNorm();
    double t = len2 > 0.0 ? (p - a).dot(ab) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return (a + t * ab - p).norm();
}

/// Shortest distance from p to the boundary of a closed polygon (world vertices).
inline double distanceToBoundary(const Vec2& p, const std::vector<Vec2>& poly)
{
    double d = INFINITY;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        d = std::min(d, distanceToSegment(p, poly[i], poly[(i + 1) % poly.size()]));
    }
    return d;
}

/// Polygon vertices placed in the world.
inline std::vector<Vec2> worldVertices(const physics::Polygon& poly, const physics::Transform& xf)
{
    std::vector<Vec2> out;
    out.reserve(poly.vertices.size());
    for (const Vec2& v : poly.vertices) {
        out.push_back(xf.apply(v));
    }
    return out;
}

// ---------------------------------------------------------------------------------------------
// Statistics

/// Least-squares slope of y against x.
inline double leastSquaresSlope(const std::vector<double>& x, const std::vector<double>& y)
{
    const double n = static_cast<double>(x.size());
    double sx = 0, sy = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        sx += x[i];
        sy += y[i];
    }
    const double mx = sx / n, my = sy / n;
    double sxy = 0, sxx = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        sxy += (x[i] - mx) * (y[i] - my);
        sxx += (x[i] - mx) * (x[i] - mx);
    }
    return sxy / sxx;
}

} // namespace rigidlab::test

Q_DECLARE_METATYPE(rigidlab::physics::Vec2)
Q_DECLARE_METATYPE(rigidlab::physics::IntegratorKind)
Q_DECLARE_METATYPE(rigidlab::physics::SolverKind)
