// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The status line's solver word: the contact solver that runs, the one the scene asked for
// (the soft step runs every world: springs, pins, gravitation and every integrator).

#include <QString>

namespace rigidlab::physics {
class World;
}

namespace rigidlab::ui {

/// The solver that runs, in a few words ("Soft step").
QString solverStatusText(const physics::World& world);
/// The same for the tooltip ("Contact solver: Soft step").
QString solverStatusTip(const physics::World& world);

} // namespace rigidlab::ui
