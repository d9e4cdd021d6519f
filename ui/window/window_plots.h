// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The window's plots and the controller: each plot follows the live samples; File › Export
// plot offers the plots that are on screen, each in four formats.

#include <QList>

#include <functional>

class QMenu;
class QWidget;

namespace rigidlab::ui {

class PlotTurns;
class PlotWidget;
class RunView;

/// Connects a plot to the run's samples, and lets it take its turns in `turns` (which follows
/// the run's frames) to drain them.
void followController(PlotWidget& plot, const RunView& run, PlotTurns& turns);

/// Fills `menu` (File › Export plot) each time it opens with the plots `onScreen` returns:
/// one submenu per plot under its title, PNG, PDF, SVG and CSV in each. The file dialog is
/// parented to `window`; the default file name is the plot's title in plain letters.
void fillExportMenu(QMenu& menu, QWidget& window, std::function<QList<PlotWidget*>()> onScreen);

} // namespace rigidlab::ui
