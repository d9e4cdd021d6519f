// SPDX-License-Identifier: GPL-3.0-or-later
// A whole lesson with the keyboard alone: open it from the start page, read its text, answer
// a question, go to the next step, run and pause, choose a body and change its velocity, and
// export the step's plots, with key events only. All along, the focus never rests on a
// control nobody can see, keys go to the focused control before the window's shortcuts
// (Space presses a focused button, arrows move in a list), and Tab leaves a table.

#include "common/export_folder.h"
#include "common/shortcuts.h"
#include "editor/edit_tools.h"
#include "lesson_player/lesson_player.h"
#include "near.h"
#include "panels/inspector_panel.h"
#include "panels/number_field.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"
#include "window/main_window.h"

#include <QAbstractItemView>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QtTest>

#include "test_main.h"

using namespace rigidlab;
using rigidlab::ui::MainWindow;

namespace {

/// Whether some of `w` shows: its part inside its parents is not empty, and at one point of a
/// 3×3 grid over that part the window's topmost widget is `w`, its child or its parent, not
/// another dock or panel lying over it.
bool seen(const QWidget& w)
{
    const QWidget* window = w.window();
    QRect r(w.mapTo(window, QPoint()), w.size());
    for (const QWidget* p = w.parentWidget(); p && p != window; p = p->parentWidget())
        r &= QRect(p->mapTo(window, QPoint()), p->size());
    r &= window->rect();
    if (!w.isVisible() || r.isEmpty())
        return false;
    for (int i = 1; i <= 3; ++i)
        for (int j = 1; j <= 3; ++j) {
            const QPoint at(r.left() + i * r.width() / 4, r.top() + j * r.height() / 4);
            const QWidget* top = window->childAt(at);
            if (!top || top == &w || w.isAncestorOf(top) || top->isAncestorOf(&w))
                return true;
        }
    return false;
}

/// Every widget that took the focus while it could not be seen: hidden, out of its window's
/// sight (Qt moves docks behind a tab away rather than hiding them), or covered by another
/// dock lying over it.
class FocusWatch : public QObject {
public:
    FocusWatch()
    {
        connect(qApp, &QApplication::focusChanged, this, [this](QWidget*, QWidget* now) {
            // The lab's window; Qt's own file dialog hides and shows parts of itself.
            if (!now || qobject_cast<QFileDialog*>(now->window()))
                return;
            ++m_stops;
            if (!seen(*now))
                m_hidden << QStringLiteral("%1 '%2' visible %3, %4x%5 at (%6, %7)")
                                .arg(QLatin1String(now->metaObject()->className()),
                                     now->objectName())
                                .arg(now->isVisible())
                                .arg(now->width())
                                .arg(now->height())
                                .arg(now->mapTo(now->window(), QPoint()).x())
                                .arg(now->mapTo(now->window(), QPoint()).y());
        });
    }
    const QStringList& hidden() const { return m_hidden; }
    int stops() const { return m_stops; }

private:
    QStringList m_hidden;
    int m_stops = 0;
};

QWidget* focused(QWidget& window)
{
    QWidget* f = QApplication::focusWidget();
    return f ? f : &window;
}

/// One key pressed and released on the focused control, then the events it caused handled,
/// as between a person's key presses.
void key(QWidget& window, Qt::Key k, Qt::KeyboardModifiers mods = Qt::NoModifier)
{
    QTest::keyClick(focused(window), k, mods);
    QCoreApplication::processEvents();
}

/// Presses Tab until `wanted` has the focus; false after a whole cycle without it.
template <typename Pred> bool tabTo(QWidget& window, Pred wanted, int most = 120)
{
    for (int i = 0; i < most; ++i) {
        if (wanted(QApplication::focusWidget()))
            return true;
        key(window, Qt::Key_Tab);
    }
    return wanted(QApplication::focusWidget());
}

/// Opens the first lesson from the start page, reads, answers a question (and lets the run go).
void openReadAnswer(MainWindow& w)
{
    ui::LessonPlayer& player = w.lessonPlayer();
    ui::SimulationController& controller = w.controller();
    // Open: Tab to "Start the first lesson" and press Space, which presses the button
    // rather than playing the simulation.
    QVERIFY(!player.lesson());
    QVERIFY(tabTo(
        w, [](QWidget* f) { return f && f->objectName() == QLatin1String("startFirstLesson"); }));
    key(w, Qt::Key_Space);
    QVERIFY(player.lesson());
    QCoreApplication::processEvents();
    QVERIFY(!controller.isRunning());

    // Read: the step's text takes the focus.
    QVERIFY(tabTo(w, [](QWidget* f) { return qobject_cast<QTextBrowser*>(f) != nullptr; }));

    // Answer: go on through the steps (Alt+Right) to one with a question, Tab to its
    // field, type and press Return: a verdict shows.
    const auto answerField = [&]() -> QLineEdit* {
        // In the Lesson dock below the player's text, not inside the player.
        QWidget* box = w.findChild<QWidget*>(QStringLiteral("lessonQuestions"));
        const auto edits = box ? box->findChildren<QLineEdit*>() : QList<QLineEdit*>();
        return edits.isEmpty() ? nullptr : edits.first();
    };
    const int steps = static_cast<int>(player.lesson()->steps.size());
    while (!answerField() && player.stepIndex() + 1 < steps) {
        const int before = player.stepIndex();
        key(w, Qt::Key_Right, Qt::AltModifier);
        QCOMPARE(player.stepIndex(), before + 1);
    }
    QLineEdit* answer = answerField();
    QVERIFY(answer);
    QVERIFY(tabTo(w, [&](QWidget* f) { return f == answer; }));
    QTest::keyClicks(answer, QStringLiteral("1"));
    QCOMPARE(answer->text(), QStringLiteral("1")); // a digit typed, not a shortcut
    key(w, Qt::Key_Return);
    bool verdict = false;
    for (QLabel* l : answer->parentWidget()->findChildren<QLabel*>())
        verdict = verdict || (l->isVisible() && l->wordWrap() && !l->text().isEmpty() &&
                              l->buddy() == nullptr && l->text() != answer->text());
    QVERIFY(verdict);
    // A wrong answer keeps the run held back: "Show me", pressed with Space, lets it go.
    if (!player.heldBack().isEmpty()) {
        QVERIFY(tabTo(w, [](QWidget* f) {
            auto* b = qobject_cast<QPushButton*>(f);
            return b && b->text() == QLatin1String("Show me");
        }));
        key(w, Qt::Key_Space);
        QVERIFY2(player.heldBack().isEmpty(), qPrintable(player.heldBack().join(u' ')));
    }
}

/// Runs and pauses from the scene, selects a body, moves it and changes its velocity.
void runPauseAndPush(MainWindow& w)
{
    ui::SimulationController& controller = w.controller();
    // Run and pause: F6 puts the focus on the scene, Space runs and pauses.
    key(w, Qt::Key_F6);
    QCOMPARE(QApplication::focusWidget(), &w.view());
    // ("Show me" may have run the step to show its value.)
    if (controller.isRunning())
        key(w, Qt::Key_Space);
    QVERIFY(!controller.isRunning());
    key(w, Qt::Key_Space);
    QVERIFY(controller.isRunning());
    key(w, Qt::Key_Space);
    QVERIFY(!controller.isRunning());

    // Select a body and change its velocity: ] selects, Shift+Right adds 0.5 m/s along
    // x through World's API, Right moves it 0.1 m, Enter shows its numbers.
    const int bodies = static_cast<int>(controller.world().bodies().size());
    for (int i = 0; i < bodies; ++i) {
        key(w, Qt::Key_BracketRight);
        const int id = w.view().selectedBody();
        if (id >= 0 && controller.world().body(id).isDynamic())
            break;
    }
    const int body = w.view().selectedBody();
    QVERIFY(body >= 0);
    QVERIFY(controller.world().body(body).isDynamic());
    const physics::Vec2 v0 = controller.world().originVelocity(body);
    const physics::Vec2 p0 = controller.world().body(body).origin();
    const long long step0 = controller.world().stepCount();
    key(w, Qt::Key_Right, Qt::ShiftModifier);
    RL_VERIFY_NEAR(controller.world().originVelocity(body).x() - v0.x(), 0.5, 1e-12, 0);
    RL_VERIFY_NEAR(controller.world().originVelocity(body).y() - v0.y(), 0.0, 1e-12, 0);
    key(w, Qt::Key_Right);
    RL_VERIFY_NEAR(controller.world().body(body).origin().x() - p0.x(), 0.1, 1e-12, 0);
    QCOMPARE(controller.world().stepCount(), step0); // the arrows moved the body, not the clock
    key(w, Qt::Key_Return);
    QVERIFY(w.inspector().isVisible());
    QVERIFY(w.inspector().isAncestorOf(QApplication::focusWidget()));
}

/// The next step by its button and the shortcuts; the step's plots exported by keys.
void nextAndExport(MainWindow& w, QObject& context)
{
    ui::LessonPlayer& player = w.lessonPlayer();
    ui::SimulationController& controller = w.controller();
    const int steps = player.lesson() ? static_cast<int>(player.lesson()->steps.size()) : 0;
    // Next: Tab to the Next button and press Space; the step changes, the run does not.
    if (player.stepIndex() + 1 < steps) {
        const int at = player.stepIndex();
        QVERIFY(tabTo(w, [](QWidget* f) {
            auto* b = qobject_cast<QPushButton*>(f);
            return b && b->text().contains(QStringLiteral("▶")) && b->isEnabled();
        }));
        key(w, Qt::Key_Space);
        QCOMPARE(player.stepIndex(), at + 1);
        QVERIFY(!controller.isRunning());
        // Back and forth with the shortcuts.
        key(w, Qt::Key_Left, Qt::AltModifier);
        QCOMPARE(player.stepIndex(), at);
        key(w, Qt::Key_PageDown, Qt::ControlModifier);
        QCOMPARE(player.stepIndex(), at + 1);
    }

    // Export: Tab to Export plots… on a step that has plots, press Space, type the folder
    // into the dialog and press Return.
    while (player.stepIndex() + 1 < steps &&
           player.lesson()->steps[static_cast<std::size_t>(player.stepIndex())].plots.isEmpty())
        key(w, Qt::Key_Right, Qt::AltModifier);
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    QVERIFY(tabTo(w, [](QWidget* f) {
        auto* b = qobject_cast<QPushButton*>(f);
        return b && b->text() == QStringLiteral("Export plots…") && b->isEnabled();
    }));
    // The folder dialog opens where the last export went; Return chooses it.
    ui::rememberExportFolder(folder.path());
    bool dialogSeen = false;
    QString chosen;
    QTimer::singleShot(0, &context, [&] {
        auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
        if (!dialog)
            return;
        dialogSeen = true;
        QTest::keyClick(dialog->focusWidget(), Qt::Key_Return);
        if (dialog->isVisible()) // never left open: the test fails below instead
            dialog->reject();
        else
            chosen = dialog->selectedFiles().value(0);
    });
    key(w, Qt::Key_Space);
    QVERIFY(dialogSeen);
    QVERIFY2(!QDir(folder.path()).entryList(QDir::Files).isEmpty(), qPrintable(folder.path()));
}

} // namespace

