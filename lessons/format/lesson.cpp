// SPDX-License-Identifier: GPL-3.0-or-later
// A lesson step's worlds: its scene, its settings on top, and one world per compared variant.

#include "format/lesson.h"
#include "format/scene_schema.h"
#include "format/view_text.h"

#include <algorithm>

#include <cassert>

namespace rigidlab::lessons {

namespace {

/// Gravity for `gravity: true` on a scene that has none [m/s^2].
const physics::Vec2 kStandardGravity(0.0, -9.81);

} // namespace

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
    for (const schema::SettingsField& f : schema::settingsFields()) {
        const schema::Value v = f.get(question.set, 0);
        if (!std::holds_alternative<std::monostate>(v)) {
            f.set(asked.settings, 0, v);
        }
    }
    return asked;
}

bool asksSettings(const Question& question)
{
    const auto fields = schema::settingsFields();
    return std::any_of(fields.begin(), fields.end(), [&](const schema::SettingsField& f) {
        return !std::holds_alternative<std::monostate>(f.get(question.set, 0));
    });
}

void applySettings(const StepSettings& settings, physics::World& world)
{
    if (settings.integrator) {
        world.setIntegrator(*settings.integrator);
    }
    if (settings.dt) {
        world.setDt(*settings.dt);
    }
    if (settings.solver) {
        world.setSolver(*settings.solver);
    }
    if (settings.iterations) {
        world.setIterations(*settings.iterations);
    }
    if (settings.restitution) {
        world.setRestitution(*settings.restitution);
    }
    if (settings.friction) {
        world.setFriction(*settings.friction);
    }
    if (settings.gravity) {
        // Off: none at all. On: the scene's own gravity, or the Earth's when it has none.
        if (!*settings.gravity) {
            world.setGravity(physics::Vec2::Zero());
        } else if (world.def().gravity == physics::Vec2::Zero()) {
            world.setGravity(kStandardGravity);
        }
    }
    // timeScale is the window's clock, not the world's.
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
