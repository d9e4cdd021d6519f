// SPDX-License-Identifier: GPL-3.0-or-later
#include "editor/edit_overlay.h"

#include "editor/edit_tools.h"
#include "editor/scene_document.h"

#include "edit/scene_edits.h"
#include "panels/number_field.h"

#include <QGraphicsScene>
#include <QPainter>
#include <QPainterPath>
#include <QPalette>
#include <QStyleOptionGraphicsItem>
#include <QWidget>

#include <cmath>

namespace rigidlab::ui {

using physics::Vec2;

namespace {

QPointF at(const Vec2& p)
{
    return {p.x(), p.y()};
}

/// The body's outline in the world [m].
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

QPen cosmetic(const QColor& colour, double width, Qt::PenStyle style = Qt::SolidLine)
{
    QPen pen(colour, width, style);
    pen.setCosmetic(true);
    return pen;
}

/// Text at a world point, upright and of a fixed pixel size whatever the zoom.
void label(QPainter* painter, const Vec2& p, const QString& text)
{
    const QPointF device = painter->transform().map(at(p));
    painter->save();
    painter->resetTransform();
    painter->setPen(cosmetic(Qt::black, 1));
    const QRectF box = painter->fontMetrics().boundingRect(text).adjusted(-3, -2, 3, 2);
    const QRectF placed = box.translated(device + QPointF(12, 20) - box.topLeft());
    painter->fillRect(placed, QColor(255, 255, 224, 230));
    painter->drawText(placed, Qt::AlignCenter, text);
    painter->restore();
}

} // namespace

EditOverlay::EditOverlay(const EditTools& tools) : m_tools(tools)
{
    setAcceptedMouseButtons(Qt::NoButton);
}

QRectF EditOverlay::boundingRect() const
{
    return scene() ? scene()->sceneRect() : QRectF();
}

void EditOverlay::paintVelocity(QPainter* painter, double zoom) const
{
    const auto arrow = m_tools.selectedArrow();
    if (!arrow) {
        return;
    }
    paintVelocityArrow(painter, *arrow, zoom);
    if (m_tools.m_drag.active && m_tools.m_drag.velocity) {
        const Vec2 v = (arrow->tip - arrow->tail) / kArrowSeconds;
        label(painter, arrow->handle, QStringLiteral("v = %1 m/s").arg(formatNumber(v.norm(), 3)));
    }
}

void EditOverlay::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget* widget)
{
    const lessons::Scene& scene = m_tools.m_document.scene();
    painter->setRenderHint(QPainter::Antialiasing);
    const QColor accent(0, 120, 215);
    const double zoom = std::max(std::hypot(painter->transform().m11(), painter->transform().m12()),
                                 1e-9); // [px/m]

    // The grid, as dots at its crossings, where snapping puts points.
    if (m_tools.m_snapAction->isChecked()) {
        const double step = m_tools.gridStep();
        // What the view shows (exposedRect is the whole item without the extended option).
        const QRectF device = widget ? QRectF(widget->rect()) : QRectF(painter->viewport());
        const QRectF shown = painter->transform().inverted().mapRect(device);
        const double x0 = std::floor(shown.left() / step) * step;
        const double y0 = std::floor(shown.top() / step) * step;
        const double nx = shown.width() / step;
        const double ny = shown.height() / step;
        if (nx * ny < 40000) {
            painter->setPen(cosmetic(QColor(0, 0, 0, 70), 2));
            for (double x = x0; x <= shown.right(); x += step) {
                for (double y = y0; y <= shown.bottom(); y += step) {
                    painter->drawPoint(QPointF(x, y));
                }
            }
        }
    }

    // Overlapping bodies, shown before the scene runs.
    painter->setBrush(QColor(220, 40, 40, 60));
    painter->setPen(cosmetic(QColor(200, 0, 0), 2, Qt::DashLine));
    for (const auto& [a, b] : lessons::edit::overlappingPairs(scene)) {
        painter->drawPath(outline(scene.bodies[static_cast<size_t>(a)])
                              .intersected(outline(scene.bodies[static_cast<size_t>(b)])));
    }
    painter->setBrush(Qt::NoBrush);

    // The selection: its outline, its origin and the rotate handle.
    const int selected = m_tools.selectedBody();
    if (selected >= 0 && static_cast<size_t>(selected) < scene.bodies.size()) {
        const auto& def = scene.bodies[static_cast<size_t>(selected)];
        painter->setPen(cosmetic(accent, 2, Qt::DashLine));
        const QPainterPath path = outline(def);
        painter->drawPath(path);
        const double reach =
            0.5 * std::max(path.boundingRect().width(), path.boundingRect().height()) +
            EditTools::kGridPixels * 0.5 / zoom;
        const Vec2 handle = def.position + physics::Rotation(def.angle).apply(Vec2(0.0, reach));
        painter->setPen(cosmetic(accent, 1.5));
        painter->drawLine(at(def.position), at(handle));
        const double r = 5.0 / zoom;
        painter->setBrush(Qt::white);
        painter->drawEllipse(at(handle), r, r);
        painter->drawEllipse(at(def.position), r * 0.6, r * 0.6);
        painter->setBrush(Qt::NoBrush);
        paintVelocity(painter, zoom);
    }

    // The selected spring.
    if (const int spring = m_tools.selectedSpring();
        spring >= 0 && static_cast<size_t>(spring) < scene.springs.size()) {
        const auto& s = scene.springs[static_cast<size_t>(spring)];
        const auto end = [&scene](physics::BodyId body, const Vec2& anchor) {
            if (body == physics::kWorld) {
                return anchor;
            }
            const auto& def = scene.bodies[static_cast<size_t>(body)];
            return Vec2(physics::Transform(def.position, def.angle).apply(anchor));
        };
        painter->setPen(cosmetic(accent, 4, Qt::DashLine));
        painter->drawLine(at(end(s.a, s.anchorA)), at(end(s.b, s.anchorB)));
    }

    // What is being drawn.
    const auto& drag = m_tools.m_drag;
    painter->setPen(cosmetic(accent, 2));
    if (drag.active) {
        const Vec2 a = drag.start;
        const Vec2 b = drag.current;
        switch (m_tools.tool()) {
        case EditTool::Circle: {
            const double r = (b - a).norm();
            painter->drawEllipse(at(a), r, r);
            painter->drawLine(at(a), at(b));
            label(painter, b, QStringLiteral("r = %1 m").arg(m_tools.metres(r)));
            break;
        }
        case EditTool::Box:
        case EditTool::Ground:
            painter->drawRect(QRectF(at(a), at(b)).normalized());
            label(painter, b,
                  QStringLiteral("%1 × %2 m")
                      .arg(m_tools.metres(std::abs(b.x() - a.x())),
                           m_tools.metres(std::abs(b.y() - a.y()))));
            break;
        case EditTool::Spring:
            painter->drawLine(at(a), at(b));
            label(painter, b, QStringLiteral("%1 m").arg(m_tools.metres((b - a).norm())));
            break;
        default:
            break;
        }
    }
    const auto& points = m_tools.polygonPoints();
    if (!points.empty()) {
        QPolygonF line;
        for (const Vec2& p : points) {
            line << at(p);
        }
        line << at(m_tools.m_pointer);
        painter->drawPolyline(line);
        // The hull that will be accepted, dashed, once the outline is not convex.
        const auto preview = lessons::edit::previewPolygon(points);
        if (preview.ok && !preview.warning.isEmpty()) {
            QPolygonF hull;
            for (const Vec2& p : preview.hull) {
                hull << at(p);
            }
            painter->setPen(cosmetic(QColor(200, 100, 0), 2, Qt::DashLine));
            painter->drawPolygon(hull);
        }
        const double r = 3.0 / zoom;
        painter->setBrush(accent);
        for (const Vec2& p : points) {
            painter->drawEllipse(at(p), r, r);
        }
        painter->setBrush(Qt::NoBrush);
        label(
            painter, m_tools.m_pointer,
            QStringLiteral("(%1; %2) m")
                .arg(m_tools.metres(m_tools.m_pointer.x()), m_tools.metres(m_tools.m_pointer.y())));
    }
    if (m_tools.m_pinStart) {
        const double r = 5.0 / zoom;
        painter->setPen(cosmetic(accent, 2));
        painter->drawEllipse(at(m_tools.m_pinStart->second), r, r);
    }
    if (const auto& snap = m_tools.bodySnap()) {
        drawSnapMarker(painter, *snap, zoom);
    }
}

void EditOverlay::drawSnapMarker(QPainter* painter, const Snap& snap, double zoom)
{
    // A square on a vertex or a centre, a diamond on an edge, a few pixels across at any zoom.
    const double r = 5.0 / zoom;
    const QPointF c = at(snap.point);
    painter->setPen(cosmetic(QColor(200, 0, 130), 2));
    painter->setBrush(QColor(255, 255, 255, 160));
    if (snap.kind == Snap::Kind::Edge) {
        painter->drawPolygon(QPolygonF{c + QPointF(r, 0), c + QPointF(0, r), c + QPointF(-r, 0),
                                       c + QPointF(0, -r)});
    } else {
        painter->drawRect(QRectF(c - QPointF(r, r), c + QPointF(r, r)));
    }
    painter->setBrush(Qt::NoBrush);
}

} // namespace rigidlab::ui