class TestKeyboard : public QObject {
    Q_OBJECT
private slots:
    void wholeLessonByKeyboard()
    {
        FocusWatch watch;
        MainWindow w;
        w.fitToScreen(QRect(0, 0, 1024, 768));
        w.show();
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));

        openReadAnswer(w);
        if (QTest::currentTestFailed())
            return;
        runPauseAndPush(w);
        if (QTest::currentTestFailed())
            return;
        nextAndExport(w, *this);
        if (QTest::currentTestFailed())
            return;

        QVERIFY2(watch.stops() > 10, qPrintable(QString::number(watch.stops())));
        QVERIFY2(watch.hidden().isEmpty(), qPrintable(watch.hidden().join(QLatin1Char('\n'))));
    }

    /// A dock lying on the window under something else (another dock mid-way through an
    /// animated rearrangement, a panel): Tab and Shift+Tab pass its plots by and still go
    /// round the window. The energy_drift lesson's compare step, its side-by-side plots
    /// covered.
    void tabSkipsADockUnderAnother()
    {
        MainWindow w;
        w.fitToScreen(QRect(0, 0, 1024, 768));
        w.show();
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
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
        w.fitToScreen(QRect(0, 0, 1024, 768));
        w.show();
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
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
        w.fitToScreen(QRect(0, 0, 1024, 768));
        w.show();
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
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
        w.fitToScreen(QRect(0, 0, 1024, 768));
        w.show();
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
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
