// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A lesson in one file (.rlesson, format v1, lessons/format/RLESSON_FORMAT.md): the lesson
// with every scene its steps use carried inside it, so that a teacher can mail it or put it on
// a shared drive as one thing. It is read by the lesson loader itself (loadLessonFile and
// loadLessonJson recognise the suffix), so the player, judging and export take it as they take
// a lesson folder.
//
// Packing reads a lesson file and the scene files it names, and writes their JSON as it is,
// each scene under "scenes/NAME.json"; unpacking writes that lesson and those scenes back as
// files, so unpack → pack gives the same bytes.

#include "format/lesson.h"

#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <map>

namespace rigidlab::lessons {

/// The version this lab reads and writes (the value of the top-level key
/// "rigidlab-lesson-file").
inline constexpr int kLessonPackFormatVersion = 1;
/// The largest .rlesson read [bytes]: a lesson and up to 100 scenes.
inline constexpr qint64 kMaxLessonPackBytes = 32 * 1024 * 1024;
/// The most scenes one file carries (a lesson has at most 100 steps).
inline constexpr int kMaxPackedScenes = 100;

/// True for a path ending in ".rlesson" (in any case).
bool isLessonPackPath(const QString& path);

/// True for a file the window opens as a lesson rather than a scene: a .rlesson, or JSON whose
/// top level holds "rigidlab-lesson". (Anything else is tried as a scene, whose loader says
/// what is wrong.)
bool isLessonDocument(const QString& path);

/// Who made the file and when; both may be empty.
struct LessonPackInfo {
    QString author; ///< free text, one line
    QString date;   ///< YYYY-MM-DD
};

/// What a .rlesson holds, its JSON as written.
struct LessonPack {
    LessonPackInfo info;
    QJsonObject lesson;                    ///< a lesson document ("rigidlab-lesson": 1, ...)
    std::map<QString, QJsonObject> scenes; ///< "scenes/NAME.json" → a scene document
};

struct LessonPackResult {
    bool ok = false;
    QString error;        ///< one line `FILE: PLACE: what is wrong`
    QStringList warnings; ///< same form
    LessonPack pack;
};

/// Gathers the lesson file at `lessonPath` (a lesson folder's .json, or a .rlesson) and the
/// scenes it names into one pack, after checking that the lesson loads. Scene paths become
/// "scenes/NAME.json" (NAME-2.json, … when two folders hold a file of one name).
LessonPackResult packLesson(const QString& lessonPath, const LessonPackInfo& info = {});

/// The bytes of a .rlesson: indented JSON, keys in order, the same pack always the same bytes.
QByteArray lessonPackBytes(const LessonPack& pack);

/// Reads the structure of a .rlesson (its version, keys, scene names), without loading the
/// lesson; `path` names it in messages.
LessonPackResult readLessonPack(const QByteArray& bytes, const QString& path);
/// The same for a document already parsed (one whose top level holds "rigidlab-lesson-file").
LessonPackResult readLessonPackObject(const QJsonObject& root, const QString& path);

/// Reads and checks a .rlesson as a lesson, every scene in `options.language`: what
/// loadLessonFile returns for a path ending in .rlesson. Places inside the lesson are named
/// `lesson.steps[2]...`, inside a scene `scenes["scenes/NAME.json"].bodies[0]...`.
LessonLoadResult loadLessonPack(const QByteArray& bytes, const QString& path,
                                const LessonLoadOptions& options = {});
/// The same for a pack already read by readLessonPack.
LessonLoadResult loadLessonPack(const LessonPack& pack, const QString& path,
                                const LessonLoadOptions& options = {});

/// Writes `pack` as files in `folder` (made if missing): the lesson as BASENAME.json, its
/// scenes under scenes/; each file written whole (atomic_file.h). `written` gets the paths.
/// Returns empty on success, else one line saying what could not be written.
QString unpackLesson(const LessonPack& pack, const QString& folder, const QString& baseName,
                     QStringList& written);

} // namespace rigidlab::lessons
