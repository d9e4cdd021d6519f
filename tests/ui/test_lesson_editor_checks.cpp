// SPDX-License-Identifier: GPL-3.0-or-later
// The lesson editor's checks that run the steps (ui/lesson_editor/step_checks.h): a step whose
// scene diverges with its settings is marked in words, a calm one is not, and a result for a
// lesson changed since is never shown. A teacher's own step: wait for Play, an end time, a hint,
// bodies by their labels, the prompt following the time; saved into her own lessons folder.

#include "test_lesson_editor.h"

#include "common/job_progress.h"
#include "view/world_view.h"

#include "format/data_dirs.h"
#include "format/lesson_catalog.h"

#include "question_kinds.h"
#include <QDoubleSpinBox>
#include <QPushButton>

using rigidlab::test::measuredOf;

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

/// A new lesson titled "Two balls meet" in `ed` on two balls with labels ("light ball", "heavy
/// ball") and a track; false when their scene does not load.
bool onTwoBalls(ui::LessonEditor& ed)
{
    const lessons::SceneLoadResult scene =
        lessons::loadSceneFile(kSource + QStringLiteral("/lessons/scenes/two_balls.json"));
    if (!scene.ok)
        return false;
    ed.newLesson(scene.scene);
    ed.draft().setText(-1, QStringLiteral("title"), QStringLiteral("en"),
                       QStringLiteral("Two balls meet"));
    return true;
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

// The checks' progress and Cancel under the problems, reached with the keyboard: Cancel stops
// the running checks, and what they would have found is never shown, also once the editor
// refreshes for a text typed; the problems say the steps were not checked.
void TestLessonEditor::cancelledStepChecksLeaveNoWarning()
{
    ui::LessonEditor ed;
    ed.show();
    QVERIFY(QTest::qWaitForWindowExposed(&ed));
    QVERIFY(onSprings(ed));
    QSignalSpy checked(&ed.stepChecks(), &ui::StepChecks::finished);
    if (ed.stepChecks().isRunning())
        QVERIFY(checked.wait(60'000));
    auto* progress = ed.findChild<ui::JobProgress*>(QStringLiteral("stepChecksProgress"));
    QVERIFY(progress != nullptr);
    QVERIFY(progress->isHidden());
    checked.clear();
    LessonDraft& d = ed.draft();
    d.setValue(0, QStringLiteral("settings"), hugeDt(), QStringLiteral("dt"));
    QVERIFY(ed.stepChecks().isRunning());
    QVERIFY(progress->isVisible());
    QPushButton* cancel = progress->cancelButton();
    QVERIFY(cancel->focusPolicy() & Qt::TabFocus);
    QCOMPARE(cancel->accessibleName(), QStringLiteral("Cancel checking the steps' scenes"));
    cancel->setFocus();
    QTest::keyClick(cancel, Qt::Key_Space);
    QVERIFY(checked.wait(60'000));
    QCOMPARE(checked.count(), 1);
    QVERIFY(!ed.stepChecks().isRunning());
    QVERIFY(ed.stepChecks().wasCancelled());
    QVERIFY(ed.stepChecks().findings().empty());
    QVERIFY(progress->isHidden());
    QVERIFY(!cancel->hasFocus());
    auto* steps = ed.findChild<QListWidget*>(QStringLiteral("lessonSteps"));
    QVERIFY(steps != nullptr);
    auto* problems = ed.findChild<QLabel*>(QStringLiteral("lessonProblems"));
    QVERIFY(problems != nullptr);
    for (int typed = 0; typed < 2; ++typed) {
        QVERIFY2(!steps->item(0)->toolTip().contains(QStringLiteral("diverged")),
                 qPrintable(steps->item(0)->toolTip()));
        QVERIFY2(!problems->text().contains(QStringLiteral("diverged")),
                 qPrintable(problems->text()));
        QVERIFY2(!problems->text().contains(QStringLiteral("Running")),
                 qPrintable(problems->text()));
        QVERIFY2(problems->text().contains(QStringLiteral("not checked")),
                 qPrintable(problems->text()));
        d.setText(0, QStringLiteral("text"), QStringLiteral("en"), QStringLiteral("Watch."));
        QVERIFY(!ed.stepChecks().isRunning());
    }
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
    // File › Back to the lesson editor is there while an editor is open, tried or not: it
    // brings the editor opened last to the front, at the step it shows.
    QVERIFY(back->isVisible());
    QCOMPARE(back->shortcuts().value(0), QKeySequence(QStringLiteral("Ctrl+Shift+L")));
    ed->selectStep(2);
    QApplication::setActiveWindow(&w);
    QTRY_COMPARE(QApplication::activeWindow(), static_cast<QWidget*>(&w));
    back->trigger();
    QTRY_COMPARE(QApplication::activeWindow(), static_cast<QWidget*>(ed));
    QCOMPARE(ed->currentStep(), 2);

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
    QVERIFY(back->isVisible()); // the editor is still open
    // Tried again, then another lesson opened: no way back to the step either.
    QTest::mouseClick(ed->findChild<QPushButton*>(QStringLiteral("tryAsStudent")), Qt::LeftButton);
    QVERIFY(bar->isVisible());
    const QStringList shipped = test::shippedLessons();
    QVERIFY(!shipped.isEmpty());
    QCOMPARE(w.openLesson(shipped.front(), true), QString());
    QVERIFY(!bar->isVisible());
    QVERIFY(back->isVisible());
    // Tried again, then the editor closed: nothing to go back to.
    QTest::mouseClick(ed->findChild<QPushButton*>(QStringLiteral("tryAsStudent")), Qt::LeftButton);
    QVERIFY(bar->isVisible());
    ed->draft().undoStack()->setClean(); // nothing to ask about on closing
    QVERIFY(ed->close());
    QTRY_VERIFY(!bar->isVisible());
    QTRY_VERIFY(!back->isVisible()); // no editor left to go back to
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

void TestLessonEditor::teachersOwnStep()
{
    QVERIFY(ui::applyLanguage(QStringLiteral("en")));
    ui::LessonEditor ed;
    QVERIFY(onTwoBalls(ed));
    LessonDraft& d = ed.draft();

    // A new step waits for Play; unticked, it starts at once.
    auto* wait = ed.stepSettings().waitForPlay();
    QVERIFY(wait != nullptr);
    QVERIFY(wait->isChecked());
    QCOMPARE(d.value(0, QStringLiteral("autoplay")), QJsonValue(false));
    wait->setChecked(false);
    QCOMPARE(d.value(0, QStringLiteral("autoplay")), QJsonValue(true));
    wait->setChecked(true);
    QCOMPARE(d.value(0, QStringLiteral("autoplay")), QJsonValue(false));
    ed.selectStep(0);
    QTest::mouseClick(ed.findChild<QPushButton*>(QStringLiteral("addStep")), Qt::LeftButton);
    QCOMPARE(d.value(1, QStringLiteral("autoplay")), QJsonValue(false));
    ed.selectStep(0);

    // The run's end time: typed, one edit, read by the loader; 0 takes it away.
    QDoubleSpinBox* end = ed.stepSettings().endTime();
    QVERIFY(end != nullptr);
    end->setValue(2.5);
    emit end->editingFinished();
    QCOMPARE(d.value(0, QStringLiteral("endTime")).toDouble(), 2.5);
    QString error;
    std::optional<lessons::Lesson> lesson = d.lesson(QStringLiteral("en"), error);
    QVERIFY2(lesson, qPrintable(error));
    QCOMPARE(lesson->steps[0].endTime, std::optional<double>(2.5));
    QVERIFY(!lesson->steps[0].autoplay);
}

void TestLessonEditor::teachersOwnQuestion()
{
    QVERIFY(ui::applyLanguage(QStringLiteral("en")));
    ui::LessonEditor ed;
    QVERIFY(onTwoBalls(ed));
    LessonDraft& d = ed.draft();
    QString error;

    // A measured question: its bodies listed by their labels, kept by their ids.
    QTest::mouseClick(ed.findChild<QPushButton*>(QStringLiteral("addMeasuredQuestion")),
                      Qt::LeftButton);
    auto* body = ed.findChild<QComboBox*>(QStringLiteral("questionBody"));
    QVERIFY(body != nullptr);
    QStringList shown;
    for (int i = 0; i < body->count(); ++i)
        shown << body->itemText(i);
    QCOMPARE(shown, (QStringList{QStringLiteral("light ball"), QStringLiteral("heavy ball")}));
    QCOMPARE(body->itemData(1).toString(), QStringLiteral("heavy"));

    // The prompt the editor wrote follows the body and the time chosen.
    const auto prompt = [&] {
        return d.value(0, QStringLiteral("questions"))
            .toArray()
            .at(0)
            .toObject()
            .value(u"prompt")
            .toObject()
            .value(u"en")
            .toString();
    };
    QVERIFY2(prompt().contains(QStringLiteral("light ball")), qPrintable(prompt()));
    body->setCurrentIndex(1);
    emit body->activated(1);
    auto* time = ed.findChild<QDoubleSpinBox*>(QStringLiteral("questionTime"));
    QVERIFY(time != nullptr);
    time->setValue(0.75);
    QVERIFY2(prompt().contains(QStringLiteral("heavy ball")), qPrintable(prompt()));
    QVERIFY2(prompt().contains(QStringLiteral("0.75")), qPrintable(prompt()));

    // A hint, per language; the player reads it.
    auto* hint = ed.findChild<QLineEdit*>(QStringLiteral("questionHint_en"));
    QVERIFY(hint != nullptr);
    hint->setFocus();
    QTest::keyClicks(hint, QStringLiteral("Momentum is kept."));
    const std::optional<lessons::Lesson> lesson = d.lesson(QStringLiteral("en"), error);
    QVERIFY2(lesson, qPrintable(error));
    QCOMPARE(lesson->steps[0].questions.at(0).hint, QStringLiteral("Momentum is kept."));
    QCOMPARE(measuredOf(lesson->steps[0].questions.at(0)).measure.body, QStringLiteral("heavy"));
    auto* answer = ed.findChild<QLabel*>(QStringLiteral("questionAnswer"));
    QVERIFY2(!answer->text().startsWith(u'⚠'), qPrintable(answer->text()));

    // Saved where Save As offers: the teacher's own lessons folder, named after the title, and
    // listed with her lessons.
    const QString path = ed.defaultSavePath();
    QCOMPARE(QFileInfo(path).absolutePath(),
             QFileInfo(lessons::userLessonsDir()).absoluteFilePath());
    QCOMPARE(QFileInfo(path).fileName(), QStringLiteral("two_balls_meet.rlesson"));
    QVERIFY(QDir().mkpath(lessons::userLessonsDir()));
    QCOMPARE(ed.saveAs(path), QString());
    bool listed = false;
    for (const lessons::LessonEntry& entry : lessons::allLessonsInOrder())
        listed = listed || (entry.own && entry.title == QStringLiteral("Two balls meet"));
    QVERIFY(listed);
    QVERIFY(ed.defaultSavePath() != path); // never over it
    QVERIFY(QFile::remove(path));
}
