// SPDX-License-Identifier: GPL-3.0-or-later
#include "measure/fit_worker.h"

#include <QThread>

#include <utility>

namespace rigidlab::ui {

FitWorker::FitWorker(QObject* parent) : QObject(parent) {}

FitWorker::~FitWorker()
{
    // The window closing mid-fit: the fit stops at its next run, and is waited for.
    if (m_thread) {
        m_cancelled->store(true);
        m_thread->wait();
        delete m_thread;
    }
}

void FitWorker::start(Job job)
{
    m_discard = false;
    m_pending = std::move(job);
    if (m_thread) {
        m_cancelled->store(true); // the new fit starts once this one stopped
        return;
    }
    launch();
}

void FitWorker::cancel()
{
    m_pending.reset();
    if (m_thread)
        m_cancelled->store(true);
}

void FitWorker::discard()
{
    cancel();
    m_discard = m_thread != nullptr;
}

void FitWorker::launch()
{
    m_cancelled = std::make_shared<std::atomic_bool>(false);
    m_runs = std::make_shared<std::atomic_int>(0);
    m_thread = QThread::create([this, job = std::move(*m_pending), cancelled = m_cancelled,
                                runs = m_runs] {
        measure::FitOptions options;
        options.cancelled = cancelled.get();
        options.runs = runs.get();
        m_result = measure::fitScene(job.scene, job.parameters, job.target, job.series, options);
    });
    m_pending.reset();
    connect(m_thread, &QThread::finished, this, &FitWorker::threadDone);
    m_thread->start(QThread::LowPriority);
}

void FitWorker::threadDone()
{
    m_thread->deleteLater();
    m_thread = nullptr;
    measure::FitResult result = std::move(m_result);
    m_result = {};
    if (m_pending) {
        launch(); // a newer fit was asked for while this one ran
        return;
    }
    if (std::exchange(m_discard, false))
        return;
    emit finished(result);
}

} // namespace rigidlab::ui
