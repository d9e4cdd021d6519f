// SPDX-License-Identifier: GPL-3.0-or-later
// A question that asks the student to set something first ("set e = 0 and run again") is
// judged on the window's run only when it is the run asked for; otherwise Check says what
// differs. Where the step locks the setting, the asked run is done without the window.

#include "lesson_player/lesson_player.h"
#include "simulation/simulation_controller.h"
#include "window/main_window.h"

#include "format/lesson.h"
#include "run/measurements.h"

#include "near.h"
#include "test_files.h"
#include "test_main.h"

#include "question_kinds.h"
#include <QTemporaryDir>
#include <QtTest>

using rigidlab::test::measuredOf;

using namespace rigidlab;
using rigidlab::test::writeFile;
using rigidlab::ui::MainWindow;

namespace {

/// Two equal weightless balls, e = 1: "a" at 2 m/s hits "b" at rest at about t = 0.65 s.
/// Both steps ask b's velocity after the hit with e = 0 (both then move at 1 m/s); the first
/// lets the student set e, the second locks it.
const char* kLesson = R"({"rigidlab-lesson": 1, "title": "Asked", "steps": [{
  "title": "Set e", "text": "Set e = 0.",
  "scene": {"rigidlab": 1, "world": {"gravity": [0, 0], "dt": 0.001, "restitution": 1},
    "bodies": [
      {"id": "a", "shape": {"type": "circle", "radius": 0.1}, "position": [-1, 0],
       "velocity": [2, 0], "mass": 1, "friction": 0},
      {"id": "b", "shape": {"type": "circle", "radius": 0.1}, "position": [0.5, 0],
       "mass": 1, "friction": 0}]},
  "settings": {"restitution": 1}, "autoplay": false,
  "panels": ["controls"], "allow": ["restitution"],
  "questions": [
    {"prompt": "b after, with e = 0?", "measure": {"kind": "velocity-x", "body": "b",
     "time": 1.5}, "unit": "m/s", "tolerance": 0.02, "set": {"restitution": 0}}
  ]}, {
  "title": "Locked", "text": "e is locked.", "scene": "inline-copy", "autoplay": false,
  "panels": ["controls"], "allow": [],
  "questions": [
    {"prompt": "b after, with e = 0?", "measure": {"kind": "velocity-x", "body": "b",
     "time": 1.5}, "unit": "m/s", "tolerance": 0.02, "set": {"restitution": 0}}
  ]}]})";

void runTo(ui::SimulationController& c, double t)
{
    while (c.world().time() < t)
        c.stepForward();
}

} // namespace

class TestLessonAskedRun : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        // The second step's scene is the first one's.
        QByteArray json(kLesson);
        const qsizetype from = json.indexOf("{\"rigidlab\": 1");
        const qsizetype to = json.indexOf("]},", from) + 2;
        json.replace("\"inline-copy\"", json.mid(from, to - from));
        m_path = m_dir.filePath(QStringLiteral("asked.json"));
        QVERIFY(writeFile(m_path, json));
    }

    void checkSaysWhatDiffersUntilTheRunIsTheAskedOne()
    {
        MainWindow w;
        QCOMPARE(w.openLesson(m_path, true), QString());
        auto& player = w.lessonPlayer();
        auto& controller = w.controller();
        const lessons::LessonStep& step = player.lesson()->steps[0];
        const lessons::Question& q = step.questions[0];
        // The asked run measures the textbook value; the step's own (e = 1) another.
        const std::optional<double> asked =
            lessons::measureAhead(lessons::askedStep(step, q), measuredOf(q).measure);
        QVERIFY(asked);
        RL_VERIFY_NEAR(*asked, 1.0, 0.02, 0); // equal masses stuck together share 2 m/s
        const std::optional<double> own = lessons::measureAhead(step, measuredOf(q).measure);
        QVERIFY(own);
        RL_VERIFY_NEAR(*own, 2.0, 0.02, 0);

        // Run with e = 1: Check is not judged; it says what to set. No try is counted.
        runTo(controller, 1.6);
        player.answer(0, QStringLiteral("1"));
        QVERIFY2(player.result(0).contains(QStringLiteral("asked with Restitution e = 0")),
                 qPrintable(player.result(0)));
        QVERIFY2(player.result(0).contains(QStringLiteral("Restitution e is 1, not 0")),
                 qPrintable(player.result(0)));
        QVERIFY(!player.result(0).contains(QStringLiteral("Right")));
        QVERIFY(player.work().tries.at(0).empty());

        // e = 0 set in the middle of the run: still not that run.
        controller.setRestitution(0);
        player.answer(0, QStringLiteral("1"));
        QVERIFY2(player.result(0).contains(QStringLiteral("was changed during the run")),
                 qPrintable(player.result(0)));
        QVERIFY(player.work().tries.at(0).empty());

        // Reset keeps e = 0 from the start: now the window's run is judged.
        controller.reset();
        runTo(controller, 1.6);
        const auto live =
            controller.lessonWatch().measurements().value(measuredOf(q).measure, step.scene);
        QVERIFY(live);
        QCOMPARE(*live, *asked);
        player.answer(0, QStringLiteral("1"));
        QVERIFY2(player.result(0).startsWith(QStringLiteral("Right: the simulation measured")),
                 qPrintable(player.result(0)));
        QCOMPARE(player.work().tries.at(0).size(), std::size_t{1});
    }

    void lockedSettingIsJudgedByTheAskedRunAhead()
    {
        MainWindow w;
        QCOMPARE(w.openLesson(m_path, true), QString());
        auto& player = w.lessonPlayer();
        player.goToStep(1);
        // The lesson says it is a mistake, and the student is not left stuck: the asked run,
        // done without the window, judges the answer.
        player.answer(0, QStringLiteral("1"));
        QVERIFY2(player.result(0).contains(QStringLiteral("does not let you set")),
                 qPrintable(player.result(0)));
        QVERIFY2(player.result(0).contains(QStringLiteral("Right: when it runs")),
                 qPrintable(player.result(0)));
        QCOMPARE(w.controller().world().time(), 0.0);
    }

private:
    QTemporaryDir m_dir;
    QString m_path;
};

RIGIDLAB_TEST_MAIN(TestLessonAskedRun)
#include "test_lesson_asked_run.moc"
