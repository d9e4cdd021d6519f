// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where the student is in a lesson: the lesson open, its step, and the tries at the step's
// questions, hence what the step still holds back. Plain data, no widgets: the lesson player
// shows it, the question judge counts the tries in it.

#include "format/answers_file.h"
#include "format/lesson.h"
#include "format/verdict.h"

#include <QStringList>

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace rigidlab::ui {

class StepState {
public:
    /// Where one question of the step stands.
    struct QuestionState {
        std::vector<lessons::AnswerTry> tries; ///< in order, each judged
        /// Its tries judged so far; `answered`: nothing is held back for it any more (its
        /// value was given, or it cannot be measured without the run it held back).
        lessons::TryCount count;
    };

    /// Opens `lesson` (at least one step) on its first step.
    void open(lessons::Lesson lesson);
    void close();
    const lessons::Lesson* lesson() const { return m_lesson.get(); }
    /// The step shown, 0-based (0 with no lesson).
    int index() const { return m_step; }
    int stepCount() const;
    /// The step shown; nullptr with no lesson.
    const lessons::LessonStep* step() const;
    bool hasBack() const { return m_lesson && m_step > 0; }
    bool hasNext() const { return m_lesson && m_step + 1 < stepCount(); }
    bool isLast() const { return m_lesson && m_step + 1 == stepCount(); }
    /// Goes to step `index`, its questions not tried yet (the same step: tried afresh). False,
    /// and nothing changes, when the lesson has no such step.
    bool goTo(int index);

    /// The questions of the step shown (none with no lesson).
    std::size_t questionCount() const { return m_questions.size(); }
    const lessons::Question& question(std::size_t i) const;
    const QuestionState& questionState(std::size_t i) const { return m_questions.at(i); }
    /// Keeps a judged try at question i, and how many of its tries have been judged against a
    /// value now (whether it is answered is setAnswered()'s to say).
    void keepTry(std::size_t i, const lessons::AnswerTry& attempt, int attempts);
    /// Question i holds nothing back any more.
    void setAnswered(std::size_t i) { m_questions.at(i).count.answered = true; }
    /// Each question's tries, in order.
    std::vector<std::vector<lessons::AnswerTry>> tries() const;
    /// What the questions not answered yet hold back ("run", "panel:collision", ...).
    QStringList heldBack() const;
    /// Whether they hold back the run itself.
    bool holdsRun() const;

private:
    std::unique_ptr<lessons::Lesson> m_lesson;
    int m_step = 0;
    std::vector<QuestionState> m_questions; ///< of the step shown
};

} // namespace rigidlab::ui
