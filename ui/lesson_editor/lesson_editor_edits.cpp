// SPDX-License-Identifier: GPL-3.0-or-later
// The lesson editor's window: edits made through its fields and buttons, and what it shows
// read back from the draft after each one (an edit, an undo, a redo, an open).
#include "lesson_editor/lesson_editor.h"
#include "lesson_editor/question_editor.h"
#include "lesson_editor/step_checks.h"
#include "lesson_editor/step_settings_editor.h"
#include "lesson_player/step_text.h"
#include "question_kinds/editor_parts.h"

#include "format/data_dirs.h"
#include "format/scene_schema.h"
#include "run/measurements.h"

#include <QAction>
#include <QCloseEvent>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QLockFile>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QSpinBox>
#include <QStyle>
#include <QTemporaryDir>
#include <QUndoStack>

namespace rigidlab::ui {

namespace {

/// The code of the editor's column `language` (editorLanguages: the window's first).
QString codeOf(int language)
{
    return editorLanguages()[static_cast<std::size_t>(language)];
}

constexpr int kColumns = static_cast<int>(kEditorLanguages);

} // namespace

QString LessonEditor::open(const QString& path)
{
    const QString error = m_draft.open(path);
    selectStep(0);
    return error;
}

QString LessonEditor::openKept(const QString& path)
{
    const QString error = m_draft.openKept(path);
    selectStep(0);
    if (error.isEmpty()) {
        discardAutosave(); // its own, if it wrote one: the kept lesson replaced it
        m_autosavePath = QFileInfo(path).absoluteFilePath();
        lockAutosave();
    }
    return error;
}

void LessonEditor::newLesson(const lessons::Scene& scene)
{
    m_draft.newLesson(tr("New lesson"), scene);
    selectStep(0);
}

int LessonEditor::currentStep() const
{
    return m_steps->currentRow();
}

void LessonEditor::selectStep(int index)
{
    m_steps->setCurrentRow(std::clamp(index, 0, std::max(m_draft.stepCount() - 1, 0)));
    refreshStepTexts();
}

void LessonEditor::addStep()
{
    const int at = currentStep();
    m_draft.addStep(at);
    selectStep(at + 1);
}

void LessonEditor::removeStep()
{
    const int at = currentStep();
    if (at < 0 || m_draft.stepCount() <= 1)
        return; // a lesson keeps at least one step
    m_draft.removeStep(at);
    selectStep(at);
}

void LessonEditor::moveUp()
{
    const int at = currentStep();
    if (at <= 0)
        return;
    m_draft.moveStep(at, at - 1);
    selectStep(at - 1);
}

void LessonEditor::moveDown()
{
    const int at = currentStep();
    if (at < 0 || at + 1 >= m_draft.stepCount())
        return;
    m_draft.moveStep(at, at + 1);
    selectStep(at + 1);
}

void LessonEditor::duplicateStep()
{
    const int at = currentStep();
    if (at < 0)
        return;
    m_draft.duplicateStep(at);
    selectStep(at + 1);
}

QString LessonEditor::save()
{
    if (m_draft.path().isEmpty()) {
        saveAsDialog();
        return {};
    }
    const QString error = m_draft.save();
    if (!error.isEmpty())
        QMessageBox::warning(this, tr("Save lesson"), error);
    else
        discardAutosave(); // the file holds it all now
    updateTitle();
    return error;
}

QString LessonEditor::saveAs(const QString& path)
{
    QString target = path;
    if (!target.endsWith(QStringLiteral(".rlesson"), Qt::CaseInsensitive))
        target += QStringLiteral(".rlesson");
    const QString error = m_draft.saveAs(target);
    if (error.isEmpty())
        discardAutosave();
    updateTitle();
    return error;
}

QString LessonEditor::defaultSavePath() const
{
    // Named after the lesson's title, in the teacher's own lessons folder, where the window's
    // Lessons list finds it; never over a lesson already there.
    const QDir folder(lessons::userLessonsDir());
    const QString stem = lessons::schema::safeFileStem(
        shownText(m_draft.value(-1, QStringLiteral("title"))), tr("lesson"));
    QString path = folder.filePath(stem + QStringLiteral(".rlesson"));
    for (int n = 2; QFileInfo::exists(path); ++n)
        path = folder.filePath(QStringLiteral("%1_%2.rlesson").arg(stem).arg(n));
    return path;
}

void LessonEditor::saveAsDialog()
{
    const QString start = m_draft.path().isEmpty() ? defaultSavePath() : m_draft.path();
    const QString path = QFileDialog::getSaveFileName(this, tr("Save lesson as"), start,
                                                      tr("Lessons in one file (*.rlesson)"));
    if (path.isEmpty())
        return;
    QDir().mkpath(QFileInfo(path).absolutePath());
    const QString error = saveAs(path);
    if (!error.isEmpty())
        QMessageBox::warning(this, tr("Save lesson"), error);
}

bool LessonEditor::autosave()
{
    if (!m_draft.isModified() || m_autosavePath.isEmpty())
        return false;
    QDir().mkpath(QFileInfo(m_autosavePath).absolutePath());
    lockAutosave(); // before the file is there, so that no other editor offers it
    return m_draft.writeCopy(m_autosavePath).isEmpty();
}

void LessonEditor::lockAutosave()
{
    if (m_autosaveLock && m_autosaveLock->isLocked())
        return;
    m_autosaveLock = std::make_unique<QLockFile>(m_autosavePath + QStringLiteral(".lock"));
    m_autosaveLock->setStaleLockTime(0); // only its process's end makes it stale
    m_autosaveLock->tryLock(0);
}

void LessonEditor::discardAutosave()
{
    if (!m_autosaveLock)
        return;
    QFile::remove(m_autosavePath);
    m_autosaveLock.reset();
}

void LessonEditor::trySelected()
{
    // The lesson as it is now, unsaved edits too, without touching its file or saved state.
    // In a folder of this process's own, a new file each time: another RigidLab on the machine
    // (another teacher's, or a test beside it) never writes over the lesson this one plays, and
    // the file stays while the window may read it again (a change of language) until the end.
    static QTemporaryDir tries;
    static int tried = 0;
    if (!tries.isValid()) {
        QMessageBox::warning(this, tr("Try as a student"), tries.errorString());
        return;
    }
    const QString path = tries.filePath(QStringLiteral("try-%1.rlesson").arg(++tried));
    const QString error = m_draft.writeCopy(path);
    if (!error.isEmpty()) {
        QMessageBox::warning(this, tr("Try as a student"), error);
        return;
    }
    emit tryAsStudent(path, std::max(currentStep(), 0));
}

void LessonEditor::sendStepScene()
{
    const int step = currentStep();
    if (step < 0)
        return;
    // Only the scene must load; what it says when it does not joins the problems below, with
    // no dialog to dismiss.
    QString error;
    const std::optional<lessons::Scene> scene = m_draft.stepScene(step, currentLanguage(), error);
    if (!scene) {
        m_problems->setText(tr("The step's scene does not open: %1").arg(error));
        return;
    }
    emit editStepScene(*scene);
}

void LessonEditor::textEdited(int step, const QString& key, int language, const QString& text)
{
    if (m_refreshing || (step < 0 && key == u"text"))
        return;
    if (m_draft.text(step, key, codeOf(language)) == text)
        return;
    m_draft.setText(step, key, codeOf(language), text);
}

void LessonEditor::refresh()
{
    m_refreshing = true;
    refreshLesson();
    refreshSteps();
    m_refreshing = false;
    refreshStepTexts();
    updateTitle();
}

void LessonEditor::refreshLesson()
{
    const std::array<std::pair<QString, std::array<QLineEdit*, kEditorLanguages>*>, 3> rows{{
        {QStringLiteral("title"), &m_title},
        {QStringLiteral("summary"), &m_summary},
        {QStringLiteral("level"), &m_level},
    }};
    for (const auto& [key, edits] : rows)
        for (int l = 0; l < kColumns; ++l) {
            QLineEdit* edit = (*edits)[static_cast<std::size_t>(l)];
            showText(edit, m_draft.text(-1, key, codeOf(l)));
            // The quiet mark of a text not written in this language: what shows instead.
            edit->setPlaceholderText(shownText(m_draft.value(-1, key)));
        }
    m_minutes->setValue(m_draft.value(-1, QStringLiteral("minutes")).toInt());
}

QString LessonEditor::stepMarks(int index, const LessonDraft::Check& check,
                                const QStringList& runLines) const
{
    QStringList marks;
    for (const QString& key : {QStringLiteral("title"), QStringLiteral("text")})
        for (const QString& code : m_draft.missingLanguages(index, key)) {
            const QString m = tr("no %1").arg(lessons::languageTitle(code));
            if (!marks.contains(m))
                marks.append(m);
        }
    const qsizetype problems = check.steps.count(index) + runLines.size();
    if (problems > 0)
        marks.append(tr("%n problem(s)", nullptr, static_cast<int>(problems)));
    return marks.join(QStringLiteral(", "));
}

void LessonEditor::checkRuns()
{
    QString error;
    const std::optional<lessons::Lesson> lesson = m_draft.lesson(currentLanguage(), error);
    if (lesson)
        m_checks->check(*lesson, m_draft.runKey());
    else
        m_checks->clear();
}

void LessonEditor::refreshSteps()
{
    const LessonDraft::Check check = m_draft.check(currentLanguage());
    checkRuns();
    const std::vector<StepFinding>& findings = m_checks->findings();
    const int keep = currentStep();
    const QIcon warn = style()->standardIcon(QStyle::SP_MessageBoxWarning);
    while (m_steps->count() > m_draft.stepCount())
        delete m_steps->takeItem(m_steps->count() - 1);
    while (m_steps->count() < m_draft.stepCount())
        m_steps->addItem(QString());
    QStringList runProblems;
    for (int i = 0; i < m_draft.stepCount(); ++i) {
        const QString title = shownText(m_draft.value(i, QStringLiteral("title")));
        const QStringList runLines = i < static_cast<int>(findings.size())
                                         ? stepCheckLines(findings[static_cast<std::size_t>(i)])
                                         : QStringList();
        for (const QString& line : runLines)
            runProblems.append(tr("Step %1: %2").arg(i + 1).arg(line));
        const QString marks = stepMarks(i, check, runLines);
        QListWidgetItem* item = m_steps->item(i);
        item->setText(marks.isEmpty() ? QStringLiteral("%1. %2").arg(i + 1).arg(title)
                                      : tr("%1. %2 — ⚠ %3").arg(i + 1).arg(title, marks));
        item->setIcon(marks.isEmpty() ? QIcon() : warn);
        QStringList lines;
        for (int k = 0; k < check.steps.size(); ++k) {
            const QString line = k == 0 && !check.error.isEmpty()
                                     ? check.error
                                     : check.warnings.value(k - (check.error.isEmpty() ? 0 : 1));
            if (check.steps[k] == i)
                lines.append(line);
        }
        item->setToolTip((QStringList{item->text()} + lines + runLines).join(u'\n'));
    }
    m_steps->setCurrentRow(std::clamp(keep, 0, m_draft.stepCount() - 1));
    QStringList all;
    if (!check.error.isEmpty())
        all.append(check.error);
    all.append(check.warnings);
    all.append(runProblems);
    QString text = all.isEmpty() ? tr("No problems found.") : all.join(u'\n');
    if (m_checks->isRunning())
        text += u'\n' + tr("Running the steps' scenes to check them…");
    else if (m_checks->wasCancelled())
        text += u'\n' + tr("The steps' scenes were not checked: the checks were cancelled.");
    m_problems->setText(text);
}

void LessonEditor::refreshStepTexts()
{
    const int step = currentStep();
    const bool was = m_refreshing;
    m_refreshing = true;
    const QStringList missingTitle = m_draft.missingLanguages(step, QStringLiteral("title"));
    const QStringList missingText = m_draft.missingLanguages(step, QStringLiteral("text"));
    QStringList written; // the languages the step's title or text is written in
    for (const lessons::Language& language : lessons::kLanguages) {
        const QString c = language.code.toString();
        if (step >= 0 && (!m_draft.text(step, QStringLiteral("title"), c).isEmpty() ||
                          !m_draft.text(step, QStringLiteral("text"), c).isEmpty()))
            written.append(c);
    }
    for (int l = 0; l < kColumns; ++l) {
        const auto i = static_cast<std::size_t>(l);
        const QString c = codeOf(l);
        const QString title = step < 0 ? QString() : m_draft.text(step, QStringLiteral("title"), c);
        const QString text = step < 0 ? QString() : m_draft.text(step, QStringLiteral("text"), c);
        showText(m_stepTitle[i], title);
        if (m_stepText[i]->toPlainText() != text)
            m_stepText[i]->setPlainText(text);
        // A quiet mark, not a refusal: the student reads the language the text has.
        const QString shownIn = lessons::textLanguage(c, written);
        m_missing[i]->setVisible(step >= 0 && !shownIn.isEmpty() &&
                                 (missingTitle.contains(c) || missingText.contains(c)));
        m_missing[i]->setText(tr("⚠ %1: not written yet; the student reads the %2 text")
                                  .arg(lessons::languageTitle(c), lessons::languageTitle(shownIn)));
        m_missing[i]->setAccessibleName(m_missing[i]->text().mid(2));
        m_stepTitle[i]->setPlaceholderText(
            step < 0 ? QString() : shownText(m_draft.value(step, QStringLiteral("title"))));
        // The preview is what the student reads in this language, the fallback included.
        m_preview[i]->showMarkdown(lessons::keepUnitsTogether(
            text.isEmpty() && step >= 0 ? m_draft.text(step, QStringLiteral("text"), shownIn)
                                        : text));
        m_stepTitle[i]->setEnabled(step >= 0);
        m_stepText[i]->setEnabled(step >= 0);
    }
    m_questions->setStep(step);
    m_settings->setStep(step);
    m_refreshing = was;
}

void LessonEditor::updateTitle()
{
    const QString name =
        m_draft.path().isEmpty() ? tr("new lesson") : QFileInfo(m_draft.path()).fileName();
    setWindowTitle(tr("%1%2 — Lesson editor — RigidLab")
                       .arg(name, m_draft.isModified() ? QStringLiteral("*") : QString()));
}

bool LessonEditor::eventFilter(QObject* watched, QEvent* event)
{
    // Undo and Redo in a text field are the lesson's, not the field's own: one history.
    if (event->type() == QEvent::ShortcutOverride || event->type() == QEvent::KeyPress) {
        auto* key = static_cast<QKeyEvent*>(event);
        const QKeySequence pressed(key->keyCombination());
        const bool undo = m_undo->shortcuts().contains(pressed);
        const bool redo = m_redo->shortcuts().contains(pressed);
        if (undo || redo) {
            event->accept();
            if (event->type() == QEvent::KeyPress)
                (undo ? m_undo : m_redo)->trigger();
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

void LessonEditor::closeEvent(QCloseEvent* event)
{
    if (m_draft.isModified()) {
        const auto answer = QMessageBox::question(
            this, tr("Lesson editor"), tr("The lesson has unsaved changes. Save them?"),
            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
        if (answer == QMessageBox::Cancel) {
            event->ignore();
            return;
        }
        // Save As asked where, and the teacher cancelled it: the lesson is still unsaved.
        if (answer == QMessageBox::Save && (!save().isEmpty() || m_draft.isModified())) {
            event->ignore();
            return;
        }
    }
    discardAutosave(); // saved, or its edits discarded on purpose
    event->accept();
}

} // namespace rigidlab::ui
