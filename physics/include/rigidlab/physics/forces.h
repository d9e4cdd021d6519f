// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Force elements beyond uniform gravity, drag and the accumulators: springs and pin joints.

#include "rigidlab/physics/math.h"

namespace rigidlab::physics {

/// Index of a body in its world. kWorld stands for a fixed point in the world.
using BodyId = int;
inline constexpr BodyId kWorld = -1;

/// A linear spring-damper between two anchors (body-local, or world points for kWorld).
struct SpringDef {
    BodyId a = kWorld;
    Vec2 anchorA = Vec2::Zero(); ///< [m]
    BodyId b = kWorld;
    Vec2 anchorB = Vec2::Zero(); ///< [m]
    double stiffness = 0.0;      ///< [N/m]
    double damping = 0.0;        ///< along the spring [N s/m]
    double restLength = 0.0;     ///< [m]
};

/// A pin: a point of body a held at a point of body b (or at a world point for kWorld).
/// Solved exactly, as a constraint force inside every force evaluation.
struct PinJointDef {
    BodyId a = kWorld;
    Vec2 anchorA = Vec2::Zero(); ///< [m]
    BodyId b = kWorld;
    Vec2 anchorB = Vec2::Zero(); ///< [m]
};

} // namespace rigidlab::physics
