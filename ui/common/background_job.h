// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Work that takes seconds (a fit that runs a scene hundreds of times, a lesson's steps run with
// every integrator) in a thread of its own, so that the window does not stall meanwhile. The
// work looks at a cancel flag between its runs and counts what it has done for a progress
// indication. Work started while another runs cancels that one and starts once it stopped; only
// the newest work's result is delivered, in the window's thread.

#include <QObject>

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <type_traits>
#include <utility>

class QThread;

namespace rigidlab::ui {

class BackgroundJob : public QObject {
    Q_OBJECT
public:
    /// What running work shares with the window: the window sets `cancelled`, the work counts.
    struct Control {
        std::atomic_bool cancelled{false}; ///< the work stops at its next look
        std::atomic_int done{0};           ///< units of work done so far
        std::atomic_int total{0};          ///< units of work in all; 0 while not known
    };

    explicit BackgroundJob(QObject* parent = nullptr);
    /// Closing mid-work: the work stops at its next look, and is waited for.
    ~BackgroundJob() override;

    /// Runs `work(control)` in the worker thread, then `deliver(result, cancelled)` with what
    /// it returned, in this object's thread; work still running is cancelled and never
    /// delivered. The work holds copies of what it reads and returns what it found: it must not
    /// touch its owner, whose members may be gone while the job's destructor waits for it.
    template <typename Work, typename Deliver> void start(Work work, Deliver deliver)
    {
        using Result = std::invoke_result_t<Work&, Control&>;
        auto result = std::make_shared<std::optional<Result>>();
        startErased([work = std::move(work), result](Control& control) { *result = work(control); },
                    [deliver = std::move(deliver), result](bool cancelled) {
                        deliver(std::move(**result), cancelled);
                    });
    }

    /// Stops the running work at its next look; it is still delivered, as cancelled.
    void cancel();
    /// Stops the running work as cancel() does, and drops it: nothing is delivered.
    void discard();
    bool isRunning() const { return m_thread != nullptr; }
    /// The running work's count so far, and of all it has to do (0: not known).
    int done() const { return m_control ? m_control->done.load() : 0; }
    int total() const { return m_control ? m_control->total.load() : 0; }

signals:
    /// Work began where none ran.
    void started();
    /// The last work ended (emitted before it is delivered): nothing runs.
    void stopped();

private:
    using ErasedWork = std::function<void(Control& control)>;
    using ErasedDeliver = std::function<void(bool cancelled)>;
    struct Pending {
        ErasedWork work;
        ErasedDeliver deliver;
    };
    void startErased(ErasedWork work, ErasedDeliver deliver);
    void launch();
    void threadDone();

    QThread* m_thread = nullptr;
    std::shared_ptr<Control> m_control;
    ErasedDeliver m_deliver;          ///< the running work's
    std::optional<Pending> m_pending; ///< to run once the running work stopped
    bool m_discard = false;           ///< the running work's result is not wanted
};

} // namespace rigidlab::ui
