// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A lesson step's plots: making them, and writing them for handouts (PNG, PDF, SVG and the
// numbers as CSV) with a caption that says the lesson, the step, the integrator and dt.
//
// The window's "Export plots" writes the live plots with exportPlots(); the headless export
// (`rigidlab-cli lesson LESSON.json --export DIR`) builds the step's worlds, runs them for the
// step's exportTime (cut at its endTime, where the window's run stops: exportRunTime()),
// samples them as the window does (step_sampler.h) and writes the same plots with
// exportStepPlots().
//
// The plots by name (LessonStep::plots) are the rows of plot_table.h. Files are named after the
// plot: DIR/02-energy-drift/compare-energy.png.

#include "plots/plot_export.h"

#include "format/lesson.h"

#include <QString>
#include <QStringList>

#include <vector>

class QWidget;

namespace rigidlab::ui {

class PlotWidget;

/// One of the step's plots by its name in the lesson (its row in plot_table.h), a child of
/// `parent`, its objectName that name; nullptr for a name the loader does not admit. The
/// window and the headless export both make their plots here.
PlotWidget* makeStepPlot(const lessons::LessonStep& step, const QString& name, QWidget* parent);

/// The step's plots (makeStepPlot), in the order it names them, children of `parent`. The
/// caller connects their source.
std::vector<PlotWidget*> makeStepPlots(const lessons::LessonStep& step, QWidget* parent);

/// The folder for a step's plots: its number from 01 and its title in lower case, words
/// joined by '-': "02-verlet-against-rk4-up-close".
QString stepFolderName(const lessons::Lesson& lesson, int step);

/// The caption under each plot's title, two lines:
/// "Energy drift: four ways to take a step, step 1: Four integrators, one spring"
/// "integrators euler, symplectic-euler, verlet, rk4 · dt = 0.01 s"
/// `settings` are those of the main world as it runs (the student may have changed dt).
QString stepCaption(const lessons::Lesson& lesson, int step, const physics::WorldDef& settings);

struct PlotFilesResult {
    bool ok = false;
    QString error;     ///< the first thing that went wrong, naming the file
    QStringList files; ///< the files written, in order
};

/// Writes each plot as NAME.png, NAME.pdf, NAME.svg and NAME.csv into `dir` (made if
/// missing), NAME being the plot's objectName, each with `caption` under its title; no SVG
/// where this build cannot write it (canExport).
PlotFilesResult exportPlots(const std::vector<PlotWidget*>& plots, const QString& dir,
                            const QString& caption, const ExportOptions& options = {});

struct StepPlots {
    std::vector<PlotWidget*> plots; ///< children of the holder given, in the step's order
    physics::WorldDef settings;     ///< of the main world as it ran
};

/// Headless: the step's worlds built and run for lessons::exportRunTime(), sampled exactly as the
/// window's controller samples them, into the step's plots, children of `holder`. The main
/// world's divergence stops the run (and its plots), as in the window.
StepPlots runStepPlots(const lessons::LessonStep& step, QWidget* holder);

/// Headless: builds the step's worlds, runs them for exportRunTime(), and writes its plots
/// into DIR/stepFolderName(), and for a step with a `sat` pair its SAT handout
/// (sat_handout.h). A step with neither writes nothing and succeeds.
PlotFilesResult exportStepPlots(const lessons::Lesson& lesson, int step, const QString& dir,
                                const ExportOptions& options = {});

/// exportStepPlots() for every step that has plots or a `sat` pair.
PlotFilesResult exportLessonPlots(const lessons::Lesson& lesson, const QString& dir,
                                  const ExportOptions& options = {});

} // namespace rigidlab::ui
