// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_player/hand_in.h"

#include "lesson_player/answers_record.h"
#include "lesson_player/question_judge.h"
#include "lesson_player/step_state.h"

#include "common/export_folder.h"
#include "common/language.h"
#include "common/modal_scope.h"
#include "worksheet/worksheet.h"

#include "format/atomic_file.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>

namespace rigidlab::ui {

// Its words are the lesson player's (its translation context), as the rest of the lesson dock.

HandIn::HandIn(const StepState& state, QuestionJudge& judge, QWidget* parent)
    : QWidget(parent), m_state(state), m_judge(judge), m_name(new QLineEdit(this)),
      m_class(new QLineEdit(this))
{
    // One row: the name wide, the class narrow; each label is its field's buddy, so that
    // Alt+letter and a screen reader both find the field.
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(0, 0, 0, 0);
    auto* nameLabel =
        new QLabel(QCoreApplication::translate("rigidlab::ui::LessonPlayer", "&Name:"), this);
    nameLabel->setBuddy(m_name);
    auto* classLabel =
        new QLabel(QCoreApplication::translate("rigidlab::ui::LessonPlayer", "C&lass:"), this);
    classLabel->setBuddy(m_class);
    m_name->setObjectName(QStringLiteral("studentName"));
    m_name->setAccessibleName(
        QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Your name"));
    m_name->setToolTip(QCoreApplication::translate("rigidlab::ui::LessonPlayer",
                                                   "Your name, for the worksheet you hand in"));
    m_name->setMaxLength(lessons::kMaxAnswerText);
    m_class->setObjectName(QStringLiteral("studentClass"));
    m_class->setAccessibleName(
        QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Your class"));
    m_class->setToolTip(QCoreApplication::translate("rigidlab::ui::LessonPlayer",
                                                    "Your class, for the worksheet you hand in"));
    m_class->setMaxLength(lessons::kMaxAnswerText);
    m_class->setMaximumWidth(QFontMetrics(font()).horizontalAdvance(u'M') * 6);
    row->addWidget(nameLabel);
    row->addWidget(m_name, 1);
    row->addWidget(classLabel);
    row->addWidget(m_class);
    m_name->setText(AnswersRecord::session().student);
    m_class->setText(AnswersRecord::session().className);
    connect(m_name, &QLineEdit::textChanged, this,
            [](const QString& text) { AnswersRecord::session().student = text.simplified(); });
    connect(m_class, &QLineEdit::textChanged, this,
            [](const QString& text) { AnswersRecord::session().className = text.simplified(); });
}

void HandIn::setStudent(const QString& name, const QString& className)
{
    m_name->setText(name);
    m_class->setText(className);
}

QString HandIn::student() const
{
    return AnswersRecord::session().student;
}

lessons::Answers HandIn::answers() const
{
    if (!m_state.lesson())
        return {};
    return AnswersRecord::session().answers(*m_state.lesson(), currentLanguage());
}

QString HandIn::handIn(const QString& pdfPath)
{
    if (!m_state.lesson())
        return QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Open a lesson first.");
    m_judge.recordSettings();
    const lessons::Answers work = answers();
    const WorksheetResult written =
        writeWorksheet(*m_state.lesson(), work, WorksheetKind::Answers, pdfPath);
    if (!written.ok)
        return written.error;
    const QString answersPath = answersPathFor(pdfPath);
    if (const QString error = lessons::writeFileAtomically(answersPath, lessons::answersJson(work));
        !error.isEmpty())
        return error;
    emit handedIn(pdfPath, answersPath);
    return QString();
}

void HandIn::handInInteractively()
{
    if (!m_state.lesson())
        return;
    const ModalScope modal;
    if (AnswersRecord::session().student.isEmpty()) {
        QMessageBox::information(
            this, QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Hand in"),
            QCoreApplication::translate("rigidlab::ui::LessonPlayer",
                                        "Type your name first: it goes on the worksheet."));
        m_name->setFocus(Qt::OtherFocusReason);
        return;
    }
    const QString proposal =
        QDir(exportFolder())
            .filePath(worksheetFileName(*m_state.lesson(), AnswersRecord::session().student));
    const QString path = QFileDialog::getSaveFileName(
        this, QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Hand in the worksheet"),
        proposal,
        QCoreApplication::translate("rigidlab::ui::LessonPlayer", "PDF document (*.pdf)"));
    if (path.isEmpty())
        return;
    rememberExportFolder(path);
    if (const QString error = handIn(path); !error.isEmpty()) {
        QMessageBox::warning(
            this, QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Cannot hand in"),
            error);
        return;
    }
    QMessageBox::information(
        this, QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Handed in"),
        QCoreApplication::translate("rigidlab::ui::LessonPlayer",
                                    "Your worksheet is in %1, your answers beside it in %2.")
            .arg(QDir::toNativeSeparators(path), QDir::toNativeSeparators(answersPathFor(path))));
}

void HandIn::writeSheetInteractively(bool key)
{
    if (!m_state.lesson())
        return;
    const ModalScope modal;
    const QString stem = QFileInfo(m_state.lesson()->path).completeBaseName();
    const QString proposal =
        QDir(exportFolder())
            .filePath(stem + (key ? QStringLiteral("-key.pdf") : QStringLiteral("-worksheet.pdf")));
    const QString path = QFileDialog::getSaveFileName(
        this,
        key ? QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Teacher's key")
            : QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Worksheet to print"),
        proposal,
        QCoreApplication::translate("rigidlab::ui::LessonPlayer", "PDF document (*.pdf)"));
    if (path.isEmpty())
        return;
    rememberExportFolder(path);
    lessons::Answers none;
    none.lessonFile = QFileInfo(m_state.lesson()->path).fileName();
    const WorksheetResult written = writeWorksheet(
        *m_state.lesson(), none, key ? WorksheetKind::Key : WorksheetKind::Empty, path);
    if (!written.ok)
        QMessageBox::warning(
            this,
            QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Cannot write the worksheet"),
            written.error);
}

} // namespace rigidlab::ui
