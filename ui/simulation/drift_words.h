// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The energy drift in words a teacher can explain to a class: what the number is the error
// of. The drift (step_sampler.h: EnergyReference) is the change of the total energy since the
// start (kinetic energy, gravity, springs), with what contacts, friction, drag and dampers
// took added back. What is left is every numerical error of the step: the integrator's; that
// of the corrections after the contacts and joints are solved (overlapping bodies pushed
// apart, pins pulled back together), which take or give energy no force accounts for; and
// that of the estimate of what resting contacts took, which grows with every step a body
// rests on another. So a method that follows a free fall exactly (velocity Verlet) still
// drifts where bodies touch (test_simulation).

#include <QString>

namespace rigidlab::ui {

/// The status bar's drift, "%1" for the number in percent: what it is the error of, or, with
/// `brief` (a projector's line), the name alone.
QString driftLabel(bool brief);
/// What the drift measures and where it comes from, for the status bar's tooltip.
QString driftExplanation();

} // namespace rigidlab::ui
