// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// rigidlab-cli lesson: a lesson's outline, or its plots written for handouts without a window.
// Argument handling only; the work is in rigidlab_lessons (loading) and rigidlab_ui (plots).

#include <QStringList>

#include <optional>

namespace rigidlab::cli {

class CommandLine;

/// `lesson LESSON.json|FILE.rlesson [--validate | --export DIR] [--lang CODE]`. Draws with the
/// window's plot widget, so it needs a QApplication (on the offscreen platform: nothing is shown).
int commandLesson(const QStringList& words);

/// `lesson pack LESSON.json -o FILE.rlesson [--author NAME] [--date YYYY-MM-DD]` and
/// `lesson unpack FILE.rlesson -o DIR` (cli_lesson_pack.cpp); nothing when `words` starts
/// with neither.
std::optional<int> commandLessonPacking(const QStringList& words);

/// `lessons`: the shipped lessons in teaching order, one line each: the file's path, a tab,
/// its title.
int commandLessons(const QStringList& words);

} // namespace rigidlab::cli
