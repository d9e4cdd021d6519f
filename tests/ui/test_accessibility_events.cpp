// SPDX-License-Identifier: GPL-3.0-or-later
// What the lab tells a screen reader, counted: the window on the welcome scene sends only a
// few accessibility events a second, paused and running (a reader handles a handful a second;
// thousands froze Orca), no widget is hidden and shown over and over, and what matters is
// told: the verdict after Check, a new lesson step, the body chosen and moved in the scene,
// play and pause, a run that diverged. A step of the first lesson that asks a question takes
// a few keys: the focus starts on the step's text, Tab reaches the answer.

// This test's accessibility bridge is a plugin built into it (Q_IMPORT_PLUGIN below).
#define QT_STATICPLUGIN

#include "build_paths.h"
#include "common/focus_first.h"
#include "common/spoken_numbers.h"
#include "event_count.h"
#include "first_question.h"
#include "lesson_player/lesson_player.h"
#include "panels/inspector_panel.h"
#include "simulation/simulation_controller.h"
#include "view/scene_narrator.h"
#include "view/world_view.h"
#include "view/world_view_accessible.h"
#include "window/main_window.h"

#include <QAccessible>
#include <QAccessibleBridge>
#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollBar>
#include <QTextBrowser>
#include <QVBoxLayout>
#include <QtPlugin>
#include <QtTest>

#include <array>

#include "projector_window.h"
#include "test_main.h"

using namespace rigidlab;
using rigidlab::test::EventCount;
using rigidlab::test::eventsPerSecond;
using rigidlab::ui::MainWindow;

class CountingBridgePlugin : public QAccessibleBridgePlugin {
    Q_OBJECT
    Q_PLUGIN_METADATA(IID QAccessibleBridgeFactoryInterface_iid FILE "counting_bridge.json")
public:
    // Qt never deletes the bridges it loads: the one bridge lives as long as the program.
    QAccessibleBridge* create(const QString&) override
    {
        static test::CountingBridge bridge;
        return &bridge;
    }
};

Q_IMPORT_PLUGIN(CountingBridgePlugin)

namespace {

/// Most accessibility events a second the window may send on its own (paused or running).
constexpr double kBudgetPerSecond = 30.0;
/// The seconds each count lasts.
constexpr int kCountMs = 2000;

void showOnProjector(MainWindow& w)
{
    w.fitToScreen(QRect(0, 0, 1024, 768));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
}

QString welcome()
{
    return QDir(MainWindow::scenesFolder()).filePath(QStringLiteral("welcome.json"));
}

/// Whether a field's events (in order) tell its focus, and no caret move before it (its
/// selection: aFieldTellsItsFocusBeforeItsSelection).
bool caretStaysBehindFocus(const QList<QAccessible::Event>& events)
{
    const qsizetype focus = events.indexOf(QAccessible::Focus);
    return focus >= 0 && !events.first(focus).contains(QAccessible::TextCaretMoved);
}

/// One key pressed and released on the focused control, then what it caused handled, as
/// between a person's key presses.
void press(Qt::Key k, Qt::KeyboardModifiers mods = Qt::NoModifier)
{
    QWidget* focused = QApplication::focusWidget();
    QTest::keyClick(focused ? focused : QApplication::activeWindow(), k, mods);
    QCoreApplication::processEvents();
}

/// A button, a text field and a spin box, one under the other: what Tab goes through.
struct TabForm {
    QWidget form;
    QPushButton* button = new QPushButton(QStringLiteral("Before"), &form);
    QLineEdit* field = new QLineEdit(&form);
    QDoubleSpinBox* spin = new QDoubleSpinBox(&form);
    TabForm()
    {
        field->setAccessibleName(QStringLiteral("Answer"));
        spin->setAccessibleName(QStringLiteral("Time step"));
        auto* layout = new QVBoxLayout(&form);
        layout->addWidget(button);
        layout->addWidget(field);
        layout->addWidget(spin);
    }
    /// Shows the form and puts the focus on its button; false if either did not happen.
    bool shownWithTheButtonFocused()
    {
        form.show();
        if (!QTest::qWaitForWindowExposed(&form))
            return false;
        button->setFocus();
        return QTest::qWaitFor([this] { return button->hasFocus(); });
    }
};

} // namespace

