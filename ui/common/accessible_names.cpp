// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/accessible_names.h"

#include <QCoreApplication>
#include <QScrollArea>
#include <QScrollBar>

namespace rigidlab::ui {

void nameScrollArea(QScrollArea& area, const QString& name)
{
    area.setAccessibleName(name);
    area.setFocusPolicy(Qt::NoFocus);
    area.verticalScrollBar()->setAccessibleName(
        QCoreApplication::translate("AccessibleNames", "Scroll %1").arg(name));
    area.horizontalScrollBar()->setAccessibleName(
        QCoreApplication::translate("AccessibleNames", "Scroll %1 sideways").arg(name));
}

} // namespace rigidlab::ui
