// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_player/question_judge.h"

#include "lesson_player/answers_record.h"
#include "lesson_player/step_state.h"

#include "simulation/lesson_watch.h"
#include "simulation/run_view.h"
#include "simulation/setting_edit.h"

#include "run/measurements.h"

namespace rigidlab::ui {

namespace {

/// A try at a measured question, with no answer yet.
lessons::AnswerTry numberTry(std::optional<double> measured, bool ahead)
{
    lessons::AnswerTry t;
    t.measured = measured;
    t.ahead = ahead;
    return t;
}

} // namespace

QuestionJudge::QuestionJudge(StepState& state, const RunView& run) : m_state(state), m_run(run) {}

QuestionJudge::Judged QuestionJudge::judge(std::size_t i, const lessons::AnswerTry& attempt)
{
    if (attempt.answer && !attempt.measured && !m_state.holdsRun()) {
        // Nothing to judge it against yet (the run has not got there): said, and not kept as
        // a try, so that the worksheet lists only answers that were judged.
        Judged out;
        lessons::TryCount count = m_state.questionState(i).count;
        out.verdict = lessons::judgeTry(m_state.question(i), attempt, count);
        out.kept = false;
        return out;
    }
    return judgeAgain(i, attempt);
}

QuestionJudge::Judged QuestionJudge::judgeAgain(std::size_t i, const lessons::AnswerTry& attempt)
{
    Judged out;
    lessons::TryCount count = m_state.questionState(i).count;
    out.verdict = lessons::judgeTry(m_state.question(i), attempt, count);
    // Counted here; whether it answered the question is said below (judgeTry's count only
    // says whether the value was given).
    m_state.keepTry(i, attempt, count.attempts);
    AnswersRecord& record = AnswersRecord::session();
    if (record.isOf(*m_state.lesson())) {
        record.keepTries(m_state.index(), m_state.questionCount(), i,
                         m_state.questionState(i).tries);
        recordSettings();
    }
    if (!out.verdict.measured && m_state.holdsRun()) {
        // Not measurable without a window within the limit: the scene runs rather than leave
        // the student with no way on.
        m_state.setAnswered(i);
        out.released = true;
        return out;
    }
    if (!out.verdict.shown || m_state.questionState(i).count.answered)
        return out;
    m_state.setAnswered(i);
    out.released = true;
    out.given = true;
    return out;
}

lessons::AnswerTry QuestionJudge::measuredTry(std::size_t i)
{
    const lessons::LessonStep& step = *m_state.step();
    const lessons::Question& q = m_state.question(i);
    const lessons::Measure& measure = q.as<lessons::MeasuredQuestion>()->measure;
    // The window's run counts when it is the run the question asks for (askedRun).
    const bool liveCounts = askedRun(i).matches();
    if (liveCounts)
        if (const auto live = m_run.lessonWatch().measurements().value(measure, step.scene))
            return numberTry(live, false);
    // While the scene may not run, the student could never get a verdict: the same run is
    // done without a window instead (it is deterministic, so it measures what the window
    // will show once it runs). So is the run a question asks for, when the window's is not it.
    if (liveCounts && !m_state.holdsRun())
        return lessons::AnswerTry{};
    auto ahead = m_ahead.find(i);
    if (ahead == m_ahead.end()) {
        // On the scene as it is now: a fitted e applied to it is what the table shows and
        // the run will measure, not the step's e as the lesson file gives it.
        lessons::LessonStep now = step;
        now.scene = m_run.scene();
        ahead =
            m_ahead.emplace(i, lessons::measureAhead(lessons::askedStep(now, q), measure)).first;
    }
    return numberTry(ahead->second, ahead->second.has_value());
}

AskedRun QuestionJudge::askedRun(std::size_t i) const
{
    return ui::askedRun(*m_state.step(), m_state.question(i), m_run.world(),
                        m_run.editLog().edits());
}

void QuestionJudge::startRecord()
{
    AnswersRecord::session().start(*m_state.lesson());
}

void QuestionJudge::recordSettings()
{
    AnswersRecord& record = AnswersRecord::session();
    if (m_state.lesson() && record.isOf(*m_state.lesson()))
        record.keepSettings(m_state.index(), m_run.world().def());
}

std::vector<std::vector<lessons::AnswerTry>> QuestionJudge::recordedTries() const
{
    const AnswersRecord& record = AnswersRecord::session();
    if (!m_state.lesson() || !record.isOf(*m_state.lesson()))
        return {};
    return record.tries(m_state.index());
}

} // namespace rigidlab::ui
