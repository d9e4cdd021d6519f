// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/background_job.h"

#include <QThread>

#include <utility>

namespace rigidlab::ui {

BackgroundJob::BackgroundJob(QObject* parent) : QObject(parent) {}

BackgroundJob::~BackgroundJob()
{
    if (m_thread) {
        m_control->cancelled.store(true);
        m_thread->wait();
        delete m_thread;
    }
}

void BackgroundJob::startErased(ErasedWork work, ErasedDeliver deliver)
{
    m_discard = false;
    m_pending = Pending{std::move(work), std::move(deliver)};
    if (m_thread) {
        m_control->cancelled.store(true); // the new work starts once this one stopped
        return;
    }
    launch();
    emit started();
}

void BackgroundJob::cancel()
{
    m_pending.reset();
    if (m_thread)
        m_control->cancelled.store(true);
}

void BackgroundJob::discard()
{
    cancel();
    m_discard = m_thread != nullptr;
}

void BackgroundJob::launch()
{
    m_control = std::make_shared<Control>();
    m_deliver = std::move(m_pending->deliver);
    m_thread = QThread::create(
        [work = std::move(m_pending->work), control = m_control] { work(*control); });
    m_pending.reset();
    connect(m_thread, &QThread::finished, this, &BackgroundJob::threadDone);
    m_thread->start(QThread::LowPriority);
}

void BackgroundJob::threadDone()
{
    m_thread->deleteLater();
    m_thread = nullptr;
    const ErasedDeliver deliver = std::exchange(m_deliver, {});
    if (m_pending) {
        launch(); // newer work was asked for while this ran: this one's result is stale
        return;
    }
    const bool wanted = !std::exchange(m_discard, false);
    const bool cancelled = m_control->cancelled.load();
    emit stopped();
    if (wanted)
        deliver(cancelled);
}

} // namespace rigidlab::ui
