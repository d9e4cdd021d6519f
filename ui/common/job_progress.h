// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A BackgroundJob's progress in a window: a bar (busy while the job does not know how much it
// has to do) and a Cancel button, shown while the job runs and hidden when it stopped. The
// button is in the Tab order and named for what it stops.

#include <QWidget>

class QProgressBar;
class QPushButton;
class QTimer;

namespace rigidlab::ui {

class BackgroundJob;

class JobProgress : public QWidget {
    Q_OBJECT
public:
    /// `what` names the bar ("Checking the steps' scenes"), `cancelName` the button.
    JobProgress(BackgroundJob& job, const QString& what, const QString& cancelName,
                QWidget* parent = nullptr);

    QPushButton* cancelButton() const { return m_cancel; }

private:
    void showProgress();
    void jobStopped();

    BackgroundJob& m_job;
    QProgressBar* m_bar = nullptr;
    QPushButton* m_cancel = nullptr;
    QTimer* m_timer = nullptr;
};

} // namespace rigidlab::ui
