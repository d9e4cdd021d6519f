// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the window calls an integrator or a contact solver: the one table of their names in
// words ("Runge–Kutta 4"), for the control panel's lists, the plots' legends and marks, and
// the captions of exported plots. Scene and lesson files use the code names ("rk4",
// physics::integratorName); a reader of a plot should not have to.

#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/integrator.h"
#include "rigidlab/physics/profile.h"

#include <QString>

namespace rigidlab::ui {

/// "Explicit Euler", "Velocity Verlet", ..., translated.
QString integratorDisplayName(physics::IntegratorKind kind);
/// "The paper's impulse", "Sequential impulse", translated.
QString solverDisplayName(physics::SolverKind kind);
/// A step's stage in words ("broad phase"), translated: the physics names it in English for
/// the CLI and stays free of languages.
QString stageDisplayName(physics::Stage stage);
/// A name from a file (a lesson's or scene's title, a file name, a folder) as a menu entry:
/// an '&' in it is shown, not taken for the entry's underlined key.
QString menuEntryText(const QString& name);
/// The display name of an integrator or solver given by its code name ("rk4",
/// "sequential-impulse"); any other text comes back as it is.
QString methodDisplayName(const QString& codeName);

} // namespace rigidlab::ui
