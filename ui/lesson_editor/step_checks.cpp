// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_editor/step_checks.h"

#include "common/number_format.h"
#include "format/divergence_message.h"
#include "format/view_text.h"
#include "run/measurements.h"
#include "run/off_stage.h"

#include "rigidlab/physics/integrator.h"
#include "rigidlab/physics/world.h"

#include <QLocale>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rigidlab::ui {

namespace {

/// How many steps the divergence run takes between looks at whether it was cancelled.
constexpr long long kStepsBetweenLooks = 256;

/// How long the step is run for: its export time, or its questions' latest time [s].
double runLength(const lessons::LessonStep& step)
{
    double until = step.exportTime;
    for (const lessons::Question& q : step.questions)
        if (const auto* measured = q.as<lessons::MeasuredQuestion>())
            until = std::max(until, measured->measure.time);
    return until;
}

/// The step's main world run with the step's settings for runLength(): its divergence, if
/// any, and the first body to leave the stage before the step's end time (nothing, too, when
/// cancelled).
void runStepWorld(const lessons::LessonStep& step, const std::atomic_bool& cancelled,
                  StepFinding& finding)
{
    std::vector<physics::World> worlds = lessons::buildStepWorlds(step);
    if (worlds.empty())
        return;
    physics::World& world = worlds.front();
    const auto steps = static_cast<long long>(std::ceil(runLength(step) / world.def().dt));
    world.updateDiagnostics(); // the energy at the start, which growth is measured against
    const lessons::StageFloor floor = lessons::stageFloor(world);
    const double end = step.endTime.value_or(std::numeric_limits<double>::infinity());
    for (long long i = 0; i < steps && !world.divergence(); ++i) {
        if (i % kStepsBetweenLooks == 0 && cancelled.load())
            return;
        world.step();
        if (!finding.offStage && world.time() < end)
            if (const auto body = lessons::offStage(world, floor))
                finding.offStage = lessons::OffStage{*body, world.time()};
    }
    finding.divergence = world.divergence();
}

/// Whether the step keeps the student from changing the integrator.
bool lockedIntegrator(const lessons::LessonStep& step)
{
    return step.allow && !step.allow->contains(QStringLiteral("integrator"));
}

/// What question `index` reads with each integrator, when that is wider than the answers
/// judged right: a student who may choose the integrator must not be marked wrong for it.
std::optional<StepFinding::Spread> spreadOf(const lessons::LessonStep& step, int index,
                                            const std::atomic_bool& cancelled)
{
    const lessons::Question& question = step.questions[static_cast<std::size_t>(index)];
    // Measured on the run the question asks for; an integrator it asks for is not the
    // student's to choose. The other kinds measure nothing.
    const auto* measured = question.as<lessons::MeasuredQuestion>();
    if (!measured || measured->set.has("integrator"))
        return std::nullopt;
    const lessons::MeasuredQuestion& q = *measured;
    const lessons::LessonStep asked = lessons::askedStep(step, question);
    const std::optional<double> value = lessons::measureAhead(asked, q.measure);
    if (!value)
        return std::nullopt;
    StepFinding::Spread spread{
        index, *value, *value, *value, std::abs(*value) * q.tolerance + q.absoluteTolerance,
        q.unit};
    for (const physics::IntegratorKind kind : physics::kAllIntegrators) {
        if (cancelled.load())
            return std::nullopt;
        lessons::LessonStep variant = asked;
        variant.settings.set("integrator", lessons::textFromView(physics::integratorName(kind)));
        if (const std::optional<double> v = lessons::measureAhead(variant, q.measure)) {
            spread.low = std::min(spread.low, *v);
            spread.high = std::max(spread.high, *v);
        }
    }
    if (spread.high - spread.low <= spread.band)
        return std::nullopt;
    return spread;
}

} // namespace

std::vector<StepFinding> runStepChecks(const lessons::Lesson& lesson,
                                       const std::atomic_bool& cancelled,
                                       std::atomic_int* stepsDone)
{
    std::vector<StepFinding> findings;
    for (const lessons::LessonStep& step : lesson.steps) {
        if (cancelled.load())
            break;
        StepFinding finding;
        runStepWorld(step, cancelled, finding);
        if (finding.divergence)
            finding.bodyLabel = step.scene.bodyLabel(finding.divergence->body);
        if (finding.offStage)
            finding.offStageLabel = step.scene.bodyLabel(finding.offStage->body);
        if (!lockedIntegrator(step))
            for (int i = 0; i < static_cast<int>(step.questions.size()); ++i)
                if (auto spread = spreadOf(step, i, cancelled))
                    finding.spreads.push_back(*spread);
        findings.push_back(std::move(finding));
        if (stepsDone)
            ++*stepsDone;
    }
    return findings;
}

QStringList stepCheckLines(const StepFinding& finding)
{
    const QLocale locale;
    QStringList lines;
    if (finding.divergence)
        lines.append(
            StepChecks::tr("The step's simulation, run with its settings, %1.")
                .arg(lessons::divergenceMessage(*finding.divergence, finding.bodyLabel, locale)));
    if (finding.offStage)
        lines.append(
            StepChecks::tr("%1 falls off the stage at t = %2 s, and the run stops there: "
                           "give the step an end time before it, or more ground.")
                .arg(finding.offStageLabel, formatReadable(finding.offStage->time, 3, 0, locale)));
    for (const StepFinding::Spread& s : finding.spreads)
        lines.append(StepChecks::tr("Question %1: the integrators a student may choose measure "
                                    "from %2 to %3 %4, wider than the answers judged right "
                                    "(%5 to %6 %4): lock the integrator (Shown and locked) or "
                                    "widen the tolerance.")
                         .arg(s.question + 1)
                         .arg(formatReadable(s.low, 4, 0, locale),
                              formatReadable(s.high, 4, 0, locale), s.unit,
                              formatReadable(s.value - s.band, 4, 0, locale),
                              formatReadable(s.value + s.band, 4, 0, locale)));
    for (QString& line : lines)
        line = lessons::keepUnitsTogether(line);
    return lines;
}

StepChecks::StepChecks(QObject* parent) : QObject(parent), m_job(new BackgroundJob(this)) {}

void StepChecks::check(const lessons::Lesson& lesson, const QByteArray& key)
{
    if (key == m_key)
        return;
    m_key = key;
    m_findings.clear(); // they were of the lesson before this edit
    m_cancelled = false;
    m_job->start(
        [lesson](BackgroundJob::Control& control) {
            control.total.store(static_cast<int>(lesson.steps.size()));
            return runStepChecks(lesson, control.cancelled, &control.done);
        },
        [this](std::vector<StepFinding> result, bool cancelled) {
            // Cancelled, the steps run so far are left unsaid rather than told as the lesson's.
            m_cancelled = cancelled;
            if (!cancelled)
                m_findings = std::move(result);
            emit finished();
        });
}

void StepChecks::clear()
{
    m_key.clear();
    m_findings.clear();
    m_cancelled = false;
    m_job->discard();
}

} // namespace rigidlab::ui
