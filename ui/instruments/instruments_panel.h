// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The instruments a student measures the scene with, one tab each: a ruler (two points, which
// snap to body centres and vertices, and the length between them in m), a protractor (the
// angle of a body, or between two lines from one vertex, in degrees), a stopwatch (started and
// stopped by hand or on an event, in s at the step's resolution) and a probe (a body's
// position, velocity, speed, ω, kinetic energy, momentum, angular momentum and the forces on
// it, live, with Copy and Plot). The frame tab switches the view and the momentum graph to the
// centre-of-mass frame of chosen bodies.
//
// Every point is typed in a field (arrow keys nudge it) as well as dragged on the scene
// (instruments_item.h draws them there), and every reading is a label with an accessible name,
// in the locale's numbers. The world is read, never changed.

#include "instruments/instrument_readings.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QPushButton;
class QTabWidget;

namespace rigidlab::ui {

class RunView;

class InstrumentsPanel : public QWidget {
    Q_OBJECT
public:
    enum Tab { RulerTab, ProtractorTab, StopwatchTab, ProbeTab, FrameTab };
    enum class ProtractorMode { Body, Lines };

    explicit InstrumentsPanel(const RunView& run, QWidget* parent = nullptr);

    QTabWidget* tabs() const { return m_tabs; }
    /// How close a dragged or typed end must come to snap [m] (the view sets it from its zoom).
    void setSnapRadius(double metres) { m_snapRadius = metres; }

    // The ruler.
    /// Puts the ruler's ends at a and b [m], snapped if snapping is on.
    void setRuler(const physics::Vec2& a, const physics::Vec2& b);
    physics::Vec2 rulerStart() const { return m_rulerA; }
    physics::Vec2 rulerEnd() const { return m_rulerB; }
    double rulerLength() const { return (m_rulerB - m_rulerA).norm(); } ///< [m]
    QString rulerText() const;
    void setSnapping(bool on);
    bool snapping() const;

    // The protractor.
    void setProtractorMode(ProtractorMode mode);
    ProtractorMode protractorMode() const;
    void setProtractorBody(int id);
    /// The two lines from `vertex` through `a` and through `b` [m] (snapped if snapping is on).
    void setProtractorLines(const physics::Vec2& vertex, const physics::Vec2& a,
                            const physics::Vec2& b);
    physics::Vec2 protractorVertex() const { return m_vertex; }
    physics::Vec2 protractorArmA() const { return m_armA; }
    physics::Vec2 protractorArmB() const { return m_armB; }
    int protractorBody() const;
    double protractorDegrees() const; ///< [°], NaN when there is nothing to measure
    QString protractorText() const;

    // The stopwatch.
    void setStartTrigger(const instruments::TriggerSpec& spec);
    void setStopTrigger(const instruments::TriggerSpec& spec);
    const instruments::Stopwatch& stopwatch() const { return m_stopwatch; }
    double stopwatchSeconds() const; ///< [s]
    QString stopwatchText() const;
    /// "stopped", "running"…, in words.
    QString stopwatchStateText() const;

    // The probe.
    void setProbeBody(int id);
    int probeBody() const;
    instruments::ProbeReading probeReading() const;
    /// The probe's lines, "x = 1,25 m" each.
    QStringList probeLines() const;
    QString probeText() const { return probeLines().join(QLatin1Char('\n')); }

    // The frame of reference.
    /// The bodies whose centre of mass is the frame; empty: the lab frame.
    std::vector<physics::BodyId> frameBodies() const;
    void setFrameBodies(const std::vector<physics::BodyId>& ids);

public slots:
    void startStopwatch();
    void stopStopwatch();
    void resetStopwatch();
    /// Reads again what is in sight (the world moved, or a setting changed): the open tab's
    /// readings, nothing while the panel is hidden. Showing the panel or a tab reads it.
    void refresh();
    void copyProbe();

signals:
    /// Something the scene draws changed (an end moved, a body chosen, a reading).
    void changed();
    /// The probe's Plot button: graphs of the probed body.
    void plotRequested(int body);
    /// The frame of reference changed (empty: the lab frame).
    void frameChanged(const std::vector<physics::BodyId>& bodies);
    /// The frame tab's button: the momenta of the frame's bodies and their sum, in that frame.
    void frameMomentumRequested(const std::vector<physics::BodyId>& bodies);

protected:
    void showEvent(QShowEvent* event) override;

private:
    QWidget* makeRulerTab();
    QWidget* makeProtractorTab();
    QWidget* makeStopwatchTab();
    QWidget* makeProbeTab();
    QWidget* makeFrameTab();
    void fillBodyLists();
    /// The fields show the points as they are now (without sending their edits back).
    void showPoints();
    void pointsTyped();
    instruments::TriggerSpec triggerFrom(QComboBox* kind) const;
    void triggersChanged();
    QString num(double v, const QString& unit, double scale = 1.0) const;

    const RunView& m_run;
    QTabWidget* m_tabs;
    double m_snapRadius = 0.05;
    physics::Vec2 m_rulerA{0, 0}, m_rulerB{1, 0};
    physics::Vec2 m_vertex{0, 0}, m_armA{1, 0}, m_armB{0, 1};
    instruments::Stopwatch m_stopwatch;
    bool m_showing = false; ///< the fields are being set from the points: not typed

    QDoubleSpinBox* m_rulerFields[4] = {}; ///< A x, A y, B x, B y
    QDoubleSpinBox* m_angleFields[6] = {}; ///< vertex, arm A, arm B: x, y each
    QCheckBox* m_snap = nullptr;
    QLabel* m_rulerReading = nullptr;
    QComboBox* m_protractorMode = nullptr;
    QComboBox* m_protractorBody = nullptr;
    QLabel* m_protractorReading = nullptr;
    QComboBox* m_startOn = nullptr;
    QComboBox* m_stopOn = nullptr;
    QComboBox* m_watchBody = nullptr;
    QDoubleSpinBox* m_lineY = nullptr;
    QLabel* m_watchReading = nullptr;
    QLabel* m_watchState = nullptr;
    QComboBox* m_probeBody = nullptr;
    QLabel* m_probeReading = nullptr;
    QComboBox* m_frame = nullptr;
    QListWidget* m_frameBodies = nullptr;
};

} // namespace rigidlab::ui
