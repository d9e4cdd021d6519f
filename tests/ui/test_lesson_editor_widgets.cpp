// SPDX-License-Identifier: GPL-3.0-or-later
// The lesson editor's window driven with keys and mouse, as a teacher would: texts and steps,
// undo, save and Try as a student, what a step shows and locks, questions, its screenshot.

#include "test_lesson_editor.h"

namespace {

template <typename W> W* child(QWidget& parent, const QString& name)
{
    W* w = parent.findChild<W*>(name);
    if (w == nullptr)
        qWarning("no %s", qPrintable(name));
    return w;
}

/// Types `text` into `field` as a teacher does: clicked, all selected (or the cursor put at the
/// end, to `append`), then the keys.
void typeInto(QWidget* field, const QString& text, bool append = false)
{
    QTest::mouseClick(field, Qt::LeftButton, {}, QPoint(5, 5));
    field->setFocus();
    if (append)
        QTest::keyClick(field, Qt::Key_End, Qt::ControlModifier);
    else
        QTest::keyClick(field, Qt::Key_A, Qt::ControlModifier);
    // Each character as a key with its text (QTest::keyClicks knows only ASCII).
    for (const QChar c : text) {
        QTest::sendKeyEvent(QTest::Press, field, Qt::Key_unknown, QString(c), {});
        QTest::sendKeyEvent(QTest::Release, field, Qt::Key_unknown, QString(c), {});
    }
}

} // namespace

void TestLessonEditor::widgetsTextsAndSteps()
{
    // File › New lesson in the window opens the editor on the scene open in it.
    m_window = std::make_unique<ui::MainWindow>();
    m_window->show();
    QCOMPARE(m_window->openScene(kSource + QStringLiteral("/lessons/scenes/four_balls.json"), true),
             QString());
    QAction* create = m_window->findChild<QAction*>(QStringLiteral("newLesson"));
    QVERIFY(create != nullptr);
    create->trigger();
    auto* ed = m_window->findChild<ui::LessonEditor*>(QStringLiteral("lessonEditor"));
    QVERIFY(ed != nullptr);
    m_editor = ed;
    ed->setAutosavePath(m_dir.filePath(QStringLiteral("autosave.rlesson")));
    QVERIFY(QTest::qWaitForWindowExposed(ed));
    ed->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(ed));
    LessonDraft& d = ed->draft();
    QCOMPARE(d.stepCount(), 1);

    // The lesson's title in both languages, its minutes.
    typeInto(child<QLineEdit>(*ed, QStringLiteral("lesson_title_cs")), QStringLiteral("Pády"));
    typeInto(child<QLineEdit>(*ed, QStringLiteral("lesson_title_en")), QStringLiteral("Drops"));
    QCOMPARE(d.text(-1, QStringLiteral("title"), QStringLiteral("cs")), QStringLiteral("Pády"));
    QCOMPARE(d.text(-1, QStringLiteral("title"), QStringLiteral("en")), QStringLiteral("Drops"));
    auto* minutes = child<QSpinBox>(*ed, QStringLiteral("lessonMinutes"));
    minutes->setFocus();
    QTest::keyClick(minutes, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(minutes, QStringLiteral("20"));
    QCOMPARE(d.value(-1, QStringLiteral("minutes")).toInt(), 20);

    // The first step's text in Czech only: English is marked missing, in the list too.
    typeInto(child<QLineEdit>(*ed, QStringLiteral("stepTitle_cs")), QStringLiteral("Sledujte"));
    typeInto(child<QPlainTextEdit>(*ed, QStringLiteral("stepText_cs")),
             QStringLiteral("Pusťte **míčky**."));
    QCOMPARE(d.text(0, QStringLiteral("text"), QStringLiteral("cs")),
             QStringLiteral("Pusťte **míčky**."));
    auto* preview = ed->findChild<QWidget*>(QStringLiteral("preview_cs"));
    QVERIFY(preview != nullptr);
    const QString shown = static_cast<QTextEdit*>(preview)->toPlainText();
    QVERIFY2(shown.contains(QStringLiteral("Pusťte míčky.")), qPrintable(shown)); // no stars
    auto* missingEn = child<QLabel>(*ed, QStringLiteral("missing_en"));
    QVERIFY(missingEn->isVisibleTo(ed));
    QVERIFY(!child<QLabel>(*ed, QStringLiteral("missing_cs"))->isVisibleTo(ed));
    auto* steps = child<QListWidget>(*ed, QStringLiteral("lessonSteps"));
    QVERIFY2(steps->item(0)->text().contains(u'⚠'), qPrintable(steps->item(0)->text()));
    typeInto(child<QLineEdit>(*ed, QStringLiteral("stepTitle_en")), QStringLiteral("Watch"));
    typeInto(child<QPlainTextEdit>(*ed, QStringLiteral("stepText_en")),
             QStringLiteral("Drop the balls."));
    QVERIFY(!missingEn->isVisibleTo(ed));
    QVERIFY2(!steps->item(0)->text().contains(u'⚠'), qPrintable(steps->item(0)->text()));

    // Steps: added by mouse and by key, duplicated, moved, removed.
    QTest::mouseClick(child<QPushButton>(*ed, QStringLiteral("addStep")), Qt::LeftButton);
    QCOMPARE(d.stepCount(), 2);
    QCOMPARE(ed->currentStep(), 1);
    typeInto(child<QLineEdit>(*ed, QStringLiteral("stepTitle_en")), QStringLiteral("Measure"));
    typeInto(child<QLineEdit>(*ed, QStringLiteral("stepTitle_cs")), QStringLiteral("Změřte"));
    steps->setFocus();
    QTest::keyClick(steps, Qt::Key_D, Qt::ControlModifier);
    QCOMPARE(d.stepCount(), 3);
    QCOMPARE(d.text(2, QStringLiteral("title"), QStringLiteral("en")), QStringLiteral("Measure"));
    QTest::keyClick(steps, Qt::Key_Up, Qt::AltModifier);
    QCOMPARE(ed->currentStep(), 1);
    QTest::keyClick(steps, Qt::Key_Up, Qt::AltModifier);
    QCOMPARE(ed->currentStep(), 0);
    QCOMPARE(d.text(0, QStringLiteral("title"), QStringLiteral("en")), QStringLiteral("Measure"));
    QTest::keyClick(steps, Qt::Key_Down, Qt::AltModifier);
    QCOMPARE(d.text(0, QStringLiteral("title"), QStringLiteral("en")), QStringLiteral("Watch"));
    QTest::keyClick(steps, Qt::Key_Delete, Qt::ControlModifier);
    QCOMPARE(d.stepCount(), 2);
}

