#pragma once
// The magnitudes a scene or a lesson may hold, and the window's fields accept.
//
// JSON numbers are finite already (1e999 is refused where it stands), but a finite number can
// still overflow the physics: a 1e300 kg mass has an infinite kinetic energy at 1e5 m/s, and a
// 1e200 m position squared is infinite. Such a value is refused when the file is read, with
// its place and the allowed range, rather than discovered later as NaN. The bounds are far
// beyond any lesson (a bullet at 300 m/s, a 1 mm body, a stiff spring of 1e7 N/m) and keep
// every product the engine forms (m v², k x², G m m / r²) well inside a double.
// See lessons/SCENE_FORMAT.md, "Limits".

#include <string_view>

namespace rigidlab::lessons::limits {

/// A closed interval of allowed values and the unit messages name.
struct Range {
    double min = 0.0;
    double max = 0.0;
    std::string_view unit; ///< "m", "kg", ... or empty
    constexpr bool contains(double v) const { return v >= min && v <= max; }
};

/// Positions, anchors and the world's points, each coordinate [m].
inline constexpr Range kCoordinate{-1e7, 1e7, "m"};
/// Sizes of shapes: radius, width, height [m].
inline constexpr Range kSize{1e-6, 1e5, "m"};
/// Polygon vertices, each coordinate, body-local [m].
inline constexpr Range kVertex{-1e5, 1e5, "m"};
/// An angle [rad].
inline constexpr Range kAngle{-1e6, 1e6, "rad"};
/// A velocity component [m/s].
inline constexpr Range kVelocity{-1e6, 1e6, "m/s"};
/// An angular velocity [rad/s].
inline constexpr Range kAngularVelocity{-1e6, 1e6, "rad/s"};
/// A body's mass, given or worked out from its density [kg].
inline constexpr Range kMass{1e-9, 1e12, "kg"};
/// Mass per area [kg/m²].
inline constexpr Range kDensity{1e-9, 1e9, "kg/m^2"};
/// A gravity component [m/s²].
inline constexpr Range kGravity{-1e4, 1e4, "m/s^2"};
/// Newton's constant between bodies [m³/(kg s²)].
inline constexpr Range kGravitation{0.0, 1e6, "m^3/(kg s^2)"};
/// Linear drag rate [1/s].
inline constexpr Range kDrag{0.0, 1e4, "1/s"};
/// Coulomb friction coefficient.
inline constexpr Range kFriction{0.0, 100.0, ""};
/// Coefficient of restitution: 0 sticks, 1 is elastic.
inline constexpr Range kRestitution{0.0, 1.0, ""};
/// The fixed time step [s] (the window shows it in ms).
inline constexpr Range kDt{1e-7, 1.0, "s"};
/// Velocity iterations of the sequential-impulse solver (whole numbers).
inline constexpr Range kIterations{1.0, 1000.0, ""};
/// Spring stiffness [N/m].
inline constexpr Range kStiffness{0.0, 1e10, "N/m"};
/// Spring damping [N s/m].
inline constexpr Range kDamping{0.0, 1e8, "N s/m"};
/// A spring's rest length [m].
inline constexpr Range kRestLength{0.0, 1e7, "m"};
/// dopri5's error tolerance per substep.
inline constexpr Range kTolerance{1e-15, 1.0, ""};
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
