// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lab's window as a class sees it on a 1024×768 projector, shown and active, with the
// first shipped lesson open: where the keyboard and screen-reader tests start.

#include "lesson_player/lesson_player.h"
#include "window/main_window.h"

#include <QString>
#include <QtTest>

namespace rigidlab::test {

/// Shows `w` at 1024×768, waits until it is the active window and opens the first lesson;
/// an empty string, or what went wrong.
inline QString openFirstLessonOnProjector(ui::MainWindow& w)
{
    w.fitToScreen(QRect(0, 0, 1024, 768));
    w.show();
    w.activateWindow();
    if (!QTest::qWaitForWindowActive(&w))
        return QStringLiteral("the window did not become active");
    return w.openLesson(w.lessonPlayer().firstLessonPath(), true);
}

} // namespace rigidlab::test
