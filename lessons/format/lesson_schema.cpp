// SPDX-License-Identifier: GPL-3.0-or-later
// The rows of a lesson step and of a question (lesson_schema.h): data, one field a row.

#include "format/lesson_schema.h"

#include "format/scene_schema_rows.h"

#include <algorithm>

namespace rigidlab::lessons::schema {

namespace {

using rows::as;

const StepField kStepFields[] = {
    {.key = "title", .kind = LessonKind::Line, .required = true, .text = &LessonStep::title},
    {.key = "text", .kind = LessonKind::Paragraphs, .text = &LessonStep::text},
    {.key = "scene", .required = true, .run = true},
    {.key = "settings", .run = true},
    {.key = "compare", .run = true},
    {.key = "plots"},
    {.key = "overlays"},
    {.key = "panels"},
    {.key = "allow", .run = true},
    {.key = "sat"},
    {.key = "editor"},
    {.key = "questions", .run = true},
    plainRow<LessonStep>({.key = "exportTime",
                          .label = QT_TRANSLATE_NOOP("SceneSchema", "Plots exported at"),
                          .kind = Kind::Number,
                          .range = {0.0, kMaxExportTime, "s"},
                          .rule = detail::NumberRule::Positive,
                          .get = numberGet<LessonStep, &LessonStep::exportTime>,
                          .set = numberSet<LessonStep, &LessonStep::exportTime>},
                         /*run=*/true),
    plainRow<LessonStep>(
        {.key = "endTime",
         .label = QT_TRANSLATE_NOOP("SceneSchema", "The run stops at"),
         .kind = Kind::Number,
         .range = {0.0, kMaxEndTime, "s"},
         .rule = detail::NumberRule::Positive,
         .get = [](const LessonStep& s,
                   std::size_t) { return s.endTime ? Value(*s.endTime) : Value(); },
         .set =
             [](LessonStep& s, std::size_t, const Value& v) {
                 s.endTime = std::holds_alternative<double>(v) ? std::optional(std::get<double>(v))
                                                               : std::nullopt;
             },
         .optional = true},
        /*run=*/true),
    plainRow<LessonStep>(
        {.key = "autoplay",
         .label = QT_TRANSLATE_NOOP("SceneSchema", "Starts at once"),
         .kind = Kind::Bool,
         .get = [](const LessonStep& s, std::size_t) { return Value(s.autoplay); },
         .set = [](LessonStep& s, std::size_t, const Value& v) { s.autoplay = as<bool>(v); }}),
};

const QuestionField kQuestionFields[] = {
    {.key = question_keys::kPrompt,
     .kind = LessonKind::Line,
     .required = true,
     .text = &Question::prompt},
    {.key = question_keys::kHint, .kind = LessonKind::Line, .text = &Question::hint},
    {.key = question_keys::kHoldBack},
};

template <class Row> const Row* findRow(std::span<const Row> rows, std::string_view key)
{
    const auto it =
        std::find_if(rows.begin(), rows.end(), [&](const Row& r) { return r.key == key; });
    return it == rows.end() ? nullptr : &*it;
}

/// How many kinds of question have a row with this key.
int kindsWithKey(std::string_view key)
{
    int kinds = 0;
    forEachQuestionKind([&]<class K>(std::type_identity<K> kind) {
        for (const KindField<K>& f : kindFields(kind))
            kinds += f.key == key ? 1 : 0;
    });
    return kinds;
}

} // namespace

std::span<const StepField> stepFields()
{
    return kStepFields;
}

std::span<const QuestionField> questionFields()
{
    return kQuestionFields;
}

std::size_t questionKindIn(const QJsonObject& object)
{
    // A key that several kinds have ("unit") tells none of them apart.
    std::size_t index = 0;
    std::size_t found = 0;
    forEachQuestionKind([&]<class K>(std::type_identity<K> kind) {
        if (found == 0 && index > 0)
            for (const KindField<K>& f : kindFields(kind))
                if (object.contains(rows::fromView(f.key)) && kindsWithKey(f.key) == 1)
                    found = index;
        ++index;
    });
    return found;
}

decltype(Question::kind) newQuestionKind(std::size_t index)
{
    decltype(Question::kind) kind;
    std::size_t at = 0;
    forEachQuestionKind([&]<class K>(std::type_identity<K>) {
        if (at++ == index)
            kind = K{};
    });
    return kind;
}

QStringList questionKindKeys(std::size_t index)
{
    QStringList keys;
    std::size_t at = 0;
    forEachQuestionKind([&]<class K>(std::type_identity<K> kind) {
        if (at++ == index)
            for (const KindField<K>& f : kindFields(kind))
                keys << rows::fromView(f.key);
    });
    return keys;
}

const StepField* findStepField(std::string_view key)
{
    return findRow(stepFields(), key);
}

const QuestionField* findQuestionField(std::string_view key)
{
    return findRow(questionFields(), key);
}

QStringList stepKeys()
{
    QStringList keys;
    for (const StepField& f : stepFields())
        keys << rows::fromView(f.key);
    return keys;
}

QStringList questionKeys()
{
    QStringList keys;
    for (const QuestionField& f : questionFields())
        keys << rows::fromView(f.key);
    for (std::size_t k = 0; k < std::variant_size_v<decltype(Question::kind)>; ++k)
        for (const QString& key : questionKindKeys(k))
            if (!keys.contains(key)) // a key that several kinds have, once
                keys << key;
    return keys;
}

} // namespace rigidlab::lessons::schema
