// SPDX-License-Identifier: GPL-3.0-or-later
// The rows of a lesson step and of a question (lesson_schema.h): data, one field a row.

#include "format/lesson_schema.h"

#include "format/scene_schema_rows.h"

#include <algorithm>

namespace rigidlab::lessons::schema {

namespace {

using rows::as;

/// A plain number of a step or question, by its member.
template <class Target, double Target::*member> Value numberGet(const Target& t, std::size_t)
{
    return t.*member;
}
template <class Target, double Target::*member>
void numberSet(Target& t, std::size_t, const Value& v)
{
    t.*member = as<double>(v);
}

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
    {.key = "exportTime",
     .kind = LessonKind::Plain,
     .value = {.key = "exportTime",
               .label = QT_TRANSLATE_NOOP("SceneSchema", "Plots exported at"),
               .kind = Kind::Number,
               .range = {0.0, kMaxExportTime, "s"},
               .rule = detail::NumberRule::Positive,
               .get = numberGet<LessonStep, &LessonStep::exportTime>,
               .set = numberSet<LessonStep, &LessonStep::exportTime>},
     .run = true},
    {.key = "endTime",
     .kind = LessonKind::Plain,
     .value = {.key = "endTime",
               .label = QT_TRANSLATE_NOOP("SceneSchema", "The run stops at"),
               .kind = Kind::Number,
               .range = {0.0, kMaxEndTime, "s"},
               .rule = detail::NumberRule::Positive,
               .get = [](const LessonStep& s,
                         std::size_t) { return s.endTime ? Value(*s.endTime) : Value(); },
               .set =
                   [](LessonStep& s, std::size_t, const Value& v) {
                       s.endTime = std::holds_alternative<double>(v)
                                       ? std::optional(std::get<double>(v))
                                       : std::nullopt;
                   },
               .optional = true},
     .run = true},
    {.key = "autoplay",
     .kind = LessonKind::Plain,
     .value = {
         .key = "autoplay",
         .label = QT_TRANSLATE_NOOP("SceneSchema", "Starts at once"),
         .kind = Kind::Bool,
         .get = [](const LessonStep& s, std::size_t) { return Value(s.autoplay); },
         .set = [](LessonStep& s, std::size_t, const Value& v) { s.autoplay = as<bool>(v); }}},
};

const QuestionField kQuestionFields[] = {
    {.key = question_keys::kPrompt,
     .kind = LessonKind::Line,
     .required = true,
     .text = &Question::prompt},
    {.key = question_keys::kHint, .kind = LessonKind::Line, .text = &Question::hint},
    {.key = question_keys::kHoldBack},
};

const KindField<MeasuredQuestion> kMeasuredFields[] = {
    {.key = question_keys::kMeasure},
    {.key = question_keys::kUnit, .kind = LessonKind::Unit, .text = &MeasuredQuestion::unit},
    {.key = question_keys::kTolerance,
     .kind = LessonKind::Plain,
     .value = {.key = question_keys::kTolerance,
               .label = QT_TRANSLATE_NOOP("SceneSchema", "Tolerance"),
               .kind = Kind::Number,
               .range = {0.0, 1.0, ""},
               .rule = detail::NumberRule::UnitInterval,
               .get = numberGet<MeasuredQuestion, &MeasuredQuestion::tolerance>,
               .set = numberSet<MeasuredQuestion, &MeasuredQuestion::tolerance>}},
    {.key = question_keys::kAbsoluteTolerance,
     .kind = LessonKind::Plain,
     .value = {.key = question_keys::kAbsoluteTolerance,
               .label = QT_TRANSLATE_NOOP("SceneSchema", "Absolute tolerance"),
               .kind = Kind::Number,
               .range = limits::kAbsoluteTolerance,
               .rule = detail::NumberRule::NonNegative,
               .get = numberGet<MeasuredQuestion, &MeasuredQuestion::absoluteTolerance>,
               .set = numberSet<MeasuredQuestion, &MeasuredQuestion::absoluteTolerance>}},
    {.key = question_keys::kSet},
};

const KindField<ChoiceQuestion> kChoiceFields[] = {
    {.key = question_keys::kChoices},
    {.key = question_keys::kAnswer},
};

template <class Row> const Row* findRow(std::span<const Row> rows, std::string_view key)
{
    const auto it =
        std::find_if(rows.begin(), rows.end(), [&](const Row& r) { return r.key == key; });
    return it == rows.end() ? nullptr : &*it;
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

std::span<const KindField<MeasuredQuestion>> kindFields(std::type_identity<MeasuredQuestion>)
{
    return kMeasuredFields;
}

std::span<const KindField<ChoiceQuestion>> kindFields(std::type_identity<ChoiceQuestion>)
{
    return kChoiceFields;
}

std::size_t questionKindIn(const QJsonObject& object)
{
    std::size_t index = 0;
    std::size_t found = 0;
    forEachQuestionKind([&]<class K>(std::type_identity<K> kind) {
        if (found == 0 && index > 0)
            for (const KindField<K>& f : kindFields(kind))
                if (object.contains(rows::fromView(f.key)))
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
        keys << questionKindKeys(k);
    return keys;
}

} // namespace rigidlab::lessons::schema
