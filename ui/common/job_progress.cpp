// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/job_progress.h"

#include "common/background_job.h"

#include <QHBoxLayout>
#include <QProgressBar>
#include <QPushButton>
#include <QTimer>

namespace rigidlab::ui {

namespace {

/// How often the bar reads the job's count [ms]: often enough to move, seldom enough for a
/// screen reader to follow.
constexpr int kProgressMs = 250;

} // namespace

JobProgress::JobProgress(BackgroundJob& job, const QString& what, const QString& cancelName,
                         QWidget* parent)
    : QWidget(parent), m_job(job)
{
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(0, 0, 0, 0);
    m_bar = new QProgressBar(this);
    m_bar->setAccessibleName(what);
    m_bar->setTextVisible(true);
    row->addWidget(m_bar, 1);
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setAccessibleName(cancelName);
    m_cancel->setToolTip(cancelName);
    row->addWidget(m_cancel);
    m_timer = new QTimer(this);
    m_timer->setInterval(kProgressMs);
    connect(m_timer, &QTimer::timeout, this, &JobProgress::showProgress);
    connect(m_cancel, &QPushButton::clicked, &m_job, &BackgroundJob::cancel);
    connect(&m_job, &BackgroundJob::started, this, [this] {
        showProgress();
        show();
        m_timer->start();
    });
    connect(&m_job, &BackgroundJob::stopped, this, &JobProgress::jobStopped);
    setVisible(m_job.isRunning());
}

void JobProgress::showProgress()
{
    const int total = m_job.total();
    m_bar->setRange(0, total); // 0 to 0: busy
    m_bar->setValue(m_job.done());
}

void JobProgress::jobStopped()
{
    m_timer->stop();
    if (m_cancel->hasFocus())
        focusNextChild(); // the keyboard is not left on a hidden button
    hide();
}

} // namespace rigidlab::ui
