// SPDX-License-Identifier: GPL-3.0-or-later
// Lesson files, format v1 (lessons/LESSON_FORMAT.md): reading and checking, the document
// level. As with scenes, the first problem found is the one reported, as
// `FILE: PLACE: what is wrong`, and the checks follow the file's order so that it is the first
// one a reader of the file would meet. A step is read in lesson_step.cpp, its settings and
// comparison in lesson_settings.cpp, its SAT pair and questions in lesson_questions.cpp.

#include "format/lesson.h"

#include "format/json_reader.h"
#include "format/lesson_pack.h"
#include "format/lesson_reading.h"

#include <QFileInfo>

namespace rigidlab::lessons {

using detail::FileMessages;

using detail::indexPlace;
using detail::JsonReader;

namespace {

constexpr int kMaxSteps = 100;
constexpr int kMaxGoals = 20;
constexpr int kMaxMinutes = 1000;
/// The largest teaching-order number a lesson may have.
constexpr int kMaxOrder = 999;
/// The longest one-line description, in characters: it shares a menu line with the title.
constexpr int kMaxDescription = 100;

class LessonReader {
public:
    LessonReader(const QString& sourceName, const QString& absolutePath,
                 const LessonLoadOptions& options)
        : m_in(sourceName),
          m_texts(m_in, options.language,
                  FileMessages::tr("no %1 text (\"%2\") in the whole lesson: it will show in %3"))
    {
        m_lesson.path = absolutePath;
        m_step.folder = QFileInfo(absolutePath).absolutePath();
        m_step.texts = &m_texts;
        m_step.embedded = options.embeddedScenes;
    }

    LessonLoadResult read(const QJsonObject& root);

private:
    bool readSteps(const QJsonObject& root);
    /// The title, in every language it has: not empty.
    bool readTitle(const QJsonObject& root);
    /// The one-line description, in every language it has: one line, short enough for a menu.
    bool readDescription(const QJsonObject& root);

    JsonReader m_in;
    detail::LocalTexts m_texts; ///< reads through m_in, declared after it
    detail::StepContext m_step; ///< the lesson's folder, the bodies of the steps so far
    Lesson m_lesson;
};

bool LessonReader::readTitle(const QJsonObject& root)
{
    if (!m_texts.line(root, u"title", {}, m_lesson.title, true))
        return false;
    for (const detail::LocalTexts::Variant& v : m_texts.variants()) {
        if (v.text.trimmed().isEmpty())
            return m_in.fail(v.place, FileMessages::tr("must not be empty"));
    }
    return true;
}

bool LessonReader::readDescription(const QJsonObject& root)
{
    if (!m_texts.line(root, u"description", {}, m_lesson.description))
        return false;
    for (const detail::LocalTexts::Variant& v : m_texts.variants()) {
        const QString& d = v.text;
        if (d.contains(QLatin1Char('\n')) || d.contains(QLatin1Char('\r')))
            return m_in.fail(v.place,
                             FileMessages::tr("must be one line (it is shown in the lesson menu); "
                                              "put longer text in \"summary\""));
        if (d.size() > kMaxDescription)
            return m_in.fail(v.place,
                             FileMessages::tr("is %1 characters long; at most %2 fit a menu line "
                                              "(put longer text in \"summary\")")
                                 .arg(d.size())
                                 .arg(kMaxDescription));
        if (d.trimmed().isEmpty())
            return m_in.fail(v.place,
                             FileMessages::tr("must not be empty (leave the key out instead)"));
    }
    return true;
}

LessonLoadResult LessonReader::read(const QJsonObject& root)
{
    const bool ok =
        m_in.formatVersion(root, QStringLiteral("rigidlab-lesson"),
                           FileMessages::tr("a lesson file"), kLessonFormatVersion) &&
        m_in.checkKeys(root, {},
                       {u"rigidlab-lesson", u"title", u"summary", u"level", u"minutes", u"order",
                        u"description", u"goals", u"steps"}) &&
        readTitle(root) && m_texts.line(root, u"summary", {}, m_lesson.summary) &&
        m_texts.line(root, u"level", {}, m_lesson.level) &&
        m_in.integer(root, u"minutes", {}, m_lesson.minutes, 0, kMaxMinutes) &&
        m_in.integer(root, u"order", {}, m_lesson.order, 1, kMaxOrder) && readDescription(root) &&
        m_texts.list(root, u"goals", {}, kMaxGoals, u"goals", m_lesson.goals) && readSteps(root);
    if (ok) {
        m_texts.warnMissing();
    }
    LessonLoadResult result;
    result.warnings = m_in.warnings();
    if (!ok) {
        result.error = m_in.error();
        return result;
    }
    result.ok = true;
    result.lesson = std::move(m_lesson);
    return result;
}

bool LessonReader::readSteps(const QJsonObject& root)
{
    const QString place = QStringLiteral("steps");
    if (!root.contains(u"steps")) {
        return m_in.fail(place, FileMessages::tr("required, but missing"));
    }
    QJsonArray steps;
    if (!m_in.asArray(root.value(u"steps"), place, steps)) {
        return false;
    }
    if (steps.isEmpty() || steps.size() > kMaxSteps) {
        return m_in.fail(place, FileMessages::tr("a lesson needs 1 to %1 steps, got %2")
                                    .arg(kMaxSteps)
                                    .arg(steps.size()));
    }
    for (qsizetype i = 0; i < steps.size(); ++i) {
        LessonStep step;
        if (!detail::readStep(m_in, steps[i], indexPlace(place, i), m_step, step)) {
            return false;
        }
        m_lesson.steps.push_back(std::move(step));
    }
    return true;
}

} // namespace

LessonLoadResult loadLessonObject(const QJsonObject& root, const QString& path,
                                  const LessonLoadOptions& options)
{
    return LessonReader(path, QFileInfo(path).absoluteFilePath(), options).read(root);
}

LessonLoadResult loadLessonJson(const QByteArray& bytes, const QString& path,
                                const LessonLoadOptions& options)
{
    if (isLessonPackPath(path)) {
        return loadLessonPack(bytes, path, options);
    }
    const detail::ParsedJson parsed = detail::parseJson(bytes, path, kMaxLessonFileBytes);
    if (!parsed.ok) {
        LessonLoadResult result;
        result.error = parsed.error;
        return result;
    }
    if (!parsed.document.isObject()) {
        LessonLoadResult result;
        result.error =
            path + FileMessages::tr(": the top level must be an object {...}, got an array");
        return result;
    }
    return loadLessonObject(parsed.document.object(), path, options);
}

LessonLoadResult loadLessonFile(const QString& path, const LessonLoadOptions& options)
{
    const detail::FileBytes file = detail::readFileBytes(
        path, isLessonPackPath(path) ? kMaxLessonPackBytes : kMaxLessonFileBytes);
    if (!file.ok) {
        LessonLoadResult result;
        result.error = file.error;
        return result;
    }
    return loadLessonJson(file.bytes, path, options);
}

} // namespace rigidlab::lessons
