// SPDX-License-Identifier: GPL-3.0-or-later
// Judging a student's answer against what the simulation measured, in words a student reads.

#include "run/measurements.h"

#include <QCoreApplication>
#include <QLocale>

#include "rigidlab/physics/overloaded.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace rigidlab::lessons {

namespace {

/// A measured value or answer as the verdict writes it.
QString formatValue(double value, const MeasuredQuestion& q)
{
    return formatAnswer(value, q.tolerance, q.unit);
}

/// The measured part of a question judged against a value.
const MeasuredQuestion& measuredPart(const Question& q)
{
    const MeasuredQuestion* m = q.as<MeasuredQuestion>();
    assert(m && "only a measured question is judged against a value");
    return *m;
}

QString notYet(const Measure& m)
{
    if (m.kind == Measure::Kind::Apex) {
        // The first bounces, the ones lessons ask about, in words; any later one by number.
        switch (m.n) {
        case 1:
            return Judge::tr("Run the simulation past the top of the first bounce first.");
        case 2:
            return Judge::tr("Run the simulation past the top of the second bounce first.");
        case 3:
            return Judge::tr("Run the simulation past the top of the third bounce first.");
        default:
            return Judge::tr("Run the simulation past the top of bounce number %1 first.").arg(m.n);
        }
    }
    return Judge::tr("Run the simulation until t = %1 s first.")
        .arg(QLocale().toString(m.time, 'g', 6));
}

} // namespace

Verdict judge(const Question& q, double answer, const Measurements& m, const Scene& scene)
{
    // Without a count of tries every answer is a last try: the value is always given.
    return judgeAttempt(q, answer, m.value(measuredPart(q).measure, scene),
                        std::numeric_limits<int>::max());
}

Verdict judgeAttempt(const Question& question, double answer, std::optional<double> value,
                     int attempt, bool ahead)
{
    const MeasuredQuestion& q = measuredPart(question);
    Verdict verdict;
    if (!value) {
        verdict.message = notYet(q.measure);
        return verdict;
    }
    verdict.measured = true;
    verdict.value = *value;
    if (!std::isfinite(answer)) {
        verdict.message = Judge::tr("Type a number first.");
        return verdict;
    }
    verdict.right =
        std::abs(answer - *value) <= q.tolerance * std::abs(*value) + q.absoluteTolerance;
    if (!verdict.right && attempt <= 1) {
        // A second try is only worth something while the value is still unknown.
        verdict.message =
            question.hint.isEmpty()
                ? Judge::tr("Not quite (you said %1). Try once more.").arg(formatValue(answer, q))
                : Judge::tr("Not quite (you said %1). Hint: %2")
                      .arg(formatValue(answer, q), question.hint);
        verdict.message = keepUnitsTogether(verdict.message);
        return verdict;
    }
    verdict.shown = true;
    // Measured ahead, the window's own run has not shown it yet: said as what it will show.
    const QString message =
        ahead
            ? (verdict.right
                   ? Judge::tr("Right: when it runs, the simulation will measure %1 (you said %2).")
                   : Judge::tr("Not quite: when it runs, the simulation will measure %1 (you "
                               "said %2)."))
            : (verdict.right ? Judge::tr("Right: the simulation measured %1 (you said %2).")
                             : Judge::tr("Not quite: the simulation measured %1 (you said %2)."));
    verdict.message =
        keepUnitsTogether(message.arg(formatValue(*value, q), formatValue(answer, q)));
    return verdict;
}

Verdict showAnswer(const Question& question, std::optional<double> value, bool ahead)
{
    const MeasuredQuestion& q = measuredPart(question);
    Verdict verdict;
    if (!value) {
        verdict.message = notYet(q.measure);
        return verdict;
    }
    verdict.measured = true;
    verdict.shown = true;
    verdict.value = *value;
    verdict.message =
        keepUnitsTogether((ahead ? Judge::tr("When it runs, the simulation will measure %1.")
                                 : Judge::tr("The simulation measured %1."))
                              .arg(formatValue(*value, q)));
    return verdict;
}

namespace {

/// A measured question's try: an answer judged against the value measured, or "Show me".
Verdict judgeMeasured(const Question& q, const AnswerTry& attempt, TryCount& count)
{
    Verdict verdict;
    if (!attempt.answer) {
        verdict = showAnswer(q, attempt.measured, attempt.ahead);
    } else {
        // Only tries judged against a value count; once the value was given, every try is
        // judged as a later one (with the value, not the hint).
        if (attempt.measured && !count.answered)
            ++count.attempts;
        verdict = judgeAttempt(q, *attempt.answer, attempt.measured,
                               count.answered ? 2 : count.attempts, attempt.ahead);
    }
    count.answered = count.answered || verdict.shown;
    return verdict;
}

} // namespace

Verdict judgeTry(const Question& q, const AnswerTry& attempt, TryCount& count)
{
    // The measured kind's verdict needs the question whole (its hint, its measure); every
    // other kind judges itself (format/question_kind.h).
    return std::visit(
        physics::Overloaded{
            [&](const MeasuredQuestion&) { return judgeMeasured(q, attempt, count); },
            [&](const auto& kind) { return judgeKindTry(kind, q.hint, attempt, count); }},
        q.kind);
}

std::optional<double> measureAhead(const LessonStep& step, const Measure& measure)
{
    std::vector<physics::World> worlds = buildStepWorlds(step);
    physics::World& world = worlds.front();
    // The export time is what the lesson's author runs the step for: the loader keeps it to
    // at most 1e7 steps, and the measure's own time to at most 3600 s.
    const double until = std::max(step.exportTime, measure.time); // [s]
    const auto maxSteps = static_cast<long long>(std::ceil(until / world.def().dt)) + 2;
    world.updateDiagnostics(); // the energy at the start, which drift is measured against
    Measurements m;
    m.reset(world, {measure});
    for (long long i = 0; i < maxSteps; ++i) {
        if (const auto value = m.value(measure, step.scene)) {
            return value;
        }
        world.step();
        if (world.divergence()) {
            return std::nullopt;
        }
        m.observe(world);
    }
    return m.value(measure, step.scene);
}

} // namespace rigidlab::lessons
