// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzz target: the answers file beside a handed-in worksheet (format/answers_file.h) on any
// bytes.
//
// Whatever the bytes, the reader returns: answers or one error line naming the source, with
// nothing half read. Answers it accepts keep within the limits (steps, questions, tries, the
// length of each text, every value finite and at most kMaxAnswerMagnitude, each text one that
// --student would take too), and written again they read back the same. They fit only the
// lesson they name: another lesson's file name is a mismatch whatever its questions.

#include "fuzz_check.h"

#include "format/answers_file.h"

#include <QByteArray>
#include <QString>

#include <cmath>
#include <cstddef>
#include <cstdint>

using namespace rigidlab;

namespace {

void checkValue(const std::optional<double>& value)
{
    FUZZ_CHECK(!value ||
               (std::isfinite(*value) && std::abs(*value) <= lessons::kMaxAnswerMagnitude));
}

void checkAnswers(const lessons::Answers& a)
{
    for (const QString* text :
         {&a.lessonFile, &a.lessonTitle, &a.language, &a.student, &a.className, &a.date})
        FUZZ_CHECK(text->size() <= lessons::kMaxAnswerText && !text->contains(u'\n') &&
                   lessons::answerTextProblem(*text).isEmpty());
    // The lesson it names, with room for every question it holds, fits; any other does not.
    std::vector<int> room(a.steps.size(), lessons::kMaxAnswerQuestions);
    FUZZ_CHECK(lessons::answersMismatch(a, a.lessonFile, room).isEmpty());
    FUZZ_CHECK(
        !lessons::answersMismatch(a, a.lessonFile + QStringLiteral(".other"), room).isEmpty());
    FUZZ_CHECK(a.steps.size() <= static_cast<std::size_t>(lessons::kMaxAnswerSteps));
    for (const lessons::StepAnswers& step : a.steps) {
        FUZZ_CHECK(!step.dt || (std::isfinite(*step.dt) && *step.dt > 0));
        FUZZ_CHECK(step.questions.size() <= static_cast<std::size_t>(lessons::kMaxAnswerQuestions));
        for (const auto& tries : step.questions) {
            FUZZ_CHECK(tries.size() <= static_cast<std::size_t>(lessons::kMaxAnswerTries));
            for (const lessons::AnswerTry& t : tries) {
                checkValue(t.answer);
                checkValue(t.measured);
            }
        }
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const QString source = QStringLiteral("fuzz.answers.json");
    const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    const lessons::AnswersLoadResult r = lessons::loadAnswersJson(bytes, source);
    if (!r.ok) {
        FUZZ_CHECK(r.error.startsWith(source + QStringLiteral(": ")));
        FUZZ_CHECK(!r.error.contains(u'\n'));
        FUZZ_CHECK(r.answers == lessons::Answers{});
        return 0;
    }
    checkAnswers(r.answers);
    const lessons::AnswersLoadResult again =
        lessons::loadAnswersJson(lessons::answersJson(r.answers), source);
    FUZZ_CHECK(again.ok && again.answers == r.answers);
    return 0;
}
