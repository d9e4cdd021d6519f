// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The window's fit (lessons/measure/fit.h) in a thread of its own, as the lesson editor runs
// its step checks (lesson_editor/step_checks.h): a fit in the lab's engine runs the scene
// hundreds of times and may take seconds, which must not stall the window. The worker counts
// the runs for a progress indication; cancel() stops the fit at its next run. A fit started
// while another runs cancels that one, and only the newest fit's result is delivered.

#include "measure/fit.h"

#include <QObject>

#include <atomic>
#include <memory>
#include <optional>
#include <vector>

class QThread;

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
    ~FitWorker() override;

    /// Fits `job` in the worker; a fit still running is cancelled and its result dropped.
    void start(Job job);
    /// Stops the running fit at its next run: finished() then brings a cancelled result.
    void cancel();
    /// Stops the running fit as cancel() does, and drops its result: no finished().
    void discard();
    bool isRunning() const { return m_thread != nullptr; }
    /// The runs of the model so far in the running fit.
    int runs() const { return m_runs ? m_runs->load() : 0; }

signals:
    /// The newest fit ended (cancelled: result.cancelled).
    void finished(const measure::FitResult& result);

private:
    void launch();
    void threadDone();

    QThread* m_thread = nullptr;
    std::shared_ptr<std::atomic_bool> m_cancelled;
    std::shared_ptr<std::atomic_int> m_runs;
    measure::FitResult m_result;  ///< written by the worker, read after it finished
    std::optional<Job> m_pending; ///< to fit once the running fit stopped
    bool m_discard = false;       ///< the running fit's result is not wanted
};

} // namespace rigidlab::ui
