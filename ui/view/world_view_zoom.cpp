// SPDX-License-Identifier: GPL-3.0-or-later
// WorldView's zoom: fitting the scene or a rectangle, the wheel, and the least size a body
// is drawn.

#include "view/world_view.h"

#include "common/theme.h"
#include "simulation/run_view.h"
#include "view/bodies_item.h"
#include "view/body_item.h"

#include <QScrollBar>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace rigidlab::ui {

namespace {

constexpr double kMinZoom = 2.0;     // pixels per metre
constexpr double kMaxZoom = 20000.0; // pixels per metre
/// The least size a moving body is drawn across [px], so that the back row sees it (larger in
/// presentation mode); a body smaller on screen is drawn grown to it.
constexpr double kMinBodyPx = 10.0;
constexpr double kMinBodyPresentationPx = 14.0;

} // namespace

QRectF WorldView::contentRect() const
{
    // A world that stopped (diverged) is left out: its bodies may lie a billion metres away,
    // and following them would shrink the worlds still running to a dot.
    QRectF box;
    const physics::World& w = m_run.world();
    if (!w.divergence())
        for (std::size_t i = 0; i < m_items.size(); ++i)
            box |= shownRect(*m_items[i], w, static_cast<physics::BodyId>(i));
    for (const Ghost& g : m_ghosts)
        if (const physics::World& vw = m_run.variant(g.variant); !vw.divergence())
            box |= shownRect(*g.item, vw, g.body);
    return box | anchorsAndExtras();
}

QRectF WorldView::shownRect(const BodyItem& item, const physics::World& world,
                            physics::BodyId body) const
{
    // With the run's event known, the scenery is framed only around it: the carts of a step
    // and the ground under them, not the whole 40 m of ground. Worlds compared side by side
    // keep theirs whole: each world's floor is part of that picture.
    const QRectF r = item.sceneBox();
    const auto i = static_cast<std::size_t>(body);
    if (m_action.isEmpty() || !m_run.variantOffset().isZero() || i >= world.bodies().size() ||
        world.bodies()[i].moves())
        return r;
    const double grow = 0.15 * std::max(m_action.width(), m_action.height()) + 0.2;
    return r & m_action.adjusted(-grow, -grow, grow, grow);
}

QRectF WorldView::anchorsAndExtras() const
{
    QRectF box;
    const physics::World& w = m_run.world();
    auto add = [&](physics::BodyId id, const physics::Vec2& anchor) {
        const physics::Vec2 p =
            id == physics::kWorld ? anchor : w.body(id).transform().apply(anchor);
        box |= QRectF(QPointF(p.x(), p.y()), QSizeF(1e-6, 1e-6));
    };
    if (!w.divergence()) {
        for (const physics::SpringDef& s : w.springs()) {
            add(s.a, s.anchorA);
            add(s.b, s.anchorB);
        }
        for (const physics::PinJointDef& j : w.joints()) {
            add(j.a, j.anchorA);
            add(j.b, j.anchorB);
        }
    }
    if (m_fitExtra)
        box |= m_fitExtra();
    if (!m_action.isEmpty())
        box |= m_action;
    return box;
}

bool WorldView::contentWithin(const QRectF& area) const
{
    // A body's outline lies within its reach of its origin at any angle: the square of that
    // half-side about the origin inside `area` holds the outline too, without mapping the
    // outline's box through the pose (contentRect's walk, every frame, cost the base-100
    // pyramid 2.3 % of its CPU). Only a body whose square crosses the edge is asked for its
    // exact box: the pyramid's top box, whose outline made the fitted area's edge, sent every
    // frame back to the full walk while it was one yes or no for all. What contentRect leaves
    // out is left out here too. A body that does not move (a ground 120 m long) is asked for its
    // exact box at once: its reach would be a square 120 m high.
    const auto within = [&](const BodyItem& item, const physics::World& world,
                            physics::BodyId body) {
        const auto i = static_cast<std::size_t>(body);
        if (i >= world.bodies().size() || world.bodies()[i].moves()) {
            const QTransform& t = item.frame();
            const double r = item.reach();
            if (area.contains(QRectF(t.dx() - r, t.dy() - r, 2 * r, 2 * r)))
                return true;
        }
        const QRectF r = shownRect(item, world, body);
        return r.isEmpty() || area.contains(r);
    };
    const physics::World& w = m_run.world();
    if (!w.divergence())
        for (std::size_t i = 0; i < m_items.size(); ++i)
            if (!within(*m_items[i], w, static_cast<physics::BodyId>(i)))
                return false;
    for (const Ghost& g : m_ghosts)
        if (const physics::World& vw = m_run.variant(g.variant);
            !vw.divergence() && !within(*g.item, vw, g.body))
            return false;
    const QRectF rest = anchorsAndExtras();
    return rest.isNull() || area.contains(rest);
}

void WorldView::setActionBounds(const QRectF& worldRect)
{
    m_action = worldRect;
    fitScene();
}

