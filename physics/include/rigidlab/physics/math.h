// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Small 2D vector helpers on top of Eigen. Angles in radians, counter-clockwise, y up.

#include <Eigen/Core>

#include <cmath>

namespace rigidlab::physics {

using Vec2 = Eigen::Vector2d;

/// 2D cross product of two vectors: the z component of (a, 0) x (b, 0).
inline double cross(const Vec2& a, const Vec2& b)
{
    return a.x() * b.y() - a.y() * b.x();
}
/// Cross of a scalar (z axis) with a vector: w x r = w * perp(r).
inline Vec2 cross(double w, const Vec2& r)
{
    return {-w * r.y(), w * r.x()};
}
/// Cross of a vector with a scalar (z axis).
inline Vec2 cross(const Vec2& r, double w)
{
    return {w * r.y(), -w * r.x()};
}
/// The vector turned by +90 degrees.
inline Vec2 perp(const Vec2& r)
{
    return {-r.y(), r.x()};
}

/// A rotation stored as cosine and sine, so that it is computed once per pose.
struct Rotation {
    double c = 1.0;
    double s = 0.0;
    Rotation() = default;
    explicit Rotation(double angle) : c(std::cos(angle)), s(std::sin(angle)) {}
    Vec2 apply(const Vec2& v) const { return {c * v.x() - s * v.y(), s * v.x() + c * v.y()}; }
    Vec2 applyInverse(const Vec2& v) const
    {
        return {c * v.x() + s * v.y(), -s * v.x() + c * v.y()};
    }
};

/// A rigid placement: world = rotation * local + translation.
struct Transform {
    Vec2 p = Vec2::Zero(); ///< translation [m]
    Rotation q;            ///< rotation
    Transform() = default;
    Transform(const Vec2& position, double angle) : p(position), q(angle) {}
    Vec2 apply(const Vec2& local) const { return q.apply(local) + p; }
    Vec2 applyInverse(const Vec2& world) const { return q.applyInverse(world - p); }
};

inline bool isFinite(const Vec2& v)
{
    return std::isfinite(v.x()) && std::isfinite(v.y());
}

} // namespace rigidlab::physics
