// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The conservation experiments behind `rigidlab-cli conserve`: what an impact
// solver must keep, measured on scenes whose exact answer is known.
//   gas     an elastic gas (e = 1, no friction, no gravity) of balls in a closed box of static
//           walls: the kinetic energy must stay what it was.
//   cradle  a row of touching elastic balls hit by one more: no step may gain energy.
// Qt-free, so that the tests and the command share it.

#include "rigidlab/physics/world.h"

#include <string>
#include <vector>

namespace rigidlab::lessons {

struct GasSpec {
    int balls = 300;       ///< how many
    double seconds = 60.0; ///< run time [s]
    double dt = 1e-3;      ///< time step [s]
    double radius = 0.1;   ///< of each ball [m]
    double speed = 5.0;    ///< each velocity component uniform in [-speed, speed) [m/s]
    double spacing = 0.5;  ///< of the starting grid [m]; the box is sized to it
    unsigned seed = 12345; ///< of the fixed linear congruential sequence
};

/// The gas as a world, with the given solver. Walls first, then the balls.
physics::World makeElasticGas(const GasSpec& spec, physics::SolverKind solver);

struct ConservationResult {
    std::string solver;
    double start = 0;     ///< kinetic energy at the start [J]
    double end = 0;       ///< at the end [J]
    double worst = 0;     ///< largest |E(t) - E(0)| / E(0) over the run
    double worstGain = 0; ///< largest one-step (E(t+dt) - E(t)) / E(t), 0 if none gained
    int escaped = 0;      ///< balls that left the box
    double seconds = 0;   ///< wall-clock time of the run [s]
    double drift() const { return start > 0 ? (end - start) / start : 0.0; }
};

ConservationResult runElasticGas(const GasSpec& spec, physics::SolverKind solver);

/// A row of `balls` touching elastic, frictionless balls of radius r, without gravity, hit
/// head-on by one more at `speed` from `gap` away, run for `steps` steps of dt.
struct CradleSpec {
    int balls = 4;
    double radius = 0.05; ///< [m]
    double speed = 1.0;   ///< of the striker [m/s]
    double gap = 0.0005;  ///< between the striker and the row [m]
    double dt = 5e-4;     ///< [s]
    int steps = 400;
};

physics::World makeCradleRow(const CradleSpec& spec, physics::SolverKind solver);
ConservationResult runCradleRow(const CradleSpec& spec, physics::SolverKind solver);

/// Newton's cradle as lessons/scenes/newtons_cradle.json builds it: five balls of 0.2 kg and
/// radius 5 cm on pins 0.6 m above them, 1 mm apart, the first pulled out by 30 degrees,
/// e = 1, dt = 0.5 ms, for `seconds`. worstGain is the largest one-step gain of the total
/// energy (kinetic + gravity) in the steps where two or more contact points pushed, relative
/// to the energy of the swing; worst the largest |E(t) - E(0)| relative to it.
ConservationResult runNewtonsCradle(physics::SolverKind solver, double seconds = 2.0);

/// The results as an aligned table for a terminal.
std::string conservationTable(const std::vector<ConservationResult>& rows);

} // namespace rigidlab::lessons
