// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_player/step_state.h"

#include <cassert>

namespace rigidlab::ui {

void StepState::open(lessons::Lesson lesson)
{
    assert(!lesson.steps.empty());
    m_lesson = std::make_unique<lessons::Lesson>(std::move(lesson));
    m_step = -1; // so that the first step is gone to
    goTo(0);
}

void StepState::close()
{
    m_lesson.reset();
    m_step = 0;
    m_questions.clear();
}

int StepState::stepCount() const
{
    return m_lesson ? static_cast<int>(m_lesson->steps.size()) : 0;
}

const lessons::LessonStep* StepState::step() const
{
    return m_lesson ? &m_lesson->steps[static_cast<std::size_t>(m_step)] : nullptr;
}

bool StepState::goTo(int index)
{
    if (!m_lesson || index < 0 || index >= stepCount())
        return false;
    m_step = index;
    m_questions.assign(step()->questions.size(), QuestionState{});
    return true;
}

const lessons::Question& StepState::question(std::size_t i) const
{
    return step()->questions.at(i);
}

void StepState::keepTry(std::size_t i, const lessons::AnswerTry& attempt, int attempts)
{
    QuestionState& q = m_questions.at(i);
    q.tries.push_back(attempt);
    q.count.attempts = attempts;
}

std::vector<std::vector<lessons::AnswerTry>> StepState::tries() const
{
    std::vector<std::vector<lessons::AnswerTry>> out;
    for (const QuestionState& q : m_questions)
        out.push_back(q.tries);
    return out;
}

QStringList StepState::heldBack() const
{
    if (!m_lesson)
        return {};
    std::vector<bool> answered;
    for (const QuestionState& q : m_questions)
        answered.push_back(q.count.answered);
    return step()->heldBack(answered);
}

bool StepState::holdsRun() const
{
    return heldBack().contains(QStringView(lessons::kHoldBackRun));
}

} // namespace rigidlab::ui
