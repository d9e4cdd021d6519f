// SPDX-License-Identifier: GPL-3.0-or-later
// The lesson editor's checks that run the steps (ui/lesson_editor/step_checks.h): a step whose
// scene diverges with its settings is marked in words, a calm one is not, and a result for a
// lesson changed since is never shown.

#include "test_lesson_editor.h"

namespace {

/// The spring oscillators (k = 40 N/m, m = 1 kg: omega = 6.3 rad/s), as a lesson's one step.
std::optional<lessons::Scene> springs()
{
    const lessons::SceneLoadResult scene =
        lessons::loadSceneFile(kSource + QStringLiteral("/lessons/scenes/spring_oscillator.json"));
    return scene.ok ? std::optional(scene.scene) : std::nullopt;
}

/// A dt of 0.5 s: omega dt = 3.2, past the 2 beyond which symplectic Euler's oscillation
/// grows at every step instead of turning round.
QJsonObject hugeDt()
{
    return QJsonObject{{QStringLiteral("dt"), 0.5}};
}

} // namespace

void TestLessonEditor::stepThatDivergesIsMarked()
{
    const std::optional<lessons::Scene> scene = springs();
    QVERIFY(scene);
    ui::LessonEditor ed;
    ed.newLesson(*scene);
    LessonDraft& d = ed.draft();
    QSignalSpy checked(&ed.stepChecks(), &ui::StepChecks::finished);
    d.addStep(0);
    d.setValue(1, QStringLiteral("settings"), hugeDt(), QStringLiteral("dt"));
    QVERIFY(checked.wait(60'000));
    const std::vector<ui::StepFinding>& findings = ed.stepChecks().findings();
    QCOMPARE(findings.size(), std::size_t{2});
    QVERIFY(!findings[0].divergence);
    QVERIFY(findings[1].divergence);
    QCOMPARE(findings[1].divergence->dt, 0.5);
    // In words, in the step list and the lesson's problems: the step, when, what.
    auto* steps = ed.findChild<QListWidget*>(QStringLiteral("lessonSteps"));
    QVERIFY(steps != nullptr);
    QVERIFY2(steps->item(1)->toolTip().contains(QStringLiteral("diverged at t = ")),
             qPrintable(steps->item(1)->toolTip()));
    QVERIFY2(steps->item(1)->text().contains(QStringLiteral("problem")),
             qPrintable(steps->item(1)->text()));
    QVERIFY2(!steps->item(0)->toolTip().contains(QStringLiteral("diverged")),
             qPrintable(steps->item(0)->toolTip()));
    const QString problems = ed.findChild<QLabel*>(QStringLiteral("lessonProblems"))->text();
    QVERIFY2(problems.contains(QStringLiteral("Step 2: The step's simulation, run with its "
                                              "settings, diverged at t = ")),
             qPrintable(problems));
    QVERIFY2(!problems.contains(QStringLiteral("Step 1: ")), qPrintable(problems));
}

void TestLessonEditor::staleStepChecksDropped()
{
    const std::optional<lessons::Scene> scene = springs();
    QVERIFY(scene);
    ui::LessonEditor ed;
    ed.newLesson(*scene);
    LessonDraft& d = ed.draft();
    QSignalSpy checked(&ed.stepChecks(), &ui::StepChecks::finished);
    // The diverging dt, taken back before its run could be shown: only the calm lesson's
    // check finishes.
    d.setValue(0, QStringLiteral("settings"), hugeDt(), QStringLiteral("dt"));
    QVERIFY(ed.stepChecks().isRunning());
    d.undoStack()->undo();
    QVERIFY(checked.wait(60'000));
    QCOMPARE(checked.count(), 1);
    QCOMPARE(ed.stepChecks().findings().size(), std::size_t{1});
    QVERIFY(!ed.stepChecks().findings()[0].divergence);
    // A text typed does not run the steps again.
    d.setText(0, QStringLiteral("text"), QStringLiteral("en"), QStringLiteral("Watch."));
    QVERIFY(!ed.stepChecks().isRunning());
    QCOMPARE(ed.stepChecks().findings().size(), std::size_t{1});
}
