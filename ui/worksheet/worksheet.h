// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A lesson's worksheet as a PDF (A4, fonts embedded, text searchable), in the language the
// lesson is read in:
//   Answers  what a student handed in: per step its questions, each try with its verdict and
//            the measured value, the step's plots as vector figures, and the settings the step
//            ran with (integrator, dt, solver) so that the run can be repeated;
//   Empty    to print before class: the questions with ruled lines to write on, the figures;
//   Key      the teacher's: the measured answers with their accepted ranges, the figures.
// The window's Hand in writes the first (with the answers file beside it,
// lessons/ANSWERS_FORMAT.md); `rigidlab-cli lesson LESSON --worksheet OUT.pdf` all three.

#include "question_kinds/kind_ui.h"

#include "format/answers_file.h"
#include "format/lesson.h"

#include <QString>

#include <vector>

namespace rigidlab::ui {

struct WorksheetResult {
    bool ok = false;
    QString error;            ///< what went wrong, naming the file
    int pages = 0;            ///< pages written
    std::vector<int> figures; ///< per step, the figures drawn (one per plot the step shows)
};

/// Writes the worksheet to `path` atomically (the whole file or nothing). `answers` gives the
/// student, the date and, for Answers, the tries and the settings each step ran with; its
/// steps beyond the lesson's are an error (answersMismatch), missing ones are unanswered.
WorksheetResult writeWorksheet(const lessons::Lesson& lesson, const lessons::Answers& answers,
                               WorksheetKind kind, const QString& path);

/// The answers file saved beside a worksheet: "jana-novak.pdf" → "jana-novak.answers.json".
QString answersPathFor(const QString& pdfPath);

/// A file name for a handed-in worksheet, safe on any disk: the lesson's file stem, then the
/// student's name without accents ("restitution-jana_novakova.pdf").
QString worksheetFileName(const lessons::Lesson& lesson, const QString& student);

} // namespace rigidlab::ui