class TestAccessibilityEvents : public QObject {
    Q_OBJECT
private slots:
    /// The counting works: Qt's events reach this test's bridge.
    void eventsAreCounted()
    {
        QLabel label(QStringLiteral("before"));
        label.show();
        QVERIFY(QTest::qWaitForWindowExposed(&label));
        EventCount count;
        label.setText(QStringLiteral("after"));
        QVERIFY2(count.total() == 1, qPrintable(count.top()));
    }

    /// The welcome scene with a body chosen, paused and then running: a few events a second,
    /// none of a widget shown and hidden again and again.
    void theWindowIsQuiet()
    {
        MainWindow w;
        QCOMPARE(w.openScene(welcome(), true), QString());
        showOnProjector(w);
        EventCount count(w);
        // A body chosen, as a student does: the inspector shows its values, which change with
        // every frame of the run.
        w.view().selectNextBody();
        QVERIFY(w.view().selectedBody() >= 0);
        QTest::qWait(300); // what the window does once, on being shown, is not counted

        const double paused = eventsPerSecond(count, kCountMs);
        qInfo("paused: %.1f events/s (%s)", paused, qPrintable(count.top()));
        QVERIFY2(paused <= kBudgetPerSecond,
                 qPrintable(QStringLiteral("%1 events/s paused, at most %2: %3")
                                .arg(paused)
                                .arg(kBudgetPerSecond)
                                .arg(count.top())));
        QVERIFY2(count.mostShowsOfOneObject() <= 2, qPrintable(count.top()));

        const double t0 = w.controller().time();
        w.controller().setRunning(true);
        const double running = eventsPerSecond(count, kCountMs);
        qInfo("running: %.1f events/s (%s)", running, qPrintable(count.top()));
        // It did run: more than a few frames' worth of simulated time passed.
        QVERIFY2(w.controller().time() - t0 > 0.25,
                 qPrintable(QStringLiteral("t from %1 to %2").arg(t0).arg(w.controller().time())));
        QVERIFY2(running <= kBudgetPerSecond,
                 qPrintable(QStringLiteral("%1 events/s running, at most %2: %3")
                                .arg(running)
                                .arg(kBudgetPerSecond)
                                .arg(count.top())));
        QVERIFY2(count.mostShowsOfOneObject() <= 2, qPrintable(count.top()));
    }

    /// The inspector opened on a moving body (Enter in the scene) while the run goes: its
    /// numbers change with every frame, and still it tells a reader of them at the calm rate,
    /// about one change a second for each of its rows, with no widget shown and hidden again and
    /// again (the mass row's "infinite" was, 110 times a second, and the forces' diagram
    /// changed its description 55 times a second: a reader said the focused mass field seconds
    /// late). The scene's own events are theWindowIsQuiet's.
    void theInspectorIsQuietWhileRunning()
    {
        MainWindow w;
        QCOMPARE(w.openScene(welcome(), true), QString());
        showOnProjector(w);
        const int body = test::askWreckingBallNumbers(w);
        QVERIFY(body >= 0);
        QVERIFY(w.inspector().isVisible());
        w.controller().setRunning(true);
        QTest::qWait(300); // the dock's opening and the run's start are not counted
        EventCount count(w);
        const double t0 = w.controller().time();
        QElapsedTimer clock;
        clock.start();
        QTest::qWait(kCountMs);
        const double seconds = static_cast<double>(clock.elapsed()) / 1000.0;
        QVERIFY2(w.controller().time() - t0 > 0.25,
                 qPrintable(QStringLiteral("t from %1 to %2").arg(t0).arg(w.controller().time())));
        QList<QObject*> inspector = w.inspector().findChildren<QObject*>();
        inspector << &w.inspector();
        int told = 0;
        for (const QObject* o : inspector)
            told += static_cast<int>(count.eventsOf(o).size());
        // Its rows, each at most once a second (common/calm_text.h), and a few more.
        const double most = 12.0;
        qInfo("inspector open, running: %.1f of its events/s (all: %s)", told / seconds,
              qPrintable(count.top()));
        QVERIFY2(told / seconds <= most,
                 qPrintable(QStringLiteral("the inspector sent %1 events/s, at most %2: %3")
                                .arg(told / seconds)
                                .arg(most)
                                .arg(count.top())));
        QVERIFY2(count.mostShowsOfOneObject() <= 2, qPrintable(count.top()));
    }

