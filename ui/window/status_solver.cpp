// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/status_solver.h"

#include "common/display_names.h"

#include <rigidlab/physics/world.h>

#include <QCoreApplication>

namespace rigidlab::ui {

QString solverStatusText(const physics::World& world)
{
    return solverDisplayName(world.def().solver);
}

QString solverStatusTip(const physics::World& world)
{
    return QCoreApplication::translate("rigidlab::ui::StatusLine", "Contact solver: %1")
        .arg(solverDisplayName(world.def().solver));
}

} // namespace rigidlab::ui
