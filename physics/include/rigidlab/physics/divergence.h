#pragma once
// Divergence: the world stops rather than draw garbage. After every step it checks that every
// body's state is finite and that the total energy has not grown past a bound; the first
// failure is kept as a diagnosis (which body, which quantity, when, with which dt and
// integrator) and the world takes no more steps until it is reset.

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
    };
    Kind kind = Kind::NonFinite;
    BodyId body = kWorld; ///< the body, or kWorld when the energy of the world as a whole
    std::string bodyName; ///< its scene id
    std::string quantity; ///< "position", "angle", "velocity", "angular velocity", "total energy"
    double value = 0;     ///< the quantity's value (for energy [J])
    double bound = 0;     ///< for energy: the largest energy allowed [J]
    double time = 0;      ///< at the end of the step that diverged [s]
    long long step = 0;   ///< that step's number
    double dt = 0;        ///< [s]
    IntegratorKind integrator = IntegratorKind::SymplecticEuler;

    /// One line for people, the same words in the CLI and the window:
    /// `diverged at t = 0.125 s (step 125, dt = 0.001 s, euler): body "ball": velocity is no
    /// longer finite`.
    std::string message() const;
};

} // namespace rigidlab::physics
