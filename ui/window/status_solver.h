// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The status line's solver word: the contact solver that runs, which is not always the one
// the scene asked for. The soft step does not yet handle springs, pin joints, gravitation or
// an integrator other than symplectic Euler; there the sequential-impulse solver stands in
// (physics::World::solverRunning()), and the status line says so instead of "soft step".

#include <QString>

namespace rigidlab::physics {
class World;
}

namespace rigidlab::ui {

/// The solver that runs, in a few words ("Sequential impulse instead of the soft step").
QString solverStatusText(const physics::World& world);
/// Why, when another solver stands in for the one asked for; the solver's name otherwise.
QString solverStatusTip(const physics::World& world);

} // namespace rigidlab::ui
