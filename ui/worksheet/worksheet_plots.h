// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A lesson step's plots filled without a window, for a worksheet: the step's worlds run for
// its exportTime and sampled as the window samples them, with the settings the student ran
// the step with (those a tried question asked for, and the answers file's integrator, dt and
// solver) on top of the step's own.

#include "plots/lesson_export.h"

#include "format/answers_file.h"
#include "format/lesson.h"

#include <vector>

class QWidget;

namespace rigidlab::ui {

class PlotWidget;

/// The step with the student's settings applied: those of a question with "set" the student
/// tried (its run is the one it was judged on), then those the answers give (nullopt keep the
/// step's). The settings stay within the step's: a comparison keeps its own integrators.
lessons::LessonStep stepAsRun(const lessons::LessonStep& step, const lessons::StepAnswers& ran);

} // namespace rigidlab::ui
