// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One graphics item per body. It draws the body's shape in the body's own frame and only
// follows the pose it is given; it holds no physics.

#include "rigidlab/physics/shape.h"

#include <QColor>
#include <QGraphicsItem>
#include <QPainterPath>
#include <QPolygonF>

namespace rigidlab::ui {

class BodyItem : public QGraphicsItem {
public:
    enum { Type = UserType + 1 };
    /// kind: 0 dynamic, 1 static, 2 kinematic, 3 a ghost (a compared world's body).
    BodyItem(int bodyId, const physics::Shape& shape, int kind, QColor fill);

    int type() const override { return Type; }
    int bodyId() const { return m_bodyId; }
    /// The colour it is filled with: the scene's "colour", or one of the view's.
    QColor fill() const { return m_fill; }
    /// Places the item: origin [m] and angle [rad] (counter-clockwise, y up).
    void setPose(double x, double y, double angle);
    void setSelectedBody(bool selected);
    /// Smooth edges (the default). A scene of hundreds of bodies draws them without: each is
    /// a few pixels across, and antialiasing them took a large part of a frame.
    void setAntialiased(bool on) { m_antialiased = on; }
    /// The least half-size [m] a moving body is drawn with, so that a small body far zoomed
    /// out still reads as a body, not a dot (the view sets it from its zoom). A static body
    /// is always drawn at its true size.
    void setMinimumRadius(double metres);

    QRectF boundingRect() const override;
    QPainterPath shape() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    /// The outline as drawn: the shape, grown about its centre to the minimum radius.
    void rebuildDrawn();

    int m_bodyId;
    int m_kind;
    QColor m_fill;
    QPainterPath m_truePath; ///< the shape at its true size [m]
    QPainterPath m_path;     ///< as drawn (see setMinimumRadius)
    QPolygonF m_truePolygon;
    QRectF m_trueCircle;
    double m_minRadius = 0; ///< [m]
    QPolygonF m_polygon;    ///< polygons: the outline, drawn as a polygon (far cheaper than a path)
    QRectF m_circle;        ///< circles: the bounding square, drawn as an ellipse
    QLineF m_radiusLine;    ///< circles: a radius, so that rotation shows
    bool m_selected = false;
    bool m_antialiased = true;
};

/// The index-th body's colour: the plots' hues, apart with any colour vision and at least
/// 3:1 against the world's background.
QColor bodyColor(int index);

} // namespace rigidlab::ui
