// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A class's hand-ins collected from one folder: every answers file in it
// ("*.answers.json", as the window's Hand in names them) read with the answers reader
// (format/answers_file.h) and judged into one table per lesson (class_table.h). A file that
// does not read, that answers another lesson, or that does not fit its lesson is left out with
// one line "FILE: what is wrong"; the rest of the class is still collected.

#include "results/class_table.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace rigidlab::lessons {

/// The names of the files read in a folder.
inline constexpr char16_t kAnswersFilePattern[] = u"*.answers.json";

struct HandedIn {
    QString file; ///< its name, without the folder
    Answers answers;
};

struct ClassFolder {
    bool ok = false;
    QString error;              ///< the folder is missing or unreadable
    std::vector<HandedIn> read; ///< by file name
    QStringList damaged;        ///< one line each: "FILE: PLACE: what is wrong"
    int files = 0;              ///< answers files found, read or not
};

/// Reads every answers file of `folder`.
ClassFolder readClassFolder(const QString& folder);

/// Which lessons to collect.
struct ClassOptions {
    /// The lesson file to judge by; empty: each lesson is looked up by the file name its
    /// answers name, among the shipped lessons and the user's own (lesson_catalog.h).
    QString lessonPath;
    /// The lesson to collect when lessonPath is empty (a file name, "restitution.json");
    /// empty: the one most answers files name (the first by name on a tie).
    QString lessonFile;
    /// Collect every lesson the folder holds answers to, a table each, instead of leaving the
    /// other lessons' files out.
    bool allLessons = false;
};

struct ClassCollection {
    bool ok = false;
    QString error; ///< nothing to collect: the folder, no answers files, the lesson
    std::vector<ClassTable> tables; ///< the lesson asked for first
    /// One line per file left out: damaged, of another lesson, not fitting its lesson.
    QStringList skipped;
    /// Every lesson the folder's answers name (file names), the most answered first.
    QStringList lessonFiles;
    /// Their titles, in the same order, as the first answers file of each names it (in the
    /// language that student played it in).
    QStringList lessonTitles;
};

ClassCollection collectClass(const QString& folder, const ClassOptions& options = {});

} // namespace rigidlab::lessons