    /// A lesson step whose view follows its bodies as they fly apart (restitution's second:
    /// two balls after their collision): the view moves its own scroll bars, hidden, as it
    /// widens. They tell a reader nothing (in the window under AT-SPI they told 14 to 80 value
    /// changes a second, and Orca, flooded, dropped the announcement that the run had paused);
    /// a scroll bar shown still has its value.
    void hiddenScrollBarsTellNoValue()
    {
        MainWindow w;
        showOnProjector(w);
        QCOMPARE(w.openLesson(test::sourcePath(u"/lessons/lessons/restitution.json"), true),
                 QString());
        w.lessonPlayer().goToStep(1);
        QTest::qWait(300); // the step's opening is not counted
        const std::array<QScrollBar*, 2> bars{w.view().horizontalScrollBar(),
                                              w.view().verticalScrollBar()};
        int moves = 0;
        for (QScrollBar* bar : bars) {
            QVERIFY(!bar->isVisible());
            connect(bar, &QScrollBar::valueChanged, this, [&moves] { ++moves; });
        }
        EventCount count(w);
        ui::SimulationController& c = w.controller();
        c.setRunning(true);
        for (int frame = 0; frame < 60 * 10 && c.isRunning(); ++frame) {
            c.advanceClock(1.0 / 60);
            QCoreApplication::processEvents();
        }
        c.setRunning(false);
        // The view did follow the balls: its hidden bars moved, and told no reader of it.
        QVERIFY2(moves > 10, qPrintable(QStringLiteral("the bars moved %1 times, t = %2 s")
                                            .arg(moves)
                                            .arg(c.world().time())));
        for (QScrollBar* bar : bars)
            QVERIFY2(count.eventsOf(bar).isEmpty(),
                     qPrintable(QStringLiteral("a hidden bar told %1 events: %2")
                                    .arg(count.eventsOf(bar).size())
                                    .arg(count.top())));
        QAccessibleInterface* hidden = QAccessible::queryAccessibleInterface(bars[0]);
        QVERIFY(hidden != nullptr);
        QCOMPARE(hidden->role(), QAccessible::ScrollBar);
        QVERIFY(hidden->valueInterface() == nullptr);
        // A bar that is shown tells its value.
        QScrollBar shown(Qt::Horizontal);
        shown.setRange(0, 100);
        shown.setValue(40);
        shown.show();
        QVERIFY(QTest::qWaitForWindowExposed(&shown));
        QAccessibleInterface* shownBar = QAccessible::queryAccessibleInterface(&shown);
        QVERIFY(shownBar != nullptr && shownBar->valueInterface() != nullptr);
        QCOMPARE(shownBar->valueInterface()->currentValue().toInt(), 40);
        QCOMPARE(shownBar->valueInterface()->maximumValue().toInt(), 100);
    }

    /// A body's new value and the status reach the bridge as a change of the item's
    /// description, which says them: Qt's AT-SPI bridge drops a value change of an item with no
    /// numeric value ("ValueChanged event and no ValueInterface").
    void sceneItemsToldAsDescriptionChanges()
    {
        MainWindow w;
        QCOMPARE(w.openScene(welcome(), true), QString());
        showOnProjector(w);
        for (int k = 0; k < 30; ++k)
            w.controller().stepForward();
        EventCount count;
        const int first = ui::WorldViewAccessible::FirstBody;
        ui::tellSceneItemChanged(w.view(), first);
        ui::tellSceneItemChanged(w.view(), ui::WorldViewAccessible::Status);
        const auto& told = count.itemEvents();
        QCOMPARE(told.size(), 2);
        QAccessibleInterface* scene = QAccessible::queryAccessibleInterface(&w.view());
        QVERIFY(scene != nullptr);
        const QString body = scene->child(first)->text(QAccessible::Description);
        QVERIFY2(body.contains(QLatin1String("m/s")), qPrintable(body)); // says its velocity
        QCOMPARE(told[0].first, QAccessible::DescriptionChanged);
        QCOMPARE(told[0].second, body);
        QCOMPARE(told[1].first, QAccessible::DescriptionChanged);
        QCOMPARE(told[1].second, w.view().narrator().status());
    }

