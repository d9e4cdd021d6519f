// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The kinds of question, each in its own file (format/question_kind.h says what a kind is made
// of): the one list of them. A new kind is its file and its place in QuestionKind; the
// window's side of it is its file in ui/question_kinds/, listed there in the same way.

#include "format/question_kinds/choice.h"
#include "format/question_kinds/measured.h"
#include "format/question_kinds/number_given.h"

#include <variant>

namespace rigidlab::lessons {

/// A question's kind: its type, and what a question of it holds besides every question's prompt,
/// hint and holdBack. The first is the kind of a question that holds no other kind's key.
using QuestionKind = std::variant<MeasuredQuestion, ChoiceQuestion, NumberGivenQuestion>;

} // namespace rigidlab::lessons
