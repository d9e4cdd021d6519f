// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The separating axis step's handout: for a lesson step with a `sat` pair, the projections of
// both polygons on every axis the test tried, as the scene places them at the step's start.
//
//   DIR/NN-step-title/sat-projections.png  one strip per tested axis: the two projection
//                                          intervals on a number line, the overlap or gap, and
//                                          the separating axis (or the axis of least
//                                          penetration) marked in words and by a frame
//   DIR/NN-step-title/sat-projections.csv  one row per tested axis: its normal, the two
//                                          intervals [m], the overlap [m] (negative: a gap)
//
// The numbers are physics::satPolygons' record of the test, the same the SAT panel steps
// through; the headless lesson export (lesson_export.h) writes them beside the plots.

#include "plots/lesson_export.h"

#include "rigidlab/physics/sat.h"

#include <QImage>

namespace rigidlab::ui {

/// The SAT record of the step's pair at the step's start; nullopt when the step names none
/// or either body is not a polygon.
std::optional<physics::SatResult> stepSatResult(const lessons::LessonStep& step);

/// The figure, `options.logicalSize` × `options.pngPixelRatio` pixels, with `caption` under
/// its title.
QImage satFigure(const lessons::LessonStep& step, const physics::SatResult& sat,
                 const QString& caption, const ExportOptions& options = {});

/// The table, in `options.csv`'s dialect: a head with units, then a row per tested axis.
QByteArray satTable(const lessons::LessonStep& step, const physics::SatResult& sat,
                    const ExportOptions& options = {});

/// Writes sat-projections.png and sat-projections.csv into `dir` (made if missing). A step
/// without a polygon pair writes nothing and succeeds.
PlotFilesResult exportSatHandout(const lessons::Lesson& lesson, int step, const QString& dir,
                                 const ExportOptions& options = {});

} // namespace rigidlab::ui
