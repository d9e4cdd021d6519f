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
//
// A question's rows are those of every question (questionFields) and those of its kind
// (kindFields, one table per type of Question::kind): the loader reads a question's kind
// from the keys it holds (questionKindIn) and the rows of that kind only.

#include "format/lesson.h"
#include "format/lesson_rows.h"
#include "format/scene_schema.h"

#include <QString>
#include <QStringList>

#include <QJsonObject>

#include <cstddef>
#include <span>
#include <string_view>
#include <type_traits>
#include <variant>

namespace rigidlab::lessons::schema {

using StepField = LessonFieldOf<LessonStep>;
/// A row every question has, whatever its kind.
using QuestionField = LessonFieldOf<Question>;

/// The rows of a lesson step, in the order of the file.
std::span<const StepField> stepFields();
/// The rows every question has, in the order of the file.
std::span<const QuestionField> questionFields();
// The rows of each kind of question, kindFields(std::type_identity<K>), are in its own file
// (format/question_kinds/): a kind of Question::kind without them does not compile where the
// kinds' rows are read.

/// Calls `f(std::type_identity<K>{})` for each kind K of Question::kind, in its order.
template <class F> void forEachQuestionKind(F&& f)
{
    [&]<class... K>(std::type_identity<std::variant<K...>>) {
        (f(std::type_identity<K>{}), ...);
    }(std::type_identity<decltype(Question::kind)>{});
}

/// The index of kind K in Question::kind (the value questionKindIn gives for it).
template <class K> constexpr std::size_t questionKindIndex()
{
    return []<class... Ks>(std::type_identity<std::variant<Ks...>>) {
        std::size_t index = 0;
        bool found = false;
        ((found = found || std::is_same_v<K, Ks>, index += found ? 0 : 1), ...);
        return index;
    }(std::type_identity<decltype(Question::kind)>{});
}

/// The index in Question::kind of the kind of question `object` is: the first kind after
/// the first that it holds a key of its own of (one no other kind has), else the first (a measured
/// question, whose keys are missing or wrong then: the loader says which).
std::size_t questionKindIn(const QJsonObject& object);
/// A new question's part of the kind at `index` of Question::kind, as its struct starts.
decltype(Question::kind) newQuestionKind(std::size_t index);
/// The keys of the kind at `index` of Question::kind, in their order.
QStringList questionKindKeys(std::size_t index);

/// The row of a step with this key, or null.
const StepField* findStepField(std::string_view key);
/// The row every question has with this key, or null.
const QuestionField* findQuestionField(std::string_view key);
/// The row of kind K with this key, or null.
template <class K> const KindField<K>* findKindField(std::string_view key)
{
    for (const KindField<K>& f : kindFields(std::type_identity<K>{}))
        if (f.key == key)
            return &f;
    return nullptr;
}

/// The keys of the rows, in their order (a question's: every question's, then each kind's).
QStringList stepKeys();
QStringList questionKeys();

} // namespace rigidlab::lessons::schema
