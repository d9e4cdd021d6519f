// SPDX-License-Identifier: GPL-3.0-or-later
// The window with the keyboard alone, with key events only: Tab and Shift+Tab pass a dock
// lying under another by, F10 walks the toolbars, Edit mode's keys do what the mouse does to
// the view, Tab leaves a table while arrows move in it, an arrow on the closed list of lessons
// opens no lesson, and single-key shortcuts can be switched off. A whole lesson walked with
// the keys is test_keyboard_lesson.cpp.

#include "common/shortcuts.h"
#include "editor/edit_tools.h"
#include "lesson_player/lesson_player.h"
#include "near.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"
#include "window/main_window.h"

#include <QAbstractItemView>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QMenu>
#include <QTableWidget>
#include <QToolBar>
#include <QToolButton>
#include <QtTest>

#include "keyboard_keys.h"
#include "projector_window.h"
#include "test_main.h"

using namespace rigidlab;
using rigidlab::test::FocusWatch;
using rigidlab::test::key;
using rigidlab::test::seen;
using rigidlab::test::showActiveOnProjector;
using rigidlab::ui::MainWindow;

class TestKeyboard : public QObject {
    Q_OBJECT
private slots:
    /// A dock lying on the window under something else (another dock mid-way through an
    /// animated rearrangement, a panel): Tab and Shift+Tab pass its plots by and still go
    /// round the window. The energy_drift lesson's compare step, its side-by-side plots
    /// covered.
    void tabSkipsADockUnderAnother()
    {
        MainWindow w;
        QVERIFY(showActiveOnProjector(w));
        QCOMPARE(
            w.openLesson(
                QDir(MainWindow::lessonsFolder()).filePath(QStringLiteral("energy_drift.json")),
                true),
            QString());
        QCoreApplication::processEvents();
        auto* compare = w.findChild<QDockWidget*>(QStringLiteral("compareDock"));
        auto* controls = w.findChild<QDockWidget*>(QStringLiteral("controlsDock"));
        QVERIFY(compare && controls && compare->isVisible() && controls->isVisible());
        // The compared plots on show (at 1024x768 they may be tabs: one shows at a time).
        QList<ui::PlotWidget*> plots;
        for (ui::PlotWidget* p : compare->findChildren<ui::PlotWidget*>())
            if (p->isVisible())
                plots << p;
        QVERIFY(!plots.isEmpty());
        for (const ui::PlotWidget* p : plots)
            QVERIFY2(seen(*p), qPrintable(p->objectName()));
        // A panel of the window's own size and colour lies over the side-by-side dock; the
        // window's layout does not move it (a dock the layout placed there, it would).
        QWidget cover(&w);
        cover.setAutoFillBackground(true);
        cover.setGeometry(compare->geometry());
        cover.show();
        cover.raise();
        QCoreApplication::processEvents();
        for (const ui::PlotWidget* p : plots)
            QVERIFY2(p->isVisible() && !seen(*p), qPrintable(p->objectName()));

        for (const Qt::Key direction : {Qt::Key_Tab, Qt::Key_Backtab}) {
            FocusWatch watch;
            QSet<QWidget*> stops;
            w.view().setFocus(Qt::OtherFocusReason);
            for (int i = 0; i < 80; ++i) {
                key(w, direction);
                if (QApplication::focusWidget() == &w.view())
                    break;
                stops << QApplication::focusWidget();
            }
            QCOMPARE(QApplication::focusWidget(), &w.view()); // a whole round
            QVERIFY2(watch.hidden().isEmpty(), qPrintable(watch.hidden().join(QLatin1Char('\n'))));
            bool controlsReached = false;
            for (QWidget* f : std::as_const(stops))
                controlsReached = controlsReached || controls->isAncestorOf(f);
            QVERIFY(controlsReached);
        }
    }

