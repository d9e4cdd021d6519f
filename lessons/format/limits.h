// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The magnitudes a scene or a lesson may hold, and the window's fields accept.
//
// JSON numbers are finite already (1e999 is refused where it stands), but a finite number can
// still overflow the physics: a 1e300 kg mass has an infinite kinetic energy at 1e5 m/s, and a
// 1e200 m position squared is infinite. Such a value is refused when the file is read, with
// its place and the allowed range, rather than discovered later as NaN. The bounds are far
// beyond any lesson (a bullet at 300 m/s, a 1 mm body, a stiff spring of 1e7 N/m) and keep
// every product the engine forms (m v², k x², G m m / r²) well inside a double.
// The engine's ranges are its own (physics/limits.h); this file names their units for messages
// and adds the ranges of the window and of lessons. See lessons/SCENE_FORMAT.md, "Limits".

#include "rigidlab/physics/limits.h"

#include <string_view>

namespace rigidlab::lessons::limits {

/// A closed interval of allowed values and the unit messages name.
struct Range {
    double min = 0.0;
    double max = 0.0;
    std::string_view unit; ///< "m", "kg", ... or empty
    constexpr bool contains(double v) const { return v >= min && v <= max; }
};

/// The engine's range (physics/limits.h, the one owner of the numbers) with the unit to name.
constexpr Range withUnit(physics::limits::Interval interval, std::string_view unit)
{
    return {interval.min, interval.max, unit};
}

/// Positions, anchors and the world's points, each coordinate [m].
inline constexpr Range kCoordinate = withUnit(physics::limits::kCoordinate, "m");
/// Sizes of shapes: radius, width, height [m].
inline constexpr Range kSize = withUnit(physics::limits::kSize, "m");
/// Polygon vertices, each coordinate, body-local [m].
inline constexpr Range kVertex = withUnit(physics::limits::kVertex, "m");
/// An angle [rad].
inline constexpr Range kAngle = withUnit(physics::limits::kAngle, "rad");
/// A velocity component [m/s].
inline constexpr Range kVelocity = withUnit(physics::limits::kVelocity, "m/s");
/// An angular velocity [rad/s].
inline constexpr Range kAngularVelocity = withUnit(physics::limits::kAngularVelocity, "rad/s");
/// A body's mass, given or worked out from its density [kg].
inline constexpr Range kMass = withUnit(physics::limits::kMass, "kg");
/// Mass per area [kg/m²].
inline constexpr Range kDensity = withUnit(physics::limits::kDensity, "kg/m^2");
/// A gravity component [m/s²].
inline constexpr Range kGravity = withUnit(physics::limits::kGravity, "m/s^2");
/// Newton's constant between bodies [m³/(kg s²)].
inline constexpr Range kGravitation = withUnit(physics::limits::kGravitation, "m^3/(kg s^2)");
/// Linear drag rate [1/s].
inline constexpr Range kDrag = withUnit(physics::limits::kDrag, "1/s");
/// Coulomb friction coefficient.
inline constexpr Range kFriction = withUnit(physics::limits::kFriction, "");
/// Coefficient of restitution: 0 sticks, 1 is elastic.
inline constexpr Range kRestitution = withUnit(physics::limits::kRestitution, "");
/// The fixed time step [s] (the window shows it in ms).
inline constexpr Range kDt = withUnit(physics::limits::kDt, "s");
/// Velocity iterations of the sequential-impulse solver (whole numbers).
inline constexpr Range kIterations = withUnit(physics::limits::kIterations, "");
/// Spring stiffness [N/m].
inline constexpr Range kStiffness = withUnit(physics::limits::kStiffness, "N/m");
/// Spring damping [N s/m].
inline constexpr Range kDamping = withUnit(physics::limits::kDamping, "N s/m");
/// A spring's rest length [m].
inline constexpr Range kRestLength = withUnit(physics::limits::kRestLength, "m");
/// dopri5's error tolerance per substep.
inline constexpr Range kTolerance = withUnit(physics::limits::kTolerance, "");
/// The window's time scale (slow motion to fast forward).
inline constexpr Range kTimeScale{0.1, 4.0, "x"};
/// A lesson question's absolute tolerance, in the question's unit.
inline constexpr Range kAbsoluteTolerance{0.0, 1e9, ""};

/// The deepest nesting of arrays and objects a scene or lesson file may have. A lesson's
/// inline scene reaches 8 (steps, a step, scene, bodies, a body, shape, vertices, a vertex).
inline constexpr int kMaxJsonDepth = 32;
/// Bodies over all the steps of one lesson (a step's scene file may be read by many steps).
inline constexpr int kMaxLessonBodies = 20000;

} // namespace rigidlab::lessons::limits
