// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The window's fit (lessons/measure/fit.h) as a BackgroundJob (common/background_job.h): a
// fit in the lab's engine runs the scene hundreds of times and may take seconds, which must not
// stall the window. The job counts the runs for a progress indication; cancel() stops the fit
// at its next run. A fit started while another runs cancels that one, and only the newest
// fit's result is delivered.

#include "common/background_job.h"

#include "measure/fit.h"

#include <QObject>

#include <vector>

namespace rigidlab::ui {

class FitWorker : public QObject {
    Q_OBJECT
public:
    /// What a fit needs, copied: the scene may change while the fit runs.
    struct Job {
        lessons::Scene scene;
        std::vector<measure::Parameter> parameters;
        measure::Target target;
        measure::Series series;
    };

    explicit FitWorker(QObject* parent = nullptr);

    /// Fits `job` in the worker; a fit still running is cancelled and its result dropped.
    void start(Job job);
    /// Stops the running fit at its next run: finished() then brings a cancelled result.
    void cancel();
    /// Stops the running fit as cancel() does, and drops its result: no finished().
    void discard();
    bool isRunning() const { return m_job->isRunning(); }
    /// The runs of the model so far in the running fit.
    int runs() const { return m_job->done(); }

signals:
    /// The newest fit ended (cancelled: result.cancelled).
    void finished(const measure::FitResult& result);

private:
    BackgroundJob* m_job = nullptr;
};

} // namespace rigidlab::ui
