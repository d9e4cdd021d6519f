// SPDX-License-Identifier: GPL-3.0-or-later
#include "editor/overlay_paint.h"

#include <QFontMetrics>
#include <QPainter>
#include <QPolygonF>

namespace rigidlab::ui::overlay {

using physics::Vec2;

QPen cosmetic(const QColor& colour, double width, Qt::PenStyle style)
{
    QPen pen(colour, width, style);
    pen.setCosmetic(true);
    return pen;
}

QPainterPath outline(const physics::BodyDef& def)
{
    const physics::Transform xf(def.position, def.angle);
    QPainterPath path;
    def.shape.visit(physics::Overloaded{[&](const physics::Circle& c) {
                                            path.addEllipse(at(xf.apply(c.center)), c.radius,
                                                            c.radius);
                                        },
                                        [&](const physics::Polygon& p) {
                                            QPolygonF poly;
                                            for (const Vec2& v : p.vertices) {
                                                poly << at(xf.apply(v));
                                            }
                                            path.addPolygon(poly);
                                            path.closeSubpath();
                                        }});
    return path;
}

void label(QPainter& painter, const Vec2& p, const QString& text)
{
    const QPointF device = painter.transform().map(at(p));
    painter.save();
    painter.resetTransform();
    painter.setPen(cosmetic(Qt::black, 1));
    const QRectF box = painter.fontMetrics().boundingRect(text).adjusted(-3, -2, 3, 2);
    const QRectF placed = box.translated(device + QPointF(12, 20) - box.topLeft());
    painter.fillRect(placed, QColor(255, 255, 224, 230));
    painter.drawText(placed, Qt::AlignCenter, text);
    painter.restore();
}

} // namespace rigidlab::ui::overlay
