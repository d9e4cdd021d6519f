// SPDX-License-Identifier: GPL-3.0-or-later
// A question's "set": the settings the student is asked to set before the run it measures.
// Read on top of the step's settings; a step that does not let the student make them loads,
// with a warning at the place.

#include "test_lesson.h"
#include "test_lesson_json.h"

#include <QTemporaryDir>

using namespace rigidlab;
using namespace rigidlab::test;
using namespace rigidlab::test::lesson_json;

void TestLesson::questionSetAsksForItsOwnRun()
{
    // Three questions ask the student to set something: one she can, one the step locks,
    // one that holds back the controls it needs. The lesson loads; the two mistakes warn at
    // their places.
    const char* speed = R"("measure": {"kind": "speed", "body": "ball", "time": 1})";
    const QString questions =
        QStringLiteral(R"("settings": {"dt": 0.002, "restitution": 0.5}, )"
                       R"("panels": ["controls"], "allow": ["restitution"], "questions": [)"
                       R"({"prompt": "a", %1, "set": {"restitution": 0}}, )"
                       R"({"prompt": "b", %1, "set": {"friction": 0.1, "restitution": 1}}, )"
                       R"({"prompt": "c", %1, "set": {"restitution": 1}, )"
                       R"("holdBack": ["panel:controls"]}, {"prompt": "d", %1}])")
            .arg(QString::fromUtf8(speed));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("lesson.json"));
    QVERIFY(writeFile(path, oneStep(qPrintable(questions))));
    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(path);
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    const QString q = path + QStringLiteral(": steps[0].questions[");
    QCOMPARE(loaded.warnings,
             (QStringList{q + QStringLiteral("1].set.friction: the student is asked to set "
                                             "friction, but this step locks it (\"allow\" does "
                                             "not list it)"),
                          q + QStringLiteral("2].set: the student is asked to set restitution "
                                             "with the controls, which this question holds back "
                                             "until it is answered")}));
    const lessons::LessonStep& step = loaded.lesson.steps[0];
    QVERIFY(lessons::asksSettings(step.questions[0]));
    QVERIFY(!lessons::asksSettings(step.questions[3]));
    // The asked run: the question's settings on top of the step's, the rest the step's.
    const lessons::LessonStep asked = lessons::askedStep(step, step.questions[1]);
    QCOMPARE(*asked.settings.get<double>("restitution"), 1.0);
    QCOMPARE(*asked.settings.get<double>("friction"), 0.1);
    QCOMPARE(*asked.settings.get<double>("dt"), 0.002);
    QCOMPARE(*lessons::askedStep(step, step.questions[3]).settings.get<double>("restitution"), 0.5);

    // Without the controls panel the student cannot set anything.
    QVERIFY(writeFile(path, oneStep(R"("questions": [{"prompt": "a", "measure": {"kind": "speed", )"
                                    R"("body": "ball", "time": 1}, "set": {"gravity": false}}])")));
    const lessons::LessonLoadResult noPanel = lessons::loadLessonFile(path);
    QVERIFY2(noPanel.ok, qPrintable(noPanel.error));
    QCOMPARE(noPanel.warnings,
             QStringList{q + QStringLiteral("0].set: the student is asked to set gravity with the "
                                            "controls, but this step does not show the controls "
                                            "panel")});
}
