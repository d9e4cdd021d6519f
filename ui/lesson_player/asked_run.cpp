// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_player/asked_run.h"

#include "common/display_names.h"
#include "common/number_format.h"

#include "format/scene_schema.h"

#include <QCoreApplication>

#include <algorithm>
#include <array>
#include <utility>

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

/// The hand-made edits that change each setting a question may ask for.
constexpr std::array<std::pair<std::string_view, SettingEdit::Kind>, 7> kEditKinds{{
    {"dt", SettingEdit::Kind::Dt},
    {"integrator", SettingEdit::Kind::Integrator},
    {"solver", SettingEdit::Kind::Solver},
    {"iterations", SettingEdit::Kind::Iterations},
    {"restitution", SettingEdit::Kind::Restitution},
    {"friction", SettingEdit::Kind::Friction},
    {"gravity", SettingEdit::Kind::Gravity},
}};

bool changes(const SettingEdit& edit, std::string_view key)
{
    // A body's own restitution and friction, set in the inspector, change the run too.
    if (edit.kind == SettingEdit::Kind::BodyMaterial)
        return key == "restitution" || key == "friction";
    return std::any_of(kEditKinds.begin(), kEditKinds.end(),
                       [&](const auto& k) { return k.first == key && k.second == edit.kind; });
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

QString label(const schema::SettingsField& f)
{
    return f.label ? QCoreApplication::translate(schema::kContext, f.label) : fromView(f.key);
}

} // namespace

AskedRun askedRun(const lessons::LessonStep& step, const lessons::Question& question,
                  const physics::World& world, const SettingEdits& edits)
{
    AskedRun run;
    if (!lessons::asksSettings(question))
        return run;
    // The world the question asks for, built as the step builds its own, and the window's:
    // compared through the scene format's world rows, which read a WorldDef's settings.
    lessons::Scene asked;
    asked.world = lessons::buildStepWorlds(lessons::askedStep(step, question)).front().def();
    lessons::Scene live;
    live.world = world.def();
    QStringList askedWords;
    for (const schema::SettingsField& f : schema::settingsFields()) {
        if (std::holds_alternative<std::monostate>(f.get(question.set, 0)))
            continue;
        const schema::Field* w = schema::findField(schema::Object::World, f.key);
        if (w == nullptr)
            continue;
        const schema::Value want = w->get(asked, 0);
        const schema::Value have = w->get(live, 0);
        askedWords << tr("%1 = %2").arg(label(f), valueText(want));
        if (want != have) {
            run.differences
                << tr("%1 is %2, not %3").arg(label(f), valueText(have), valueText(want));
        } else if (std::any_of(edits.begin(), edits.end(), [&](const SettingEdit& e) {
                       return e.step > 0 && changes(e, f.key);
                   })) {
            run.differences << tr("%1 was changed during the run").arg(label(f));
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
