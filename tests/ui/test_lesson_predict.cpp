// SPDX-License-Identifier: GPL-3.0-or-later
// Predict, then see: what a lesson question holds back (a panel, a column, the running of the
// scene) stays out of sight until the student has answered; a wrong first try reads the
// lesson's hint and not the value; a second try or "Show me" gives the value.

#include "lesson_player/lesson_panels.h"
#include "lesson_player/lesson_player.h"
#include "simulation/simulation_controller.h"
#include "window/main_window.h"

#include "format/lesson.h"
#include "run/measurements.h"

#include "near.h"
#include "test_files.h"
#include "test_main.h"

#include "question_kinds.h"
#include <QAction>
#include <QDockWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

using rigidlab::test::measuredOf;

using namespace rigidlab;
using rigidlab::test::writeFile;
using rigidlab::ui::MainWindow;

namespace {

/// Two equal balls, weightless, e = 1: "a" at 2 m/s hits "b" at rest head on at about
/// t = 0.65 s and stops, "b" leaves at 2 m/s. Question 0 asks b's velocity and holds back the
/// run and the inspector; question 1 asks a's and holds back the collision's "after" column.
const char* kLesson = R"({"rigidlab-lesson": 1, "title": "Predict", "steps": [{
  "title": "Two balls", "text": "Predict first.",
  "scene": {"rigidlab": 1, "world": {"gravity": [0, 0], "dt": 0.001, "restitution": 1},
    "bodies": [
      {"id": "a", "shape": {"type": "circle", "radius": 0.1}, "position": [-1, 0],
       "velocity": [2, 0], "mass": 1, "restitution": 1, "friction": 0},
      {"id": "b", "shape": {"type": "circle", "radius": 0.1}, "position": [0.5, 0],
       "mass": 1, "restitution": 1, "friction": 0}]},
  "panels": ["collision", "inspector"],
  "questions": [
    {"prompt": "b after?", "measure": {"kind": "velocity-x", "body": "b", "time": 1.5},
     "unit": "m/s", "tolerance": 0.02, "hint": "Equal masses swap their velocities.",
     "holdBack": ["run", "panel:inspector"]},
    {"prompt": "a after?", "measure": {"kind": "velocity-x", "body": "a", "time": 1.5},
     "unit": "m/s", "tolerance": 0.02, "absoluteTolerance": 0.02,
     "hint": "Momentum before is all a's.", "holdBack": ["column:collision.after"]}
  ]}]})";

QAction* actionNamed(MainWindow& w, const QString& text)
{
    for (QAction* a : w.findChildren<QAction*>())
        if (a->text() == text)
            return a;
    return nullptr;
}

/// Column c of a lesson table in its wide form, one cell per quantity, whichever form the
/// table's width shows.
QStringList column(const ui::FittingTable* table, int c)
{
    QStringList cells;
    for (const QStringList& row : table->wideText().rows)
        cells << (c < row.size() ? row[c] : QString());
    return cells;
}

} // namespace

