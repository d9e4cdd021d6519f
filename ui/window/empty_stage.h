// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A lesson step's run with nothing left to see: every moving body has left what the view shows
// (two balls that part after their collision and fly out at both sides). The run pauses once
// there and says why, as it does when a body falls off the stage; Play runs on.

#include <QObject>

#include <functional>

namespace rigidlab::ui {

class SimulationController;
class WorldView;

class EmptyStageWatch : public QObject {
public:
    /// Watches `controller`'s run as `view` shows it while `watching()` (a lesson step is
    /// shown); `tell` says why the run paused.
    EmptyStageWatch(SimulationController& controller, const WorldView& view,
                    std::function<bool()> watching, std::function<void(double)> tell,
                    QObject* parent);

    /// Whether a moving body of the run is in what the view shows now (none moves: false; a
    /// view not shown: true).
    bool anyMovingBodyInSight() const;

private:
    void afterFrame();

    SimulationController& m_controller;
    const WorldView& m_view;
    std::function<bool()> m_watching;
    std::function<void(double)> m_tell;
    double m_seenAt = -1;  ///< the last time [s] a moving body was in sight; -1: not this run
    bool m_paused = false; ///< this run has paused for it (once, as for leaving the stage)
    double m_pausedAt = 0; ///< when [s]
};

} // namespace rigidlab::ui
