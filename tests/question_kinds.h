// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A question's part of one kind, for tests that know which kind a question is: std::get throws
// on another kind, and Qt Test reports the exception as the test's failure.

#include "format/lesson.h"

#include <variant>

namespace rigidlab::test {

inline const lessons::MeasuredQuestion& measuredOf(const lessons::Question& q)
{
    return std::get<lessons::MeasuredQuestion>(q.kind);
}
inline lessons::MeasuredQuestion& measuredOf(lessons::Question& q)
{
    return std::get<lessons::MeasuredQuestion>(q.kind);
}
inline const lessons::ChoiceQuestion& choiceOf(const lessons::Question& q)
{
    return std::get<lessons::ChoiceQuestion>(q.kind);
}
inline bool isChoice(const lessons::Question& q)
{
    return std::holds_alternative<lessons::ChoiceQuestion>(q.kind);
}

} // namespace rigidlab::test
