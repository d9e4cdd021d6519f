// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lessons the lab ships, as the window finds them: what the window tests walk through.

#include "lesson_player/lesson_player.h"
#include "window/main_window.h"

#include "format/lesson.h"

#include "step_walk.h"

#include <QCoreApplication>
#include <QDir>
#include <QStringList>
#include <QtTest>

namespace rigidlab::test {

inline QStringList shippedLessons()
{
    const QDir dir(ui::MainWindow::lessonsFolder());
    QStringList out;
    for (const QString& f : dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name))
        out << dir.filePath(f);
    return out;
}

/// Opens every shipped lesson in `w` and goes to each of its steps that the walk visits (every
/// step, but in the sanitizer pass: step_walk.h) in turn, its events processed, then calls
/// visit(path, index, step) there. False as soon as a lesson does not open or a check in
/// `visit` fails (QTest has recorded it): the test should stop then.
template <typename Visit>
bool visitShippedSteps(ui::MainWindow& w, Visit visit)
{
    StepWalk walk;
    for (const QString& path : shippedLessons()) {
        if (!QTest::qCompare(w.openLesson(path, true), QString(), "w.openLesson(path, true)",
                             "QString()", __FILE__, __LINE__))
            return false;
        const int count = static_cast<int>(w.lessonPlayer().lesson()->steps.size());
        for (int i = 0; i < count; ++i) {
            if (!walk.visits(w.lessonPlayer().lesson()->steps[static_cast<std::size_t>(i)], i))
                continue;
            w.lessonPlayer().goToStep(i);
            QCoreApplication::processEvents();
            visit(path, i, w.lessonPlayer().lesson()->steps[static_cast<std::size_t>(i)]);
            if (QTest::currentTestFailed())
                return false;
        }
    }
    return true;
}

} // namespace rigidlab::test
