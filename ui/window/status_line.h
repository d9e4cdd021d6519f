// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where the run is, below the world: the status bar (time, real-time rate, energy drift,
// stage timings when asked for) and the timeline to go back to any earlier moment.

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

class QAction;
class QLabel;
class QMainWindow;
class QSlider;

namespace rigidlab::ui {

class SimulationController;
class WorldView;

class StatusLine : public QObject {
    Q_OBJECT
public:
    /// Fills `window`'s status bar and adds the timeline toolbar at its bottom.
    StatusLine(QMainWindow& window, SimulationController& controller, WorldView& view);

    /// View › Status details: steps/s, frame and stage timings in the status bar.
    QAction* detailsAction() const { return m_detailsAction; }
    /// What the status bar shows now, its visible parts joined.
    QString text() const;
    /// Shorter texts and no developer details on a projector.
    void setPresentation(bool on);
    /// Stage timings and steps per second, where View › Status details asks for them and
    /// presentation mode does not hide them.
    void setDetailsShown(bool shown);

public slots:
    void update();
    void updateTimeline();

private:
    void buildTimeline();
    /// The energy drift and what was dissipated, in short where `brief`.
    QString driftText(bool brief) const;
    QString detailsText(bool running) const;

    QMainWindow& m_window;
    SimulationController& m_controller;
    WorldView& m_view;
    bool m_presentation = false;
    bool m_messageShown = false; ///< a status-bar message stands in the line's place
    QSlider* m_timeline = nullptr;
    QLabel* m_timeLabel = nullptr;
    QLabel* m_time = nullptr;
    QLabel* m_rate = nullptr;
    QLabel* m_drift = nullptr;
    QLabel* m_solver = nullptr; ///< the contact solver that runs (status_solver.h)
    QLabel* m_slow = nullptr;
    QLabel* m_details = nullptr;
    QAction* m_detailsAction = nullptr;
    QElapsedTimer m_timelineMoved; ///< since the timeline's slider last moved with the clock
    QTimer m_timelineLater;        ///< moves it once the calm interval is over
};

} // namespace rigidlab::ui
