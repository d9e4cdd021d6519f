// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the force and torque accumulators of one body hold, force by force: its weight, the
// drag, each spring, and what the user added (the grab), each with the point it acts at and
// its torque about the centre of mass, and their sums. Read from the world's state as it is
// now, through the engine's own force laws (forces.cpp), so that the sums are the force and
// torque the next step starts from. Pin joints' constraint forces and contacts are not
// applied forces and are not listed; mutual gravitation is listed as one sum.

#include "rigidlab/physics/world.h"

#include <vector>

namespace rigidlab::physics {

enum class ForceKind {
    Weight,      ///< m g, at the centre of mass
    Drag,        ///< −k m v and −k I ω, at the centre of mass
    Spring,      ///< spring `index` of World::springs(), at its anchor on the body
    Applied,     ///< the user's force and torque for the next step (World::applyForce)
    Gravitation, ///< the other bodies' pull together, at the centre of mass
};

struct ForceTerm {
    ForceKind kind = ForceKind::Weight;
    int index = -1;            ///< the spring's index, for ForceKind::Spring
    Vec2 force = Vec2::Zero(); ///< [N]
    Vec2 point = Vec2::Zero(); ///< where it acts, in the world [m]
    double torque = 0.0;       ///< about the body's centre of mass [N m]
};

struct ForceBreakdown {
    std::vector<ForceTerm> terms; ///< the non-zero ones, in the order of ForceKind
    Vec2 force = Vec2::Zero();    ///< their sum: the force accumulator [N]
    double torque = 0.0;          ///< their sum: the torque accumulator [N m]
};

/// The forces on body `id` now; empty for a body that forces do not move (static, kinematic).
ForceBreakdown forceBreakdown(const World& world, BodyId id);

} // namespace rigidlab::physics
