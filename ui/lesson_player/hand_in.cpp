// SPDX-License-Identifier: GPL-3.0-or-later
// Handing in a lesson's worksheet: the student's name and class, and the PDF with the answers
// file (the session's answers_record) beside it.

#include "lesson_player/lesson_player.h"

#include "lesson_player/answers_record.h"

#include "common/export_folder.h"
#include "common/language.h"
#include "common/modal_scope.h"
#include "common/shortcuts.h"
#include "worksheet/worksheet.h"

#include "format/atomic_file.h"

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
    m_studentName->setText(AnswersRecord::session().student);
    m_studentClass->setText(AnswersRecord::session().className);
    connect(m_studentName, &QLineEdit::textChanged, this,
            [](const QString& text) { AnswersRecord::session().student = text.simplified(); });
    connect(m_studentClass, &QLineEdit::textChanged, this,
            [](const QString& text) { AnswersRecord::session().className = text.simplified(); });
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
    return AnswersRecord::session().student;
}

lessons::Answers LessonPlayer::answers() const
{
    if (!lesson())
        return {};
    return AnswersRecord::session().answers(*lesson(), currentLanguage());
}

QString LessonPlayer::handIn(const QString& pdfPath)
{
    if (!lesson())
        return tr("Open a lesson first.");
    m_judge.recordSettings();
    const lessons::Answers work = answers();
    const WorksheetResult written =
        writeWorksheet(*lesson(), work, WorksheetKind::Answers, pdfPath);
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
    if (!lesson())
        return;
    const ModalScope modal;
    if (AnswersRecord::session().student.isEmpty()) {
        QMessageBox::information(this, tr("Hand in"),
                                 tr("Type your name first: it goes on the worksheet."));
        m_studentName->setFocus(Qt::OtherFocusReason);
        return;
    }
    const QString proposal =
        QDir(exportFolder())
            .filePath(worksheetFileName(*lesson(), AnswersRecord::session().student));
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
        action->setEnabled(lesson() != nullptr);
        connect(this, &LessonPlayer::stepActivated, action, [action] { action->setEnabled(true); });
        connect(this, &LessonPlayer::lessonClosed, action, [action] { action->setEnabled(false); });
    }
}

void LessonPlayer::writeSheetInteractively(bool key)
{
    if (!lesson())
        return;
    const ModalScope modal;
    const QString stem = QFileInfo(lesson()->path).completeBaseName();
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
    none.lessonFile = QFileInfo(lesson()->path).fileName();
    const WorksheetResult written =
        writeWorksheet(*lesson(), none, key ? WorksheetKind::Key : WorksheetKind::Empty, path);
    if (!written.ok)
        QMessageBox::warning(this, tr("Cannot write the worksheet"), written.error);
}

void LessonPlayer::showHandIn()
{
    // The lesson's last step: Hand in is how it ends.
    const bool last = m_state.isLast();
    m_handIn->setText(last ? tr("Finish: hand in the worksheet…") : tr("Hand in…"));
}

} // namespace rigidlab::ui
