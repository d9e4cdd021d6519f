// SPDX-License-Identifier: GPL-3.0-or-later
// Handing in a lesson's worksheet: the student's name and class, the record of every step's
// tries and settings, and the PDF with the answers file beside it.

#include "lesson_player/lesson_player.h"

#include "common/export_folder.h"
#include "common/language.h"
#include "common/modal_scope.h"
#include "common/shortcuts.h"
#include "simulation/simulation_controller.h"
#include "worksheet/worksheet.h"

#include "format/atomic_file.h"

#include <QDate>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QVBoxLayout>

namespace rigidlab::ui {

namespace {

/// What the session remembers: who the student is, and the work on the lesson last opened
/// (kept through a language switch, which makes the window anew, and through reopening the
/// same lesson; another lesson starts a new record).
struct SessionRecord {
    QString student;
    QString className;
    QString lessonPath;
    std::vector<lessons::StepAnswers> steps;
};

SessionRecord& session()
{
    static SessionRecord record;
    return record;
}

} // namespace

void LessonPlayer::buildStudentFields(QVBoxLayout* layout)
{
    // One row: the name wide, the class narrow; each label is its field's buddy, so that
    // Alt+letter and a screen reader both find the field.
    auto* row = new QHBoxLayout(m_studentBox);
    row->setContentsMargins(0, 0, 0, 0);
    auto* nameLabel = new QLabel(tr("&Name:"), m_studentBox);
    nameLabel->setBuddy(m_studentName);
    auto* classLabel = new QLabel(tr("C&lass:"), m_studentBox);
    classLabel->setBuddy(m_studentClass);
    m_studentName->setObjectName(QStringLiteral("studentName"));
    m_studentName->setAccessibleName(tr("Your name"));
    m_studentName->setToolTip(tr("Your name, for the worksheet you hand in"));
    m_studentName->setMaxLength(lessons::kMaxAnswerText);
    m_studentClass->setObjectName(QStringLiteral("studentClass"));
    m_studentClass->setAccessibleName(tr("Your class"));
    m_studentClass->setToolTip(tr("Your class, for the worksheet you hand in"));
    m_studentClass->setMaxLength(lessons::kMaxAnswerText);
    m_studentClass->setMaximumWidth(QFontMetrics(font()).horizontalAdvance(u'M') * 6);
    row->addWidget(nameLabel);
    row->addWidget(m_studentName, 1);
    row->addWidget(classLabel);
    row->addWidget(m_studentClass);
    m_studentName->setText(session().student);
    m_studentClass->setText(session().className);
    connect(m_studentName, &QLineEdit::textChanged, this,
            [](const QString& text) { session().student = text.simplified(); });
    connect(m_studentClass, &QLineEdit::textChanged, this,
            [](const QString& text) { session().className = text.simplified(); });
    m_handIn->setObjectName(QStringLiteral("handIn"));
    // A key as well as the button (Help › Controls lists it).
    const QList<QKeySequence> keys = controlKeys("handIn");
    if (!keys.isEmpty())
        m_handIn->setShortcut(keys.front());
    m_handIn->setToolTip(tr("Write your worksheet as a PDF: the questions, your answers and "
                            "their verdicts, the plots and the settings (%1)")
                             .arg(controlKeysText("handIn")));
    layout->addWidget(m_studentBox);
}

void LessonPlayer::setStudent(const QString& name, const QString& className)
{
    m_studentName->setText(name);
    m_studentClass->setText(className);
}

QString LessonPlayer::student() const
{
    return session().student;
}

void LessonPlayer::startRecord(const lessons::Lesson& lesson)
{
    SessionRecord& record = session();
    if (record.lessonPath == lesson.path && record.steps.size() == lesson.steps.size())
        return;
    record.lessonPath = lesson.path;
    record.steps.assign(lesson.steps.size(), lessons::StepAnswers{});
}

void LessonPlayer::recordTry(std::size_t i)
{
    SessionRecord& record = session();
    if (!m_lesson || record.lessonPath != m_lesson->path)
        return;
    lessons::StepAnswers& step = record.steps.at(static_cast<std::size_t>(m_step));
    if (step.questions.size() < m_rows.size())
        step.questions.resize(m_rows.size());
    step.questions[i] = m_rows[i].tries;
    recordSettings();
}

void LessonPlayer::replayRecordedTries()
{
    const SessionRecord& record = session();
    if (!m_lesson || record.lessonPath != m_lesson->path)
        return;
    // Copied: judging a try writes the record again (the same tries, in the same order).
    const std::vector<std::vector<QuestionTry>> questions =
        record.steps.at(static_cast<std::size_t>(m_step)).questions;
    m_replaying = true;
    for (std::size_t i = 0; i < std::min(questions.size(), m_rows.size()); ++i)
        for (const QuestionTry& attempt : questions[i])
            applyTry(i, attempt);
    m_replaying = false;
}

void LessonPlayer::recordSettings()
{
    SessionRecord& record = session();
    if (!m_lesson || record.lessonPath != m_lesson->path)
        return;
    const physics::WorldDef& def = m_controller.world().def();
    lessons::StepAnswers& step = record.steps.at(static_cast<std::size_t>(m_step));
    step.integrator = def.integrator;
    step.dt = def.dt;
    step.solver = def.solver;
}

lessons::Answers LessonPlayer::answers() const
{
    lessons::Answers out;
    if (!m_lesson)
        return out;
    out.lessonFile = QFileInfo(m_lesson->path).fileName();
    out.lessonTitle = m_lesson->title;
    out.language = currentLanguage();
    out.student = session().student;
    out.className = session().className;
    out.date = QDate::currentDate().toString(Qt::ISODate);
    if (session().lessonPath == m_lesson->path)
        out.steps = session().steps;
    // Steps after the last one visited add nothing.
    while (!out.steps.empty() && out.steps.back() == lessons::StepAnswers{})
        out.steps.pop_back();
    return out;
}

QString LessonPlayer::handIn(const QString& pdfPath)
{
    if (!m_lesson)
        return tr("Open a lesson first.");
    recordSettings();
    const lessons::Answers work = answers();
    const WorksheetResult written =
        writeWorksheet(*m_lesson, work, WorksheetKind::Answers, pdfPath);
    if (!written.ok)
        return written.error;
    const QString answersPath = answersPathFor(pdfPath);
    if (const QString error = lessons::writeFileAtomically(answersPath, lessons::answersJson(work));
        !error.isEmpty())
        return error;
    emit handedIn(pdfPath, answersPath);
    return QString();
}

void LessonPlayer::handInInteractively()
{
    if (!m_lesson)
        return;
    const ModalScope modal;
    if (session().student.isEmpty()) {
        QMessageBox::information(this, tr("Hand in"),
                                 tr("Type your name first: it goes on the worksheet."));
        m_studentName->setFocus(Qt::OtherFocusReason);
        return;
    }
    const QString proposal =
        QDir(exportFolder()).filePath(worksheetFileName(*m_lesson, session().student));
    const QString path = QFileDialog::getSaveFileName(this, tr("Hand in the worksheet"), proposal,
                                                      tr("PDF document (*.pdf)"));
    if (path.isEmpty())
        return;
    rememberExportFolder(path);
    if (const QString error = handIn(path); !error.isEmpty()) {
        QMessageBox::warning(this, tr("Cannot hand in"), error);
        return;
    }
    QMessageBox::information(
        this, tr("Handed in"),
        tr("Your worksheet is in %1, your answers beside it in %2.")
            .arg(QDir::toNativeSeparators(path), QDir::toNativeSeparators(answersPathFor(path))));
}

void LessonPlayer::addWorksheetActions(QMenu& menu)
{
    QAction* empty = menu.addAction(tr("Works&heet to print…"), this,
                                    [this] { writeSheetInteractively(false); });
    empty->setObjectName(QStringLiteral("emptyWorksheet"));
    empty->setToolTip(tr("The open lesson's questions with lines to write on, and its figures"));
    QAction* key =
        menu.addAction(tr("Teacher's &key…"), this, [this] { writeSheetInteractively(true); });
    key->setObjectName(QStringLiteral("worksheetKey"));
    key->setToolTip(tr("The open lesson's questions with the values the simulation measures"));
    for (QAction* action : {empty, key}) {
        action->setEnabled(m_lesson != nullptr);
        connect(this, &LessonPlayer::stepActivated, action, [action] { action->setEnabled(true); });
        connect(this, &LessonPlayer::lessonClosed, action, [action] { action->setEnabled(false); });
    }
}

void LessonPlayer::writeSheetInteractively(bool key)
{
    if (!m_lesson)
        return;
    const ModalScope modal;
    const QString stem = QFileInfo(m_lesson->path).completeBaseName();
    const QString proposal =
        QDir(exportFolder())
            .filePath(stem + (key ? QStringLiteral("-key.pdf") : QStringLiteral("-worksheet.pdf")));
    const QString path =
        QFileDialog::getSaveFileName(this, key ? tr("Teacher's key") : tr("Worksheet to print"),
                                     proposal, tr("PDF document (*.pdf)"));
    if (path.isEmpty())
        return;
    rememberExportFolder(path);
    lessons::Answers none;
    none.lessonFile = QFileInfo(m_lesson->path).fileName();
    const WorksheetResult written =
        writeWorksheet(*m_lesson, none, key ? WorksheetKind::Key : WorksheetKind::Empty, path);
    if (!written.ok)
        QMessageBox::warning(this, tr("Cannot write the worksheet"), written.error);
}

void LessonPlayer::showHandIn()
{
    // The lesson's last step: Hand in is how it ends.
    const bool last = m_lesson && m_step + 1 == static_cast<int>(m_lesson->steps.size());
    m_handIn->setText(last ? tr("Finish: hand in the worksheet…") : tr("Hand in…"));
}

} // namespace rigidlab::ui
