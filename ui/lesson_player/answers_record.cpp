// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_player/answers_record.h"

#include <QDate>
#include <QFileInfo>

namespace rigidlab::ui {

AnswersRecord& AnswersRecord::session()
{
    static AnswersRecord record;
    return record;
}

void AnswersRecord::start(const lessons::Lesson& lesson)
{
    if (m_lessonPath == lesson.path && m_steps.size() == lesson.steps.size())
        return;
    m_lessonPath = lesson.path;
    m_steps.assign(lesson.steps.size(), lessons::StepAnswers{});
}

bool AnswersRecord::isOf(const lessons::Lesson& lesson) const
{
    return m_lessonPath == lesson.path;
}

void AnswersRecord::keepTries(int step, std::size_t questions, std::size_t i,
                              const std::vector<lessons::AnswerTry>& tries)
{
    lessons::StepAnswers& s = m_steps.at(static_cast<std::size_t>(step));
    if (s.questions.size() < questions)
        s.questions.resize(questions);
    s.questions[i] = tries;
}

void AnswersRecord::keepSettings(int step, const physics::WorldDef& def)
{
    lessons::StepAnswers& s = m_steps.at(static_cast<std::size_t>(step));
    s.integrator = def.integrator;
    s.dt = def.dt;
    s.solver = def.solver;
}

std::vector<std::vector<lessons::AnswerTry>> AnswersRecord::tries(int step) const
{
    return m_steps.at(static_cast<std::size_t>(step)).questions;
}

lessons::Answers AnswersRecord::answers(const lessons::Lesson& lesson,
                                        const QString& language) const
{
    lessons::Answers out;
    out.lessonFile = QFileInfo(lesson.path).fileName();
    out.lessonTitle = lesson.title;
    out.language = language;
    out.student = student;
    out.className = className;
    out.date = QDate::currentDate().toString(Qt::ISODate);
    if (isOf(lesson))
        out.steps = m_steps;
    // Steps after the last one visited add nothing.
    while (!out.steps.empty() && out.steps.back() == lessons::StepAnswers{})
        out.steps.pop_back();
    return out;
}

} // namespace rigidlab::ui
