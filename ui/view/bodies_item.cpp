// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/bodies_item.h"

#include "view/body_item.h"

#include <QGraphicsScene>
#include <QPainter>
#include <QStyleOptionGraphicsItem>

#include <cmath>
#include <utility>

namespace rigidlab::ui {

namespace {

/// A body less than this across on screen [px] is drawn as a dot of its colour and size: its
/// outline and fill would only blur into two or three pixels anyway, and a dot costs the
/// raster engine a fraction of a polygon.
constexpr double kDotPx = 3.0;

} // namespace

BodiesItem::BodiesItem()
{
    // The view picks bodies itself (WorldView::bodyAt); the exposed rect culls bodies out of
    // sight.
    setAcceptedMouseButtons(Qt::NoButton);
    setAcceptHoverEvents(false);
    setFlag(ItemUsesExtendedStyleOption);
    setZValue(1); // under every overlay, as the bodies' own items were
}

void BodiesItem::setBodies(std::vector<const BodyItem*> inOrder)
{
    m_bodies = std::move(inOrder);
    update();
}

void BodiesItem::setAntialiased(bool on)
{
    m_antialiased = on;
    update();
}

QRectF BodiesItem::boundingRect() const
{
    return scene() ? scene()->sceneRect() : QRectF();
}

void BodiesItem::paintWhole(QPainter& painter, const BodyItem& body, const QTransform& toDevice)
{
    painter.setWorldTransform(body.frame() * toDevice);
    body.draw(painter);
}

void BodiesItem::paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget*)
{
    const QTransform toDevice = painter->worldTransform();
    const double pxPerMetre = std::hypot(toDevice.m11(), toDevice.m12());
    const QRectF shown = option->exposedRect; // [m]
    painter->setRenderHint(QPainter::Antialiasing, m_antialiased);
    // The selected body comes last, whole, so that no neighbour covers its outline.
    const BodyItem* selected = nullptr;
    // Dots are placed in device pixels: the painter stays there from one dot to the next, and
    // goes back only for a body painted whole (a settled pile is thousands of dots in a row).
    bool inDevicePixels = false;
    for (const BodyItem* body : m_bodies) {
        const QTransform& frame = body->frame(); // the body's frame in the scene [m]
        const double x = frame.dx(), y = frame.dy(), r = body->reach();
        if (x + r < shown.left() || x - r > shown.right() || y + r < shown.top() ||
            y - r > shown.bottom() || !std::isfinite(x) || !std::isfinite(y))
            continue;
        if (body->selectedBody()) {
            selected = body;
        } else if (const double px = body->drawnSize() * pxPerMetre; px < kDotPx) {
            if (!inDevicePixels)
                painter->resetTransform();
            inDevicePixels = true;
            body->drawDot(*painter, toDevice.map(QPointF(x, y)), px);
        } else {
            inDevicePixels = false;
            paintWhole(*painter, *body, toDevice);
        }
    }
    if (selected)
        paintWhole(*painter, *selected, toDevice);
    painter->setWorldTransform(toDevice);
}

} // namespace rigidlab::ui
