// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A class's answers to one lesson as one table: a row per student (name, class, date), a
// group of columns per question (first answer, verdict, tries, hint or Show me used) and a
// summary row (the share right at the first answer, per question). The tries of each
// answers file are judged again, in order, as the lesson player judged them (judgeTry), so
// that the table says what the student read on the screen.
//
// The columns are one list (classColumns()): the window's table, the text on the command
// line, the CSV and the PDF all take their heads and cells from it.

#include "format/answers_file.h"
#include "format/lesson.h"

#include <QString>

#include <optional>
#include <vector>

namespace rigidlab::lessons {

/// How a student's first answer to a question was judged.
enum class FirstVerdict {
    None,        ///< no answer given (or only "Show me")
    Right,       ///< right at the first answer
    NotRight,    ///< the first answer was not right
    NotMeasured, ///< only answers checked before the run had measured the value
};

/// What one student did with one question.
struct QuestionOutcome {
    /// Answers judged against a measured value or choices made; a Check before the run had
    /// measured anything judges nothing and is not a try.
    int tries = 0;
    std::optional<double> firstNumber; ///< the first answer to a measured question
    QString firstChoice;               ///< the first option chosen (a choice question)
    FirstVerdict first = FirstVerdict::None;
    bool hint = false;   ///< a wrong first answer read the question's hint
    bool showMe = false; ///< "Show me" gave the answer away
    bool operator==(const QuestionOutcome&) const = default;
};

struct StudentRow {
    QString file; ///< the answers file's name, without its folder
    QString student;
    QString className;
    QString date;                           ///< YYYY-MM-DD, as handed in
    std::vector<QuestionOutcome> questions; ///< per question of the lesson, step by step
};

/// A question of the lesson as the table heads it.
struct QuestionHead {
    int step = 0;     ///< 0-based
    int question = 0; ///< 0-based, within the step
    QString unit;     ///< a measured question's unit ("m"); empty for a choice question
    bool choice = false;
};

struct ClassTable {
    QString lessonFile;  ///< the lesson's file name, without its folder
    QString lessonTitle; ///< in the language it was read in
    std::vector<QuestionHead> questions;
    std::vector<StudentRow> rows; ///< by file name

    /// How many students were right at their first answer to question `q`.
    int rightFirst(std::size_t q) const;
    /// rightFirst(q) of all the students, in per cent; nullopt without students.
    std::optional<double> rightFirstPercent(std::size_t q) const;
};

/// The table's heads for `lesson` (no rows yet).
ClassTable emptyClassTable(const Lesson& lesson);

/// A student's row: `answers` (which fit the lesson, answersMismatch()) judged again.
StudentRow studentRow(const Lesson& lesson, const Answers& answers, const QString& file);

// ---- The columns: one list ----

/// What a column shows.
enum class ClassColumnKind {
    Student,
    Class,
    Date,
    FirstAnswer, ///< of one question
    Verdict,     ///< of its first answer; the summary row's share right at the first answer
    Tries,
    Help, ///< hint or Show me used
};

struct ClassColumn {
    ClassColumnKind kind = ClassColumnKind::Student;
    int question = -1; ///< index into ClassTable::questions; -1 for a student's own columns
};

/// Every column of the table, in order: the student's, then a group per question.
std::vector<ClassColumn> classColumns(const ClassTable& table);

/// The head of a column in the language in effect: "Name", "1.2 first answer [m]".
QString classColumnHead(const ClassTable& table, const ClassColumn& column);

/// A cell: its text for people (numbers in the language's format) and, for a number, the
/// number itself (for sorting and for CSV, which writes it in its dialect).
struct ClassCell {
    QString text;
    std::optional<double> number;
};

/// The cell of a student's row (`row` < table.rows.size()).
ClassCell classCell(const ClassTable& table, std::size_t row, const ClassColumn& column);
/// The cell of the summary row: its name under Name, the share right at the first answer
/// (in %) under each question's Verdict, empty elsewhere.
ClassCell classSummaryCell(const ClassTable& table, const ClassColumn& column);

} // namespace rigidlab::lessons
