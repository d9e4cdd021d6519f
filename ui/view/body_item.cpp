// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/body_item.h"

#include "common/theme.h"
#include "plots/plot_widget.h"

#include <QPainter>

#include <QTransform>

#include <algorithm>
#include <array>
#include <cmath>

namespace rigidlab::ui {

namespace {

/// The fill of static bodies: a light grey under their hatching.
const QColor kGround(0xb8, 0xb8, 0xb8);

} // namespace

QColor bodyColor(int index)
{
    // The plots' hues (plotColor): one palette for curves and bodies, told apart with any
    // colour vision and at least 3:1 against the world's background. Its first six colours
    // are the hues; the seventh, ink, is no body's.
    constexpr int kHues = 6;
    return plotColor(((index % kHues) + kHues) % kHues);
}

BodyItem::BodyItem(int bodyId, const physics::Shape& shape, int kind, QColor fill)
    : m_bodyId(bodyId), m_kind(kind), m_fill(fill), m_edge(fill.darker(160)),
      m_needle(fill.darker(220))
{
    shape.visit(physics::Overloaded{[this](const physics::Circle& c) {
                                        const QPointF centre(c.center.x(), c.center.y());
                                        m_truePath.addEllipse(centre, c.radius, c.radius);
                                        m_trueCircle =
                                            QRectF(centre.x() - c.radius, centre.y() - c.radius,
                                                   2 * c.radius, 2 * c.radius);
                                    },
                                    [this](const physics::Polygon& polygon) {
                                        for (const auto& v : polygon.vertices)
                                            m_truePolygon << QPointF(v.x(), v.y());
                                        m_truePath.addPolygon(m_truePolygon);
                                        m_truePath.closeSubpath();
                                    }});
    rebuildDrawn();
    setAcceptHoverEvents(false);
    setZValue(kind == 1 ? 0 : 1);
}

void BodyItem::setPose(double x, double y, double angle, const physics::Rotation& rotation)
{
    // One transform instead of a position and a rotation in degrees, which Qt would turn back
    // into a sine and a cosine. As QTransform(m11, m12, m21, m22, dx, dy) maps a row vector:
    // rotated by the angle, then moved to the origin. The view flips y, so a positive angle
    // turns counter-clockwise on screen. A body at rest is given the pose it has: no new
    // transform for it (the ground, a sleeping pile), every frame.
    if (x == m_pose[0] && y == m_pose[1] && angle == m_pose[2])
        return;
    m_pose = {x, y, angle};
    const double c = rotation.c, s = rotation.s;
    m_frame = QTransform(c, s, -s, c, x, y);
}

bool BodyItem::containsScenePoint(const QPointF& p) const
{
    // Into the body's frame: the shift undone, then the rotation (its inverse, the transpose).
    const double c = m_frame.m11(), s = m_frame.m12();
    const double dx = p.x() - m_frame.dx(), dy = p.y() - m_frame.dy();
    return m_path.contains(QPointF(c * dx + s * dy, -s * dx + c * dy));
}

void BodyItem::setMinimumRadius(double metres)
{
    metres = m_kind == 1 || !std::isfinite(metres) ? 0.0 : std::max(0.0, metres);
    if (metres == m_minRadius)
        return;
    m_minRadius = metres;
    rebuildDrawn();
}

void BodyItem::rebuildDrawn()
{
    // Grown about the centre of its bounding box by one factor, so that the shape keeps its
    // proportions and its radius line still shows the rotation.
    const QRectF box = m_truePath.boundingRect();
    const double half = 0.5 * std::max(box.width(), box.height());
    const double k = half > 0 && half < m_minRadius ? m_minRadius / half : 1.0;
    const QPointF c = box.center();
    QTransform grow;
    grow.translate(c.x(), c.y());
    grow.scale(k, k);
    grow.translate(-c.x(), -c.y());
    prepareGeometryChange();
    m_path = grow.map(m_truePath);
    if (!m_trueCircle.isNull()) {
        m_circle = grow.mapRect(m_trueCircle);
        m_radiusLine =
            QLineF(m_circle.center(), m_circle.center() + QPointF(0.5 * m_circle.width(), 0));
    } else {
        m_polygon = grow.map(m_truePolygon);
    }
    const QRectF drawn = m_path.boundingRect();
    m_drawnSize = std::max(drawn.width(), drawn.height());
    m_reach = 0;
    for (const QPointF& corner :
         {drawn.topLeft(), drawn.topRight(), drawn.bottomLeft(), drawn.bottomRight()})
        m_reach = std::max(m_reach, std::hypot(corner.x(), corner.y()));
}

void BodyItem::setSelectedBody(bool selected)
{
    m_selected = selected;
}

QRectF BodyItem::boundingRect() const
{
    // Cosmetic pens are a few pixels wide whatever the zoom; a little margin in metres
    // would not scale, so the view repaints with a full-viewport update instead.
    return m_path.boundingRect();
}

QPainterPath BodyItem::shape() const
{
    return m_path;
}

void BodyItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*)
{
    draw(*painter);
}

void BodyItem::drawDot(QPainter& painter, const QPointF& at, double sidePx) const
{
    const double half = 0.5 * std::max(1.0, sidePx);
    painter.fillRect(QRectF(at.x() - half, at.y() - half, 2 * half, 2 * half),
                     m_kind == 1 ? kGround : m_fill);
}

void BodyItem::draw(QPainter& painter) const
{
    // The selected body's outline is thick and near black: it shows without telling by colour.
    QPen pen(m_selected ? QColor(20, 20, 20) : m_edge, theme::lineWidth(m_selected ? 3.0 : 1.0));
    pen.setCosmetic(true);
    painter.setPen(pen);
    if (m_kind == 1) {
        // Static bodies: grey with hatching, so they read as fixed ground.
        painter.setBrush(kGround);
        painter.drawPath(m_path);
        QBrush hatch(QColor(0x80, 0x80, 0x80), Qt::BDiagPattern);
        hatch.setTransform(QTransform::fromScale(0.02, 0.02));
        painter.setBrush(hatch);
        painter.drawPath(m_path);
    } else if (m_kind == 3) {
        // A ghost: its colour's outline over a faint fill, so that the bodies it overlaps
        // stay visible.
        QPen outline(m_fill, theme::lineWidth(2.5));
        outline.setCosmetic(true);
        painter.setPen(outline);
        QColor fill = m_fill;
        fill.setAlpha(60);
        painter.setBrush(fill);
        painter.drawPath(m_path);
    } else {
        QColor fill = m_fill;
        if (m_kind == 2)
            fill.setAlpha(120); // kinematic: see-through
        painter.setBrush(fill);
        if (m_polygon.isEmpty())
            painter.drawEllipse(m_circle);
        else
            painter.drawPolygon(m_polygon);
    }
    if (!m_radiusLine.isNull()) {
        QPen line(m_needle, theme::lineWidth(2.0));
        line.setCosmetic(true);
        painter.setPen(line);
        painter.drawLine(m_radiusLine);
    }
}

} // namespace rigidlab::ui
