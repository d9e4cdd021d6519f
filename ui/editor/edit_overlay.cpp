// SPDX-License-Identifier: GPL-3.0-or-later
#include "editor/edit_overlay.h"

#include "editor/edit_tools.h"
#include "editor/overlay_paint.h"

#include "edit/scene_edits.h"

#include <QGraphicsScene>
#include <QPainter>
#include <QStyleOptionGraphicsItem>
#include <QWidget>

#include <cmath>

namespace rigidlab::ui {

using overlay::at;
using overlay::cosmetic;
using physics::Vec2;

EditOverlay::EditOverlay(const EditTools& tools) : m_tools(tools)
{
    setAcceptedMouseButtons(Qt::NoButton);
}

QRectF EditOverlay::boundingRect() const
{
    return scene() ? scene()->sceneRect() : QRectF();
}

void EditOverlay::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget* widget)
{
    painter->setRenderHint(QPainter::Antialiasing);
    const double zoom = std::max(std::hypot(painter->transform().m11(), painter->transform().m12()),
                                 1e-9); // [px/m]
    paintGrid(*painter, widget);
    paintOverlaps(*painter);
    paintSelectedBody(*painter, zoom);
    paintSelectedSpring(*painter);
    painter->setPen(cosmetic(overlay::accent(), 2));
    painter->setBrush(Qt::NoBrush);
    m_tools.activeTool().paint(*painter, zoom);
    if (const auto& snap = m_tools.bodySnap()) {
        paintSnapMarker(*painter, *snap, zoom);
    }
}

void EditOverlay::paintGrid(QPainter& painter, const QWidget* widget) const
{
    if (!m_tools.snapping()) {
        return;
    }
    const double step = m_tools.gridStep();
    // What the view shows (exposedRect is the whole item without the extended option).
    const QRectF device = widget ? QRectF(widget->rect()) : QRectF(painter.viewport());
    const QRectF shown = painter.transform().inverted().mapRect(device);
    const double x0 = std::floor(shown.left() / step) * step;
    const double y0 = std::floor(shown.top() / step) * step;
    if ((shown.width() / step) * (shown.height() / step) >= 40000) {
        return;
    }
    painter.setPen(cosmetic(QColor(0, 0, 0, 70), 2));
    for (double x = x0; x <= shown.right(); x += step) {
        for (double y = y0; y <= shown.bottom(); y += step) {
            painter.drawPoint(QPointF(x, y));
        }
    }
}

void EditOverlay::paintOverlaps(QPainter& painter) const
{
    const lessons::Scene& scene = m_tools.scene();
    painter.setBrush(QColor(220, 40, 40, 60));
    painter.setPen(cosmetic(QColor(200, 0, 0), 2, Qt::DashLine));
    for (const auto& [a, b] : lessons::edit::overlappingPairs(scene)) {
        painter.drawPath(overlay::outline(scene.bodies[static_cast<size_t>(a)])
                             .intersected(overlay::outline(scene.bodies[static_cast<size_t>(b)])));
    }
    painter.setBrush(Qt::NoBrush);
}

void EditOverlay::paintSelectedBody(QPainter& painter, double zoom) const
{
    const lessons::Scene& scene = m_tools.scene();
    const int selected = m_tools.selectedBody();
    if (selected < 0 || static_cast<size_t>(selected) >= scene.bodies.size()) {
        return;
    }
    const auto& def = scene.bodies[static_cast<size_t>(selected)];
    painter.setPen(cosmetic(overlay::accent(), 2, Qt::DashLine));
    const QPainterPath path = overlay::outline(def);
    painter.drawPath(path);
    const double reach = 0.5 * std::max(path.boundingRect().width(), path.boundingRect().height()) +
                         EditTools::kGridPixels * 0.5 / zoom;
    const Vec2 handle = def.position + physics::Rotation(def.angle).apply(Vec2(0.0, reach));
    painter.setPen(cosmetic(overlay::accent(), 1.5));
    painter.drawLine(at(def.position), at(handle));
    const double r = 5.0 / zoom;
    painter.setBrush(Qt::white);
    painter.drawEllipse(at(handle), r, r);
    painter.drawEllipse(at(def.position), r * 0.6, r * 0.6);
    painter.setBrush(Qt::NoBrush);
    if (const auto arrow = m_tools.selectedArrow()) {
        paintVelocityArrow(&painter, *arrow, zoom);
    }
}

void EditOverlay::paintSelectedSpring(QPainter& painter) const
{
    const lessons::Scene& scene = m_tools.scene();
    const int spring = m_tools.selectedSpring();
    if (spring < 0 || static_cast<size_t>(spring) >= scene.springs.size()) {
        return;
    }
    const auto& s = scene.springs[static_cast<size_t>(spring)];
    const auto end = [&scene](physics::BodyId body, const Vec2& anchor) {
        if (body == physics::kWorld) {
            return anchor;
        }
        const auto& def = scene.bodies[static_cast<size_t>(body)];
        return Vec2(physics::Transform(def.position, def.angle).apply(anchor));
    };
    painter.setPen(cosmetic(overlay::accent(), 4, Qt::DashLine));
    painter.drawLine(at(end(s.a, s.anchorA)), at(end(s.b, s.anchorB)));
}

void EditOverlay::paintSnapMarker(QPainter& painter, const Snap& snap, double zoom)
{
    // A square on a vertex or a centre, a diamond on an edge, a few pixels across at any zoom.
    const double r = 5.0 / zoom;
    const QPointF c = at(snap.point);
    painter.setPen(cosmetic(QColor(200, 0, 130), 2));
    painter.setBrush(QColor(255, 255, 255, 160));
    if (snap.kind == Snap::Kind::Edge) {
        painter.drawPolygon(QPolygonF{c + QPointF(r, 0), c + QPointF(0, r), c + QPointF(-r, 0),
                                      c + QPointF(0, -r)});
    } else {
        painter.drawRect(QRectF(c - QPointF(r, r), c + QPointF(r, r)));
    }
    painter.setBrush(Qt::NoBrush);
}

} // namespace rigidlab::ui