void TestLessonEditor::widgetsUndoSaveAndTry()
{
    QVERIFY(m_editor != nullptr);
    ui::LessonEditor* ed = m_editor;
    ui::MainWindow& w = *m_window;
    LessonDraft& d = ed->draft();
    auto* steps = child<QListWidget>(*ed, QStringLiteral("lessonSteps"));
    steps->setFocus();
    // Undo and redo with the keys, in a text field too: one history, the lesson's.
    QTest::keyClick(steps, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(d.stepCount(), 3);
    QTest::keyClick(steps, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(d.stepCount(), 2);
    QTest::keyClick(steps, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(d.stepCount(), 3);
    auto* enText = child<QPlainTextEdit>(*ed, QStringLiteral("stepText_en"));
    ed->selectStep(0);
    typeInto(enText, QStringLiteral(" Now."), true);
    QCOMPARE(d.text(0, QStringLiteral("text"), QStringLiteral("en")),
             QStringLiteral("Drop the balls. Now."));
    QTest::keyClick(enText, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(d.text(0, QStringLiteral("text"), QStringLiteral("en")),
             QStringLiteral("Drop the balls."));
    QCOMPARE(enText->toPlainText(), QStringLiteral("Drop the balls."));

    // Autosave while unsaved; Save As, then Ctrl+S; reopened, the same lesson.
    QVERIFY(ed->autosave());
    QVERIFY(QFileInfo::exists(ed->autosavePath()));
    const QString path = m_dir.filePath(QStringLiteral("teacher.rlesson"));
    QCOMPARE(ed->saveAs(path), QString());
    QVERIFY(!d.isModified());
    QVERIFY(!ed->autosave()); // nothing unsaved
    typeInto(child<QLineEdit>(*ed, QStringLiteral("lesson_summary_en")), QStringLiteral("Balls."));
    QVERIFY(d.isModified());
    QTest::keyClick(steps, Qt::Key_S, Qt::ControlModifier);
    QVERIFY(!d.isModified());
    ui::LessonEditor again;
    QCOMPARE(again.open(path), QString());
    QCOMPARE(again.draft().stepCount(), 3);
    QCOMPARE(again.draft().text(-1, QStringLiteral("summary"), QStringLiteral("en")),
             QStringLiteral("Balls."));
    QCOMPARE(child<QLineEdit>(again, QStringLiteral("stepTitle_cs"))->text(),
             QStringLiteral("Sledujte"));

    // Try as a student from step 2: the window plays it there; the editor stays at it.
    ed->selectStep(1);
    QTest::mouseClick(child<QPushButton>(*ed, QStringLiteral("tryAsStudent")), Qt::LeftButton);
    QVERIFY(w.lessonPlayer().lesson() != nullptr);
    QCOMPARE(static_cast<int>(w.lessonPlayer().lesson()->steps.size()), 3);
    QCOMPARE(w.lessonPlayer().stepIndex(), 1);
    QCOMPARE(ed->currentStep(), 1);
}

// What a step shows and what the student may change, ticked with the keyboard: a plot shown,
// a control locked, the export time typed; each an edit that Ctrl+Z takes back, and the
// lesson the player reads has them.
void TestLessonEditor::widgetsShownAndLocked()
{
    QVERIFY(m_editor != nullptr);
    ui::LessonEditor* ed = m_editor;
    LessonDraft& d = ed->draft();
    ed->selectStep(0);
    auto* pages = child<QTabWidget>(*ed, QStringLiteral("stepPages"));
    for (int i = 0; i < pages->count(); ++i)
        if (pages->widget(i)->isAncestorOf(&ed->stepSettings()))
            pages->setCurrentIndex(i);
    QVERIFY(pages->currentWidget()->isAncestorOf(&ed->stepSettings()));
    ed->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(ed));
    ui::StepSettingsEditor& settings = ed->stepSettings();
    QCheckBox* energy = settings.box(QStringLiteral("plots"), QStringLiteral("energy"));
    QCheckBox* dt = settings.box(QStringLiteral("allow"), QStringLiteral("dt"));
    QVERIFY(energy != nullptr && dt != nullptr);
    const bool energyBefore = energy->isChecked();
    QVERIFY2(dt->isChecked(), "a new step lets the student change every control");
    const QJsonValue allowBefore = d.value(0, QStringLiteral("allow"));
    const QJsonValue timeBefore = d.value(0, QStringLiteral("exportTime"));

    dt->setFocus();
    QTest::keyClick(dt, Qt::Key_Space);
    QVERIFY(!dt->isChecked());
    const QJsonArray allow = d.value(0, QStringLiteral("allow")).toArray();
    QVERIFY2(!allow.isEmpty() && !allow.contains(QStringLiteral("dt")),
             qPrintable(QJsonDocument(allow).toJson(QJsonDocument::Compact)));
    QString error;
    std::optional<lessons::Lesson> lesson = d.lesson(QStringLiteral("en"), error);
    QVERIFY2(lesson.has_value(), qPrintable(error));
    QVERIFY(lesson->steps[0].allow.has_value());
    QVERIFY(!lesson->steps[0].allow->contains(QStringLiteral("dt")));
    QVERIFY(lesson->steps[0].allow->contains(QStringLiteral("integrator")));

    energy->setFocus();
    QTest::keyClick(energy, Qt::Key_Space);
    QCOMPARE(energy->isChecked(), !energyBefore);
    QCOMPARE(d.value(0, QStringLiteral("plots")).toArray().contains(QStringLiteral("energy")),
             !energyBefore);

    auto* time = child<QDoubleSpinBox>(*ed, QStringLiteral("stepExportTime"));
    time->setFocus();
    time->selectAll();
    QTest::keyClicks(time, QLocale().toString(2.5));
    QTest::keyClick(time, Qt::Key_Return);
    RL_VERIFY_NEAR(d.value(0, QStringLiteral("exportTime")).toDouble(), 2.5, 1e-12, 0.0);

    // Undone in turn: the time, the plot, the lock; each box shows the draft again.
    energy->setFocus();
    QCOMPARE(d.undoStack()->undoText(), tr("export time"));
    QTest::keyClick(energy, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(d.value(0, QStringLiteral("exportTime")), timeBefore);
    QTest::keyClick(energy, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(energy->isChecked(), energyBefore);
    QTest::keyClick(energy, Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(dt->isChecked());
    QCOMPARE(d.value(0, QStringLiteral("allow")), allowBefore);
    // Locked again for the lesson saved below.
    QTest::keyClick(energy, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(!dt->isChecked());
}

// A step's scene drawn in the window: the window's scene taken for step 2 (undoable), and
// step 1's scene sent to the window's scene editor.
void TestLessonEditor::widgetsStepSceneFromTheWindow()
{
    QVERIFY(m_editor != nullptr);
    ui::LessonEditor* ed = m_editor;
    LessonDraft& d = ed->draft();
    const auto stepBodies = [&d](int step) {
        QString error;
        const std::optional<lessons::Lesson> lesson = d.lesson(QStringLiteral("en"), error);
        QStringList ids;
        if (lesson)
            for (const physics::BodyDef& b :
                 lesson->steps[static_cast<std::size_t>(step)].scene.bodies)
                ids << QString::fromStdString(b.name);
        return ids;
    };
    const QStringList before = stepBodies(1);
    QCOMPARE(m_window->openScene(kSource + QStringLiteral("/lessons/scenes/two_balls.json"), true),
             QString());
    QStringList window;
    for (const physics::BodyDef& b : m_window->document()->scene().bodies)
        window << QString::fromStdString(b.name);
    QVERIFY(window != before);

    ed->selectStep(1);
    QTest::mouseClick(child<QPushButton>(*ed, QStringLiteral("takeWindowScene")), Qt::LeftButton);
    QCOMPARE(stepBodies(1), window);
    d.undoStack()->undo();
    QCOMPARE(stepBodies(1), before);
    d.undoStack()->redo();
    QCOMPARE(stepBodies(1), window);

    ed->selectStep(0);
    QTest::mouseClick(child<QPushButton>(*ed, QStringLiteral("editStepScene")), Qt::LeftButton);
    QStringList sent;
    for (const physics::BodyDef& b : m_window->document()->scene().bodies)
        sent << QString::fromStdString(b.name);
    QCOMPARE(sent, stepBodies(0));
    QVERIFY(m_window->editTools().editing());
    m_window->editTools().setEditing(false);
}

void TestLessonEditor::widgetsQuestions()
{
    QVERIFY(m_editor != nullptr);
    ui::LessonEditor* ed = m_editor;
    LessonDraft& d = ed->draft();
    ed->selectStep(0);
    const auto questions = [&d] { return d.value(0, QStringLiteral("questions")).toArray(); };

    // A measured question: the body from the scene's bodies, the quantity from a list.
    QTest::mouseClick(child<QPushButton>(*ed, QStringLiteral("addMeasuredQuestion")),
                      Qt::LeftButton);
    QCOMPARE(questions().size(), 1);
    auto* body = child<QComboBox>(*ed, QStringLiteral("questionBody"));
    QVERIFY(body->count() > 0);
    body->setFocus();
    QTest::keyClick(body, Qt::Key_End);
    const QString chosen = body->currentData().toString();
    QCOMPARE(questions().at(0).toObject().value(u"measure").toObject().value(u"body").toString(),
             chosen);
    auto* kind = child<QComboBox>(*ed, QStringLiteral("questionKind"));
    kind->setFocus();
    QTest::keyClick(kind, Qt::Key_Down); // speed → velocity x
    QCOMPARE(questions().at(0).toObject().value(u"measure").toObject().value(u"kind").toString(),
             QStringLiteral("velocity-x"));
    typeInto(child<QLineEdit>(*ed, QStringLiteral("questionPrompt_cs")),
             QStringLiteral("Jak rychle?"));
    QCOMPARE(questions().at(0).toObject().value(u"prompt").toObject().value(u"cs").toString(),
             QStringLiteral("Jak rychle?"));
    // A word mended in the middle: each key is an edit, and the cursor stays where it types.
    auto* promptCs = child<QLineEdit>(*ed, QStringLiteral("questionPrompt_cs"));
    promptCs->setFocus();
    promptCs->setCursorPosition(3);
    QTest::keyClicks(promptCs, QStringLiteral(" to"));
    QCOMPARE(promptCs->cursorPosition(), 6);
    QCOMPARE(questions().at(0).toObject().value(u"prompt").toObject().value(u"cs").toString(),
             QStringLiteral("Jak to rychle?"));
    // The lab's own answer beside the tolerance, or why it has none.
    const QString answer = child<QLabel>(*ed, QStringLiteral("questionAnswer"))->text();
    QVERIFY2(answer.contains(QStringLiteral("measures")) || answer.contains(u'⚠'),
             qPrintable(answer));

    // A predict-first question holds the run back; undone with the key, it is gone.
    QTest::mouseClick(child<QPushButton>(*ed, QStringLiteral("addPredictQuestion")),
                      Qt::LeftButton);
    QCOMPARE(questions().size(), 2);
    QVERIFY(
        questions().at(1).toObject().value(u"holdBack").toArray().contains(QStringLiteral("run")));
    QVERIFY(child<QCheckBox>(*ed, QStringLiteral("questionHoldRun"))->isChecked());
    // With a question's fields open the editor still fits a 1024×768 projector below its
    // title bar (at most 48 px): the pages scroll instead of growing the window.
    const QSize least = ed->minimumSizeHint();
    QVERIFY2(least.width() <= 1024 && least.height() <= 768 - 48,
             qPrintable(QStringLiteral("%1×%2 px").arg(least.width()).arg(least.height())));
    auto* steps = child<QListWidget>(*ed, QStringLiteral("lessonSteps"));
    steps->setFocus();
    QTest::keyClick(steps, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(questions().size(), 1);
    QTest::keyClick(steps, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(questions().size(), 2);
    QCOMPARE(ed->save(), QString());
    ui::LessonEditor again;
    QCOMPARE(again.open(ed->draft().path()), QString());
    QCOMPARE(again.draft().value(0, QStringLiteral("questions")).toArray().size(), 2);
    ed->close();
    m_window.reset();
}

void TestLessonEditor::screenshotOfTheEditor()
{
    // rigidlab --screenshots writes the lesson editor at the size asked for.
    ui::ScreenshotOptions options;
    options.folder = m_dir.filePath(QStringLiteral("shots"));
    options.size = QSize(1024, 768);
    options.welcome = false;
    options.lessons = QStringList{};
    const ui::ScreenshotResult r = ui::writeScreenshots(options);
    QVERIFY2(r.ok, qPrintable(r.error));
    QVERIFY2(r.files.contains(QStringLiteral("lesson-editor.png")), qPrintable(r.files.join(u' ')));
    const QImage image(m_dir.filePath(QStringLiteral("shots/lesson-editor.png")));
    QCOMPARE(image.size(), QSize(1024, 768));
}

// Alt and an underlined letter reach one control of the editor, in English and in Czech, on
// each page of the step (with a measured question's fields open, and a choice's).
void TestLessonEditor::editorMnemonicsAreUnique_data()
{
    QTest::addColumn<QString>("language");
    QTest::newRow("en") << QStringLiteral("en");
    QTest::newRow("cs") << QStringLiteral("cs");
}

void TestLessonEditor::editorMnemonicsAreUnique()
{
    QFETCH(QString, language);
    QVERIFY(ui::applyLanguage(language));
    const lessons::SceneLoadResult scene =
        lessons::loadSceneFile(kSource + QStringLiteral("/lessons/scenes/two_balls.json"));
    QVERIFY2(scene.ok, qPrintable(scene.error));
    QStringList clashes;
    {
        ui::LessonEditor ed;
        ed.newLesson(scene.scene);
        ed.show();
        auto* pages = child<QTabWidget>(ed, QStringLiteral("stepPages"));
        QTest::mouseClick(child<QPushButton>(ed, QStringLiteral("addMeasuredQuestion")),
                          Qt::LeftButton);
        for (int i = 0; i < pages->count(); ++i) {
            pages->setCurrentIndex(i);
            for (const QString& line : test::windowMnemonicClashes(ed))
                clashes << pages->tabText(i) + QStringLiteral(": ") + line;
        }
        pages->setCurrentIndex(0);
        auto* type = child<QComboBox>(ed, QStringLiteral("questionType"));
        QVERIFY(type != nullptr);
        type->setCurrentIndex(type->count() - 1); // a choice of answers
        for (const QString& line : test::windowMnemonicClashes(ed))
            clashes << QStringLiteral("choice: ") + line;
    }
    ui::applyLanguage(QStringLiteral("en"));
    clashes.removeDuplicates();
    QVERIFY2(clashes.isEmpty(), qPrintable(clashes.join(u'\n')));
}

namespace {

/// Clicks the button named `button` of the message box that opens next (a modal one).
void clickInNextBox(const QString& button)
{
    QTimer::singleShot(0, [button] {
        QWidget* modal = QApplication::activeModalWidget();
        auto* b = modal ? modal->findChild<QAbstractButton*>(button) : nullptr;
        QVERIFY2(b != nullptr, qPrintable(button));
        b->click();
    });
}

/// The button of a QMessageBox for a standard button, named so clickInNextBox finds it.
void nameStandardButtons()
{
    QTimer::singleShot(0, [] {
        if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget()))
            for (QAbstractButton* b : box->buttons())
                b->setObjectName(QString::number(box->standardButton(b)));
    });
}

} // namespace

// A lesson being written when the lab crashed (its editor gone without closing) is offered
// at the next New lesson: opened as unsaved work, and its autosave gone once it is saved.
void TestLessonEditor::keptLessonAfterACrash()
{
    const lessons::SceneLoadResult scene =
        lessons::loadSceneFile(kSource + QStringLiteral("/lessons/scenes/two_balls.json"));
    QVERIFY2(scene.ok, qPrintable(scene.error));
    QString kept;
    {
        auto crashed = std::make_unique<ui::LessonEditor>();
        kept = crashed->autosavePath();
        crashed->newLesson(scene.scene);
        crashed->draft().setText(-1, QStringLiteral("title"), QStringLiteral("cs"),
                                 QStringLiteral("Srážky"));
        QVERIFY(crashed->autosave());
    } // destroyed without closing, as a crash leaves it
    QVERIFY(QFileInfo::exists(kept));
    QCOMPARE(ui::LessonEditor::keptLessons(), QStringList{kept});

    ui::MainWindow w;
    auto* create = w.findChild<QAction*>(QStringLiteral("newLesson"));
    QVERIFY(create != nullptr);
    clickInNextBox(QStringLiteral("keptCancel")); // cancel: nothing opens, it stays
    create->trigger();
    QVERIFY(w.findChildren<ui::LessonEditor*>().isEmpty());
    QVERIFY(QFileInfo::exists(kept));

    clickInNextBox(QStringLiteral("keptOpen"));
    create->trigger();
    const QList<ui::LessonEditor*> editors = w.findChildren<ui::LessonEditor*>();
    QCOMPARE(editors.size(), 1);
    ui::LessonEditor* ed = editors.front();
    QCOMPARE(ed->draft().text(-1, QStringLiteral("title"), QStringLiteral("cs")),
             QStringLiteral("Srážky"));
    QVERIFY2(ed->draft().isModified(), "what was kept is unsaved work");
    QVERIFY2(ed->draft().path().isEmpty(), "Save asks where, not into the autosave");
    // Another New lesson while it is open asks nothing: the open editor holds the autosave's
    // lock, and writes its own file.
    QVERIFY(ed->autosave());
    QVERIFY(ui::LessonEditor::keptLessons().isEmpty());
    create->trigger();
    QCOMPARE(w.findChildren<ui::LessonEditor*>().size(), 2);
    delete w.findChildren<ui::LessonEditor*>().back();
    QCOMPARE(ed->saveAs(m_dir.filePath(QStringLiteral("kept"))), QString());
    QVERIFY2(!QFileInfo::exists(kept), "saved: the autosave is not needed any more");
    QVERIFY(!ed->draft().isModified());
    delete ed;
}

// Closing the window while the lesson editor has unsaved edits asks first, and Cancel keeps
// both open.
void TestLessonEditor::windowClosingAsksTheEditor()
{
    ui::MainWindow w;
    w.show();
    ui::LessonEditor* ed = w.editLesson(QString());
    QVERIFY(ed != nullptr);
    ed->draft().setText(-1, QStringLiteral("title"), QStringLiteral("en"),
                        QStringLiteral("Collisions"));
    QVERIFY(ed->draft().isModified());
    const QPointer<ui::LessonEditor> editor = ed;
    // Save, and the Save As that asks where cancelled: nothing is saved, so nothing closes.
    auto* rejectFileDialog = new QTimer(ed);
    rejectFileDialog->setInterval(10);
    connect(rejectFileDialog, &QTimer::timeout, rejectFileDialog, [rejectFileDialog] {
        if (auto* d = qobject_cast<QFileDialog*>(QApplication::activeModalWidget())) {
            d->reject();
            rejectFileDialog->stop();
        }
    });
    rejectFileDialog->start();
    nameStandardButtons();
    clickInNextBox(QString::number(QMessageBox::Save));
    QVERIFY2(!ed->close(), "the lesson is not saved yet");
    QVERIFY(!rejectFileDialog->isActive()); // the dialog came and was cancelled
    QVERIFY(editor->draft().isModified());
    nameStandardButtons();
    clickInNextBox(QString::number(QMessageBox::Cancel));
    QVERIFY2(!w.close(), "Cancel keeps the window open");
    QVERIFY(editor && editor->isVisible());
    QVERIFY(editor->draft().isModified());
    nameStandardButtons();
    clickInNextBox(QString::number(QMessageBox::Discard));
    QVERIFY(w.close());
    QVERIFY(editor.isNull() || !editor->isVisible());
}

// A tolerance tighter than what the integrators a student may choose measure is said in the
// step's problems, once the runs in the worker are done; with the integrator locked it is not.
void TestLessonEditor::toleranceTighterThanIntegrators()
{
    const lessons::SceneLoadResult scene =
        lessons::loadSceneFile(kSource + QStringLiteral("/lessons/scenes/spring_oscillator.json"));
    QVERIFY2(scene.ok, qPrintable(scene.error));
    ui::LessonEditor ed;
    ed.newLesson(scene.scene);
    LessonDraft& d = ed.draft();
    QSignalSpy checked(&ed.stepChecks(), &ui::StepChecks::finished);
    // Where the undamped block is at 5 s, to 1 %: explicit Euler's amplitude has grown by then.
    const QJsonObject question =
        QJsonDocument::fromJson(R"({"prompt": {"en": "Where?", "cs": "Kde?"},
        "measure": {"kind": "position-y", "body": "undamped", "time": 5},
        "unit": "m", "tolerance": 0.01})")
            .object();
    d.setValue(0, QStringLiteral("questions"), QJsonArray{question}, QStringLiteral("question"));
    d.setValue(0, QStringLiteral("exportTime"), 6, QStringLiteral("export time"));
    auto* problems = child<QLabel>(ed, QStringLiteral("lessonProblems"));
    auto* steps = child<QListWidget>(ed, QStringLiteral("lessonSteps"));
    QVERIFY(checked.wait(60'000));
    QCOMPARE(ed.stepChecks().findings().size(), std::size_t{1});
    QCOMPARE(ed.stepChecks().findings()[0].spreads.size(), std::size_t{1});
    QVERIFY2(problems->text().contains(QStringLiteral("Step 1: Question 1: the integrators")),
             qPrintable(problems->text()));
    QVERIFY2(steps->item(0)->toolTip().contains(QStringLiteral("integrators")),
             qPrintable(steps->item(0)->toolTip()));
    // Locked: the student cannot choose another integrator, so there is nothing to warn of.
    d.setValue(0, QStringLiteral("allow"), QJsonArray{QStringLiteral("timeScale")},
               QStringLiteral("lock"));
    QVERIFY(checked.wait(60'000));
    QVERIFY(ed.stepChecks().findings()[0].spreads.empty());
    QVERIFY2(!problems->text().contains(QStringLiteral("integrators")),
             qPrintable(problems->text()));
}
