// SPDX-License-Identifier: GPL-3.0-or-later
// Lesson files: a step's "settings" on top of its scene's and the worlds its "compare" runs
// side by side (lessons/LESSON_FORMAT.md). Read for lesson_step.cpp.

#include "format/field_reading.h"
#include "format/lesson_reading.h"
#include "format/scene_loader.h"
#include "format/view_text.h"

#include <array>

namespace rigidlab::lessons::detail {

namespace {

/// A settings object at `at`: the keys of the settings rows, each read by its row.
bool readSettingsObject(JsonReader& in, const QJsonValue& value, const QString& at,
                        StepSettings& settings)
{
    QJsonObject s;
    QStringList keys;
    for (const schema::Field& f : schema::settings()) {
        keys << QString::fromLatin1(f.key.data(), qsizetype(f.key.size()));
    }
    if (!in.asObject(value, at, s) || !in.checkKeys(s, at, keys)) {
        return false;
    }
    for (const schema::Field& f : schema::settings()) {
        schema::Value v;
        if (!readPlainValue(in, f, s, at, v)) {
            return false;
        }
        if (!std::holds_alternative<std::monostate>(v)) {
            settings.set(f.key, v);
        }
    }
    return true;
}

} // namespace

bool readSettings(JsonReader& in, const QJsonObject& object, const QString& place,
                  StepSettings& settings)
{
    if (!object.contains(u"settings")) {
        return true;
    }
    return readSettingsObject(in, object.value(u"settings"), joinPlace(place, u"settings"),
                              settings);
}

bool readQuestionSet(JsonReader& in, const QJsonObject& question, const QString& place,
                     const LessonStep& step, const QStringList& holdBack, StepSettings& set)
{
    if (!question.contains(u"set")) {
        return true;
    }
    const QString at = joinPlace(place, u"set");
    if (!readSettingsObject(in, question.value(u"set"), at, set)) {
        return false;
    }
    const QStringList keys = question.value(u"set").toObject().keys();
    if (keys.isEmpty()) {
        return in.fail(at, FileMessages::tr("sets nothing (leave the key out when the student "
                                            "sets nothing)"));
    }
    if (set.has("timeScale")) {
        return in.fail(joinPlace(at, u"timeScale"),
                       FileMessages::tr("slow motion does not change what is measured: leave it "
                                        "out"));
    }
    if (step.compare && !step.compare->integrators.empty() && set.has("integrator")) {
        return in.fail(joinPlace(at, u"integrator"),
                       FileMessages::tr("this step compares integrators, each world its own: "
                                        "the student cannot choose one"));
    }
    if (step.compare && !step.compare->solvers.empty() && set.has("solver")) {
        return in.fail(joinPlace(at, u"solver"),
                       FileMessages::tr("this step compares solvers, each world its own: the "
                                        "student cannot choose one"));
    }
    // A question the student cannot set up is a mistake in the lesson, but not one that
    // keeps it from loading: the editor marks it and the player judges such a question by
    // the run the question asks for, done without a window.
    for (const QString& key : keys) {
        if (step.allow && !step.allow->contains(key)) {
            in.warn(joinPlace(at, key),
                    FileMessages::tr("the student is asked to set %1, but this step locks it "
                                     "(\"allow\" does not list it)")
                        .arg(key));
        }
    }
    if (!step.panels.contains(u"controls")) {
        in.warn(at, FileMessages::tr("the student is asked to set %1 with the controls, but this "
                                     "step does not show the controls panel")
                        .arg(keys.join(u", ")));
    } else if (holdBack.contains(u"panel:controls")) {
        in.warn(at, FileMessages::tr("the student is asked to set %1 with the controls, which "
                                     "this question holds back until it is answered")
                        .arg(keys.join(u", ")));
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
    if (step.settings.has(byIntegrator ? "integrator" : "solver")) {
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
