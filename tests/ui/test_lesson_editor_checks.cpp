// SPDX-License-Identifier: GPL-3.0-or-later
// The lesson editor's checks that run the steps (ui/lesson_editor/step_checks.h): a step whose
// scene diverges with its settings is marked in words, a calm one is not, and a result for a
// lesson changed since is never shown.

#include "test_lesson_editor.h"

#include "view/world_view.h"

namespace {

/// A new lesson in `ed` whose one step is the spring oscillators (k = 40 N/m, m = 1 kg:
/// omega = 6.3 rad/s); false when their scene does not load.
bool onSprings(ui::LessonEditor& ed)
{
    const lessons::SceneLoadResult scene =
        lessons::loadSceneFile(kSource + QStringLiteral("/lessons/scenes/spring_oscillator.json"));
    if (scene.ok)
        ed.newLesson(scene.scene);
    return scene.ok;
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
    ui::LessonEditor ed;
    QVERIFY(onSprings(ed));
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
    ui::LessonEditor ed;
    QVERIFY(onSprings(ed));
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

// Try as a student from the editor, and back: the window shows the way back while that lesson
// plays (a bar and a key), which raises the editor at the step the student is on; another
// lesson or a scene opened takes it away.
void TestLessonEditor::tryAndBackToTheEditor()
{
    ui::MainWindow w;
    w.setUnsavedAsker([] { return int(QMessageBox::Discard); });
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    ui::LessonEditor* ed = w.editLesson(QString());
    QVERIFY(ed != nullptr);
    ed->draft().addStep(0);
    ed->draft().addStep(1);
    auto* back = w.findChild<QAction*>(QStringLiteral("backToLessonEditor"));
    QVERIFY(back != nullptr);
    QVERIFY(!back->isVisible()); // nothing tried yet
    QCOMPARE(back->shortcuts().value(0), QKeySequence(QStringLiteral("Ctrl+Shift+L")));

    ed->selectStep(1);
    QTest::mouseClick(ed->findChild<QPushButton*>(QStringLiteral("tryAsStudent")), Qt::LeftButton);
    QCOMPARE(w.lessonPlayer().stepIndex(), 1);
    auto* bar = w.findChild<QToolBar*>(QStringLiteral("backToLessonEditorBar"));
    QVERIFY(bar != nullptr);
    QVERIFY(bar->isVisible());
    QVERIFY(back->isVisible());
    // The student goes on to the last step; the editor, meanwhile, shows the first.
    w.lessonPlayer().goToStep(2);
    ed->selectStep(0);
    auto* button = qobject_cast<QToolButton*>(bar->widgetForAction(back));
    QVERIFY(button != nullptr);
    QCOMPARE(button->accessibleName().isEmpty() ? button->text() : button->accessibleName(),
             QStringLiteral("Back to the lesson editor"));
    QTest::mouseClick(button, Qt::LeftButton);
    QCOMPARE(ed->currentStep(), 2);
    QVERIFY(ed->isVisible());
    QTRY_COMPARE(QApplication::activeWindow(), static_cast<QWidget*>(ed));
    QVERIFY(bar->isVisible()); // the lesson still plays: the way back stays

    // The key, from the window (the scene has the focus: a field would take the letter that
    // QTest sends with Ctrl, which a real keyboard does not).
    w.lessonPlayer().goToStep(1);
    QApplication::setActiveWindow(&w); // the editor, a window of the window's, stays active else
    QTRY_COMPARE(QApplication::activeWindow(), static_cast<QWidget*>(&w));
    w.view().setFocus();
    QTest::keyClick(&w.view(), Qt::Key_L, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(ed->currentStep(), 1);

    // A scene opened leaves the lesson: no way back.
    QCOMPARE(w.openScene(kSource + QStringLiteral("/lessons/scenes/spring_oscillator.json"), true),
             QString());
    QVERIFY(!bar->isVisible());
    QVERIFY(!back->isVisible());
    // Tried again, then another lesson opened: no way back either.
    QTest::mouseClick(ed->findChild<QPushButton*>(QStringLiteral("tryAsStudent")), Qt::LeftButton);
    QVERIFY(bar->isVisible());
    const QStringList shipped = test::shippedLessons();
    QVERIFY(!shipped.isEmpty());
    QCOMPARE(w.openLesson(shipped.front(), true), QString());
    QVERIFY(!bar->isVisible());
    QVERIFY(!back->isVisible());
    // Tried again, then the editor closed: nothing to go back to.
    QTest::mouseClick(ed->findChild<QPushButton*>(QStringLiteral("tryAsStudent")), Qt::LeftButton);
    QVERIFY(bar->isVisible());
    ed->draft().undoStack()->setClean(); // nothing to ask about on closing
    QVERIFY(ed->close());
    QTRY_VERIFY(!bar->isVisible());
}

void TestLessonEditor::questionAsksTheStudentToSet()
{
    // A measured question that asks the student to set e = 0 first: chosen from the
    // settings' list, the value typed; a step without the controls is a problem, named.
    ui::LessonEditor ed;
    QVERIFY(onSprings(ed));
    LessonDraft& d = ed.draft();
    ed.selectStep(0);
    auto* add = ed.findChild<QPushButton*>(QStringLiteral("addMeasuredQuestion"));
    QVERIFY(add != nullptr);
    QTest::mouseClick(add, Qt::LeftButton);
    auto* czech = ed.findChild<QLineEdit*>(QStringLiteral("questionPrompt_cs"));
    QVERIFY(czech != nullptr);
    czech->setFocus();
    QTest::keyClicks(czech, QStringLiteral("Jak rychle?"));
    auto* key = ed.findChild<QComboBox*>(QStringLiteral("questionSetKey"));
    QVERIFY(key != nullptr);
    const int restitution = key->findData(QStringLiteral("restitution"));
    QVERIFY(restitution > 0);
    key->setCurrentIndex(restitution);
    emit key->activated(restitution);
    auto* value = ed.findChild<QLineEdit*>(QStringLiteral("questionSetNumber"));
    QVERIFY(value != nullptr);
    value->setFocus();
    value->selectAll();
    QTest::keyClicks(value, QStringLiteral("0.25"));
    QTest::keyClick(value, Qt::Key_Return);
    const auto set = [&d] {
        return d.value(0, QStringLiteral("questions"))
            .toArray()
            .at(0)
            .toObject()
            .value(u"set")
            .toObject();
    };
    QCOMPARE(set(), (QJsonObject{{QStringLiteral("restitution"), 0.25}}));
    const LessonDraft::Check check = d.check(QStringLiteral("en"));
    QVERIFY2(check.error.isEmpty(), qPrintable(check.error));
    QVERIFY2(check.warnings.join(u'\n').contains(
                 QStringLiteral("questions[0].set: the student is asked to set restitution with "
                                "the controls, but this step does not show the controls panel")),
             qPrintable(check.warnings.join(u'\n')));
    // Each change is one undo step: the value typed, then the setting chosen (at the start
    // of its range).
    d.undoStack()->undo();
    QCOMPARE(set(), (QJsonObject{{QStringLiteral("restitution"), 0.0}}));
    d.undoStack()->undo();
    QVERIFY(set().isEmpty());
    d.undoStack()->redo();
    d.undoStack()->redo();
    QCOMPARE(set(), (QJsonObject{{QStringLiteral("restitution"), 0.25}}));
    // "Nothing" removes the key.
    key->setCurrentIndex(0);
    emit key->activated(0);
    QVERIFY(set().isEmpty());
    QVERIFY(!d.value(0, QStringLiteral("questions")).toArray().at(0).toObject().contains(u"set"));
}