    /// F10 puts the focus on the toolbar: the arrows move along its buttons (not Step nor
    /// Back), Down goes to the editor's tools in Edit mode, Space presses a button, Escape
    /// goes back; Help lists the key.
    void toolbarByKeyboard()
    {
        MainWindow w;
        QVERIFY(showActiveOnProjector(w));
        QVERIFY(ui::controlsHelpHtml({}).contains(
            QKeySequence(Qt::Key_F10).toString(QKeySequence::NativeText)));
        auto* bar = w.findChild<QToolBar*>(QStringLiteral("simulationToolbar"));
        QVERIFY(bar);
        const auto buttonOf = [](QWidget* f) { return qobject_cast<QToolButton*>(f); };
        w.view().setFocus(Qt::OtherFocusReason);
        key(w, Qt::Key_F10);
        QToolButton* first = buttonOf(QApplication::focusWidget());
        QVERIFY(first && bar->isAncestorOf(first));
        // Right along the buttons to Play, the clock standing still.
        const long long step = w.controller().world().stepCount();
        QToolButton* play = nullptr;
        for (int i = 0; i < 12 && !play; ++i) {
            key(w, Qt::Key_Right);
            QToolButton* b = buttonOf(QApplication::focusWidget());
            QVERIFY(b && bar->isAncestorOf(b));
            if (b->defaultAction() && b->defaultAction()->objectName() == QLatin1String("play"))
                play = b;
        }
        QVERIFY(play);
        QCOMPARE(w.controller().world().stepCount(), step);
        key(w, Qt::Key_Left);
        QVERIFY(QApplication::focusWidget() != play);
        key(w, Qt::Key_Right);
        QCOMPARE(QApplication::focusWidget(), play);
        key(w, Qt::Key_Space);
        QVERIFY(w.controller().isRunning());
        QCOMPARE(QApplication::focusWidget(), play);
        key(w, Qt::Key_Return);
        QVERIFY(!w.controller().isRunning());
        key(w, Qt::Key_Escape);
        QCOMPARE(QApplication::focusWidget(), &w.view());

        // In Edit mode, Down goes to the editor's row of tools, Up back.
        w.editTools().setEditing(true);
        QCoreApplication::processEvents();
        auto* tools = w.findChild<QToolBar*>(QStringLiteral("editToolbar"));
        QVERIFY(tools && tools->isVisible());
        w.view().setFocus(Qt::OtherFocusReason);
        key(w, Qt::Key_F10);
        key(w, Qt::Key_Down);
        QVERIFY(tools->isAncestorOf(QApplication::focusWidget()));
        QCOMPARE(w.editTools().tool(), ui::EditTool::Select);
        key(w, Qt::Key_Home);
        key(w, Qt::Key_Right); // the second tool, Rotate
        key(w, Qt::Key_Space);
        QCOMPARE(w.editTools().tool(), ui::EditTool::Rotate);
        key(w, Qt::Key_Up);
        QVERIFY(bar->isAncestorOf(QApplication::focusWidget()));
        key(w, Qt::Key_Escape);
        QCOMPARE(QApplication::focusWidget(), &w.view());
    }

