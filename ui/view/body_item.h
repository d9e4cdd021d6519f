// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One body's drawing: its shape in the body's own frame, the pose it is given, its colour and
// whether it is selected; it holds no physics. The view does not add it to the scene: one
// BodiesItem paints every body in a single pass (bodies_item.h), and this item keeps the
// geometry that picking, the labels and the screen reader ask for (its scene bounding box,
// its outline).

#include "rigidlab/physics/math.h"
#include "rigidlab/physics/shape.h"

#include <QColor>
#include <QGraphicsItem>
#include <QPainterPath>
#include <QPolygonF>
#include <QTransform>

#include <array>
#include <limits>

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
    /// Places the body: origin [m] and angle [rad] (counter-clockwise, y up). Its frame() is
    /// then the body's frame in the scene: rotation by the angle, then the origin. The item's
    /// own transform() stays the identity: it is in no scene, and Qt's setTransform() (its
    /// notifications and its copy) was a per cent of the frame of a 5,050-body pyramid.
    /// `rotation` is the angle's cosine and sine, computed once by whoever gave the pose
    /// (SimulationController::drawPose, Body::transform()).
    void setPose(double x, double y, double angle, const physics::Rotation& rotation);
    /// The body's frame in the scene, as setPose made it.
    const QTransform& frame() const { return m_frame; }
    /// The drawn outline's bounding box in the scene [m] (what sceneBoundingRect() would give
    /// with frame() as the item's transform): picking, the labels, the screen reader's
    /// rectangles.
    QRectF sceneBox() const { return m_frame.mapRect(boundingRect()); }
    void setSelectedBody(bool selected);
    bool selectedBody() const { return m_selected; }
    /// The least half-size [m] a moving body is drawn with, so that a small body far zoomed
    /// out still reads as a body, not a dot (the view sets it from its zoom). A static body
    /// is always drawn at its true size.
    void setMinimumRadius(double metres);
    /// How far the drawn outline reaches from the origin [m]: a circle about the pose that
    /// holds the whole drawing, whatever the angle.
    double reach() const { return m_reach; }
    /// The drawn outline's larger side [m].
    double drawnSize() const { return m_drawnSize; }
    /// Whether the scene point [m] lies on the body as drawn (grown to the minimum radius).
    bool containsScenePoint(const QPointF& p) const;

    /// Draws the body in its own frame [m]: the painter's transform must place that frame.
    void draw(QPainter& painter) const;
    /// Draws the body as a square dot of its colour, `sidePx` across, centred on device point
    /// `at` (the painter in device pixels): what a body two or three pixels across can show.
    void drawDot(QPainter& painter, const QPointF& at, double sidePx) const;

    QRectF boundingRect() const override;
    QPainterPath shape() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    /// The outline as drawn: the shape, grown about its centre to the minimum radius.
    void rebuildDrawn();

    int m_bodyId;
    int m_kind;
    QColor m_fill;
    QColor m_edge;           ///< the outline's colour, darker than the fill
    QColor m_needle;         ///< circles: the radius line's colour
    double m_reach = 0;      ///< see reach() [m]
    double m_drawnSize = 0;  ///< see drawnSize() [m]
    QPainterPath m_truePath; ///< the shape at its true size [m]
    QPainterPath m_path;     ///< as drawn (see setMinimumRadius)
    QPolygonF m_truePolygon;
    QRectF m_trueCircle;
    double m_minRadius = 0; ///< [m]
    QPolygonF m_polygon;    ///< polygons: the outline, drawn as a polygon (far cheaper than a path)
    QRectF m_circle;        ///< circles: the bounding square, drawn as an ellipse
    QLineF m_radiusLine;    ///< circles: a radius, so that rotation shows
    bool m_selected = false;
    static constexpr double kNoPose = std::numeric_limits<double>::quiet_NaN();
    /// The pose last given to setPose: x [m], y [m], angle [rad]; none before the first (NaN
    /// equals nothing).
    std::array<double, 3> m_pose{kNoPose, kNoPose, kNoPose};
    QTransform m_frame; ///< see frame()
};

/// The index-th body's colour: the plots' hues, apart with any colour vision and at least
/// 3:1 against the world's background.
QColor bodyColor(int index);

} // namespace rigidlab::ui
