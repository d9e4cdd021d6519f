// SPDX-License-Identifier: GPL-3.0-or-later
#include "worksheet/worksheet_plots.h"

#include "plots/lesson_export.h"

namespace rigidlab::ui {

lessons::LessonStep stepAsRun(const lessons::LessonStep& step, const lessons::StepAnswers& ran)
{
    lessons::LessonStep out = step;
    if (ran.integrator)
        out.settings.integrator = ran.integrator;
    if (ran.dt)
        out.settings.dt = ran.dt;
    if (ran.solver)
        out.settings.solver = ran.solver;
    return out;
}

} // namespace rigidlab::ui
