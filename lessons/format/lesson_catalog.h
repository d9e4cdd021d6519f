// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The shipped lessons in the order they are taught, then the user's own (userLessonsDir(),
// data_dirs.h). Each lesson file may give its place ("order"), a one-line description and its
// duration ("minutes"); the lesson menu lists them numbered, "1. Title — description (≈N min)",
// the user's own marked as such, and a start page opens the first shipped one.

#include <QString>

#include <vector>

namespace rigidlab::lessons {

/// What a lesson menu shows of one lesson.
struct LessonEntry {
    QString path; ///< absolute
    QString title;
    QString description; ///< one line, may be empty
    int order = 0;       ///< the file's "order"; 0: not given
    int minutes = 0;     ///< estimated time [min]; 0: not given
    bool own = false;    ///< one of the user's own lessons, not a shipped one
    QString author;      ///< who made it (a .rlesson's "author"); may be empty
    QString date; ///< YYYY-MM-DD: an own .rlesson's "date", else the file's; empty for the rest
};

/// The lessons of `folder` that load (lesson files *.json and lessons in one file *.rlesson),
/// in teaching order: by their "order", then those without
/// one, each group by file name. A file that does not load is left out (the tests check that
/// every shipped one loads).
std::vector<LessonEntry> lessonsInOrder(const QString& folder);

/// lessonsInOrder(shippedLessonsDir()) (data_dirs.h): the first one is where a newcomer starts.
std::vector<LessonEntry> shippedLessonsInOrder();

/// What the lesson menu lists: shippedLessonsInOrder(), then the user's own lessons
/// (lessonsInOrder(userLessonsDir()), then of each added folder), each marked `own`, with its
/// author and date.
std::vector<LessonEntry> allLessonsInOrder();

/// The folders of lessons the user added (a shared drive, say), kept in the settings under
/// "lessons/folders"; each is listed after the data folder's own lessons.
QStringList addedLessonFolders();
/// Adds `folder` (absolute) to them, once; false when it was there already.
bool addLessonFolder(const QString& folder);
/// Removes `folder` from them; false when it was not there.
bool removeLessonFolder(const QString& folder);

/// The menu line of the lesson at 1-based `position` in the teaching order:
/// "1. Title — description (≈N min)", the parts that are not given left out; a lesson of the
/// user's own ends in "(your own)".
QString lessonMenuText(const LessonEntry& entry, int position);

} // namespace rigidlab::lessons
