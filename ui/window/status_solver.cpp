// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/status_solver.h"

#include "common/display_names.h"

#include <rigidlab/physics/world.h>

#include <QCoreApplication>

namespace rigidlab::ui {

QString solverStatusText(const physics::World& world)
{
    const QString running = solverDisplayName(world.solverRunning());
    if (world.softStepStandIn() == physics::SoftStepStandIn::None)
        return running;
    return QCoreApplication::translate("rigidlab::ui::StatusLine", "%1 instead of the soft step")
        .arg(running);
}

QString solverStatusTip(const physics::World& world)
{
    const char* why = nullptr;
    switch (world.softStepStandIn()) {
    case physics::SoftStepStandIn::None:
        return QCoreApplication::translate("rigidlab::ui::StatusLine", "Contact solver: %1")
            .arg(solverDisplayName(world.solverRunning()));
    case physics::SoftStepStandIn::Integrator:
        why = QT_TRANSLATE_NOOP("rigidlab::ui::StatusLine",
                                "The soft step runs only with the symplectic Euler integrator.");
        break;
    case physics::SoftStepStandIn::Springs:
        why = QT_TRANSLATE_NOOP("rigidlab::ui::StatusLine",
                                "The soft step does not handle springs yet.");
        break;
    case physics::SoftStepStandIn::Joints:
        why = QT_TRANSLATE_NOOP("rigidlab::ui::StatusLine",
                                "The soft step does not handle pin joints yet.");
        break;
    case physics::SoftStepStandIn::Gravitation:
        why = QT_TRANSLATE_NOOP("rigidlab::ui::StatusLine",
                                "The soft step does not handle gravitation between bodies yet.");
        break;
    }
    return QCoreApplication::translate("rigidlab::ui::StatusLine",
                                       "%1 The sequential-impulse solver runs instead.")
        .arg(QCoreApplication::translate("rigidlab::ui::StatusLine", why));
}

} // namespace rigidlab::ui
