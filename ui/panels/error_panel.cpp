// SPDX-License-Identifier: GPL-3.0-or-later
#include "panels/error_panel.h"

#include "plots/work_precision_plot.h"

#include <QComboBox>
#include <QDockWidget>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

namespace rigidlab::ui {

ErrorPanel::ErrorPanel(QWidget* parent)
    : QWidget(parent), m_problem(new QComboBox(this)), m_run(new QPushButton(tr("Run"), this)),
      m_cancel(new QPushButton(tr("Cancel"), this)), m_progress(new QProgressBar(this)),
      m_status(new QLabel(this)), m_plot(new WorkPrecisionPlot(this))
{
    m_options.points = 4;
    m_options.minTimingSeconds = 0.01;
    m_problem->addItems(lessons::sweepProblemNames());
    m_problem->setToolTip(tr("The reference problem whose diagram is shown"));
    m_cancel->setEnabled(false);
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    auto* bar = new QHBoxLayout;
    bar->addWidget(new QLabel(tr("Problem"), this));
    bar->addWidget(m_problem);
    bar->addWidget(m_run);
    bar->addWidget(m_cancel);
    bar->addWidget(m_progress, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(bar);
    layout->addWidget(m_status);
    layout->addWidget(m_plot, 1);
    m_plot->setProblem(m_problem->currentText());
    connect(m_problem, &QComboBox::currentTextChanged, m_plot, &WorkPrecisionPlot::setProblem);
    connect(m_run, &QPushButton::clicked, this, &ErrorPanel::start);
    connect(m_cancel, &QPushButton::clicked, this, &ErrorPanel::cancel);
}

void ErrorPanel::placeDock(QDockWidget& dock, const QRect& available, bool compact)
{
    if (!compact) {
        dock.setFloating(false);
        return;
    }
    // Most of the screen, centred, leaving a margin for the window manager's frame.
    constexpr int kMargin = 24;
    const QSize preferred(960, 640);
    const QSize room = available.size() - QSize(2 * kMargin, 2 * kMargin);
    const QSize size = preferred.boundedTo(room).expandedTo(QSize(200, 200));
    dock.setFloating(true);
    dock.setGeometry(QRect(available.topLeft() + QPoint((available.width() - size.width()) / 2,
                                                        (available.height() - size.height()) / 2),
                           size));
}

ErrorPanel::~ErrorPanel()
{
    // Closing the window mid-sweep: stop after the row in progress, and wait for it. The rows
    // still queued for this panel are dropped with it.
    if (m_thread) {
        m_cancelled = true;
        m_thread->wait();
        delete m_thread;
    }
}

void ErrorPanel::start()
{
    if (m_thread)
        return;
    m_plot->clearRows();
    m_plot->setProblem(m_problem->currentText());
    m_cancelled = false;
    m_run->setEnabled(false);
    m_cancel->setEnabled(true);
    m_status->setText(tr("Running every integrator on every reference problem…"));
    const lessons::SweepOptions options = m_options;
    // The sweep runs in its own thread; each row comes back to this thread by a queued call.
    m_thread = QThread::create([this, options] {
        lessons::runSweep(options, [this](const lessons::SweepRow& row, int done, int total) {
            QMetaObject::invokeMethod(
                this, [this, row, done, total] { rowArrived(row, done, total); },
                Qt::QueuedConnection);
            return !m_cancelled.load();
        });
    });
    connect(m_thread, &QThread::finished, this, &ErrorPanel::threadDone);
    m_thread->start();
}

void ErrorPanel::cancel()
{
    m_cancelled = true;
    m_status->setText(tr("Cancelling after the row in progress…"));
}

void ErrorPanel::rowArrived(const lessons::SweepRow& row, int done, int total)
{
    m_progress->setRange(0, total);
    m_progress->setValue(done);
    m_plot->addRow(row);
}

void ErrorPanel::threadDone()
{
    m_thread->deleteLater();
    m_thread = nullptr;
    m_run->setEnabled(true);
    m_cancel->setEnabled(false);
    const int rows = static_cast<int>(m_plot->rows().size());
    m_status->setText(m_cancelled ? tr("Cancelled after %1 rows.").arg(rows)
                                  : tr("%1 rows: CPU time of each run is the smallest of repeated "
                                       "runs.")
                                        .arg(rows));
    emit finished(rows);
}

} // namespace rigidlab::ui
