// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The choice kind of question (format/question_kind.h): one of a few options is right, nothing
// is measured. Its options and its right one are parts, read in format/lesson_questions.cpp.

#include "format/question_kind.h"

#include <QString>
#include <QStringList>

namespace rigidlab::lessons {

/// The fewest and the most options a choice question offers.
inline constexpr int kMinChoices = 2;
inline constexpr int kMaxChoices = 6;

/// A question answered by picking one of a few texts; nothing is measured.
struct ChoiceQuestion {
    /// The options, in the language the lesson is kept in (kMinChoices to kMaxChoices).
    QStringList choices;
    int answer = 0; ///< the right one of `choices` (0-based)
};

namespace schema {

namespace question_keys {
inline constexpr std::string_view kChoices = "choices";
inline constexpr std::string_view kAnswer = "answer";
} // namespace question_keys

inline std::span<const KindField<ChoiceQuestion>> kindFields(std::type_identity<ChoiceQuestion>)
{
    static const KindField<ChoiceQuestion> rows[] = {
        {.key = question_keys::kChoices},
        {.key = question_keys::kAnswer},
    };
    return rows;
}

} // namespace schema

inline QString otherKindsKey(const ChoiceQuestion&)
{
    return notForQuestionWith(
        schema::question_keys::kChoices,
        detail::FileMessages::tr("it is answered by choosing, nothing is measured"));
}

inline std::optional<KindProblem> kindProblem(const ChoiceQuestion&)
{
    return std::nullopt; // its answer is read after its options, within their range
}

inline AnswerForm answerForm(const ChoiceQuestion&)
{
    return {QString(), true};
}

/// A choice question's try: nothing is measured, so every try is judged. A wrong first try
/// reads the hint (the right option stays hidden while a second try is worth something);
/// later tries, a right one and "Show me" name the right option. An option's text keeps a
/// number and its unit on one line, as a measured verdict does.
inline Verdict judgeKindTry(const ChoiceQuestion& q, const QString& hint, const AnswerTry& attempt,
                            TryCount& count)
{
    // A try recorded with another lesson's options may name one the question no longer has.
    const QString rightText =
        q.answer >= 0 && q.answer < q.choices.size() ? q.choices[q.answer] : QString();
    Verdict verdict;
    verdict.measured = true;
    verdict.value = q.answer;
    if (!attempt.choice) {
        verdict.shown = true;
        verdict.message = keepUnitsTogether(Judge::tr("The right answer: “%1”.").arg(rightText));
        count.answered = true;
        return verdict;
    }
    if (!count.answered)
        ++count.attempts;
    verdict.right = attempt.right;
    const QString chosen = attempt.choiceText;
    if (!verdict.right && !count.answered && count.attempts <= 1) {
        verdict.message = keepUnitsTogether(
            hint.isEmpty() ? Judge::tr("Not quite (you chose “%1”). Try once more.").arg(chosen)
                           : Judge::tr("Not quite (you chose “%1”). Hint: %2").arg(chosen, hint));
        return verdict;
    }
    verdict.shown = true;
    verdict.message = keepUnitsTogether(
        verdict.right ? Judge::tr("Right: “%1”.").arg(chosen)
                      : Judge::tr("Not quite: the right answer is “%1” (you chose “%2”).")
                            .arg(rightText, chosen));
    count.answered = true;
    return verdict;
}

} // namespace rigidlab::lessons
