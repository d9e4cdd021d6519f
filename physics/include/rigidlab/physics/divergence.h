// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Divergence: the world stops rather than draw garbage. After every step it checks that every
// body's state is finite and that the total energy has not grown past a bound; the first
// failure is kept as a diagnosis (which body, which quantity, when, with which dt and
// integrator) and the world takes no more steps until it is reset. A step whose bodies crowd
// past the work budget (work_budget.h) stops the world the same way, before it moves anything:
// it stops rather than freeze the machine.
//
// The diagnosis is data only, no words: the window words it in the user's language
// (ui/divergence_text.h) and the command line in English (lessons/divergence_message.h).

#include "rigidlab/physics/forces.h"
#include "rigidlab/physics/integrator.h"

#include <string>

namespace rigidlab::physics {

/// When the world counts as diverged.
struct DivergenceSettings {
    bool enabled = true;
    /// The total energy may grow by this many times its scale at the start, where the scale
    /// is the larger of the kinetic plus absolute potential energies at the first step and
    /// energyFloorPerKg times the moving mass (so that a world starting at rest has one).
    double energyGrowth = 1e6;
    double energyFloorPerKg = 1.0; ///< [J/kg]
};

struct Divergence {
    enum class Kind {
        NonFinite,    ///< a body's position, angle or velocity is NaN or infinite
        EnergyGrowth, ///< the total energy grew past the bound
        /// More pairs of bodies overlap or nearly touch than the step's budget (work_budget.h)
        Crowded,
    };
    /// What stopped being a simulation.
    enum class Quantity {
        Position,        ///< a body's position [m]
        Angle,           ///< a body's angle [rad]
        Velocity,        ///< a body's velocity [m/s]
        AngularVelocity, ///< a body's angular velocity [rad/s]
        TotalEnergy,     ///< the world's total energy [J]
        BodyPairs,       ///< pairs of bodies whose boxes overlap [1]
    };
    Kind kind = Kind::NonFinite;
    /// The body (for crowding, one of the pair that crossed the budget), or kWorld when the
    /// energy of the world as a whole.
    BodyId body = kWorld;
    std::string bodyName; ///< its scene id (data from the scene, not words)
    Quantity quantity = Quantity::Position;
    /// For energy: the total energy at the step that diverged [J]; for crowding: the pairs
    /// found (at least) [1].
    double value = 0;
    /// For energy: the largest energy allowed [J]; for crowding: the budget of pairs [1].
    double bound = 0;
    double start = 0;   ///< for energy: the total energy at the first step [J]
    double time = 0;    ///< at the end of the step that diverged (crowding: its start) [s]
    long long step = 0; ///< that step's number
    double dt = 0;      ///< [s]
    IntegratorKind integrator = IntegratorKind::SymplecticEuler;
};

} // namespace rigidlab::physics