    /// In the scene: the body chosen with ] (its name and speed), moved with an arrow (where
    /// it is now, once the keys rest), play and pause, and a run that diverged are told.
    void sceneChangesAreAnnounced()
    {
        MainWindow w;
        QCOMPARE(w.openScene(welcome(), true), QString());
        showOnProjector(w);
        EventCount count(w);
        ui::WorldView& view = w.view();
        view.setFocus();
        QTest::keyClick(&view, Qt::Key_BracketRight);
        const int body = view.selectedBody();
        QVERIFY(body >= 0);
        const QString label = w.controller().scene().bodyLabel(body);
        QCOMPARE(count.announced().size(), 1);
        QVERIFY2(count.announced().last().startsWith(label + QStringLiteral(", speed ")),
                 qPrintable(count.announced().last()));

        // Three presses, one announcement once the keys rest, with the new position.
        for (int i = 0; i < 3; ++i)
            QTest::keyClick(&view, Qt::Key_Right);
        QCOMPARE(count.announced().size(), 1);
        QTRY_COMPARE(count.announced().size(), 2);
        const QString moved = count.announced().last();
        QVERIFY2(moved.startsWith(label + QStringLiteral(": position (")) &&
                     moved.contains(QStringLiteral("velocity (")),
                 qPrintable(moved));
        QTest::qWait(2 * ui::SceneNarrator::kSettleMs); // no second one for the same presses
        QCOMPARE(count.announced().size(), 2);

        w.controller().setRunning(true);
        QCOMPARE(count.announced().last(), QStringLiteral("Running."));
        w.controller().setRunning(false);
        QVERIFY2(count.announced().last().startsWith(QStringLiteral("Paused at ")),
                 qPrintable(count.announced().last()));

        // The stiff spring past its stability limit: Verlet at dt = 10 ms diverges at once.
        QCOMPARE(
            w.openScene(rigidlab::test::sourcePath(u"/lessons/scenes/stiff_spring.json"), true),
            QString());
        w.controller().setDt(0.01);
        for (int k = 0; k < 10000 && !w.controller().world().divergence(); ++k)
            w.controller().stepForward();
        QVERIFY(w.controller().world().divergence());
        QVERIFY2(count.announced().contains(QStringLiteral("The simulation diverged and stopped.")),
                 qPrintable(count.announced().join(u'|')));
    }

    /// A text field reached by Tab tells its focus before anything else: Orca takes a caret
    /// event of a field as its new focus, silently, and then says nothing for the focus event.
    void aFieldTellsItsFocusFirst()
    {
        ui::tellFieldFocusFirst();
        TabForm form;
        QLineEdit* const field = form.field;
        QDoubleSpinBox* const spin = form.spin;
        QVERIFY(form.shownWithTheButtonFocused());
        QPushButton* const button = form.button;
        EventCount count;
        QTest::keyClick(button, Qt::Key_Tab);
        QVERIFY(field->hasFocus());
        QVERIFY2(caretStaysBehindFocus(count.eventsOf(field)), qPrintable(count.orderOf(field)));
        QTest::keyClick(field, Qt::Key_Tab);
        QVERIFY(spin->hasFocus());
        // A spin box's focus is told of the box, its caret of the field inside it.
        const QLineEdit* spinField = spin->findChild<QLineEdit*>();
        QVERIFY2(count.eventsOf(spin).contains(QAccessible::Focus),
                 qPrintable(count.orderOf(spin)));
        QVERIFY2(!count.eventsOf(spinField).contains(QAccessible::TextCaretMoved),
                 qPrintable(count.orderOf(spinField)));
    }

