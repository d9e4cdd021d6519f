// SPDX-License-Identifier: GPL-3.0-or-later
#include "editor/velocity_arrow.h"

#include "rigidlab/physics/shape.h"

#include <QPainter>
#include <QPainterPath>
#include <QPen>

#include <algorithm>
#include <cmath>

namespace rigidlab::ui {

using physics::Vec2;

namespace {

/// The stub reaches this far beyond the body's outline [px].
constexpr double kStubPixels = 24.0;
/// The handle's radius [px].
constexpr double kHandlePixels = 5.0;
/// The arrowhead's length [px].
constexpr double kHeadPixels = 10.0;

QPointF at(const Vec2& p)
{
    return {p.x(), p.y()};
}

/// The largest distance of the body's outline from its origin [m].
double reachOf(const physics::BodyDef& def)
{
    return def.shape.visit(
        physics::Overloaded{[](const physics::Circle& c) { return c.center.norm() + c.radius; },
                            [](const physics::Polygon& p) {
                                double r = 0.0;
                                for (const Vec2& v : p.vertices) {
                                    r = std::max(r, v.norm());
                                }
                                return r;
                            }});
}

QPen cosmetic(const QColor& colour, double width, Qt::PenStyle style = Qt::SolidLine)
{
    QPen pen(colour, width, style);
    pen.setCosmetic(true);
    return pen;
}

} // namespace

std::optional<VelocityArrow> velocityArrow(const physics::BodyDef& def, double zoom)
{
    if (def.type == physics::BodyType::Static) {
        return std::nullopt;
    }
    const double pixel = 1.0 / std::max(zoom, 1e-9); // [m]
    VelocityArrow arrow;
    arrow.tail = def.position;
    arrow.tip = def.position + def.velocity * kArrowSeconds;
    const double stub = reachOf(def) + kStubPixels * pixel;
    const Vec2 along = arrow.tip - arrow.tail;
    const double length = along.norm();
    if (length >= stub) {
        arrow.handle = arrow.tip;
    } else {
        const Vec2 direction = length > 0.5 * pixel ? Vec2(along / length) : Vec2(1.0, 0.0);
        arrow.handle = arrow.tail + stub * direction;
    }
    return arrow;
}

Vec2 draggedVelocity(const Vec2& start, const Vec2& press, const Vec2& pointer, double step)
{
    Vec2 v = start + (pointer - press) / kArrowSeconds;
    if (step > 0) {
        for (int i = 0; i < 2; ++i) {
            v[i] = std::round(v[i] / step) * step;
        }
    }
    return v;
}

void paintVelocityArrow(QPainter* painter, const VelocityArrow& arrow, double zoom)
{
    const QColor colour(0, 140, 70);
    const double pixel = 1.0 / std::max(zoom, 1e-9); // [m]
    painter->save();
    painter->setBrush(Qt::NoBrush);
    if (arrow.handle != arrow.tip) {
        painter->setPen(cosmetic(colour, 1.0, Qt::DashLine));
        painter->drawLine(at(arrow.tail), at(arrow.handle));
    }
    const Vec2 along = arrow.tip - arrow.tail;
    const double length = along.norm();
    if (length > pixel) {
        painter->setPen(cosmetic(colour, 2.5));
        painter->drawLine(at(arrow.tail), at(arrow.tip));
        // The head: two barbs back from the tip, a fixed size on screen (shorter for a short
        // arrow, so that it never points backwards).
        const Vec2 back = -along / length * std::min(kHeadPixels * pixel, 0.5 * length);
        const Vec2 side(-back.y() * 0.5, back.x() * 0.5);
        QPainterPath head;
        head.moveTo(at(arrow.tip));
        head.lineTo(at(arrow.tip + back + side));
        head.lineTo(at(arrow.tip + back - side));
        head.closeSubpath();
        painter->setBrush(colour);
        painter->drawPath(head);
    }
    painter->setPen(cosmetic(colour, 2.0));
    painter->setBrush(Qt::white);
    const double r = kHandlePixels * pixel;
    painter->drawEllipse(at(arrow.handle), r, r);
    painter->restore();
}

} // namespace rigidlab::ui
