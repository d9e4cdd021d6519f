// SPDX-License-Identifier: GPL-3.0-or-later
// Lesson files: a step's "settings" on top of its scene's and the worlds its "compare" runs
// side by side (lessons/LESSON_FORMAT.md). Read for lesson_step.cpp.

#include "format/lesson_reading.h"
#include "format/scene_loader.h"
#include "format/view_text.h"

#include <array>

namespace rigidlab::lessons::detail {

namespace {

constexpr double kMinTimeScale = 0.1;
constexpr double kMaxTimeScale = 4.0;

} // namespace

bool readSettings(JsonReader& in, const QJsonObject& object, const QString& place,
                  StepSettings& settings)
{
    if (!object.contains(u"settings")) {
        return true;
    }
    const QString at = joinPlace(place, u"settings");
    QJsonObject s;
    if (!in.asObject(object.value(u"settings"), at, s) ||
        !in.checkKeys(s, at,
                      {u"integrator", u"dt", u"solver", u"iterations", u"restitution", u"friction",
                       u"gravity", u"timeScale"})) {
        return false;
    }
    QString name;
    if (s.contains(u"integrator")) {
        if (!in.string(s, u"integrator", at, name)) {
            return false;
        }
        settings.integrator = physics::integratorFromName(name.toStdString());
        if (!settings.integrator) {
            return in.fail(joinPlace(at, u"integrator"), unknownIntegrator(name));
        }
    }
    if (s.contains(u"dt")) {
        double dt = 0;
        if (!in.number(s, u"dt", at, dt, NumberRule::Positive)) {
            return false;
        }
        if (dt < kMinDt || dt > kMaxDt) {
            return in.fail(joinPlace(at, u"dt"),
                           FileMessages::tr("must be from %1 to %2 s, got %3")
                               .arg(formatNumber(kMinDt), formatNumber(kMaxDt), formatNumber(dt)));
        }
        settings.dt = dt;
    }
    if (s.contains(u"solver")) {
        if (!in.string(s, u"solver", at, name)) {
            return false;
        }
        settings.solver = physics::solverFromName(name.toStdString());
        if (!settings.solver) {
            return in.fail(joinPlace(at, u"solver"), unknownSolver(name));
        }
    }
    if (s.contains(u"iterations")) {
        int n = 0;
        if (!in.integer(s, u"iterations", at, n, 1, kMaxIterations)) {
            return false;
        }
        settings.iterations = n;
    }
    double value = 0;
    if (s.contains(u"restitution")) {
        if (!in.number(s, u"restitution", at, value, NumberRule::UnitInterval,
                       limits::kRestitution)) {
            return false;
        }
        settings.restitution = value;
    }
    if (s.contains(u"friction")) {
        if (!in.number(s, u"friction", at, value, NumberRule::NonNegative, limits::kFriction)) {
            return false;
        }
        settings.friction = value;
    }
    if (s.contains(u"gravity")) {
        bool on = true;
        if (!in.boolean(s, u"gravity", at, on)) {
            return false;
        }
        settings.gravity = on;
    }
    if (s.contains(u"timeScale")) {
        if (!in.number(s, u"timeScale", at, value, NumberRule::Positive)) {
            return false;
        }
        if (value < kMinTimeScale || value > kMaxTimeScale) {
            return in.fail(joinPlace(at, u"timeScale"),
                           FileMessages::tr("must be from %1 to %2, got %3")
                               .arg(formatNumber(kMinTimeScale), formatNumber(kMaxTimeScale),
                                    formatNumber(value)));
        }
        settings.timeScale = value;
    }
    return true;
}

bool readCompare(JsonReader& in, const QJsonObject& object, const QString& place, LessonStep& step)
{
    if (!object.contains(u"compare")) {
        return true;
    }
    const QString at = joinPlace(place, u"compare");
    QJsonObject c;
    if (!in.asObject(object.value(u"compare"), at, c) ||
        !in.checkKeys(c, at, {u"integrators", u"solvers", u"offset"})) {
        return false;
    }
    const bool byIntegrator = c.contains(u"integrators");
    if (byIntegrator && c.contains(u"solvers")) {
        return in.fail(joinPlace(at, u"solvers"),
                       FileMessages::tr("compare \"integrators\" or \"solvers\", not both"));
    }
    if (!byIntegrator && !c.contains(u"solvers")) {
        return in.fail(at, FileMessages::tr("needs \"integrators\" or \"solvers\": the worlds to "
                                            "run side by side"));
    }
    const QStringView key = byIntegrator ? QStringView(u"integrators") : QStringView(u"solvers");
    const QString listAt = joinPlace(at, key);
    if (byIntegrator ? step.settings.integrator.has_value() : step.settings.solver.has_value()) {
        return in.fail(listAt,
                       FileMessages::tr("settings.%1 is given too: the main world runs the first "
                                        "of this list, so leave settings.%1 out")
                           .arg(byIntegrator ? u"integrator" : u"solver"));
    }
    QJsonArray list;
    if (!in.asArray(c.value(key), listAt, list)) {
        return false;
    }
    if (list.size() < 2 || list.size() > kMaxVariants) {
        return in.fail(
            listAt,
            FileMessages::tr("compares 2 to %1 worlds, got %2").arg(kMaxVariants).arg(list.size()));
    }
    Comparison comparison;
    QStringList seen;
    const bool named = readDistinctNames(
        in, list, listAt,
        [&](const QString& name, const QString& itemAt) {
            if (byIntegrator) {
                const auto kind = physics::integratorFromName(name.toStdString());
                if (!kind)
                    return in.fail(itemAt, unknownIntegrator(name));
                comparison.integrators.push_back(*kind);
            } else {
                const auto kind = physics::solverFromName(name.toStdString());
                if (!kind)
                    return in.fail(itemAt, unknownSolver(name));
                comparison.solvers.push_back(*kind);
            }
            return true;
        },
        seen);
    if (!named) {
        return false;
    }
    if (!in.vec2(c, u"offset", at, comparison.offset, limits::kCoordinate)) {
        return false;
    }
    step.compare = comparison;
    return true;
}

} // namespace rigidlab::lessons::detail
