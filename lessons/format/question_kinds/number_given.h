// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The number-given kind of question (format/question_kind.h): the lesson states the right
// number and how far off an answer may be ("number": 0.8, "within": 0.05), for what a student
// works out on paper (a momentum before the run, an energy by the formula); nothing is
// measured, so it is judged at once.

#include "format/question_kind.h"

#include <QString>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rigidlab::lessons {

/// The most an answer given by the lesson may be (as a typed answer, kMaxAnswerMagnitude).
inline constexpr limits::Range kGivenNumberRange{-kMaxAnswerMagnitude, kMaxAnswerMagnitude, ""};

/// A question answered by a number the lesson gives: right within `within` of `number`.
struct NumberGivenQuestion {
    double number = 0; ///< the right answer, in `unit`
    double within = 0; ///< how far off an answer may be and still be right, in `unit` (> 0)
    QString unit;      ///< shown after the answer box, e.g. "kg m/s"
};

namespace schema {

namespace question_keys {
inline constexpr std::string_view kNumber = "number";
inline constexpr std::string_view kWithin = "within";
} // namespace question_keys

inline std::span<const KindField<NumberGivenQuestion>>
kindFields(std::type_identity<NumberGivenQuestion>)
{
    static const KindField<NumberGivenQuestion> rows[] = {
        plainRow<NumberGivenQuestion>(
            {.key = question_keys::kNumber,
             .label = QT_TRANSLATE_NOOP("SceneSchema", "Right answer"),
             .kind = Kind::Number,
             .range = kGivenNumberRange,
             .get = numberGet<NumberGivenQuestion, &NumberGivenQuestion::number>,
             .set = numberSet<NumberGivenQuestion, &NumberGivenQuestion::number>,
             .required = true}),
        plainRow<NumberGivenQuestion>(
            {.key = question_keys::kWithin,
             .label = QT_TRANSLATE_NOOP("SceneSchema", "Right within"),
             .kind = Kind::Number,
             .range = kGivenNumberRange,
             .rule = detail::NumberRule::Positive,
             .get = numberGet<NumberGivenQuestion, &NumberGivenQuestion::within>,
             .set = numberSet<NumberGivenQuestion, &NumberGivenQuestion::within>,
             .required = true}),
        {.key = question_keys::kUnit, .kind = LessonKind::Unit, .text = &NumberGivenQuestion::unit},
    };
    return rows;
}

} // namespace schema

inline QString otherKindsKey(const NumberGivenQuestion&)
{
    return notForQuestionWith(schema::question_keys::kNumber,
                              detail::FileMessages::tr("its answer is the number the lesson gives, "
                                                       "nothing is measured or chosen"));
}

inline std::optional<KindProblem> kindProblem(const NumberGivenQuestion&)
{
    return std::nullopt; // its rows check each value, and no two depend on each other
}

inline AnswerForm answerForm(const NumberGivenQuestion& q)
{
    return {q.unit, false};
}

/// Whether `answer` is right: within the band, its edges included as a teacher types them
/// (|0.75 - 0.8| is 0.05000000000000004 in binary, a few units in the last place over 0.05).
inline bool isRightAnswer(const NumberGivenQuestion& q, double answer)
{
    const double roundOff =
        4 * std::numeric_limits<double>::epsilon() * std::max(std::abs(answer), std::abs(q.number));
    return std::abs(answer - q.number) <= q.within + roundOff;
}

/// A value in the question's unit as its verdicts, the worksheet and the editor write it: with
/// as many digits as tell `within` apart from the number.
inline QString formatGiven(const NumberGivenQuestion& q, double value)
{
    const double relative = q.number == 0 ? q.within : q.within / std::abs(q.number);
    return formatAnswer(value, relative, q.unit);
}

/// A try: a number typed, or "Show me". The answer is known from the start, so every try is
/// judged: a wrong first one reads the hint, a later one (and a right one) gives the number.
inline Verdict judgeKindTry(const NumberGivenQuestion& q, const QString& hint,
                            const AnswerTry& attempt, TryCount& count)
{
    const QString right = formatGiven(q, q.number);
    Verdict verdict;
    verdict.measured = true;
    verdict.value = q.number;
    if (!attempt.answer) {
        verdict.shown = true;
        verdict.message = keepUnitsTogether(Judge::tr("The right answer is %1.").arg(right));
        count.answered = true;
        return verdict;
    }
    if (!count.answered)
        ++count.attempts;
    verdict.right = isRightAnswer(q, *attempt.answer);
    const QString said = formatGiven(q, *attempt.answer);
    if (!verdict.right && !count.answered && count.attempts <= 1) {
        verdict.message = keepUnitsTogether(
            hint.isEmpty() ? Judge::tr("Not quite (you said %1). Try once more.").arg(said)
                           : Judge::tr("Not quite (you said %1). Hint: %2").arg(said, hint));
        return verdict;
    }
    verdict.shown = true;
    verdict.message = keepUnitsTogether(
        verdict.right
            ? Judge::tr("Right: the answer is %1 (you said %2).").arg(right, said)
            : Judge::tr("Not quite: the right answer is %1 (you said %2).").arg(right, said));
    count.answered = true;
    return verdict;
}

} // namespace rigidlab::lessons