class TestLessonPredict : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_path = m_dir.filePath(QStringLiteral("predict.json"));
        QVERIFY(writeFile(m_path, kLesson));
    }

    void heldBackStaysHiddenUntilTwoWrongTries()
    {
        MainWindow w;
        QCOMPARE(w.openLesson(m_path, true), QString());
        auto& player = w.lessonPlayer();
        auto& controller = w.controller();
        const lessons::LessonStep& step = player.lesson()->steps[0];
        // Before an answer: the inspector stays closed, the collision panel open, and the
        // scene does not run, even when Play is pressed.
        QVERIFY(w.dock(QStringLiteral("inspector"))->isHidden());
        QVERIFY(!w.dock(QStringLiteral("collision"))->isHidden());
        QVERIFY(!controller.isRunning());
        QAction* play = actionNamed(w, QObject::tr("Play"));
        QVERIFY(play);
        QVERIFY(!play->isEnabled());
        play->trigger();
        QVERIFY(!controller.isRunning());
        QCOMPARE(controller.world().time(), 0.0);

        // The value the answer is judged against, measured without the window.
        const std::optional<double> b =
            lessons::measureAhead(step, measuredOf(step.questions[0]).measure);
        QVERIFY(b);
        RL_VERIFY_NEAR(*b, 2.0, 0.02, 0); // equal masses, e = 1: b takes a's 2 m/s
        const QString bText = QString::number(*b, 'g', 3) + QStringLiteral("\u00a0m/\u2060s");

        // A wrong first try: the hint, not the value; everything stays held.
        player.answer(0, QStringLiteral("5"));
        QVERIFY2(player.result(0).contains(step.questions[0].hint), qPrintable(player.result(0)));
        QVERIFY2(!player.result(0).contains(bText), qPrintable(player.result(0)));
        QVERIFY(!player.result(0).contains(QStringLiteral("measured")));
        QVERIFY(w.dock(QStringLiteral("inspector"))->isHidden());
        QVERIFY(!controller.isRunning());
        QVERIFY(!play->isEnabled());

        // A wrong second try: the value, said as what the held run will measure, and the
        // inspector and the run are released.
        player.answer(0, QStringLiteral("4"));
        QVERIFY2(player.result(0).contains(QStringLiteral("will measure ") + bText),
                 qPrintable(player.result(0)));
        QVERIFY(!w.dock(QStringLiteral("inspector"))->isHidden());
        QVERIFY(play->isEnabled());
        QVERIFY(controller.isRunning()); // predicted, now see
        QVERIFY(!player.heldBack().contains(QStringLiteral("run")));

        // The second question still holds back the "after" column: run past the hit.
        controller.setRunning(false);
        while (controller.world().time() < 1.6)
            controller.stepForward();
        QVERIFY(!controller.lessonWatch().measurements().collisions().empty());
        ui::CollisionPanel& panel = w.collisionPanel();
        panel.refresh();
        const ui::FittingTable* table = panel.table();
        QVERIFY(table->wideText().rows.size() >= 4);
        for (const QString& cell : column(table, 2))
            QVERIFY2(cell.isEmpty() || cell == QStringLiteral("?"), qPrintable(cell));
        bool numbers = false;
        for (const QString& cell : column(table, 1))
            numbers = numbers || cell.contains(QRegularExpression(QStringLiteral("[0-9]")));
        QVERIFY(numbers); // "before" stays

        // Show me: the value now, measured by the run in the window; the column fills in.
        player.showMe(1);
        QVERIFY2(player.result(1).startsWith(QStringLiteral("The simulation measured")),
                 qPrintable(player.result(1)));
        QVERIFY(player.heldBack().isEmpty());
        numbers = false;
        for (const QString& cell : column(table, 2)) {
            QVERIFY(cell != QStringLiteral("?"));
            numbers = numbers || cell.contains(QRegularExpression(QStringLiteral("[0-9]")));
        }
        QVERIFY(numbers);
    }

    void rightAnswerReleasesAtOnce()
    {
        MainWindow w;
        QCOMPARE(w.openLesson(m_path, true), QString());
        auto& player = w.lessonPlayer();
        const lessons::LessonStep& step = player.lesson()->steps[0];
        const std::optional<double> b =
            lessons::measureAhead(step, measuredOf(step.questions[0]).measure);
        QVERIFY(b);
        QVERIFY(w.dock(QStringLiteral("inspector"))->isHidden());
        player.answer(0, QString::number(*b, 'g', 10));
        QVERIFY2(player.result(0).startsWith(QStringLiteral("Right")),
                 qPrintable(player.result(0)));
        QVERIFY(!w.dock(QStringLiteral("inspector"))->isHidden());
        QVERIFY(w.controller().isRunning());
        // The run in the window measures what the run ahead did.
        w.controller().setRunning(false);
        while (w.controller().world().time() < 1.6)
            w.controller().stepForward();
        const auto live = w.controller().lessonWatch().measurements().value(
            measuredOf(step.questions[0]).measure, step.scene);
        QVERIFY(live);
        QCOMPARE(*live, *b);
        // Restarting the step holds it all back again.
        player.restartStep();
        QVERIFY(w.dock(QStringLiteral("inspector"))->isHidden());
        QVERIFY(!w.controller().isRunning());
        QCOMPARE(player.heldBack().size(), 3);
    }

    void showMeBeforeTheRunMeasuresAhead()
    {
        MainWindow w;
        QCOMPARE(w.openLesson(m_path, true), QString());
        auto& player = w.lessonPlayer();
        player.showMe(0);
        // Measured ahead: said as what the run, still at t = 0, will measure.
        QCOMPARE(w.controller().world().time(), 0.0);
        QVERIFY2(player.result(0).startsWith(
                     QStringLiteral("When it runs, the simulation will measure 2")),
                 qPrintable(player.result(0)));
        QVERIFY(!w.dock(QStringLiteral("inspector"))->isHidden());
        QVERIFY(w.controller().isRunning());
        // Leaving the lesson gives Play back.
        player.goToStep(0);
        QVERIFY(!actionNamed(w, QObject::tr("Play"))->isEnabled());
        player.closeLesson();
        QVERIFY(actionNamed(w, QObject::tr("Play"))->isEnabled());
    }

    void shippedRestitutionStepsHoldBack()
    {
        // The teacher's case: restitution step 2 shows the collision panel without the
        // velocities after the hit until both are answered; step 3 shows its controls once
        // answered.
        MainWindow w;
        QCOMPARE(w.openLesson(
                     QDir(MainWindow::lessonsFolder()).filePath(QStringLiteral("restitution.json")),
                     true),
                 QString());
        auto& player = w.lessonPlayer();
        player.goToStep(1);
        QVERIFY(!w.dock(QStringLiteral("collision"))->isHidden());
        for (int k = 0; k < 1500; ++k)
            w.controller().stepForward();
        QVERIFY(!w.controller().lessonWatch().measurements().collisions().empty());
        w.collisionPanel().refresh();
        for (const QString& cell : column(w.collisionPanel().table(), 2))
            QVERIFY2(cell.isEmpty() || cell == QStringLiteral("?"), qPrintable(cell));
        player.goToStep(2);
        QVERIFY(w.dock(QStringLiteral("controls"))->isHidden());
        // Show me needs the value: before the run gets there it says so and holds on.
        player.showMe(0);
        QVERIFY2(player.result(0).startsWith(QStringLiteral("Run the simulation")),
                 qPrintable(player.result(0)));
        QVERIFY(w.dock(QStringLiteral("controls"))->isHidden());
        for (int k = 0; k < 1600; ++k)
            w.controller().stepForward();
        player.showMe(0);
        QVERIFY2(player.result(0).startsWith(QStringLiteral("The simulation measured")),
                 qPrintable(player.result(0)));
        QVERIFY(!w.dock(QStringLiteral("controls"))->isHidden());
    }

    void unmeasurableAheadLetsTheSceneRun()
    {
        // A ball with no floor never bounces: the run ahead cannot measure its apex within the
        // step's export time, so the answer lets the scene run instead of leaving the student
        // stuck.
        const QString path = m_dir.filePath(QStringLiteral("nofloor.json"));
        QVERIFY(writeFile(path, R"({"rigidlab-lesson": 1, "title": "t", "steps": [{"title": "s",
          "scene": {"rigidlab": 1, "bodies": [{"id": "ball",
            "shape": {"type": "circle", "radius": 0.1}, "position": [0, 1]}]},
          "exportTime": 0.1,
          "questions": [{"prompt": "p", "measure": {"kind": "apex", "body": "ball"},
            "unit": "m", "hint": "h", "holdBack": ["run"]}]}]})"));
        MainWindow w;
        QCOMPARE(w.openLesson(path, true), QString());
        QVERIFY(!w.controller().isRunning());
        w.lessonPlayer().answer(0, QStringLiteral("1"));
        QVERIFY2(w.lessonPlayer().result(0).startsWith(QStringLiteral("Run the simulation")),
                 qPrintable(w.lessonPlayer().result(0)));
        QVERIFY(w.lessonPlayer().heldBack().isEmpty());
        QVERIFY(w.controller().isRunning());
    }

private:
    QTemporaryDir m_dir;
    QString m_path;
};

RIGIDLAB_TEST_MAIN(TestLessonPredict)
#include "test_lesson_predict.moc"
