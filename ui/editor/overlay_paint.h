// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The drawing pieces Edit mode's overlay and its tools share: world points as scene points,
// pens a fixed number of pixels wide at any zoom, labels that stay upright and readable.

#include "rigidlab/physics/body.h"
#include "rigidlab/physics/math.h"

#include <QColor>
#include <QPainterPath>
#include <QPen>
#include <QPointF>

class QPainter;

namespace rigidlab::ui::overlay {

/// The editor's colour: the selection, the shape being drawn.
inline QColor accent()
{
    return {0, 120, 215};
}

inline QPointF at(const physics::Vec2& p)
{
    return {p.x(), p.y()};
}

/// A pen `width` pixels wide whatever the zoom.
QPen cosmetic(const QColor& colour, double width, Qt::PenStyle style = Qt::SolidLine);

/// The body's outline in the world [m].
QPainterPath outline(const physics::BodyDef& def);

/// Text at a world point, upright and of a fixed pixel size whatever the zoom.
void label(QPainter& painter, const physics::Vec2& p, const QString& text);

} // namespace rigidlab::ui::overlay
