// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Judging the tries at the step's questions: a measured answer against what the window's run
// measures (or the run asked for, done without a window), each try counted in the step's state
// and kept in the session's answers record, and what an answer releases of what the step holds
// back. No widgets: the lesson player shows what it returns.

#include "lesson_player/asked_run.h"

#include "format/answers_file.h"
#include "format/verdict.h"

#include <cstddef>
#include <map>
#include <optional>

namespace rigidlab::ui {

class RunView;
class StepState;

class QuestionJudge {
public:
    /// Judges the questions of `state`'s step, on the run `run` shows.
    QuestionJudge(StepState& state, const RunView& run);

    /// What became of a try.
    struct Judged {
        lessons::Verdict verdict;
        /// False: not judged yet (a typed number with nothing measured to judge it against
        /// while the run can still get there): `verdict.message` says so; nothing is kept.
        bool kept = true;
        /// Question i holds nothing back any more: the step's heldBack() is shorter.
        bool released = false;
        /// Its value was given: there is nothing more to show.
        bool given = false;
    };
    /// Judges a try at question i: kept with the step's tries and in the record, counted, and
    /// what it releases released.
    Judged judge(std::size_t i, const lessons::AnswerTry& attempt);
    /// The same for a try judged before (the record's, the work kept through a language
    /// switch): kept whether or not it was measured.
    Judged judgeAgain(std::size_t i, const lessons::AnswerTry& attempt);
    /// A try at measured question i without an answer yet: the value it is judged against
    /// (nullopt while not measured yet) and whether it was measured ahead, without a window.
    lessons::AnswerTry measuredTry(std::size_t i);
    /// How the window's run stands to the one question i asks for.
    AskedRun askedRun(std::size_t i) const;
    /// What a run without a window measured is measured again when next asked (the scene
    /// changed, or the step's questions are asked anew).
    void forgetMeasuredAhead() { m_ahead.clear(); }

    /// Starts the session's record of the open lesson, unless it is the lesson it is of.
    void startRecord();
    /// Keeps the settings the current step's world runs with in the record.
    void recordSettings();
    /// The tries the record holds for the current step, each question's in order.
    std::vector<std::vector<lessons::AnswerTry>> recordedTries() const;

private:
    StepState& m_state;
    const RunView& m_run;
    /// Per measured question, what a run without a window measured (nullopt: nothing within
    /// the limit), once measured.
    std::map<std::size_t, std::optional<double>> m_ahead;
};

} // namespace rigidlab::ui
