// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A student's answers to a lesson, as the window saves them beside a handed-in worksheet
// (lessons/ANSWERS_FORMAT.md): who, when, and per step the tries at each question with the
// value each was judged against, and the settings the step ran with. A teacher regenerates
// the worksheet from it (`rigidlab-cli lesson LESSON --worksheet OUT.pdf --answers FILE`).

#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/integrator.h"

#include <QByteArray>
#include <QString>

#include <optional>
#include <vector>

namespace rigidlab::lessons {

/// The version this reader reads (the value of the top-level key "rigidlab-answers").
inline constexpr int kAnswersFormatVersion = 1;
/// The largest answers file read [bytes].
inline constexpr qint64 kMaxAnswersFileBytes = 1024 * 1024;
/// The most steps, questions per step and tries per question a file may hold.
inline constexpr int kMaxAnswerSteps = 200;
inline constexpr int kMaxAnswerQuestions = 50;
inline constexpr int kMaxAnswerTries = 100;
/// The largest answer or measured value kept, in the question's unit (the window takes no
/// larger answer).
inline constexpr double kMaxAnswerMagnitude = 1e15;
/// The longest name, class, lesson title or file name kept [characters].
inline constexpr int kMaxAnswerText = 200;

/// The longest option text a choice try keeps [characters].
inline constexpr int kMaxAnswerChoiceText = 1000;

/// One try at a question: an answer checked, an option chosen, or "Show me" (neither).
struct AnswerTry {
    std::optional<double> answer;   ///< in the question's unit; nullopt: "Show me" or a choice
    std::optional<double> measured; ///< what it was judged against; nullopt: not measured yet
    bool ahead = false;             ///< measured by a run without a window (held-back run)
    /// A choice question's try: the option chosen (0-based); nullopt: "Show me" or a number.
    std::optional<int> choice;
    QString choiceText; ///< the option chosen, as the student read it
    bool right = false; ///< whether `choice` was the right option
    bool operator==(const AnswerTry&) const = default;
};

/// A step's work and the settings its main world ran with (nullopt: not visited).
struct StepAnswers {
    std::vector<std::vector<AnswerTry>> questions; ///< per question, its tries in order
    std::optional<physics::IntegratorKind> integrator;
    std::optional<double> dt; ///< [s]
    std::optional<physics::SolverKind> solver;
    bool operator==(const StepAnswers&) const = default;
};

struct Answers {
    QString lessonFile;  ///< the lesson's file name, without its folder
    QString lessonTitle; ///< in the language it was played in
    QString language;    ///< the code it was played in (languages.h)
    QString student;
    QString className;
    QString date; ///< ISO 8601, YYYY-MM-DD
    std::vector<StepAnswers> steps;
    bool operator==(const Answers&) const = default;
};

struct AnswersLoadResult {
    bool ok = false;
    QString error; ///< one line `FILE: PLACE: what is wrong`
    Answers answers;
};

/// Reads and checks an answers file (at most kMaxAnswersFileBytes).
AnswersLoadResult loadAnswersFile(const QString& path);
/// The same for bytes in memory; `path` names them in messages.
AnswersLoadResult loadAnswersJson(const QByteArray& bytes, const QString& path);
/// The file's bytes: what loadAnswersJson() reads back to the same Answers.
QByteArray answersJson(const Answers& answers);

/// Empty when `answers` fits the lesson in the file `lessonFile` (its name, without the folder)
/// with these question counts per step, else the reason ("lesson: answers to \"stacks.json\",
/// not to \"restitution.json\"", "steps[2].questions: 3 questions, the lesson's step 3 has
/// 2"). Answers that name no lesson (an empty sheet's) fit any.
QString answersMismatch(const Answers& answers, const QString& lessonFile,
                        const std::vector<int>& questionsPerStep);

/// Empty when `text` may be a line of an answers file (a student's or a class's name): at most
/// kMaxAnswerText characters, one line; else the reason ("longer than 200 characters").
QString answerTextProblem(const QString& text);

} // namespace rigidlab::lessons
