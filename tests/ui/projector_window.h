// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lab's window as a class sees it on a 1024×768 projector, shown (and active, where keys
// are pressed), with a shipped lesson open: where the keyboard and screen-reader tests start.

#include "lesson_player/lesson_player.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"
#include "window/main_window.h"

#include <QDir>
#include <QString>
#include <QtTest>

namespace rigidlab::test {

/// A shipped lesson's file, by its file name ("restitution.json").
inline QString shippedLessonFile(const char* file)
{
    return QDir(ui::MainWindow::lessonsFolder()).filePath(QLatin1String(file));
}

/// Shows `w` at 1024×768 and lets it do what it does once it is idle, as a screen reader
/// finds it.
inline void showOnProjector(ui::MainWindow& w)
{
    w.fitToScreen(QRect(0, 0, 1024, 768));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QCoreApplication::processEvents();
}

/// Shows `w` at 1024×768 and waits until it is the active window, where key events go;
/// false when it does not become active.
inline bool showActiveOnProjector(ui::MainWindow& w)
{
    w.fitToScreen(QRect(0, 0, 1024, 768));
    w.show();
    w.activateWindow();
    return QTest::qWaitForWindowActive(&w);
}

/// Shows `w` at 1024×768, waits until it is the active window and opens the first lesson;
/// an empty string, or what went wrong.
inline QString openFirstLessonOnProjector(ui::MainWindow& w)
{
    if (!showActiveOnProjector(w))
        return QStringLiteral("the window did not become active");
    return w.openLesson(w.lessonPlayer().firstLessonPath(), true);
}

/// In the welcome scene, the wrecking ball (its second body) chosen with ] ] in the scene and
/// its numbers asked for with Return, as a student without a mouse does: the ball's body,
/// or -1 when the keys chose another.
inline int askWreckingBallNumbers(ui::MainWindow& w)
{
    w.view().setFocus();
    QTest::keyClick(&w.view(), Qt::Key_BracketRight);
    QTest::keyClick(&w.view(), Qt::Key_BracketRight);
    const int body = w.view().selectedBody();
    if (body < 0 || !w.controller().world().body(body).isDynamic())
        return -1;
    QTest::keyClick(&w.view(), Qt::Key_Return);
    return body;
}

} // namespace rigidlab::test