    /// In Edit mode the keys do what the mouse does to the view: Insert offers the bodies to
    /// add at the view's centre, + and − zoom, 0 fits, Ctrl+arrows pan; Help lists them.
    void editorViewByKeyboard()
    {
        MainWindow w;
        QVERIFY(showActiveOnProjector(w));
        const QString help = ui::controlsHelpHtml({});
        for (const Qt::Key k : {Qt::Key_Insert, Qt::Key_Plus, Qt::Key_Minus, Qt::Key_0})
            QVERIFY2(help.contains(QKeySequence(k).toString(QKeySequence::NativeText)),
                     qPrintable(QKeySequence(k).toString(QKeySequence::NativeText)));
        QCOMPARE(
            w.openScene(QDir(MainWindow::scenesFolder()).filePath(QStringLiteral("welcome.json")),
                        true),
            QString());
        ui::EditTools& tools = w.editTools();
        tools.setEditing(true);
        QCoreApplication::processEvents();
        w.view().setFocus(Qt::OtherFocusReason);
        ui::WorldView& view = w.view();
        const auto middle = [&] { return view.worldAt(view.viewport()->rect().center()); };

        // Zoom: + by a wheel step about the middle, − back, 0 fits again.
        key(w, Qt::Key_0);
        const double fitted = view.zoom();
        const physics::Vec2 c0 = middle();
        key(w, Qt::Key_Plus);
        RL_VERIFY_NEAR(view.zoom() / fitted, 1.2, 1e-9, 0);
        RL_VERIFY_NEAR((middle() - c0).norm(), 0.0, 2.0 / view.zoom(), 0);
        key(w, Qt::Key_Minus);
        key(w, Qt::Key_Minus);
        RL_VERIFY_NEAR(view.zoom() / fitted, 1.0 / 1.2, 1e-9, 0);
        key(w, Qt::Key_0);
        RL_VERIFY_NEAR(view.zoom(), fitted, 1e-9 * fitted, 0);

        // Pan: Ctrl+Right shows what lies right, Ctrl+Up what lies above; the clock stays.
        const long long step = w.controller().world().stepCount();
        const physics::Vec2 p0 = middle();
        key(w, Qt::Key_Right, Qt::ControlModifier);
        const physics::Vec2 p1 = middle();
        QVERIFY2(p1.x() > p0.x(), qPrintable(QStringLiteral("%1 %2").arg(p0.x()).arg(p1.x())));
        RL_VERIFY_NEAR(p1.y(), p0.y(), 2.0 / view.zoom(), 0);
        key(w, Qt::Key_Up, Qt::ControlModifier);
        QVERIFY(middle().y() > p1.y());
        QCOMPARE(w.controller().world().stepCount(), step);

        // Insert: a menu of bodies; Down and Return add a box at the view's centre.
        const std::size_t before = tools.scene().bodies.size();
        key(w, Qt::Key_Insert);
        auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
        QVERIFY(menu);
        QVERIFY(!menu->accessibleName().isEmpty());
        QCOMPARE(menu->actions().size(), 4);
        QTest::keyClick(menu, Qt::Key_Down);
        QTest::keyClick(menu, Qt::Key_Return);
        QCoreApplication::processEvents();
        QCOMPARE(tools.scene().bodies.size(), before + 1);
        const physics::BodyDef& added = tools.scene().bodies.back();
        QVERIFY(added.shape.asPolygon() && added.type == physics::BodyType::Dynamic);
        QCOMPARE(tools.tool(), ui::EditTool::Box);
        RL_VERIFY_NEAR((added.position - tools.viewCentre()).norm(), 0.0, 1e-9, 0);
        QCOMPARE(tools.selectedBody(), static_cast<int>(before));
        // The keys go on in the scene, on the new body (not in the History list).
        QTRY_COMPARE(QApplication::focusWidget(), static_cast<QWidget*>(&view));
        // One undo step takes it away.
        key(w, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(tools.scene().bodies.size(), before);
    }

    /// Tab leaves a table rather than walking its cells; arrows move within it.
    void tabLeavesATable()
    {
        MainWindow w;
        QVERIFY(showActiveOnProjector(w));
        QCOMPARE(w.openLesson(
                     QDir(MainWindow::lessonsFolder()).filePath(QStringLiteral("restitution.json")),
                     true),
                 QString());
        QTableWidget* table = nullptr;
        for (QTableWidget* t : w.findChildren<QTableWidget*>())
            if (t->isVisible() && t->rowCount() > 1)
                table = t;
        QVERIFY(table);
        table->setFocus(Qt::TabFocusReason);
        QCOMPARE(QApplication::focusWidget(), table);
        table->setCurrentCell(0, 0);
        const long long step = w.controller().world().stepCount();
        key(w, Qt::Key_Down);
        QCOMPARE(table->currentRow(), 1);                   // the arrow moved in the table
        QCOMPARE(w.controller().world().stepCount(), step); // and was not Step
        key(w, Qt::Key_Tab);
        QVERIFY(QApplication::focusWidget() != table);
        key(w, Qt::Key_Backtab);
        key(w, Qt::Key_Backtab);
        QVERIFY(QApplication::focusWidget() != table);
    }

    /// An arrow on the closed list of lessons opens the list, not the lessons it passes.
    void arrowsOnTheLessonListOpenNoLesson()
    {
        MainWindow w;
        w.show();
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        auto* box = w.lessonPlayer().findChild<QComboBox*>(QStringLiteral("lessonChoice"));
        QVERIFY(box);
        QVERIFY(!w.lessonPlayer().lesson());
        const int before = box->currentIndex();
        box->setFocus();
        key(w, Qt::Key_Down);
        key(w, Qt::Key_Down);
        QVERIFY(!w.lessonPlayer().lesson());
        QCOMPARE(box->currentIndex(), before);
        QVERIFY(box->view()->isVisible());
        QTest::keyClick(box->view(), Qt::Key_Escape);
        QVERIFY(!w.lessonPlayer().lesson());
    }

    /// Single-key shortcuts switched off: S no longer steps; Ctrl shortcuts still work.
    void singleKeysCanBeSwitchedOff()
    {
        MainWindow w;
        w.show();
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        w.view().setFocus();
        const long long start = w.controller().world().stepCount();
        key(w, Qt::Key_S);
        QCOMPARE(w.controller().world().stepCount(), start + 1);
        key(w, Qt::Key_K, Qt::ControlModifier | Qt::ShiftModifier); // off
        key(w, Qt::Key_S);
        key(w, Qt::Key_Space);
        QCOMPARE(w.controller().world().stepCount(), start + 1);
        QVERIFY(!w.controller().isRunning());
        key(w, Qt::Key_K, Qt::ControlModifier | Qt::ShiftModifier); // on again
        key(w, Qt::Key_S);
        QCOMPARE(w.controller().world().stepCount(), start + 2);
    }
};

RIGIDLAB_TEST_MAIN(TestKeyboard)
#include "test_keyboard.moc"