    /// A field that Tab or Shift+Tab reaches selects its text; its focus is told before that
    /// selection, so that a reader says the field's label and value first, not "0,64 selected"
    /// and then the label.
    void aFieldTellsItsFocusBeforeItsSelection()
    {
        ui::tellFieldFocusFirst();
        TabForm form;
        QLineEdit* const field = form.field;
        QDoubleSpinBox* const spin = form.spin;
        field->setText(QStringLiteral("0,64"));
        spin->setValue(0.5);
        QVERIFY(form.shownWithTheButtonFocused());
        const QLineEdit* spinField = spin->findChild<QLineEdit*>();
        // Tab into the field, Tab into the spin box, Shift+Tab back into the field.
        const QList<std::pair<QWidget*, Qt::Key>> moves{
            {field, Qt::Key_Tab}, {spin, Qt::Key_Tab}, {field, Qt::Key_Backtab}};
        for (const auto& [to, key] : moves) {
            EventCount count;
            QTest::keyClick(QApplication::focusWidget(), key);
            QVERIFY(to->hasFocus());
            // A spin box's focus is told of the box, its selection of the field inside it.
            const QObject* text = to == spin ? static_cast<const QObject*>(spinField) : to;
            // The text is selected, as Tab does, at once or as soon as events are handled.
            QTRY_VERIFY2(count.firstIndex(text, QAccessible::TextSelectionChanged) >= 0,
                         qPrintable(QStringLiteral("no selection: ") + count.orderOf(text)));
            const qsizetype focus = count.firstIndex(to, QAccessible::Focus);
            const qsizetype selection = count.firstIndex(text, QAccessible::TextSelectionChanged);
            QVERIFY2(
                focus >= 0 && focus < selection,
                qPrintable(QStringLiteral("focus at %1, selection at %2 (%3: %4; text: %5)")
                               .arg(focus)
                               .arg(selection)
                               .arg(to->accessibleName(), count.orderOf(to), count.orderOf(text))));
        }
        // A key typed at once after Tab still replaces the whole text.
        QTest::keyClick(field, Qt::Key_Tab);
        QVERIFY(spin->hasFocus());
        QTest::keyClick(spin, Qt::Key_Backtab);
        QVERIFY(field->hasFocus());
        QTest::keyClicks(field, QStringLiteral("7"));
        QCOMPARE(field->text(), QStringLiteral("7"));
    }

    /// F6 on the scene that has the focus already moves nothing, so a reader would say
    /// nothing: the scene's name and summary are told instead.
    void focusSceneKeyOnTheSceneSaysWhereItIs()
    {
        MainWindow w;
        QCOMPARE(w.openScene(welcome(), true), QString());
        showOnProjector(w);
        w.view().setFocus();
        QTRY_COMPARE(QApplication::focusWidget(), &w.view());
        EventCount count(w);
        press(Qt::Key_F6);
        QCOMPARE(QApplication::focusWidget(), &w.view());
        QCOMPARE(count.announced().size(), 1);
        const QString told = count.announced().last();
        QVERIFY2(told.startsWith(QStringLiteral("Scene: ")) &&
                     told.contains(QStringLiteral("On stage: ")),
                 qPrintable(told));
    }

    /// In a lesson: each step is told (its number, title and first sentence) and its text
    /// takes the focus; the verdict after Check is told with the text it shows.
    void lessonChangesAreAnnounced()
    {
        MainWindow w;
        showOnProjector(w);
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        EventCount count(w);
        ui::LessonPlayer& player = w.lessonPlayer();
        QCOMPARE(w.openLesson(player.firstLessonPath(), true), QString());
        const auto& steps = player.lesson()->steps;
        const QString first =
            QStringLiteral("Step 1 of %1: %2. ").arg(steps.size()).arg(steps.front().title);
        QVERIFY2(!count.announced().isEmpty() && count.announced().last().startsWith(first),
                 qPrintable(count.announced().join(u'|')));
        QTRY_VERIFY(qobject_cast<QTextBrowser*>(QApplication::focusWidget()));
        // The focused text says itself: a reader speaks a text of this kind by its name.
        auto* text = qobject_cast<QTextBrowser*>(QApplication::focusWidget());
        const QString said = QAccessible::queryAccessibleInterface(text)->text(QAccessible::Name);
        QVERIFY2(!said.isEmpty() && said == ui::spokenSigns(text->toPlainText().simplified()),
                 qPrintable(said));

        const MeasuredQuestion q = runToFirstQuestion(w);
        QVERIFY(q.step >= 0 && q.value);
        const QString title = steps[static_cast<std::size_t>(q.step)].title;
        QVERIFY2(
            count.announced().last().startsWith(
                QStringLiteral("Step %1 of %2: %3. ").arg(q.step + 1).arg(steps.size()).arg(title)),
            qPrintable(count.announced().last()));
        // The first sentence of the text, not all of it.
        QVERIFY(count.announced().last().size() < 400);
        const qsizetype before = count.announced().size();
        player.answer(0, QLocale().toString(*q.value)); // typed, then Return
        QVERIFY(!player.result(0).isEmpty());
        // The verdict first (a right answer may then let the run go: "Running.").
        QVERIFY2(count.announced().size() > before &&
                     count.announced().at(before) == player.result(0).simplified(),
                 qPrintable(count.announced().mid(before).join(u'|') + QStringLiteral(" / ") +
                            player.result(0)));
    }

