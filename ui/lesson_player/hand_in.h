// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Handing in a lesson's worksheet: the student's name and class, typed once above the lesson
// and kept for the session, and the worksheet as a PDF with the answers file beside it, both
// written from the session's answers record; for the teacher, the empty worksheet and the key.

#include "format/answers_file.h"

#include <QWidget>

class QLineEdit;

namespace rigidlab::ui {

class QuestionJudge;
class StepState;

class HandIn : public QWidget {
    Q_OBJECT
public:
    /// The name and class fields; hands in the lesson `state` has open, `judge` keeping the
    /// settings of the step it is on.
    HandIn(const StepState& state, QuestionJudge& judge, QWidget* parent = nullptr);

    void setStudent(const QString& name, const QString& className);
    QString student() const;
    /// The work on the open lesson so far, every step visited, with who and when.
    lessons::Answers answers() const;
    /// Writes the worksheet to `pdfPath` and the answers beside it (answersPathFor). Returns
    /// the error, empty on success.
    QString handIn(const QString& pdfPath);
    /// Asks for the name if none is typed, then for the file, and hands in.
    void handInInteractively();
    /// Asks for a file and writes the empty worksheet (or the key) of the open lesson there.
    void writeSheetInteractively(bool key);

signals:
    /// A worksheet was handed in: the PDF and the answers file beside it.
    void handedIn(const QString& pdfPath, const QString& answersPath);

private:
    const StepState& m_state;
    QuestionJudge& m_judge;
    QLineEdit* m_name;
    QLineEdit* m_class;
};

} // namespace rigidlab::ui
