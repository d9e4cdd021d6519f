// SPDX-License-Identifier: GPL-3.0-or-later
#include "measure/fit_worker.h"

#include <utility>

namespace rigidlab::ui {

FitWorker::FitWorker(QObject* parent) : QObject(parent), m_job(new BackgroundJob(this)) {}

void FitWorker::start(Job job)
{
    m_job->start(
        [job = std::move(job)](BackgroundJob::Control& control) {
            measure::FitOptions options;
            options.cancelled = &control.cancelled;
            options.runs = &control.done;
            return measure::fitScene(job.scene, job.parameters, job.target, job.series, options);
        },
        [this](measure::FitResult result, bool) { emit finished(result); });
}

void FitWorker::cancel()
{
    m_job->cancel();
}

void FitWorker::discard()
{
    m_job->discard();
}

} // namespace rigidlab::ui