void WorldView::fitScene()
{
    m_autoFit = true;
    m_fitted = contentRect();
    if (m_fitted.isEmpty())
        return;
    // Auto-fit may later widen to follow bodies that swing or bounce a little outside the
    // start, but not far: a body that leaves the scene (the cue ball of a break, a pendulum
    // gone over the top) would shrink everything still in it to dots.
    const double grow = std::max(0.25 * std::max(m_fitted.width(), m_fitted.height()), 0.5);
    m_fitLimit = m_fitted.adjusted(-grow, -grow, grow, grow);
    m_startFit = m_fitted;
    m_stoppedCount = stoppedCount();
    showRect(m_fitted);
    // A panel's drawing may be sized partly in pixels: measure it again at the new zoom.
    for (int round = 0; round < 4 && m_fitExtra && !m_fitted.contains(contentRect()); ++round) {
        m_fitted |= contentRect();
        showRect(m_fitted);
    }
}

void WorldView::fitRect(QRectF worldRect, double marginPx)
{
    const double w = viewport()->width() - 2 * marginPx, h = viewport()->height() - 2 * marginPx;
    if (worldRect.isEmpty() || w < 10 || h < 10)
        return;
    setZoom(std::min(w / worldRect.width(), h / worldRect.height()));
    centerOn(worldRect.center());
    // Resizing shows this again (with showRect's margin on top), and auto-fit does not widen
    // it to the rest of the scene.
    const double m = marginPx / zoom();
    m_autoFit = true;
    m_fitted = worldRect.adjusted(-m, -m, m, m);
    m_fitLimit = m_fitted;
    m_startFit = m_fitted;
}

void WorldView::showRect(QRectF box)
{
    if (box.isEmpty() || viewport()->width() < 10 || viewport()->height() < 10)
        return;
    const double margin = 0.08 * std::max(box.width(), box.height()) + 0.05;
    box.adjust(-margin, -margin, margin, margin);
    // The legend of compared worlds takes the top of the view: the bodies go below it.
    //   +------------------+
    //   | legend           |  top
    //   |------------------|
    //   |   box, centred   |  height - top
    //   +------------------+
    m_legendReserved = legendHeight();
    const int top = std::min(m_legendReserved, viewport()->height() / 2);
    setZoom(
        std::min(viewport()->width() / box.width(), (viewport()->height() - top) / box.height()));
    // Screen up is world +y: the view's centre lies half the legend above the box's centre.
    centerOn(box.center() + QPointF(0, 0.5 * top / zoom()));
}

void WorldView::setZoom(double pixelsPerMetre)
{
    const double s = std::clamp(pixelsPerMetre, kMinZoom, kMaxZoom);
    setTransform(QTransform::fromScale(s, -s));
    applyMinimumBodySize();
}

double WorldView::minimumBodyRadius() const
{
    const double px = theme::presentation() ? kMinBodyPresentationPx : kMinBodyPx;
    return 0.5 * px / zoom();
}

void WorldView::applyMinimumBodySize()
{
    // In a crowd (hundreds of bodies) a body grown to the readable size only covers its
    // neighbours: the base-100 pyramid's 2 px boxes grown to 10 px painted each pixel some
    // 25 times over and hid the pile's shape. There the bodies keep their true size, and only
    // the selected one is grown, so that it stays in sight.
    const double r = minimumBodyRadius();
    for (const auto& item : m_items)
        item->setMinimumRadius(m_crowded && !item->selectedBody() ? 0.0 : r);
    for (const Ghost& g : m_ghosts)
        g.item->setMinimumRadius(m_crowded ? 0.0 : r);
    m_bodiesItem->update();
}

void WorldView::wheelEvent(QWheelEvent* event)
{
    const double steps = event->angleDelta().y() / 120.0;
    if (steps == 0)
        return;
    // Zoom about the point under the cursor (the transformation anchor).
    m_autoFit = false;
    const double factor = std::pow(1.2, steps);
    const double target = std::clamp(zoom() * factor, kMinZoom, kMaxZoom);
    scale(target / zoom(), target / zoom());
    applyMinimumBodySize();
    event->accept();
}

void WorldView::zoomBy(double factor)
{
    const QPointF middle = mapToScene(viewport()->rect().center());
    m_autoFit = false;
    setZoom(zoom() * factor);
    centerOn(middle);
}

void WorldView::panBy(const QPoint& pixels)
{
    m_autoFit = false;
    horizontalScrollBar()->setValue(horizontalScrollBar()->value() + pixels.x());
    verticalScrollBar()->setValue(verticalScrollBar()->value() + pixels.y());
}

void WorldView::resizeEvent(QResizeEvent* event)
{
    QGraphicsView::resizeEvent(event);
    if (m_autoFit)
        showRect(m_fitted.isEmpty() ? contentRect() : m_fitted);
}

} // namespace rigidlab::ui
