// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The instruments drawn on the scene: the ruler with its length, the protractor's lines and
// arc with the angle, the stopwatch's line, and the probe's numbers beside the probed body.
// Lines are drawn in the world's metres, text upright in pixels. The ends are dragged with
// the mouse (InstrumentsMouse, an event filter on the view); the panel's fields do the same by
// keyboard.

#include "rigidlab/physics/math.h"

#include <QGraphicsItem>
#include <QObject>
#include <QTransform>

#include <optional>

namespace rigidlab::ui {

class InstrumentsPanel;
class RunView;
class WorldView;

class InstrumentsItem : public QGraphicsItem {
public:
    InstrumentsItem(const InstrumentsPanel& panel, const RunView& run);
    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    void paintRuler(QPainter& p) const;
    void paintProtractor(QPainter& p) const;
    void paintStopwatchLine(QPainter& p) const;
    void paintProbe(QPainter& p) const;

    const InstrumentsPanel& m_panel;
    const RunView& m_run;
    QTransform m_device; ///< world to device pixels, while painting
};

/// Dragging the instruments' ends on the view: an end within a few pixels of the press is
/// dragged; Shift and a drag lays a new ruler (the Ruler tab) or a new first line (the
/// Protractor tab); a click on a body with the Probe tab open probes it.
class InstrumentsMouse : public QObject {
    Q_OBJECT
public:
    InstrumentsMouse(InstrumentsPanel& panel, WorldView& view);
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    enum class Handle { RulerA, RulerB, Vertex, ArmA, ArmB };
    std::optional<Handle> handleAt(const QPoint& viewPos) const;
    void moveHandle(Handle h, const physics::Vec2& to);

    InstrumentsPanel& m_panel;
    WorldView& m_view;
    std::optional<Handle> m_dragging;
};

} // namespace rigidlab::ui
