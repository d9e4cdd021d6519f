// SPDX-License-Identifier: GPL-3.0-or-later
#include "worksheet/worksheet_plots.h"

#include "plots/lesson_export.h"

#include "format/view_text.h"

namespace rigidlab::ui {

lessons::LessonStep stepAsRun(const lessons::LessonStep& step, const lessons::StepAnswers& ran)
{
    lessons::LessonStep out = step;
    // A question that asks the student to set something ("set e = 0 and run again") was judged
    // on that run: a step whose such question was tried shows it (the last one tried).
    for (std::size_t q = 0; q < step.questions.size() && q < ran.questions.size(); ++q)
        if (lessons::asksSettings(step.questions[q]) && !ran.questions[q].empty())
            out = lessons::askedStep(step, step.questions[q]);
    if (ran.integrator)
        out.settings.set("integrator",
                         lessons::textFromView(physics::integratorName(*ran.integrator)));
    if (ran.dt)
        out.settings.set("dt", *ran.dt);
    if (ran.solver)
        out.settings.set("solver", lessons::textFromView(physics::solverName(*ran.solver)));
    return out;
}

} // namespace rigidlab::ui
