// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Helpers of the lesson-physics tests (test_lesson_physics*.cpp).

#include "test_lesson.h"

#include <cmath>

namespace rigidlab::test {

inline const lessons::LessonStep& stepOf(const lessons::Lesson& lesson, std::size_t i)
{
    return lesson.steps.at(i);
}

inline physics::BodyId bodyId(const lessons::Scene& scene, const char* id)
{
    const auto index = scene.bodyIndex(QString::fromLatin1(id));
    Q_ASSERT(index);
    return *index;
}

/// Step `index` of the shipped lesson `name`, its worlds built to run side by side as the
/// window runs them: where a claim of the lesson's text is checked.
struct ShippedStep {
    lessons::Lesson lesson;
    const lessons::LessonStep& step;
    StepRun run;

    ShippedStep(const char* name, std::size_t index)
        : lesson(shippedLesson(name)), step(stepOf(lesson, index)), run(step)
    {
    }
    ShippedStep(const ShippedStep&) = delete; // `step` is of this one's lesson
    ShippedStep& operator=(const ShippedStep&) = delete;
    /// Runs the step to the time its plots are exported; what its first world measured.
    const lessons::Measurements& runToExport()
    {
        run.run(step.exportTime);
        return run.measurements[0];
    }
};

/// The verdict on `answer` to question `q` of `step`, the step run to the time its plots are
/// exported.
inline lessons::Verdict judgedAtExport(const lessons::LessonStep& step, const lessons::Question& q,
                                       double answer)
{
    StepRun run(step);
    run.run(step.exportTime);
    return lessons::judge(q, answer, run.measurements[0], step.scene);
}

/// The relative energy drift of a world since `e0` [%], as the lessons measure it.
inline double driftPercent(const physics::World& w, double e0)
{
    return (w.diagnostics().total - e0) / std::abs(e0) * 100.0;
}

} // namespace rigidlab::test
