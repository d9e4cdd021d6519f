// SPDX-License-Identifier: GPL-3.0-or-later
// Lesson files: one step, its text, its scene (inline or a file) and the names of what it
// shows (lessons/LESSON_FORMAT.md). Read for lesson_loader.cpp.
//
// Nothing in a lesson is ever executed: texts are shown, names are looked up in fixed lists,
// and scene files are read only from where scene_path.cpp allows.

#include "format/editor_tools.h"
#include "format/lesson_reading.h"
#include "format/scene_loader.h"
#include "format/scene_path.h"
#include "format/scene_schema.h"

#include <QDir>
#include <QFileInfo>

#include <array>
#include <cassert>

namespace rigidlab::lessons::detail {

namespace {

constexpr double kMaxExportSteps = 1e7; ///< exportTime / dt at most

template <typename Names> QString joinNames(const Names& names)
{
    QStringList list;
    for (std::string_view n : names) {
        list.append(QLatin1String(n.data(), static_cast<qsizetype>(n.size())));
    }
    return list.join(u", ");
}

/// A scene loader's message `SOURCE: PLACE: what` as a place under the lesson's `at` and the
/// rest: (`at.PLACE`, `what`), which JsonReader joins back into `SOURCE: at.PLACE: what`.
std::pair<QString, QString> rebase(const QString& message, const QString& source, const QString& at)
{
    const QString prefix = source + QStringLiteral(": ");
    const QString rest = message.startsWith(prefix) ? message.mid(prefix.size()) : message;
    const qsizetype colon = rest.indexOf(QStringLiteral(": "));
    if (colon < 0) {
        return {at, rest};
    }
    return {at + u'.' + rest.left(colon), rest.mid(colon + 2)};
}

/// A list of distinct names, each one of `known`.
template <typename Known>
bool readNames(JsonReader& in, const QJsonObject& object, QStringView key, const QString& place,
               const Known& known, QStringView what, QStringList& out)
{
    if (!object.contains(key)) {
        return true;
    }
    const QString at = joinPlace(place, key);
    QJsonArray list;
    if (!in.asArray(object.value(key), at, list)) {
        return false;
    }
    return readDistinctNames(
        in, list, at,
        [&](const QString& name, const QString& itemAt) {
            for (std::string_view k : known) {
                if (name == QLatin1String(k.data(), static_cast<qsizetype>(k.size())))
                    return true;
            }
            return in.fail(itemAt, FileMessages::tr("unknown %1 \"%2\" (expected %3)")
                                       .arg(what.toString(), name, joinNames(known)));
        },
        out);
}

/// A scene the lesson file carries inside it, by the path the step names it with.
bool readEmbeddedScene(JsonReader& in, const QString& name, const QString& place,
                       const StepContext& context, LessonStep& step)
{
    const auto it = context.embedded->find(name);
    if (it == context.embedded->end()) {
        QStringList held;
        for (const auto& [key, scene] : *context.embedded)
            held.append(key);
        return in.fail(
            place, FileMessages::tr("\"%1\" is not among the scenes this file holds "
                                    "(%2)")
                       .arg(name, held.isEmpty() ? FileMessages::tr("none") : held.join(u", ")));
    }
    step.scene = it->second;
    return true;
}

bool readSceneFile(JsonReader& in, const QString& relative, const QString& place,
                   const StepContext& context, LessonStep& step)
{
    if (context.embedded) {
        return readEmbeddedScene(in, relative, place, context, step);
    }
    // The rules for where a scene file may be are in scene_path.cpp.
    const ScenePathResult resolved = resolveScenePath(context.folder, relative);
    if (!resolved.ok) {
        return in.fail(place, resolved.error);
    }
    const QString& readPath = resolved.readPath;
    const FileBytes file = readFileBytes(readPath, kMaxSceneFileBytes);
    if (!file.ok) {
        return in.fail(place, file.error);
    }
    // Messages name the scene file as the lesson's own name leads to it.
    const QString shown =
        QDir::cleanPath(QDir(QFileInfo(in.sourceName()).path()).filePath(relative));
    const SceneLoadResult loaded =
        loadSceneJson(file.bytes, shown, SceneLoadOptions{context.texts->language()});
    for (const QString& w : loaded.warnings) {
        in.warn(place, w);
    }
    if (!loaded.ok) {
        return in.fail(place, loaded.error);
    }
    step.scene = loaded.scene;
    step.scenePath = resolved.absolutePath;
    return true;
}

bool readScene(JsonReader& in, const QJsonObject& object, const QString& place,
               const StepContext& context, LessonStep& step)
{
    const QString at = joinPlace(place, u"scene");
    const auto it = object.constFind(u"scene");
    if (it == object.constEnd()) {
        return in.fail(at, FileMessages::tr("required, but missing (a scene object, or the path "
                                            "of a scene file)"));
    }
    if (it.value().isString()) {
        return readSceneFile(in, it.value().toString(), at, context, step);
    }
    if (!it.value().isObject()) {
        return in.fail(at, FileMessages::tr("must be a scene object {...} or the path of a scene "
                                            "file, got ") +
                               describeJson(it.value()));
    }
    const SceneLoadResult loaded = loadSceneObject(it.value().toObject(), in.sourceName(),
                                                   SceneLoadOptions{context.texts->language()});
    for (const QString& w : loaded.warnings) {
        const auto [wherePlace, what] = rebase(w, in.sourceName(), at);
        in.warn(wherePlace, what);
    }
    if (!loaded.ok) {
        const auto [wherePlace, what] = rebase(loaded.error, in.sourceName(), at);
        return in.fail(wherePlace, what);
    }
    step.scene = loaded.scene;
    return true;
}

/// The step's "editor": {"tools": [...], "properties": [...]}: each list absent means all,
/// empty means none.
bool readEditorLock(JsonReader& in, const QJsonObject& object, const QString& place,
                    LessonStep& step)
{
    if (!object.contains(u"editor")) {
        return true;
    }
    const QString at = joinPlace(place, u"editor");
    QJsonObject editor;
    EditorLock lock;
    if (!in.asObject(object.value(u"editor"), at, editor) ||
        !in.checkKeys(editor, at, {u"tools", u"properties"}) ||
        !readNames(in, editor, u"tools", at, kEditorToolNames, u"tool", lock.tools) ||
        !readNames(in, editor, u"properties", at, schema::editorPropertyNames(), u"property",
                   lock.properties)) {
        return false;
    }
    if (!editor.contains(u"tools"))
        for (std::string_view name : kEditorToolNames)
            lock.tools << QLatin1String(name.data(), static_cast<qsizetype>(name.size()));
    if (!editor.contains(u"properties"))
        for (std::string_view name : schema::editorPropertyNames())
            lock.properties << QLatin1String(name.data(), static_cast<qsizetype>(name.size()));
    step.editor = lock;
    return true;
}

/// The step's "allow", when it has one: the controls the student may change.
bool readAllow(JsonReader& in, const QJsonObject& object, const QString& place, LessonStep& step)
{
    if (!object.contains(u"allow"))
        return true;
    QStringList allow;
    if (!readNames(in, object, u"allow", place, schema::stepControlNames(), u"control", allow))
        return false;
    step.allow = allow;
    return true;
}

/// A part of a step (a row of kind Part), by its key, read by its own function.
bool readStepPart(JsonReader& in, std::string_view key, const QJsonObject& object,
                  const QString& place, StepContext& context, LessonStep& step)
{
    if (key == "scene")
        return readScene(in, object, place, context, step);
    if (key == "settings")
        return readSettings(in, object, place, step.settings);
    if (key == "compare")
        return readCompare(in, object, place, step);
    if (key == "plots")
        return readNames(in, object, u"plots", place, kStepPlotNames, u"plot", step.plots);
    if (key == "overlays")
        return readNames(in, object, u"overlays", place, kStepOverlayNames, u"overlay",
                         step.overlays);
    if (key == "panels")
        return readNames(in, object, u"panels", place, kStepPanelNames, u"panel", step.panels);
    if (key == "allow")
        return readAllow(in, object, place, step);
    if (key == "sat")
        return readSat(in, object, place, step.scene, step.sat);
    if (key == "editor")
        return readEditorLock(in, object, place, step);
    if (key == "questions")
        return readQuestions(in, *context.texts, object, place, step, step.questions);
    assert(false && "a step part without a reader");
    return in.fail(joinPlace(place, QString::fromUtf8(key.data(), qsizetype(key.size()))),
                   FileMessages::tr("unknown key"));
}

/// What a step's parts must agree on, once all are read; adds its bodies to `context.bodies`.
bool checkStep(JsonReader& in, const QString& place, StepContext& context, const LessonStep& step)
{
    // Every step keeps its scene: many steps reading one large scene file add up.
    context.bodies += static_cast<qint64>(step.scene.bodies.size());
    if (context.bodies > limits::kMaxLessonBodies) {
        return in.fail(joinPlace(place, u"scene"),
                       FileMessages::tr("the steps up to this one hold %1 bodies in all, more "
                                        "than the limit of %2 for a lesson")
                           .arg(context.bodies)
                           .arg(limits::kMaxLessonBodies));
    }
    for (qsizetype i = 0; i < step.plots.size(); ++i) {
        if (step.plots[i].startsWith(u"compare-") && !step.compare) {
            return in.fail(indexPlace(joinPlace(place, u"plots"), i),
                           FileMessages::tr("\"%1\" plots the worlds of \"compare\", and this "
                                            "step has none")
                               .arg(step.plots[i]));
        }
    }
    const QString exportPlace = joinPlace(place, u"exportTime");
    const double dt = step.settings.get<double>("dt").value_or(step.scene.world.dt);
    if (step.exportTime / dt > kMaxExportSteps) {
        return in.fail(exportPlace,
                       FileMessages::tr("%1 s at a step of %2 s is more than %3 steps")
                           .arg(formatNumber(step.exportTime), formatNumber(dt),
                                QString::number(static_cast<qint64>(kMaxExportSteps))));
    }
    const int panelSat = static_cast<int>(step.panels.indexOf(u"sat"));
    if (panelSat >= 0 && !step.sat) {
        return in.fail(indexPlace(joinPlace(place, u"panels"), panelSat),
                       FileMessages::tr("the \"sat\" panel needs the pair it looks at: add "
                                        "\"sat\": {\"a\": ID, \"b\": ID} to the step"));
    }
    // A question measured after the run stops would need Play again: said, not refused.
    for (std::size_t i = 0; step.endTime && i < step.questions.size(); ++i) {
        const MeasuredQuestion* q = step.questions[i].as<MeasuredQuestion>();
        if (q && q->measure.kind != Measure::Kind::Apex && q->measure.time > *step.endTime)
            in.warn(joinPlace(place, u"endTime"),
                    FileMessages::tr("the run stops at %1 s, before questions[%2] measures at "
                                     "%3 s")
                        .arg(formatNumber(*step.endTime))
                        .arg(i)
                        .arg(formatNumber(q->measure.time)));
    }
    return true;
}

} // namespace

bool readDistinctNames(
    JsonReader& in, const QJsonArray& list, const QString& at,
    const std::function<bool(const QString& name, const QString& itemAt)>& accept, QStringList& out)
{
    for (qsizetype i = 0; i < list.size(); ++i) {
        const QString itemAt = indexPlace(at, i);
        if (!list[i].isString()) {
            return in.fail(itemAt, FileMessages::tr("must be a name \"...\", got ") +
                                       describeJson(list[i]));
        }
        const QString name = list[i].toString();
        if (out.contains(name)) {
            return in.fail(itemAt, FileMessages::tr("\"%1\" is listed twice").arg(name));
        }
        if (!accept(name, itemAt)) {
            return false;
        }
        out.append(name);
    }
    return true;
}

bool readStep(JsonReader& in, const QJsonValue& value, const QString& place, StepContext& context,
              LessonStep& step)
{
    QJsonObject object;
    if (!in.asObject(value, place, object) || !in.checkKeys(object, place, schema::stepKeys())) {
        return false;
    }
    // The rows in the file's order: the texts and plain values as their rows say, each part
    // by its own function.
    for (const schema::StepField& row : schema::stepFields()) {
        const bool ok = row.kind == schema::LessonKind::Part
                            ? readStepPart(in, row.key, object, place, context, step)
                            : readLessonRow(in, *context.texts, row, object, place, step);
        if (!ok)
            return false;
    }
    return checkStep(in, place, context, step);
}

} // namespace rigidlab::lessons::detail
