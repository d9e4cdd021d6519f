// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_player/asked_run.h"

#include "common/display_names.h"
#include "common/number_format.h"

#include "format/scene_schema.h"

#include <QCoreApplication>

#include <algorithm>

namespace rigidlab::ui {

namespace {

namespace schema = lessons::schema;

QString tr(const char* text)
{
    return QCoreApplication::translate("rigidlab::ui::AskedRun", text);
}

QString fromView(std::string_view s)
{
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

/// Whether a hand-made edit changes the setting `key`: its own, or a body's material, whose
/// restitution and friction stand in for the world's (the body rows that fall back to it).
bool changes(const SettingEdit& edit, std::string_view key)
{
    if (edit.object == schema::Object::World)
        return edit.key == key;
    if (edit.key != body_edit::kMaterial)
        return false;
    const auto rows = schema::fields(schema::Object::Body);
    return std::any_of(rows.begin(), rows.end(),
                       [&](const schema::Field& f) { return f.fallback == key; });
}

/// A world setting as a student reads it on the controls.
QString valueText(const schema::Value& v)
{
    if (const double* d = std::get_if<double>(&v))
        return formatReadable(*d, 6);
    if (const int* i = std::get_if<int>(&v))
        return QLocale().toString(*i);
    if (const QString* s = std::get_if<QString>(&v))
        return methodDisplayName(*s);
    if (const physics::Vec2* g = std::get_if<physics::Vec2>(&v))
        return g->isZero() ? tr("off") : tr("on");
    if (const bool* b = std::get_if<bool>(&v))
        return *b ? tr("on") : tr("off");
    return {};
}

} // namespace

AskedRun askedRun(const lessons::LessonStep& step, const lessons::Question& question,
                  const physics::World& world, const SettingEdits& edits)
{
    AskedRun run;
    if (!lessons::asksSettings(question))
        return run;
    // Only a measured question asks for settings.
    const lessons::StepSettings& set = question.as<lessons::MeasuredQuestion>()->set;
    // The world the question asks for, built as the step builds its own, and the window's:
    // compared through the scene format's world rows, which read a WorldDef's settings.
    lessons::Scene asked;
    asked.world = lessons::buildStepWorlds(lessons::askedStep(step, question)).front().def();
    lessons::Scene live;
    live.world = world.def();
    QStringList askedWords;
    for (const schema::Field& f : schema::settings()) {
        if (!set.has(f.key))
            continue;
        const schema::Field* w = schema::worldRowOf(f);
        if (w == nullptr)
            continue;
        const schema::Value want = w->get(asked, 0);
        const schema::Value have = w->get(live, 0);
        askedWords << tr("%1 = %2").arg(schema::label(f), valueText(want));
        if (want != have) {
            run.differences
                << tr("%1 is %2, not %3").arg(schema::label(f), valueText(have), valueText(want));
        } else if (std::any_of(edits.begin(), edits.end(), [&](const SettingEdit& e) {
                       return e.step > 0 && changes(e, f.key);
                   })) {
            run.differences << tr("%1 was changed during the run").arg(schema::label(f));
        }
        const QString key = fromView(f.key);
        if ((step.allow && !step.allow->contains(key)) || !step.panels.contains(u"controls") ||
            question.holdBack.contains(u"panel:controls"))
            run.studentCanSet = false;
    }
    run.asked = askedWords.join(QStringLiteral(", "));
    return run;
}

QString askedRunAdvice(const AskedRun& run)
{
    if (run.matches())
        return {};
    if (!run.studentCanSet)
        return tr("This question is asked with %1, which this step does not let you set (a "
                  "mistake in the lesson): it is judged by that run done without the window.")
            .arg(run.asked);
    return tr("This question is asked with %1, from the start of the run. In your run %2: set "
              "it with the controls, press Reset and run again, then check.")
        .arg(run.asked, run.differences.join(QStringLiteral("; ")));
}

} // namespace rigidlab::ui
