// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one table of the window's docks: each dock's object name and its name with an
// underlined letter, which is its entry in View › Panels. The dock's title is that name
// without the letter's mark: a dock's own title has none (its tab would underline the letter
// and take Alt and it from the window's controls). The letters are chosen here together, in
// each language, so that no two entries share one. Every part of the window that makes a dock
// (the window's layout, the editor's docks, the instruments) names it through nameDock(), so
// the title is written once. Here in common/ because the instruments, a layer below the
// window, make a dock too.
//
// The object name is what QMainWindow::saveState() keeps for a dock: a teacher's saved layout
// finds each dock again by it, so a dock keeps its name from one version to the next.

#include <QString>
#include <QStringView>
#include <QtGlobal>

#include <array>

class QDockWidget;

namespace rigidlab::ui {

struct PanelEntry {
    const char* dock; ///< the dock's object name
    const char* text; ///< for translate() in context "rigidlab::ui::MainWindow"
};

inline constexpr std::array<PanelEntry, 15> kPanelEntries{{
    {"lessonDock", QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "&Lesson")},
    {"controlsDock", QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "&Controls")},
    {"inspectorDock", QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "&Inspector")},
    {"energyDock", QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "&Energy")},
    {"momentumDock", QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "&Momentum")},
    {"driftDock", QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "&Drift")},
    {"satDock", QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "&Axis test")},
    {"bouncesDock", QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "&Bounces")},
    {"collisionDock", QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "C&ollision")},
    {"errorDock", QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "E&rror vs run time")},
    {"measurementDock", QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Meas&urement")},
    {"compareDock", QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "&Side by side")},
    {"propertiesDock", QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "&Properties")},
    {"historyDock", QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "&History")},
    {"instrumentsDock", QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "I&nstruments")},
}};

/// The entry of the dock whose object name is `dock`, or null.
const PanelEntry* panelEntry(QStringView dock);
/// The entry's text in the window's language, with its underlined letter.
QString panelEntryText(const PanelEntry& entry);
/// The title of the dock whose object name is `dock`: its entry's text without the mark of
/// its underlined letter. A dock without an entry is a programming error.
QString dockTitle(QStringView dock);
/// Gives `dock` its object name and its title from its entry.
void nameDock(QDockWidget& dock, const QString& objectName);

} // namespace rigidlab::ui
