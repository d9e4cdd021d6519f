// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_editor/lesson_draft.h"

#include "format/atomic_file.h"
#include "format/data_dirs.h"
#include "format/languages.h"
#include "format/lesson_schema.h"
#include "format/scene_loader.h"
#include "format/scene_writer.h"

#include <QDate>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QRegularExpression>
#include <QUndoCommand>
#include <QUndoStack>

#include <set>

namespace rigidlab::ui {

namespace {

/// A text value as the editor shows it: paragraphs (a list of lines) joined by line breaks.
QString joinText(const QJsonValue& v)
{
    if (v.isString())
        return v.toString();
    QStringList lines;
    for (const QJsonValue& line : v.toArray())
        lines.append(line.toString());
    return lines.join(u'\n');
}

/// The scenes the steps name, and no other: an edit that drops a step drops its scene.
void pruneScenes(lessons::LessonPack& pack)
{
    std::set<QString> used;
    for (const QJsonValue& step : pack.lesson.value(u"steps").toArray())
        if (step.toObject().value(u"scene").isString())
            used.insert(step.toObject().value(u"scene").toString());
    for (auto it = pack.scenes.begin(); it != pack.scenes.end();)
        it = used.count(it->first) ? std::next(it) : pack.scenes.erase(it);
}

bool isShippedFile(const QString& path)
{
    const QString shipped = QFileInfo(lessons::shippedDataDir()).canonicalFilePath();
    const QString file = QFileInfo(path).canonicalFilePath();
    return !shipped.isEmpty() && file.startsWith(shipped + u'/');
}

} // namespace

/// One edit: the lesson before and after. Typing into one text merges into one edit.
class LessonDraft::Edit : public QUndoCommand {
public:
    Edit(LessonDraft& draft, lessons::LessonPack before, lessons::LessonPack after,
         const QString& name, int mergeId)
        : QUndoCommand(name), m_draft(draft), m_before(std::move(before)),
          m_after(std::move(after)), m_mergeId(mergeId)
    {
    }
    void redo() override { set(m_after); }
    void undo() override { set(m_before); }
    int id() const override { return m_mergeId; }
    bool mergeWith(const QUndoCommand* other) override
    {
        if (other->id() != id())
            return false;
        m_after = static_cast<const Edit*>(other)->m_after;
        return true;
    }

private:
    void set(const lessons::LessonPack& pack)
    {
        m_draft.m_pack = pack;
        emit m_draft.changed();
    }
    LessonDraft& m_draft;
    lessons::LessonPack m_before;
    lessons::LessonPack m_after;
    int m_mergeId;
};

LessonDraft::LessonDraft(QObject* parent) : QObject(parent), m_undo(new QUndoStack(this)) {}

void LessonDraft::newLesson(const QString& title, const lessons::Scene& scene)
{
    const QString language = lessons::lessonLanguage();
    QJsonObject step{
        {QStringLiteral("title"), QJsonObject{{language, tr("Step 1")}}},
        {QStringLiteral("scene"), QJsonDocument::fromJson(lessons::sceneToJson(scene)).object()},
        {QStringLiteral("autoplay"), false}};
    m_pack = {};
    m_pack.lesson = QJsonObject{{QStringLiteral("rigidlab-lesson"), lessons::kLessonFormatVersion},
                                {QStringLiteral("title"), QJsonObject{{language, title}}},
                                {QStringLiteral("steps"), QJsonArray{step}}};
    m_path.clear();
    m_undo->clear();
    emit changed();
}

QString LessonDraft::open(const QString& path)
{
    const lessons::LessonPackResult packed = lessons::packLesson(path);
    if (!packed.ok)
        return packed.error;
    m_pack = packed.pack;
    // A folder's lesson becomes a .rlesson of its own, a shipped one a copy: Save asks where.
    m_path = lessons::isLessonPackPath(path) && !isShippedFile(path)
                 ? QFileInfo(path).absoluteFilePath()
                 : QString();
    m_undo->clear();
    emit changed();
    return {};
}

QString LessonDraft::openKept(const QString& path)
{
    const QString error = open(path);
    if (!error.isEmpty())
        return error;
    m_path.clear();
    m_undo->resetClean(); // no state of it is saved anywhere but in the autosave
    emit changed();
    return {};
}

bool LessonDraft::isModified() const
{
    return !m_undo->isClean();
}

int LessonDraft::stepCount() const
{
    return static_cast<int>(stepArray().size());
}

QJsonObject LessonDraft::stepObject(int index) const
{
    return stepArray().at(index).toObject();
}

QJsonValue LessonDraft::value(int step, const QString& key) const
{
    return (step < 0 ? m_pack.lesson : stepObject(step)).value(key);
}

QString LessonDraft::text(int step, const QString& key, const QString& language) const
{
    const QJsonValue v = value(step, key);
    if (v.isObject())
        return joinText(v.toObject().value(language));
    // A plain string (or list of lines) is English.
    return language == lessons::kFallbackLanguage ? joinText(v) : QString();
}

QStringList LessonDraft::missingLanguages(int step, const QString& key) const
{
    QStringList missing;
    bool any = false;
    for (const lessons::Language& l : lessons::kLanguages) {
        const QString code = l.code.toString();
        if (text(step, key, code).trimmed().isEmpty())
            missing.append(code);
        else
            any = true;
    }
    return any ? missing : QStringList();
}

void LessonDraft::apply(const lessons::LessonPack& after, const QString& name, int mergeId)
{
    lessons::LessonPack pruned = after;
    pruneScenes(pruned);
    m_undo->push(new Edit(*this, m_pack, pruned, name, mergeId));
}

QJsonArray LessonDraft::stepArray() const
{
    return m_pack.lesson.value(u"steps").toArray();
}

void LessonDraft::applySteps(const QJsonArray& steps, const QString& name)
{
    lessons::LessonPack next = m_pack;
    next.lesson.insert(QStringLiteral("steps"), steps);
    apply(next, name);
}

lessons::LessonPack LessonDraft::withValue(int step, const QString& key, const QJsonValue& v) const
{
    lessons::LessonPack after = m_pack;
    if (step < 0) {
        v.isNull() ? after.lesson.remove(key) : void(after.lesson.insert(key, v));
        return after;
    }
    QJsonArray steps = stepArray();
    QJsonObject object = steps.at(step).toObject();
    v.isNull() ? object.remove(key) : void(object.insert(key, v));
    steps[step] = object;
    after.lesson.insert(QStringLiteral("steps"), steps);
    return after;
}

void LessonDraft::setValue(int step, const QString& key, const QJsonValue& v, const QString& name)
{
    apply(withValue(step, key, v), name);
}

void LessonDraft::setText(int step, const QString& key, const QString& language,
                          const QString& newText)
{
    const QJsonValue old = value(step, key);
    QJsonObject texts = old.isObject() ? old.toObject() : QJsonObject();
    if (!old.isObject() && !old.isNull() && !old.isUndefined())
        texts.insert(lessons::kFallbackLanguage.toString(), old); // a plain text was English
    if (newText.isEmpty()) {
        texts.remove(language);
    } else if (key == u"text" && newText.contains(u'\n')) {
        texts.insert(language, QJsonArray::fromStringList(newText.split(u'\n')));
    } else {
        texts.insert(language, newText);
    }
    const QJsonValue v = texts.isEmpty() ? QJsonValue() : QJsonValue(texts);
    // One undo step for a run of typing into one text.
    const int mergeId = static_cast<int>(
        qHash(QStringLiteral("%1/%2/%3").arg(step).arg(key, language)) & 0x7fffffff);
    apply(withValue(step, key, v), tr("Edit text"), mergeId);
}

void LessonDraft::addStep(int after)
{
    QJsonArray steps = stepArray();
    const int at = std::clamp(after + 1, 0, static_cast<int>(steps.size()));
    // The new step starts from the scene of the step before it (the first step's for a new
    // first step).
    const QJsonValue scene =
        steps.isEmpty() ? QJsonValue() : steps.at(std::max(at - 1, 0)).toObject().value(u"scene");
    // A new step waits for Play, as every shipped one does: the class reads and predicts first.
    QJsonObject step{{QStringLiteral("title"),
                      QJsonObject{{lessons::lessonLanguage(), tr("Step %1").arg(at + 1)}}},
                     {QStringLiteral("autoplay"), false}};
    if (!scene.isUndefined())
        step.insert(QStringLiteral("scene"), scene);
    steps.insert(at, step);
    applySteps(steps, tr("Add step"));
}

void LessonDraft::removeStep(int index)
{
    QJsonArray steps = stepArray();
    if (index < 0 || index >= steps.size())
        return;
    steps.removeAt(index);
    applySteps(steps, tr("Remove step"));
}

void LessonDraft::moveStep(int from, int to)
{
    QJsonArray steps = stepArray();
    if (from < 0 || from >= steps.size() || to < 0 || to >= steps.size() || from == to)
        return;
    const QJsonValue moved = steps.takeAt(from);
    steps.insert(to, moved);
    applySteps(steps, tr("Move step"));
}

void LessonDraft::duplicateStep(int index)
{
    QJsonArray steps = stepArray();
    if (index < 0 || index >= steps.size())
        return;
    steps.insert(index + 1, steps.at(index));
    applySteps(steps, tr("Duplicate step"));
}

void LessonDraft::setStepScene(int index, const lessons::Scene& scene)
{
    setValue(index, QStringLiteral("scene"),
             QJsonDocument::fromJson(lessons::sceneToJson(scene)).object(), tr("Set scene"));
}

QJsonObject LessonDraft::sceneObject(int step) const
{
    const QJsonValue ref = value(step, QStringLiteral("scene"));
    if (ref.isObject())
        return ref.toObject();
    const auto packed = m_pack.scenes.find(ref.toString());
    return packed != m_pack.scenes.end() ? packed->second : QJsonObject();
}

std::optional<lessons::Scene> LessonDraft::stepScene(int step, const QString& language,
                                                     QString& error) const
{
    // The scene alone: a text of the lesson not yet written, or any other problem elsewhere in
    // it, does not keep the teacher from drawing the step's scene.
    const QJsonObject object = sceneObject(step);
    if (object.isEmpty()) {
        error = tr("Step %1 has no scene yet.").arg(step + 1);
        return std::nullopt;
    }
    const lessons::SceneLoadResult r = lessons::loadSceneObject(
        object, tr("step %1's scene").arg(step + 1), lessons::SceneLoadOptions{language});
    if (!r.ok) {
        error = r.error;
        return std::nullopt;
    }
    return r.scene;
}

void LessonDraft::setAuthor(const QString& author)
{
    lessons::LessonPack next = m_pack;
    next.info.author = author;
    apply(next, tr("Set author"));
}

LessonDraft::Check LessonDraft::check(const QString& language) const
{
    const QString name = m_path.isEmpty() ? tr("new lesson.rlesson") : m_path;
    lessons::LessonLoadOptions options;
    options.language = language;
    const lessons::LessonLoadResult r = lessons::loadLessonPack(m_pack, name, options);
    Check check;
    check.error = r.error;
    check.warnings = r.warnings;
    static const QRegularExpression stepPlace(QStringLiteral(": lesson\\.steps\\[(\\d+)\\]"));
    QStringList lines = r.warnings;
    if (!r.ok)
        lines.prepend(r.error);
    for (const QString& line : lines) {
        const QRegularExpressionMatch m = stepPlace.match(line);
        check.steps.append(m.hasMatch() ? m.captured(1).toInt() : -1);
    }
    return check;
}

QByteArray LessonDraft::runKey() const
{
    QJsonArray steps;
    for (const QJsonValue& v : m_pack.lesson.value(u"steps").toArray()) {
        const QJsonObject step = v.toObject();
        // The fields the runs depend on, as the lesson schema's rows say.
        QJsonObject run;
        for (const lessons::schema::StepField& row : lessons::schema::stepFields()) {
            const QString key = QString::fromUtf8(row.key.data(), qsizetype(row.key.size()));
            if (row.run)
                run.insert(key, step.value(key));
        }
        // A scene named by its file is the pack's copy of that file.
        const QJsonValue scene = step.value(u"scene");
        const auto packed = m_pack.scenes.find(scene.toString());
        run.insert(QStringLiteral("scene"),
                   packed != m_pack.scenes.end() ? QJsonValue(packed->second) : scene);
        steps.append(run);
    }
    return QJsonDocument(steps).toJson(QJsonDocument::Compact);
}

std::optional<lessons::Lesson> LessonDraft::lesson(const QString& language, QString& error) const
{
    lessons::LessonLoadOptions options;
    options.language = language;
    const lessons::LessonLoadResult r = lessons::loadLessonPack(
        m_pack, m_path.isEmpty() ? tr("new lesson.rlesson") : m_path, options);
    if (!r.ok) {
        error = r.error;
        return std::nullopt;
    }
    return r.lesson;
}

QString LessonDraft::save()
{
    if (m_path.isEmpty())
        return tr("The lesson has no file yet: use Save As.");
    return saveAs(m_path);
}

QString LessonDraft::saveAs(const QString& path)
{
    if (!lessons::isLessonPackPath(path))
        return tr("%1: a lesson is saved as one file ending in .rlesson").arg(path);
    if (isShippedFile(path))
        return tr("%1 comes with RigidLab and is not overwritten.").arg(path);
    lessons::LessonPack dated = m_pack;
    if (isModified() || path != m_path || dated.info.date.isEmpty())
        dated.info.date = QDate::currentDate().toString(Qt::ISODate);
    const QString error = lessons::writeFileAtomically(path, lessons::lessonPackBytes(dated));
    if (!error.isEmpty())
        return error;
    m_pack.info.date = dated.info.date;
    m_path = QFileInfo(path).absoluteFilePath();
    m_undo->setClean();
    emit changed();
    return {};
}

QString LessonDraft::writeCopy(const QString& path) const
{
    return lessons::writeFileAtomically(path, lessons::lessonPackBytes(m_pack));
}

} // namespace rigidlab::ui
