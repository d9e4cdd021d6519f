// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/accessible_factories.h"

#include "common/announcer.h"
#include "common/line_edit_accessible.h"
#include "common/scroll_bar_accessible.h"
#include "common/tab_bar_accessible.h"
#include "plots/plot_accessible.h"
#include "view/world_view_accessible.h"

#include <QAccessible>

#include <array>

namespace rigidlab::ui {

void installAccessibleFactories()
{
    static const bool installed = [] {
        const std::array<QAccessible::InterfaceFactory, 6> factories{
            lineEditInterface, tabBarInterface,    scrollBarInterface,
            plotInterface,     worldViewInterface, announcerInterface};
        for (QAccessible::InterfaceFactory factory : factories)
            QAccessible::installFactory(factory);
        return true;
    }();
    Q_UNUSED(installed);
}

} // namespace rigidlab::ui
