// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The magnitudes the engine is built for: numbers only. The world's setters assert them
// (a value outside is a programming error of the caller), and lessons/limits.h refuses a file
// or a typed value outside them, with a message of its own.
//
// Every bound keeps the products the engine forms (m v², k x², G m m / r²) well inside a
// double: a finite number can still overflow, as a 1e300 kg mass at 1e5 m/s has an infinite
// kinetic energy, or a 1e200 m position squared is infinite.

namespace rigidlab::physics::limits {

/// A closed interval of allowed values.
struct Interval {
    double min = 0.0;
    double max = 0.0;
    /// False for NaN.
    constexpr bool contains(double v) const { return v >= min && v <= max; }
};

inline constexpr Interval kCoordinate{-1e7, 1e7};      ///< a position coordinate [m]
inline constexpr Interval kSize{1e-6, 1e5};            ///< radius, width, height [m]
inline constexpr Interval kVertex{-1e5, 1e5};          ///< body-local vertex coordinate [m]
inline constexpr Interval kAngle{-1e6, 1e6};           ///< [rad]
inline constexpr Interval kVelocity{-1e6, 1e6};        ///< a velocity component [m/s]
inline constexpr Interval kAngularVelocity{-1e6, 1e6}; ///< [rad/s]
inline constexpr Interval kMass{1e-9, 1e12};           ///< [kg]
inline constexpr Interval kDensity{1e-9, 1e9};         ///< [kg/m²]
inline constexpr Interval kGravity{-1e4, 1e4};         ///< a gravity component [m/s²]
inline constexpr Interval kGravitation{0.0, 1e6};      ///< Newton's constant [m³/(kg s²)]
inline constexpr Interval kDrag{0.0, 1e4};             ///< linear drag rate [1/s]
inline constexpr Interval kFriction{0.0, 100.0};       ///< Coulomb coefficient [1]
inline constexpr Interval kRestitution{0.0, 1.0};      ///< coefficient of restitution [1]
inline constexpr Interval kDt{1e-7, 1.0};              ///< the fixed time step [s]
inline constexpr Interval kIterations{1.0, 1000.0};    ///< solver velocity iterations (whole)
inline constexpr Interval kStiffness{0.0, 1e10};       ///< spring stiffness [N/m]
inline constexpr Interval kDamping{0.0, 1e8};          ///< spring damping [N s/m]
inline constexpr Interval kRestLength{0.0, 1e7};       ///< a spring's rest length [m]
inline constexpr Interval kTolerance{1e-15, 1.0};      ///< dopri5's error tolerance [1]

} // namespace rigidlab::physics::limits
