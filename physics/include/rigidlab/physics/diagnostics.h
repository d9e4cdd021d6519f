// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the world measures after every step.

#include "rigidlab/physics/math.h"

#include <cmath>

namespace rigidlab::physics {

struct Diagnostics {
    double translationalKinetic = 0; ///< sum of m v^2 / 2 [J]
    double rotationalKinetic = 0;    ///< sum of I w^2 / 2 [J]
    double kinetic = 0;              ///< [J]
    double gravityPotential = 0;     ///< -m g.x, zero at the origin [J]
    double springPotential = 0;      ///< k (L - L0)^2 / 2 [J]
    double gravitationPotential = 0; ///< -G m1 m2 / r [J]
    double potential = 0;            ///< [J]
    double total = 0;                ///< kinetic + potential [J]
    Vec2 momentum = Vec2::Zero();    ///< linear momentum [kg m/s]
    double angularMomentum = 0;      ///< about the world origin [kg m^2/s]
    // Energy taken out of the bodies by what is not conservative, so far (world start). What
    // a kinematic body pushes in through a contact counts as a negative loss. So that
    // total + dissipated - (total at the start) is the integrator's error alone.
    double collisionLoss = 0; ///< taken by contacts, friction included (dissipation.cpp) [J]
    double dragLoss = 0;      ///< taken by linear drag [J]
    double dampingLoss = 0;   ///< taken by the dampers of springs [J]
    double dissipated = 0;    ///< collisionLoss + dragLoss + dampingLoss [J]
    int contacts = 0;         ///< contact points this step
};

/// How much energy is in play: the kinetic energy and each potential energy's size [J]. A scale
/// for energy errors that stays large when the total happens to be near zero (a body that falls
/// from rest at the origin). Gravity and gravitation potentials may be negative; a spring's is not.
inline double energyParts(const Diagnostics& d)
{
    return d.kinetic + std::abs(d.gravityPotential) + d.springPotential +
           std::abs(d.gravitationPotential);
}

} // namespace rigidlab::physics
