// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The command line's words for a divergence (physics::Divergence is data only). The CLI's
// messages stay English; the window words the same data through tr() (ui/divergence_text.h).

#include "rigidlab/physics/divergence.h"

#include <QString>

namespace rigidlab::lessons {

/// The quantity as a noun: "position", "angular velocity", "total energy".
QString quantityName(physics::Divergence::Quantity quantity);

/// One line, numbers with a decimal point:
/// `diverged at t = 0.125 s (step 125, dt = 0.001 s, euler): body "ball": velocity is no
/// longer finite`, or `... : the total energy grew to 1e+06 J, past the bound of 1e+06 J
/// (body "mass" holds the most kinetic energy)`.
QString divergenceMessage(const physics::Divergence& d);

} // namespace rigidlab::lessons
