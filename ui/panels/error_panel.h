// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The "Error vs run time" panel: the work-precision sweep of rigidlab-cli error-vs-time, run in
// a background thread with a progress bar and Cancel, drawn live as it goes; the diagram
// exports like every other plot (right-click).

#include "numerics/error_vs_time.h"

#include <QThread>
#include <QWidget>

#include <atomic>

class QComboBox;
class QDockWidget;
class QProgressBar;
class QPushButton;
class QLabel;

namespace rigidlab::ui {

class WorkPrecisionPlot;

class ErrorPanel : public QWidget {
    Q_OBJECT
public:
    explicit ErrorPanel(QWidget* parent = nullptr);
    ~ErrorPanel() override;

    WorkPrecisionPlot* plot() const { return m_plot; }
    bool isRunning() const { return m_thread != nullptr; }
    /// The sweep's options (the window's: each problem's own steps, 4 points, short timing).
    lessons::SweepOptions& options() { return m_options; }

    /// Where the panel's dock opens. On a small screen (`compact`) the bottom dock area has
    /// no room for a readable diagram: the dock floats over the window instead, inside the
    /// screen's `available` area, large enough for a plot of kMinPlotHeight px or more.
    static void placeDock(QDockWidget& dock, const QRect& available, bool compact);

public slots:
    void start();
    void cancel();

signals:
    void finished(int rows);

private:
    void rowArrived(const lessons::SweepRow& row, int done, int total);
    void threadDone();

    QComboBox* m_problem;
    QPushButton* m_run;
    QPushButton* m_cancel;
    QProgressBar* m_progress;
    QLabel* m_status;
    WorkPrecisionPlot* m_plot;
    lessons::SweepOptions m_options;
    QThread* m_thread = nullptr;
    std::atomic<bool> m_cancelled{false};
};

} // namespace rigidlab::ui
