// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A plot as a screen reader reads it. QCustomPlot paints everything itself, so to assistive
// technology a plot was an empty box; this gives a PlotWidget (and the QCustomPlot inside it)
// the role of a chart, its title as the name and, as its description, the plot described in
// words: the axes with their units and ranges, each series with its value now and its least
// and greatest. The same text is the plot menu's "Describe this plot".

#include <QString>

class QAccessibleInterface;
class QObject;

namespace rigidlab::ui {

class PlotWidget;

/// The plot in words (drained first by the caller if it wants the newest points).
QString describePlot(const PlotWidget& plot);

/// The factory of the plots' interfaces (installed with the window's others,
/// window/accessible_factories.h).
QAccessibleInterface* plotInterface(const QString& className, QObject* object);

} // namespace rigidlab::ui
