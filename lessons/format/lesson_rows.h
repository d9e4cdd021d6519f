// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a row of the lesson format is (lesson_schema.h has the step's and every question's
// rows): the shape of a row, and the keys of a question spelt once. Apart from
// lesson_schema.h so that a kind of question (format/question_kinds/) can write its own rows
// in its own file, below lesson.h, which lists the kinds.

#include "format/scene_schema.h"

#include <QString>

#include <cstddef>
#include <string_view>
#include <variant>

namespace rigidlab::lessons::schema {

/// How a lesson row is read and edited.
enum class LessonKind {
    Line,       ///< one line of text in the lesson's languages (one is enough), not empty
    Paragraphs, ///< Markdown in the lesson's languages: a string or an array of lines
    Unit,       ///< a symbol ("m/s", the same in every language) or a worded unit per language
    Plain,      ///< a number or a flag: its `value` row reads and ranges it (field_reading.h)
    Part,       ///< read by its own function
};

template <class Target> struct LessonFieldOf {
    std::string_view key; ///< the JSON key
    LessonKind kind = LessonKind::Part;
    bool required = false;
    /// Line, Paragraphs, Unit: where the text goes, in the language the lesson is read in.
    QString Target::*text = nullptr;
    /// Plain: the value's row, as a scene field's (its kind Number or Bool, range, rule, label,
    /// get and set), read by detail::readPlainField.
    FieldOf<Target> value{};
    /// Whether the steps' runs depend on it: the editor's checks run them again when it
    /// changes (the texts never make them).
    bool run = false;
};

/// A row of one kind of question (format/question_kinds/).
template <class K> using KindField = LessonFieldOf<K>;

/// A row of kind Plain, made from its value's row: the row's key and whether the file must give
/// it are the value's, so that neither is written twice.
template <class Target>
LessonFieldOf<Target> plainRow(const FieldOf<Target>& value, bool run = false)
{
    return {.key = value.key,
            .kind = LessonKind::Plain,
            .required = value.required,
            .value = value,
            .run = run};
}

/// A row's get and set of a plain number, by its member.
template <class Target, double Target::*member> Value numberGet(const Target& t, std::size_t)
{
    return t.*member;
}
template <class Target, double Target::*member>
void numberSet(Target& t, std::size_t, const Value& v)
{
    t.*member = std::get<double>(v);
}

/// The JSON keys of a question's rows, spelt once: the rows are written with them, and the
/// lesson editor, which edits a lesson's JSON, names a question's keys through them (jsonKey).
/// Those of every question, and the unit of a typed answer, which several kinds have; a kind's
/// own keys are in its file (format/question_kinds/).
namespace question_keys {
inline constexpr std::string_view kPrompt = "prompt";
inline constexpr std::string_view kHint = "hint";
inline constexpr std::string_view kHoldBack = "holdBack";
inline constexpr std::string_view kUnit = "unit";
} // namespace question_keys

/// A row's key as a JSON object's.
inline QString jsonKey(std::string_view key)
{
    return QString::fromUtf8(key.data(), qsizetype(key.size()));
}

} // namespace rigidlab::lessons::schema
