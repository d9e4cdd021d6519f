// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lesson editor's checks that run the steps' scenes: whether a step's scene diverges when
// run with the step's settings for its export time (and up to its questions' latest time),
// whether a body falls off the stage before the step's end time, and whether the integrators
// a student may choose measure a question wider apart than the answers judged right. These runs
// take seconds, so they run as a BackgroundJob (common/background_job.h); an edit while they run
// cancels them, a result for a lesson that has changed since is dropped, and the teacher may
// cancel them. The findings are data; the editor words them (stepCheckLines).

#include "common/background_job.h"

#include "format/lesson.h"
#include "run/off_stage.h"

#include "rigidlab/physics/divergence.h"

#include <QObject>
#include <QStringList>

#include <atomic>
#include <optional>
#include <vector>

namespace rigidlab::ui {

/// What the runs found in one step.
struct StepFinding {
    std::optional<physics::Divergence> divergence; ///< the step's own run diverged
    QString bodyLabel;                             ///< the diverged body, as the scene labels it
    /// The first body to fall off the stage before the step's end time (run/off_stage.h).
    std::optional<lessons::OffStage> offStage;
    QString offStageLabel; ///< that body, as the scene labels it
    /// A question whose answers judged right are narrower than what the integrators measure.
    struct Spread {
        int question = 0; ///< its index in the step
        double low = 0;   ///< the least any integrator measures
        double high = 0;  ///< the greatest
        double value = 0; ///< what the step's own integrator measures
        double band = 0;  ///< half the width of the answers judged right
        QString unit;
    };
    std::vector<Spread> spreads;
};

/// The runs of every step of `lesson`, one after another; stops early (returning what it has)
/// once `cancelled` is set. `stepsDone`, when given, counts the steps checked.
std::vector<StepFinding> runStepChecks(const lessons::Lesson& lesson,
                                       const std::atomic_bool& cancelled,
                                       std::atomic_int* stepsDone = nullptr);

/// The findings in words, one line each, in the lab's language and numbers.
QStringList stepCheckLines(const StepFinding& finding);

class StepChecks : public QObject {
    Q_OBJECT
public:
    explicit StepChecks(QObject* parent = nullptr);

    /// Checks `lesson` in the worker; a check of an older lesson still running is cancelled
    /// and its result never shown. `key` says what the runs depend on: the same key as the
    /// last check's starts nothing.
    void check(const lessons::Lesson& lesson, const QByteArray& key);
    /// Forgets the findings (the lesson cannot be read): nothing is being checked.
    void clear();
    bool isRunning() const { return m_job->isRunning(); }
    /// Whether the last check was cancelled by hand (job().cancel()): it found nothing.
    bool wasCancelled() const { return m_cancelled; }
    /// The last finished check's findings, one per step (empty while none finished).
    const std::vector<StepFinding>& findings() const { return m_findings; }
    /// The worker, for a progress indication and its Cancel (which finishes with no findings).
    BackgroundJob& job() { return *m_job; }

signals:
    /// A check finished, or was cancelled, for the lesson as it is now: findings() holds it.
    void finished();

private:
    BackgroundJob* m_job = nullptr;
    std::vector<StepFinding> m_findings;
    QByteArray m_key; ///< what the last check asked depended on
    bool m_cancelled = false;
};

} // namespace rigidlab::ui
