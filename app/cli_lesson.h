// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// rigidlab-cli lesson: a lesson's outline, or its plots written for handouts without a window.
// Argument handling only; the work is in rigidlab_lessons (loading) and rigidlab_ui (plots).

#include <QStringList>

namespace rigidlab::cli {

/// `lesson LESSON.json [--export DIR]`. Draws with the window's plot widget, so it needs a
/// QApplication (on the offscreen platform: nothing is shown).
int commandLesson(const QStringList& words);

/// `lessons`: the shipped lessons in teaching order, one line each: the file's path, a tab,
/// its title.
int commandLessons(const QStringList& words);

} // namespace rigidlab::cli
