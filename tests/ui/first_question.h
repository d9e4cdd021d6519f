// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A lesson's first question, measured: the window opens the first step that asks something
// and runs until the simulation has measured what the question asks (tests of answer boxes).

#include "lesson_player/lesson_player.h"
#include "simulation/simulation_controller.h"
#include "window/main_window.h"

#include "question_kinds.h"

#include <optional>

struct MeasuredQuestion {
    int step = -1;               ///< the first step with a question, -1 if none
    std::optional<double> value; ///< what its first question measures, once measured
};

/// Goes to the first step of the open lesson that has a question and steps the world until
/// that question's measurement exists (at most `maxSteps` steps).
inline MeasuredQuestion runToFirstQuestion(rigidlab::ui::MainWindow& w, int maxSteps = 200000)
{
    MeasuredQuestion q;
    rigidlab::ui::LessonPlayer& player = w.lessonPlayer();
    const auto& steps = player.lesson()->steps;
    for (int i = 0; i < static_cast<int>(steps.size()) && q.step < 0; ++i)
        if (!steps[static_cast<std::size_t>(i)].questions.empty())
            q.step = i;
    if (q.step < 0)
        return q;
    player.goToStep(q.step);
    const auto& st = steps[static_cast<std::size_t>(q.step)];
    for (int k = 0; k < maxSteps && !q.value; ++k) {
        w.controller().stepForward();
        q.value = w.controller().lessonWatch().measurements().value(
            rigidlab::test::measuredOf(st.questions[0]).measure, st.scene);
    }
    return q;
}
