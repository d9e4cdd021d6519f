// SPDX-License-Identifier: GPL-3.0-or-later
// The menu bar takes the keyboard only when asked (Alt alone), and then shows where it is: a
// chord's Alt (Alt+→ for the next step) leaves no focus in it, in whatever order and however
// often the keys come, and it never holds the focus with no title highlighted.

#include "lesson_player/lesson_player.h"
#include "window/main_window.h"

#include <QApplication>
#include <QMenu>
#include <QMenuBar>
#include <QWindow>
#include <QtTest>

#include "projector_window.h"
#include "test_main.h"

using namespace rigidlab;
using rigidlab::ui::MainWindow;

namespace {

QWidget* focused(QWidget& window)
{
    QWidget* f = QApplication::focusWidget();
    return f ? f : &window;
}

} // namespace

class TestMenuBarFocus : public QObject {
    Q_OBJECT
private slots:
    /// Alt used with an arrow for the next step leaves no focus in the menu bar, however long
    /// Alt is held (its key repeats while the step is set up) and in whatever order the keys
    /// come back (a screen reader's bridge hands them back late): Alt alone, pressed and
    /// released, still opens it.
    void altArrowLeavesTheMenuBarAlone_data()
    {
        QTest::addColumn<bool>("altRepeats");
        QTest::addColumn<bool>("rightReleasedLast");
        QTest::addColumn<bool>("altSeenAgain");
        QTest::newRow("tapped") << false << false << false;
        QTest::newRow("Alt held, repeating") << true << false << false;
        QTest::newRow("Alt let go first") << false << true << false;
        QTest::newRow("Alt held, let go first") << true << true << false;
        // Alt's press comes again after the chord, as it does when the window gets the
        // keyboard back with Alt down: Qt arms its menu bar anew.
        QTest::newRow("Alt seen again") << false << true << true;
    }
    void altArrowLeavesTheMenuBarAlone()
    {
        QFETCH(bool, altRepeats);
        QFETCH(bool, rightReleasedLast);
        QFETCH(bool, altSeenAgain);
        MainWindow w;
        QCOMPARE(test::openFirstLessonOnProjector(w), QString());
        ui::LessonPlayer& player = w.lessonPlayer();
        QCoreApplication::processEvents();
        QWidget* menuBar = w.menuWidget();
        QVERIFY(menuBar != nullptr);
        const int at = player.stepIndex();
        // As the platform sends them, to the window (through its shortcut map): Alt's own
        // press without the modifier, everything after it with Alt down.
        QWindow* window = w.windowHandle();
        const auto send = [window](bool press, Qt::Key k, Qt::KeyboardModifiers mods,
                                   bool repeat = false) {
            QTest::simulateEvent(window, press, k, mods, QString(), repeat);
            QCoreApplication::processEvents();
        };
        send(true, Qt::Key_Alt, Qt::NoModifier);
        send(true, Qt::Key_Right, Qt::AltModifier);
        QCOMPARE(player.stepIndex(), at + 1);
        if (altRepeats)
            for (int i = 0; i < 3; ++i)
                send(true, Qt::Key_Alt, Qt::AltModifier, true);
        if (altSeenAgain)
            send(true, Qt::Key_Alt, Qt::NoModifier);
        if (!rightReleasedLast)
            send(false, Qt::Key_Right, Qt::AltModifier);
        send(false, Qt::Key_Alt, Qt::AltModifier);
        if (rightReleasedLast)
            send(false, Qt::Key_Right, Qt::NoModifier);
        QCoreApplication::processEvents();
        QTest::qWait(20); // the step's text takes the focus from a zero timer
        QVERIFY2(!menuBar->hasFocus(), focused(w)->metaObject()->className());
        // Tab goes on among the window's controls, not along the menu titles.
        QTest::keyClick(focused(w), Qt::Key_Tab);
        QCoreApplication::processEvents();
        QVERIFY2(QApplication::focusWidget() && QApplication::focusWidget() != menuBar,
                 focused(w)->metaObject()->className());
        // Alt alone still opens the menu bar for the keyboard (and Esc leaves it).
        send(true, Qt::Key_Alt, Qt::NoModifier);
        send(false, Qt::Key_Alt, Qt::AltModifier);
        QVERIFY(menuBar->hasFocus());
        QVERIFY(qobject_cast<QMenuBar*>(menuBar)->activeAction() != nullptr);
        QTest::keyClick(focused(w), Qt::Key_Escape);
        QCoreApplication::processEvents();
        QVERIFY(!menuBar->hasFocus());
        // The menu bar holding the focus with no title highlighted gives it back.
        QWidget* before = QApplication::focusWidget();
        QVERIFY(before != nullptr);
        menuBar->setFocus(Qt::MenuBarFocusReason);
        QTest::qWait(20);
        QVERIFY2(!menuBar->hasFocus(), focused(w)->metaObject()->className());
        QCOMPARE(QApplication::focusWidget(), before);
        // Alt and a menu's letter open the menu, and it stays open.
        send(true, Qt::Key_Alt, Qt::NoModifier);
        send(true, Qt::Key_F, Qt::AltModifier);
        send(false, Qt::Key_F, Qt::AltModifier);
        send(false, Qt::Key_Alt, Qt::AltModifier);
        QTest::qWait(20);
        auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
        QVERIFY(menu != nullptr);
        QCOMPARE(menu->title(), QStringLiteral("&File"));
        menu->close();
    }
};

RIGIDLAB_TEST_MAIN(TestMenuBarFocus)
#include "test_menu_bar_focus.moc"
