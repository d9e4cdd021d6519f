// SPDX-License-Identifier: GPL-3.0-or-later
// A whole lesson with the keyboard alone: open it from the start page, read its text, answer
// a question, go to the next step, run and pause, choose a body and change its velocity, and
// export the step's plots, with key events only. All along, the focus never rests on a
// control nobody can see, and keys go to the focused control before the window's shortcuts
// (Space presses a focused button, not Play).

#include "common/export_folder.h"
#include "lesson_player/lesson_player.h"
#include "near.h"
#include "panels/inspector_panel.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"
#include "window/main_window.h"

#include <QApplication>
#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QTimer>
#include <QtTest>

#include "keyboard_keys.h"
#include "projector_window.h"
#include "test_main.h"

using namespace rigidlab;
using rigidlab::test::FocusWatch;
using rigidlab::test::key;
using rigidlab::test::showActiveOnProjector;
using rigidlab::ui::MainWindow;

namespace {

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

class TestKeyboardLesson : public QObject {
    Q_OBJECT
private slots:
    void wholeLessonByKeyboard()
    {
        FocusWatch watch;
        MainWindow w;
        QVERIFY(showActiveOnProjector(w));

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

    // From the scene, one Tab reaches the step's answer (a box, or the question's options),
    // not the list of lessons and the step's text first; Tab from there goes on to the step's
    // own controls, Shift+Tab back to its text. Help › Controls says so. On a step that asks
    // nothing, Tab from the scene goes where it always goes.
    void tabFromTheSceneReachesTheAnswer_data()
    {
        QTest::addColumn<QString>("lesson");
        QTest::newRow("typed answers") << QStringLiteral("restitution.json");
        QTest::newRow("options") << QStringLiteral("tunnelling.json");
    }
    void tabFromTheSceneReachesTheAnswer()
    {
        QFETCH(QString, lesson);
        MainWindow w;
        QVERIFY(showActiveOnProjector(w));
        QCOMPARE(w.openLesson(test::shippedLessonFile(qPrintable(lesson)), true), QString());
        ui::LessonPlayer& player = w.lessonPlayer();
        auto* questions = w.findChild<QWidget*>(QStringLiteral("lessonQuestions"));
        QVERIFY(questions);
        int asked = 0;
        const int steps = static_cast<int>(player.lesson()->steps.size());
        for (int s = 0; s < steps; ++s) {
            player.goToStep(s);
            QCoreApplication::processEvents();
            const QString where = QStringLiteral("%1, step %2").arg(lesson).arg(s + 1);
            const bool asks =
                !player.lesson()->steps[static_cast<std::size_t>(s)].questions.empty();
            key(w, Qt::Key_F6);
            QCOMPARE(QApplication::focusWidget(), &w.view());
            key(w, Qt::Key_Tab); // one press
            QWidget* answer = QApplication::focusWidget();
            QVERIFY2(answer, qPrintable(where));
            if (!asks) {
                QVERIFY2(!questions->isAncestorOf(answer), qPrintable(where));
                continue;
            }
            ++asked;
            QVERIFY2(answer == player.firstAnswer() && questions->isAncestorOf(answer) &&
                         (qobject_cast<QLineEdit*>(answer) || qobject_cast<QRadioButton*>(answer)),
                     qPrintable(where + QStringLiteral(": the focus on ") +
                                QLatin1String(answer->metaObject()->className()) + u' ' +
                                answer->objectName()));
            key(w, Qt::Key_Tab);
            QWidget* next = QApplication::focusWidget();
            QVERIFY2(next && next != answer && next != &w.view() &&
                         answer->parentWidget()->parentWidget()->isAncestorOf(next),
                     qPrintable(where + QStringLiteral(": Tab from the answer to ") +
                                (next ? QLatin1String(next->metaObject()->className())
                                      : QLatin1String("nothing"))));
            key(w, Qt::Key_Tab, Qt::ShiftModifier);
            QCOMPARE(QApplication::focusWidget(), answer);
            key(w, Qt::Key_Tab, Qt::ShiftModifier);
            QVERIFY2(qobject_cast<QTextBrowser*>(QApplication::focusWidget()), qPrintable(where));
        }
        QVERIFY(asked > 0);
        QVERIFY(w.controlsHelpText().contains(
            QKeySequence(Qt::Key_Tab).toString(QKeySequence::NativeText).toHtmlEscaped()));
    }
};

RIGIDLAB_TEST_MAIN(TestKeyboardLesson)
#include "test_keyboard_lesson.moc"
