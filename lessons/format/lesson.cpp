// SPDX-License-Identifier: GPL-3.0-or-later
// A lesson step's worlds: its scene, its settings on top, and one world per compared variant.

#include "format/lesson.h"
#include "format/scene_schema.h"
#include "format/view_text.h"

#include <algorithm>

#include <cassert>

namespace rigidlab::lessons {

QString Comparison::label(int i) const
{
    assert(i >= 0 && i < count());
    const auto index = static_cast<std::size_t>(i);
    if (index < integrators.size()) {
        return textFromView(physics::integratorName(integrators[index]));
    }
    if (index < solvers.size()) {
        return textFromView(physics::solverName(solvers[index]));
    }
    return {};
}

QStringList LessonStep::heldBack(const std::vector<bool>& answered) const
{
    // Something two questions hold back stays held until both are answered: the second
    // question's answer may be in it too.
    QStringList held;
    for (std::size_t i = 0; i < questions.size(); ++i) {
        if (i < answered.size() && answered[i]) {
            continue;
        }
        for (const QString& name : questions[i].holdBack) {
            if (!held.contains(name)) {
                held.append(name);
            }
        }
    }
    return held;
}

LessonStep askedStep(const LessonStep& step, const Question& question)
{
    LessonStep asked = step;
    // Only a measured question runs the step; the others ask it as it is.
    if (const MeasuredQuestion* measured = question.as<MeasuredQuestion>()) {
        for (const schema::Field& f : schema::settings()) {
            if (measured->set.has(f.key)) {
                asked.settings.set(f.key, measured->set.value(f.key));
            }
        }
    }
    return asked;
}

bool asksSettings(const Question& question)
{
    const MeasuredQuestion* measured = question.as<MeasuredQuestion>();
    return measured && !measured->set.empty();
}

std::vector<int> questionCounts(const Lesson& lesson)
{
    std::vector<int> counts;
    for (const LessonStep& step : lesson.steps)
        counts.push_back(static_cast<int>(step.questions.size()));
    return counts;
}

void applySettings(const StepSettings& settings, physics::World& world)
{
    // In the table's order; the time scale is the window's clock, not the world's (no apply).
    for (const schema::Field& f : schema::settings()) {
        if (f.apply && settings.has(f.key)) {
            f.apply(world, settings.value(f.key));
        }
    }
}

double exportRunTime(const LessonStep& step)
{
    return step.endTime ? std::min(step.exportTime, *step.endTime) : step.exportTime;
}

std::vector<physics::World> buildStepWorlds(const LessonStep& step)
{
    physics::World main = buildWorld(step.scene);
    applySettings(step.settings, main);
    std::vector<physics::World> worlds;
    const int count = step.compare ? step.compare->count() : 0;
    if (count == 0) {
        worlds.push_back(std::move(main));
        return worlds;
    }
    worlds.reserve(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        physics::World variant = main;
        const auto index = static_cast<std::size_t>(i);
        if (index < step.compare->integrators.size()) {
            variant.setIntegrator(step.compare->integrators[index]);
        }
        if (index < step.compare->solvers.size()) {
            variant.setSolver(step.compare->solvers[index]);
        }
        worlds.push_back(std::move(variant));
    }
    return worlds;
}

} // namespace rigidlab::lessons