    /// A panel shown by its key (or the View menu) takes the focus: the student who asked for
    /// it works in it next.
    void aDockShownByItsActionTakesTheFocus()
    {
        MainWindow w;
        QCOMPARE(w.openScene(welcome(), true), QString());
        showOnProjector(w);
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QDockWidget* inspector = w.dock(QStringLiteral("inspector"));
        QVERIFY(inspector);
        inspector->toggleViewAction()->trigger(); // hidden
        QVERIFY(!inspector->isVisible());
        w.view().setFocus();
        inspector->toggleViewAction()->trigger(); // shown again, as its key would
        QTRY_VERIFY(inspector->isAncestorOf(QApplication::focusWidget()));
    }

    /// The first lesson from its start to its end, counted: each step begins with the focus
    /// on its text, and a step with a question takes at most kMostKeysPerStep key presses:
    /// Tab to the answer, type it (one press counted for the typing), Return, Alt+Right.
    void firstLessonInFewKeysAStep()
    {
        constexpr int kMostKeysPerStep = 6;
        MainWindow w;
        QCOMPARE(test::openFirstLessonOnProjector(w), QString());
        ui::LessonPlayer& player = w.lessonPlayer();
        const int steps = static_cast<int>(player.lesson()->steps.size());
        int asked = 0;
        for (int s = 0; s < steps; ++s) {
            QCOMPARE(player.stepIndex(), s);
            QCoreApplication::processEvents();
            QVERIFY2(
                qobject_cast<QTextBrowser*>(QApplication::focusWidget()),
                qPrintable(QStringLiteral("step %1: the focus on %2")
                               .arg(s + 1)
                               .arg(QApplication::focusWidget()
                                        ? QApplication::focusWidget()->metaObject()->className()
                                        : "nothing")));
            int presses = 0;
            // The questions sit in the Lesson dock below the player's text, not inside the player.
            QWidget* box = w.findChild<QWidget*>(QStringLiteral("lessonQuestions"));
            const QList<QLineEdit*> answers =
                box ? box->findChildren<QLineEdit*>() : QList<QLineEdit*>();
            if (!answers.isEmpty()) {
                ++asked;
                while (QApplication::focusWidget() != answers.first() && presses < 20) {
                    press(Qt::Key_Tab);
                    ++presses;
                }
                QVERIFY2(
                    QApplication::focusWidget() == answers.first(),
                    qPrintable(
                        QStringLiteral("step %1: not reached in %2 Tabs").arg(s + 1).arg(presses)));
                QTest::keyClicks(answers.first(), QStringLiteral("1"));
                ++presses;
                press(Qt::Key_Return);
                ++presses;
            }
            if (s + 1 < steps) {
                press(Qt::Key_Right, Qt::AltModifier);
                ++presses;
                QCOMPARE(player.stepIndex(), s + 1);
            }
            QVERIFY2(presses <= kMostKeysPerStep,
                     qPrintable(QStringLiteral("step %1: %2 key presses, at most %3")
                                    .arg(s + 1)
                                    .arg(presses)
                                    .arg(kMostKeysPerStep)));
        }
        QVERIFY(asked > 0);
    }
};

RIGIDLAB_TEST_MAIN(TestAccessibilityEvents)
#include "test_accessibility_events.moc"
