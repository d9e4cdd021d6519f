// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a kind of question is made of, for a kind written in its own file
// (format/question_kinds/, listed in format/question_kinds.h). A kind K is a struct with what a
// question of that kind holds besides every question's prompt, hint and holdBack, and these
// functions beside it, found by its type (each an overload, so that a kind without one does not
// compile where it is called):
//
//   schema::kindFields(std::type_identity<K>)   its rows (lesson_rows.h): its keys, texts and
//                                               plain values; the loader, the list of allowed
//                                               keys and the editor's change of kind read them
//   otherKindsKey(const K&)        what another kind's key in a question of this kind is told
//   kindProblem(const K&)          a check across its fields, after its rows were read
//   answerForm(const K&)           the unit a typed answer is in, or that it is chosen (the
//                                  class table's column)
//   judgeKindTry(const K&, hint, try, count)   its verdict on a try (the measured kind's needs
//                                  a run, so it is in lessons/run/judge.cpp)
//
// A row of kind Part is read by readKindPart (format/lesson_questions.cpp), for the kinds that
// have parts with a shape of their own (a measure, options). What a kind shows in the window
// (the player's answer row, the worksheet's lines, the editor's page) is in ui/question_kinds/.

#include "format/answers_file.h"
#include "format/lesson_rows.h"
#include "format/verdict.h"

#include <QCoreApplication>
#include <QString>

#include <optional>
#include <span>
#include <string_view>
#include <type_traits>

namespace rigidlab::lessons {

/// What a check across a kind's fields finds wrong: at which key, and what.
struct KindProblem {
    std::string_view key;
    QString message;
};

/// How a kind's question is answered, as the class table shows its column.
struct AnswerForm {
    QString unit;        ///< a typed number's unit ("m"); empty: none (or a choice)
    bool chosen = false; ///< answered by choosing an option, not by typing a number
};

/// What another kind's key in a question of a kind is told (the kind's otherKindsKey): that it
/// is not for a question with the kind's own `key`, and `why`.
inline QString notForQuestionWith(std::string_view key, const QString& why)
{
    return detail::FileMessages::tr("not for a question with \"%1\": %2")
        .arg(schema::jsonKey(key), why);
}

} // namespace rigidlab::lessons
