// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/document.h"

#include "format/json_reader.h"

#include "format/lesson.h"
#include "format/lesson_pack.h"
#include "format/scene_loader.h"

#include <QJsonObject>

#include <array>

namespace rigidlab::lessons {

QString countNoun(qsizetype n, QStringView one, QStringView many)
{
    return QString::number(n) + u' ' + (n == 1 ? one : many).toString();
}

namespace {

DocumentCheck checkScene(const QJsonObject& root, const QString& sourceName)
{
    SceneLoadResult loaded = loadSceneObject(root, sourceName);
    DocumentCheck check;
    check.kind = QStringLiteral("scene");
    check.ok = loaded.ok;
    check.error = loaded.error;
    check.warnings = loaded.warnings;
    if (loaded.ok) {
        check.summary =
            countNoun(static_cast<qsizetype>(loaded.scene.bodies.size()), u"body", u"bodies") +
            QStringLiteral(", ") +
            countNoun(static_cast<qsizetype>(loaded.scene.springs.size()), u"spring", u"springs") +
            QStringLiteral(", ") +
            countNoun(static_cast<qsizetype>(loaded.scene.joints.size()), u"joint", u"joints");
    }
    return check;
}

DocumentCheck lessonCheck(const LessonLoadResult& loaded)
{
    DocumentCheck check;
    check.kind = QStringLiteral("lesson");
    check.ok = loaded.ok;
    check.error = loaded.error;
    check.warnings = loaded.warnings;
    if (loaded.ok) {
        qsizetype questions = 0;
        qsizetype plots = 0;
        for (const LessonStep& step : loaded.lesson.steps) {
            questions += static_cast<qsizetype>(step.questions.size());
            plots += step.plots.size();
        }
        check.summary =
            QStringLiteral("lesson \"%1\": ").arg(loaded.lesson.title) +
            countNoun(static_cast<qsizetype>(loaded.lesson.steps.size()), u"step", u"steps") +
            QStringLiteral(", ") + countNoun(questions, u"question", u"questions") +
            QStringLiteral(", ") + countNoun(plots, u"plot", u"plots");
    }
    return check;
}

DocumentCheck checkLessonPack(const QJsonObject& root, const QString& sourceName)
{
    const LessonPackResult read = readLessonPackObject(root, sourceName);
    if (!read.ok) {
        DocumentCheck check;
        check.kind = QStringLiteral("lesson");
        check.error = read.error;
        return check;
    }
    DocumentCheck check = lessonCheck(loadLessonPack(read.pack, sourceName));
    if (check.ok)
        check.summary +=
            QStringLiteral(", ") + countNoun(static_cast<qsizetype>(read.pack.scenes.size()),
                                             u"scene inside", u"scenes inside");
    return check;
}

DocumentCheck checkLesson(const QJsonObject& root, const QString& sourceName)
{
    return lessonCheck(loadLessonObject(root, sourceName));
}

/// A kind of document: the top-level key that holds its format version, and its checker.
struct DocumentKind {
    QStringView versionKey;
    QStringView name;
    DocumentCheck (*check)(const QJsonObject& root, const QString& sourceName);
};

// A new kind of document is one more row here.
constexpr std::array kKinds = {
    DocumentKind{u"rigidlab", u"a scene", &checkScene},
    DocumentKind{u"rigidlab-lesson", u"a lesson", &checkLesson},
    DocumentKind{u"rigidlab-lesson-file", u"a lesson in one file (.rlesson)", &checkLessonPack},
};

/// The largest document of any kind [bytes].
constexpr qint64 kMaxDocumentBytes = kMaxLessonPackBytes;

} // namespace

DocumentCheck checkDocumentFile(const QString& path)
{
    DocumentCheck check;
    const detail::FileBytes file = detail::readFileBytes(path, kMaxDocumentBytes);
    if (!file.ok) {
        check.error = file.error;
        return check;
    }
    const detail::ParsedJson parsed = detail::parseJson(file.bytes, path, kMaxDocumentBytes);
    if (!parsed.ok) {
        check.error = parsed.error;
        return check;
    }
    if (!parsed.document.isObject()) {
        check.error =
            path + QStringLiteral(": the top level must be an object {...}, got an array");
        return check;
    }
    const QJsonObject root = parsed.document.object();
    QStringList expected;
    for (const DocumentKind& kind : kKinds) {
        if (root.contains(kind.versionKey)) {
            return kind.check(root, path);
        }
        expected.append(QStringLiteral("\"%1\" for %2").arg(kind.versionKey, kind.name));
    }
    check.error = path + QStringLiteral(": not a RigidLab document: no format version key (%1)")
                             .arg(expected.join(u", "));
    return check;
}

} // namespace rigidlab::lessons
