// SPDX-License-Identifier: GPL-3.0-or-later
#include "measure/measured_trail.h"

#include <QPainter>
#include <QWidget>

#include <algorithm>

namespace rigidlab::ui {

namespace {
/// Above the bodies, below the teaching overlays' labels.
constexpr double kZ = 5.0;
} // namespace

MeasuredTrailItem::MeasuredTrailItem()
{
    setZValue(kZ);
    setAcceptedMouseButtons(Qt::NoButton);
}

void MeasuredTrailItem::setPoints(std::vector<QPointF> points)
{
    prepareGeometryChange();
    m_points = std::move(points);
    m_bounds = QRectF();
    for (const QPointF& p : m_points)
        m_bounds = m_bounds.united(QRectF(p, QSizeF(0, 0)));
    // Room for the crosses at any zoom the view allows (at least 1 px per cm).
    m_bounds.adjust(-0.1, -0.1, 0.1, 0.1);
    update();
}

QRectF MeasuredTrailItem::boundingRect() const
{
    return m_bounds;
}

void MeasuredTrailItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget* widget)
{
    if (m_points.empty())
        return;
    const double scale = std::max(1e-9, std::abs(painter->worldTransform().m11()));
    const double r = kCrossPx / scale;
    // Faint: the body drawn over it stays the thing to look at.
    QColor colour = widget ? widget->palette().color(QPalette::Text) : QColor(Qt::black);
    colour.setAlpha(140);
    QPen pen(colour, 1.2);
    pen.setCosmetic(true);
    painter->setPen(pen);
    for (const QPointF& p : m_points) {
        painter->drawLine(p + QPointF(-r, -r), p + QPointF(r, r));
        painter->drawLine(p + QPointF(-r, r), p + QPointF(r, -r));
    }
}

} // namespace rigidlab::ui
