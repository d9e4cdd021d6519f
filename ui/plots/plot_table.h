// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The plots, one row each: the lesson format's name, the titles the window and the lesson
// editor give it, and how it is made. The window makes its own plots (the rows that are not
// of compared worlds) and gives their docks its full title as their tooltip; a lesson step,
// the Export of its plots and the headless export (rigidlab-cli lesson --export) make a step's
// plots by name from it; the lesson editor lists them from it. A plot of one quantity of the
// world is a row with that quantity's label, unit and sample; a plot of another shape gives how
// it is made.
// Nothing else names a plot: a plot is found by its row's name, never by its place in a list
// (test_code_shape checks that no production file but this one and the lesson format's list
// writes a plot's name).

#include "simulation/sample_buffer.h"

#include <QString>
#include <QStringView>

#include <string_view>

class QWidget;

namespace rigidlab::lessons {
struct LessonStep;
}

namespace rigidlab::ui {

class PlotWidget;

// The plots of another shape than one quantity: standard_plots.cpp (the main world's) and
// lesson_export.cpp (the compared worlds').
PlotWidget* makeEnergyPlot(QWidget* parent);
PlotWidget* makeMomentumPlot(QWidget* parent);
PlotWidget* makeDriftPlot(QWidget* parent);
PlotWidget* makeCompareEnergyPlot(const lessons::LessonStep& step, QWidget* parent);
PlotWidget* makeCompareDriftPlot(const lessons::LessonStep& step, QWidget* parent);

struct PlotRow {
    std::string_view name; ///< the lesson format's name (lessons::kStepPlotNames)
    /// Full (the dock's, the Export menu's, the lesson editor's), for
    /// QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", …).
    const char* title = nullptr;
    /// Short, likewise: a plot of compared worlds, its tab in their dock, which says what the
    /// worlds are compared in. (The window's own plots are short on their docks' tabs, which
    /// are titled from common/dock_names.h.)
    const char* shortTitle = nullptr;
    /// A plot of one quantity of the main world: its axis label (translated likewise), its
    /// unit and its value in a sample; the plot is made from them.
    const char* quantity = nullptr;
    const char* unit = nullptr;
    double (*sample)(const Sample&) = nullptr;
    /// A plot of the main world of another shape: how it is made.
    PlotWidget* (*make)(QWidget* parent) = nullptr;
    /// A plot of the worlds a step compares: how it is made. Only in a step with "compare",
    /// never one of the window's own plots.
    PlotWidget* (*makeCompared)(const lessons::LessonStep& step, QWidget* parent) = nullptr;

    /// One of the window's own plots (of the main world), with a dock of its own.
    constexpr bool inWindow() const { return makeCompared == nullptr; }
};

/// Every plot, in the order of lessons::kStepPlotNames (plot_table.cpp checks it).
inline constexpr PlotRow kPlotRows[] = {
    {.name = "energy",
     .title = QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Energy"),
     .make = makeEnergyPlot},
    {.name = "momentum",
     .title = QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Momentum"),
     .make = makeMomentumPlot},
    {.name = "drift",
     .title = QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Energy drift"),
     .make = makeDriftPlot},
    {.name = "compare-energy",
     .title = QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Energy of the compared"),
     .shortTitle = QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Energy"),
     .makeCompared = makeCompareEnergyPlot},
    {.name = "compare-drift",
     .title = QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Drift of the compared"),
     .shortTitle = QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Drift"),
     .makeCompared = makeCompareDriftPlot},
};

/// The row with this name, or null.
const PlotRow* findPlot(QStringView name);
/// The row's name as a QString (a dock's object name, a plot's).
QString plotName(const PlotRow& row);
/// The title of `row` in the window's language (full, or short for a tab: the full one for a
/// row without a short one).
QString plotTitle(const PlotRow& row, bool full = true);
/// A plot of the main world by its row, a child of `parent`, its object name the row's.
PlotWidget* makeWorldPlot(const PlotRow& row, QWidget* parent);

} // namespace rigidlab::ui
