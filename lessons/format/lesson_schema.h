// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lesson format's fields, one row each, as the scene's are in scene_schema.h: what a lesson
// step and a question hold (lessons/LESSON_FORMAT.md). The lesson loader takes a step's and a
// question's keys from these rows (an unknown key is refused, naming them), reads the texts and
// the plain values (numbers, flags) through them, and checks each as its row says; the lesson
// editor takes each field's range, default and label from them and writes its texts in the
// languages a row's kind allows. A part with a shape of its own (a scene, settings, compared
// worlds, the names a step shows, a measure, the options of a choice) is a row of kind Part,
// read by its own function (lesson_step.cpp, lesson_questions.cpp). A new step or question
// field is one row here, and what reads it (the player, the export).

#include "format/scene_schema.h"

#include <QString>
#include <QStringList>

#include <span>
#include <string_view>

namespace rigidlab::lessons::schema {

/// How a lesson row is read and edited.
enum class LessonKind {
    Line,       ///< one line of text in the lesson's languages (one is enough), not empty
    Paragraphs, ///< Markdown in the lesson's languages: a string or an array of lines
    Unit,       ///< a symbol ("m/s", the same in every language) or a worded unit per language
    Plain,      ///< a number or a flag: its `value` row reads and ranges it (field_reading.h)
    Part,       ///< read by its own function
};

/// The kinds of question a question row belongs to (the keys of the other kind are refused).
enum class QuestionKinds { All, Measured, Choice };

template <class Target> struct LessonFieldOf {
    std::string_view key; ///< the JSON key
    LessonKind kind = LessonKind::Part;
    bool required = false;
    /// Line, Paragraphs, Unit: where the text goes, in the language the lesson is read in.
    QString Target::*text = nullptr;
    /// Plain: the value's row, as a scene field's (its kind Number or Bool, range, rule, label,
    /// get and set), read by detail::readPlainField.
    FieldOf<Target> value{};
    /// Questions: which kind of question has it.
    QuestionKinds kinds = QuestionKinds::All;
    /// Whether the steps' runs depend on it: the editor's checks run them again when it
    /// changes (the texts never make them).
    bool run = false;
};

using StepField = LessonFieldOf<LessonStep>;
using QuestionField = LessonFieldOf<Question>;

/// The rows of a lesson step, in the order of the file.
std::span<const StepField> stepFields();
/// The rows of a question, in the order of the file.
std::span<const QuestionField> questionFields();
/// The row of a step with this key, or null.
const StepField* findStepField(std::string_view key);
/// The row of a question with this key, or null.
const QuestionField* findQuestionField(std::string_view key);

/// The keys of the rows, in their order (`kinds`: only those of the questions of that kind,
/// and those of every question).
QStringList stepKeys();
QStringList questionKeys(QuestionKinds kinds = QuestionKinds::All);

} // namespace rigidlab::lessons::schema
