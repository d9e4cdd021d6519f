// SPDX-License-Identifier: GPL-3.0-or-later
// The lesson player's questions: answer boxes, Check and Show me, verdicts, and what the
// answers release of what the step holds back.

#include "lesson_player/lesson_player.h"

#include "lesson_player/asked_run.h"
#include "lesson_player/question_area.h"
#include "lesson_player/step_text.h"

#include "common/announcer.h"
#include "panels/number_field.h"
#include "question_kinds/question_kinds.h"
#include "simulation/simulation_controller.h"

#include "run/measurements.h"

#include <QButtonGroup>
#include <QLabel>
#include <QLineEdit>
#include <QPointer>
#include <QPushButton>
#include <QScrollArea>
#include <QTimer>
#include <QVBoxLayout>

#include <cmath>
#include <variant>

namespace rigidlab::ui {

namespace {

/// The largest answer taken, in the question's unit: far beyond any measured value, and small
/// enough that |answer - measured| stays finite.
constexpr double kMaxAnswer = 1e15;

/// Says under a question what to do before it can be judged (nothing is counted).
void askFirst(QLabel* result, const QString& text)
{
    result->setStyleSheet(QStringLiteral("color: #a05a00;"));
    result->setText(text);
    result->setVisible(true);
}

/// A try at a measured question, with no answer yet.
QuestionTry numberTry(std::optional<double> measured, bool ahead)
{
    QuestionTry t;
    t.measured = measured;
    t.ahead = ahead;
    return t;
}

} // namespace

void LessonPlayer::buildQuestions()
{
    while (QLayoutItem* item = m_questionLayout->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    m_rows.clear();
    if (!m_lesson)
        return;
    const lessons::LessonStep& step = m_lesson->steps[static_cast<size_t>(m_step)];
    for (std::size_t i = 0; i < step.questions.size(); ++i) {
        const lessons::Question& q = step.questions[i];
        auto* box = new QWidget(m_questionBox);
        auto* v = new QVBoxLayout(box);
        v->setContentsMargins(0, 4, 0, 4);
        auto* prompt = new QLabel(lessons::keepUnitsTogether(q.prompt), box);
        prompt->setWordWrap(true);
        v->addWidget(prompt);
        m_questionLayout->addWidget(box);
        // Each kind builds its row (ui/question_kinds/); the player judges what it hands in.
        std::visit([&](const auto& kind) { addRow(answerRow(kind, prompt, v, rowHooks(i))); },
                   q.kind);
    }
    orderTabs();
}

void LessonPlayer::addRow(const AnswerRow& parts)
{
    QuestionRow row;
    row.edit = parts.edit;
    row.choices = parts.choices;
    row.check = parts.check;
    row.result = parts.result;
    row.show = parts.show;
    m_rows.push_back(row);
}

RowHooks LessonPlayer::rowHooks(std::size_t i)
{
    // Each hook does nothing once the row is gone (another step, no lesson).
    const auto live = [this, i] { return m_lesson && i < m_rows.size(); };
    RowHooks hooks;
    hooks.prompt = m_lesson->steps[static_cast<size_t>(m_step)].questions[i].prompt;
    hooks.judge = [this, i, live](const QuestionTry& attempt) {
        return live() && judge(i, attempt);
    };
    hooks.typedNumber = [this, i, live]() -> std::optional<double> {
        return live() ? typedAnswer(i) : std::nullopt;
    };
    hooks.askFirst = [this, i, live](const QString& text) {
        if (live())
            askFirst(m_rows[i].result, text);
    };
    hooks.measured = [this, i, live] { return live() ? measuredTry(i) : QuestionTry{}; };
    hooks.askedRun = [this, i, live] {
        RunAdvice out;
        if (!live())
            return out;
        const AskedRun asked = askedRunOf(i);
        if (!asked.matches())
            out.advice = askedRunAdvice(asked);
        out.setFirst = !asked.matches() && asked.studentCanSet;
        return out;
    };
    return hooks;
}

void LessonPlayer::orderTabs()
{
    // Made after the buttons below them, the questions would come last to Tab: the step's
    // text, its questions with their answers, then Back, Next and the others, as they are
    // shown.
    QList<QWidget*> order{m_text};
    for (QWidget* w : m_questionBox->findChildren<QWidget*>())
        if (w->focusPolicy() & Qt::TabFocus)
            order << w;
    order << m_back << m_next << m_restart << m_export << m_handIn;
    for (qsizetype k = 1; k < order.size(); ++k)
        setTabOrder(order[k - 1], order[k]);
}

std::optional<double> LessonPlayer::typedAnswer(std::size_t i)
{
    QuestionRow& row = m_rows[i];
    const std::optional<double> parsed = parseNumber(row.edit->text());
    if (!parsed) {
        askFirst(row.result, tr("Type a number first."));
        return std::nullopt;
    }
    if (std::abs(*parsed) > kMaxAnswer) {
        askFirst(row.result, tr("Type a number from %1 to %2.")
                                 .arg(formatNumber(-kMaxAnswer), formatNumber(kMaxAnswer)));
        return std::nullopt;
    }
    return parsed;
}

bool LessonPlayer::judge(std::size_t i, const QuestionTry& attempt)
{
    if (attempt.answer && !attempt.measured &&
        !heldBack().contains(QStringView(lessons::kHoldBackRun))) {
        // Nothing to judge it against yet (the run has not got there): said, and not kept as
        // a try, so that the worksheet lists only answers that were judged.
        lessons::TryCount count{m_rows[i].attempts, m_rows[i].answered};
        const lessons::Question& q = m_lesson->steps[static_cast<size_t>(m_step)].questions[i];
        askFirst(m_rows[i].result, lessons::judgeTry(q, attempt, count).message);
        return false;
    }
    applyTry(i, attempt);
    return true;
}

AskedRun LessonPlayer::askedRunOf(std::size_t i) const
{
    const lessons::LessonStep& step = m_lesson->steps[static_cast<size_t>(m_step)];
    return askedRun(step, step.questions[i], m_controller.world(), m_controller.editLog().edits());
}

QuestionTry LessonPlayer::measuredTry(std::size_t i)
{
    const lessons::LessonStep& step = m_lesson->steps[static_cast<size_t>(m_step)];
    const lessons::Question& q = step.questions[i];
    const lessons::Measure& measure = q.as<lessons::MeasuredQuestion>()->measure;
    // The window's run counts when it is the run the question asks for (askedRun).
    const bool liveCounts = askedRunOf(i).matches();
    if (liveCounts)
        if (const auto live = m_controller.lessonWatch().measurements().value(measure, step.scene))
            return numberTry(live, false);
    // While the scene may not run, the student could never get a verdict: the same run is
    // done without a window instead (it is deterministic, so it measures what the window
    // will show once it runs). So is the run a question asks for, when the window's is not it.
    if (liveCounts && !heldBack().contains(QStringView(lessons::kHoldBackRun)))
        return QuestionTry{};
    QuestionRow& row = m_rows[i];
    if (!row.aheadDone) {
        // On the scene as it is now: a fitted e applied to it is what the table shows and
        // the run will measure, not the step's e as the lesson file gives it.
        lessons::LessonStep now = step;
        now.scene = m_controller.scene();
        row.ahead = lessons::measureAhead(lessons::askedStep(now, q), measure);
        row.aheadDone = true;
    }
    return numberTry(row.ahead, row.ahead.has_value());
}

void LessonPlayer::applyTry(std::size_t i, const QuestionTry& attempt)
{
    const lessons::Question& q = m_lesson->steps[static_cast<size_t>(m_step)].questions[i];
    QuestionRow& row = m_rows[i];
    row.tries.push_back(attempt);
    recordTry(i);
    // Counted here; whether it answered the question is settle()'s to say (it also releases
    // what the question held back).
    lessons::TryCount count{row.attempts, row.answered};
    const lessons::Verdict verdict = lessons::judgeTry(q, attempt, count);
    row.attempts = count.attempts;
    settle(i, verdict);
}

StepWork LessonPlayer::work() const
{
    StepWork out;
    for (const QuestionRow& row : m_rows) {
        out.tries.push_back(row.tries);
        // A choice question's "box" is the option chosen, by its index.
        out.typed << (row.edit                       ? row.edit->text()
                      : row.choices->checkedId() < 0 ? QString()
                                                     : QString::number(row.choices->checkedId()));
    }
    return out;
}

void LessonPlayer::restoreWork(const StepWork& work)
{
    if (!m_lesson)
        return;
    // Fresh rows: those shown may already hold the record's tries, the same as `work`'s.
    buildQuestions();
    for (std::size_t i = 0; i < m_rows.size(); ++i) {
        if (i < work.tries.size())
            for (const QuestionTry& attempt : work.tries[i])
                applyTry(i, attempt);
        if (i >= static_cast<std::size_t>(work.typed.size()))
            continue;
        const QString& typed = work.typed[static_cast<qsizetype>(i)];
        if (m_rows[i].edit)
            m_rows[i].edit->setText(typed);
        else if (QAbstractButton* option = m_rows[i].choices->button(typed.toInt());
                 option && !typed.isEmpty())
            option->setChecked(true);
    }
}

void LessonPlayer::settle(std::size_t i, const lessons::Verdict& v)
{
    QuestionRow& row = m_rows[i];
    row.result->setStyleSheet(!v.measured ? QStringLiteral("color: #a05a00;")
                              : v.right   ? QStringLiteral("color: #1e7b34; font-weight: bold;")
                              : v.shown   ? QStringLiteral("color: #b3261e; font-weight: bold;")
                                          : QStringLiteral("color: #a05a00; font-weight: bold;"));
    // A choice's verdict is marked as well as worded and coloured (a number's says its value).
    const QString mark = !row.choices || !v.measured ? QString()
                         : v.right                   ? QStringLiteral("✓ ")
                         : v.shown && row.tries.back().choice == std::nullopt
                             ? QStringLiteral("◆ ")
                             : QStringLiteral("✗ ");
    row.result->setText(mark + v.message);
    row.result->setVisible(true);
    revealResult(i);
    // The verdict is told, where the focus stays on the answer or the Check button: a label
    // that changes out of the focus is not read.
    if (!m_replaying)
        announce(*row.result, row.result->text());
    if (!v.measured && heldBack().contains(QStringView(lessons::kHoldBackRun))) {
        // Not measurable without a window within the limit: let the scene run rather than
        // leave the student with no way on.
        row.answered = true;
        if (!m_replaying)
            emit heldBackChanged(heldBack());
        return;
    }
    if (!v.shown || row.answered)
        return;
    row.answered = true;
    row.show->setEnabled(false);
    if (!m_replaying)
        emit heldBackChanged(heldBack());
}

void LessonPlayer::revealResult(std::size_t i)
{
    // The questions are in sight below the text, but a later question's verdict may lie below
    // the bottom of their area when they do not all fit. Once the layout has made room for
    // it, it is scrolled into sight (the question's box with it, so that the answer stays
    // beside its verdict).
    const QPointer<QLabel> result = m_rows[i].result;
    const QPointer<QScrollArea> area = m_questionArea;
    QTimer::singleShot(0, this, [result, area] {
        if (result && area && result->isVisible())
            area->ensureWidgetVisible(result, 0, 8);
    });
}

QStringList LessonPlayer::heldBack() const
{
    if (!m_lesson)
        return {};
    std::vector<bool> answered;
    for (const QuestionRow& row : m_rows)
        answered.push_back(row.answered);
    return m_lesson->steps[static_cast<size_t>(m_step)].heldBack(answered);
}

void LessonPlayer::showMe(int question)
{
    if (question < 0 || question >= static_cast<int>(m_rows.size()))
        return;
    m_rows[static_cast<size_t>(question)].show->click();
}

void LessonPlayer::choose(int question, int option)
{
    if (question < 0 || question >= static_cast<int>(m_rows.size()) ||
        !m_rows[static_cast<size_t>(question)].choices)
        return;
    QButtonGroup* group = m_rows[static_cast<size_t>(question)].choices;
    if (QAbstractButton* b = group->button(option))
        b->setChecked(true);
    m_rows[static_cast<size_t>(question)].check->click();
}

void LessonPlayer::answer(int question, const QString& text)
{
    if (question < 0 || question >= static_cast<int>(m_rows.size()) ||
        !m_rows[static_cast<size_t>(question)].edit)
        return;
    m_rows[static_cast<size_t>(question)].edit->setText(text);
    emit m_rows[static_cast<size_t>(question)].edit->returnPressed();
}

QString LessonPlayer::result(int question) const
{
    if (question < 0 || question >= static_cast<int>(m_rows.size()))
        return QString();
    return m_rows[static_cast<size_t>(question)].result->text();
}

} // namespace rigidlab::ui
