// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/dock_names.h"

#include <QCoreApplication>
#include <QDockWidget>

#include <algorithm>

namespace rigidlab::ui {

const PanelEntry* panelEntry(QStringView dock)
{
    const auto found =
        std::find_if(kPanelEntries.begin(), kPanelEntries.end(),
                     [dock](const PanelEntry& e) { return dock == QLatin1String(e.dock); });
    return found == kPanelEntries.end() ? nullptr : &*found;
}

QString panelEntryText(const PanelEntry& entry)
{
    return QCoreApplication::translate("rigidlab::ui::MainWindow", entry.text);
}

QString dockTitle(QStringView dock)
{
    const PanelEntry* entry = panelEntry(dock);
    Q_ASSERT(entry); // every dock of the window has its entry
    return entry ? panelEntryText(*entry).remove(QLatin1Char('&')) : dock.toString();
}

void nameDock(QDockWidget& dock, const QString& objectName)
{
    dock.setObjectName(objectName);
    dock.setWindowTitle(dockTitle(objectName));
}

} // namespace rigidlab::ui
