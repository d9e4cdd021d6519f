// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/world_view.h"

#include "common/theme.h"
#include "panels/divergence_text.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "view/body_item.h"

#include <QLocale>
#include <QMouseEvent>
#include <QScrollBar>
#include <QToolTip>
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

WorldView::WorldView(SimulationController& controller, QWidget* parent)
    : QGraphicsView(parent), m_controller(controller), m_scene(new QGraphicsScene(this))
{
    m_scene->setSceneRect(-1e5, -1e5, 2e5, 2e5);
    m_scene->setItemIndexMethod(QGraphicsScene::NoIndex); // items move every frame
    setScene(m_scene);
    m_overlays = new OverlayItem(m_controller);
    m_overlays->setFrozenPose(
        [this](int world, physics::BodyId body) { return frozenPose(world, body); });
    m_scene->addItem(m_overlays);
    setRenderHint(QPainter::Antialiasing);
    setViewportUpdateMode(QGraphicsView::FullViewportUpdate);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setTransformationAnchor(QGraphicsView::AnchorUnderMouse);
    setDragMode(QGraphicsView::NoDrag);
    setMinimumSize(320, 240);
    setTransform(QTransform::fromScale(100, -100)); // y up
    setFocusPolicy(Qt::StrongFocus);
    connect(&m_controller, &SimulationController::sceneLoaded, this, &WorldView::rebuild);
    connect(&m_controller, &SimulationController::worldChanged, this, &WorldView::syncPoses);
    connect(&m_controller, &SimulationController::rewound, this,
            [this] { m_overlays->clearTrails(); });
    rebuild();
}

std::vector<const BodyItem*> WorldView::ghostItems(int variant) const
{
    std::vector<const BodyItem*> out;
    for (const Ghost& g : m_ghosts)
        if (g.variant == variant)
            out.push_back(g.item);
    return out;
}

const BodyItem* WorldView::itemFor(int id) const
{
    return id >= 0 && id < static_cast<int>(m_items.size()) ? m_items[static_cast<size_t>(id)]
                                                            : nullptr;
}

/// From this many bodies on, they are drawn without antialiasing (see BodyItem).
constexpr std::size_t kManyBodies = 300;

void WorldView::rebuild()
{
    for (BodyItem* item : m_items)
        delete item;
    m_items.clear();
    for (const Ghost& g : m_ghosts)
        delete g.item;
    m_ghosts.clear();
    const bool comparing = !m_controller.variantLabels().isEmpty();
    m_selected = -1;
    const auto& bodies = m_controller.world().bodies();
    int colour = 0;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const physics::Body& b = bodies[i];
        const int kind = b.type == physics::BodyType::Static      ? 1
                         : b.type == physics::BodyType::Kinematic ? 2
                                                                  : 0;
        // When worlds are compared, each has one colour, the same as its plot curve.
        const QColor fill = kind == 1   ? QColor(Qt::gray)
                            : comparing ? plotColor(0)
                                        : bodyColor(colour++);
        auto* item = new BodyItem(static_cast<int>(i), b.shape, kind, fill);
        item->setAntialiased(bodies.size() < kManyBodies);
        item->setMinimumRadius(minimumBodyRadius());
        m_scene->addItem(item);
        m_items.push_back(item);
    }
    // A compared world drawn beside the main one (an offset) needs its floor and walls too,
    // or its bodies stand in mid-air; drawn over the main one, its static bodies would only
    // repeat the main world's.
    const bool beside = !m_controller.variantOffset().isZero();
    for (int v = 0; v < m_controller.variantCount(); ++v) {
        const auto& vb = m_controller.variant(v).bodies();
        for (std::size_t i = 0; i < vb.size(); ++i) {
            if (!vb[i].moves() && !beside)
                continue;
            auto* item = new BodyItem(static_cast<int>(i), vb[i].shape, 3, plotColor(v + 1));
            item->setZValue(vb[i].moves() ? 2 : 1.5);
            item->setAcceptedMouseButtons(Qt::NoButton);
            item->setMinimumRadius(minimumBodyRadius());
            m_scene->addItem(item);
            m_ghosts.push_back({v, static_cast<int>(i), item, physics::Transform()});
        }
    }
    m_overlays->clearTrails();
    m_drawnRunning.clear();
    syncPoses();
    m_autoFit = true;
    fitScene();
    emit bodySelected(-1);
}

void WorldView::syncPoses()
{
    // A stopped world stays drawn, frozen where it last was in sight while it ran (in the
    // steps before it diverged its bodies may already fly far off): not gone, and its last
    // sane pose.
    const auto transformAt = [](const physics::Vec2& origin, double angle) {
        physics::Transform t;
        t.q = physics::Rotation(angle);
        t.p = origin;
        return t;
    };
    const QRectF shown = mapToScene(viewport()->rect()).boundingRect();
    const auto inSight = [&shown](const physics::Vec2& p) {
        return std::isfinite(p.x()) && std::isfinite(p.y()) &&
               (shown.isEmpty() || shown.contains(QPointF(p.x(), p.y())));
    };
    const std::size_t worlds = static_cast<std::size_t>(m_controller.variantCount()) + 1;
    m_drawnRunning.resize(worlds, false);
    const physics::World& main = m_controller.world();
    const bool mainFrozen = main.divergence() && m_drawnRunning[0];
    std::vector<Pose> poses(m_items.size());
    bool mainSane = !main.divergence();
    for (std::size_t i = 0; i < m_items.size(); ++i) {
        poses[i] = m_controller.drawPose(static_cast<physics::BodyId>(i));
        mainSane = mainSane && inSight(poses[i].origin);
    }
    m_itemPoses.resize(m_items.size());
    for (std::size_t i = 0; i < m_items.size(); ++i) {
        if (mainSane || !m_drawnRunning[0])
            m_itemPoses[i] = transformAt(poses[i].origin, poses[i].angle);
        const physics::Transform& t = m_itemPoses[i];
        if (mainFrozen)
            m_items[i]->setPose(t.p.x(), t.p.y(), std::atan2(t.q.s, t.q.c));
        else
            m_items[i]->setPose(poses[i].origin.x(), poses[i].origin.y(), poses[i].angle);
    }
    m_drawnRunning[0] = m_drawnRunning[0] || mainSane;

    std::vector<bool> sane(worlds, true);
    for (const Ghost& g : m_ghosts) {
        const physics::World& vw = m_controller.variant(g.variant);
        const physics::Vec2 o =
            vw.body(g.body).origin() + (g.variant + 1) * m_controller.variantOffset();
        const auto w = static_cast<std::size_t>(g.variant) + 1;
        sane[w] = sane[w] && !vw.divergence() && inSight(o);
    }
    for (Ghost& g : m_ghosts) {
        const physics::World& vw = m_controller.variant(g.variant);
        const auto w = static_cast<std::size_t>(g.variant) + 1;
        const physics::Body& b = vw.body(g.body);
        const physics::Vec2 shift = (g.variant + 1) * m_controller.variantOffset();
        if (sane[w] || !m_drawnRunning[w])
            g.pose = transformAt(b.origin(), b.angle);
        if (vw.divergence() && m_drawnRunning[w]) {
            const physics::Vec2 o = g.pose.p + shift;
            g.item->setPose(o.x(), o.y(), std::atan2(g.pose.q.s, g.pose.q.c));
        } else {
            const physics::Vec2 o = b.origin() + shift;
            g.item->setPose(o.x(), o.y(), b.angle);
        }
    }
    for (std::size_t w = 1; w < worlds; ++w)
        m_drawnRunning[w] = m_drawnRunning[w] || sane[w];
    if (const int stopped = stoppedCount(); stopped != m_stoppedCount) {
        // A world stopped: what auto-fit widened to follow it is given back, so that the
        // worlds still running are shown as large as at the start.
        m_stoppedCount = stopped;
        if (m_autoFit && !m_startFit.isEmpty()) {
            m_fitted = m_startFit | (contentRect() & m_fitLimit);
            showRect(m_fitted);
        }
    }
    if (m_autoFit && !m_fitted.isEmpty()) {
        // Follow bodies that leave the fitted area, by widening it (within the limit).
        const QRectF wanted = (m_fitted | contentRect()) & m_fitLimit;
        if (!m_fitted.contains(wanted)) {
            m_fitted |= wanted;
            showRect(m_fitted);
        } else if (legendHeight() != m_legendReserved) {
            showRect(m_fitted); // a world stopped: its legend line grew, the bodies move down
        }
    }
    m_overlays->refresh();
}

std::optional<physics::Transform> WorldView::frozenPose(int world, physics::BodyId body) const
{
    const auto w = static_cast<std::size_t>(world);
    if (w >= m_drawnRunning.size() || !m_drawnRunning[w] || !stoppedWorld(world))
        return std::nullopt;
    if (world == 0)
        return body >= 0 && static_cast<std::size_t>(body) < m_itemPoses.size()
                   ? std::optional(m_itemPoses[static_cast<std::size_t>(body)])
                   : std::nullopt;
    for (const Ghost& g : m_ghosts)
        if (g.variant == world - 1 && g.body == static_cast<int>(body))
            return g.pose;
    return std::nullopt;
}

void WorldView::selectBody(int id)
{
    if (m_selected >= 0 && m_selected < static_cast<int>(m_items.size()))
        m_items[static_cast<size_t>(m_selected)]->setSelectedBody(false);
    m_selected = id >= 0 && id < static_cast<int>(m_items.size()) ? id : -1;
    if (m_selected >= 0)
        m_items[static_cast<size_t>(m_selected)]->setSelectedBody(true);
    emit bodySelected(m_selected);
}

QRectF WorldView::contentRect() const
{
    // A world that stopped (diverged) is left out: its bodies may lie a billion metres away,
    // and following them would shrink the worlds still running to a dot.
    QRectF box;
    const physics::World& w = m_controller.world();
    if (!w.divergence())
        for (const BodyItem* item : m_items)
            box |= item->sceneBoundingRect();
    for (const Ghost& g : m_ghosts)
        if (!m_controller.variant(g.variant).divergence())
            box |= g.item->sceneBoundingRect();
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
    return box;
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
    const double r = minimumBodyRadius();
    for (BodyItem* item : m_items)
        item->setMinimumRadius(r);
    for (const Ghost& g : m_ghosts)
        g.item->setMinimumRadius(r);
}

physics::Vec2 WorldView::toWorld(const QPoint& viewPos) const
{
    const QPointF p = mapToScene(viewPos);
    return {p.x(), p.y()};
}

void WorldView::mousePressEvent(QMouseEvent* event)
{
    m_lastMouse = event->pos();
    if (event->button() == Qt::MiddleButton) {
        m_panning = true;
        setCursor(Qt::ClosedHandCursor);
        return;
    }
    if (event->button() != Qt::LeftButton)
        return QGraphicsView::mousePressEvent(event);
    BodyItem* hit = nullptr;
    for (QGraphicsItem* item : items(event->pos()))
        if ((hit = qgraphicsitem_cast<BodyItem*>(item)))
            break;
    if (!hit) {
        m_panning = true;
        setCursor(Qt::ClosedHandCursor);
        return;
    }
    selectBody(hit->bodyId());
    m_autoFit = false; // the view must hold still under the hand that drags
    m_controller.grab(hit->bodyId(), toWorld(event->pos()));
    if (m_controller.grabbed())
        setCursor(Qt::ClosedHandCursor);
}

void WorldView::mouseMoveEvent(QMouseEvent* event)
{
    const QPoint delta = event->pos() - m_lastMouse;
    m_lastMouse = event->pos();
    if (m_panning) {
        m_autoFit = false;
        horizontalScrollBar()->setValue(horizontalScrollBar()->value() - delta.x());
        verticalScrollBar()->setValue(verticalScrollBar()->value() - delta.y());
        return;
    }
    if (m_controller.grabbed()) {
        m_controller.dragTo(toWorld(event->pos()));
        m_overlays->update();
        return;
    }
    QGraphicsView::mouseMoveEvent(event);
}

void WorldView::mouseReleaseEvent(QMouseEvent* event)
{
    m_panning = false;
    m_controller.release();
    unsetCursor();
    QGraphicsView::mouseReleaseEvent(event);
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

void WorldView::resizeEvent(QResizeEvent* event)
{
    QGraphicsView::resizeEvent(event);
    if (m_autoFit)
        showRect(m_fitted.isEmpty() ? contentRect() : m_fitted);
}

void WorldView::drawBackground(QPainter* painter, const QRectF& rect)
{
    // In device pixels and without antialiasing: a solid fill and whole-pixel lines are the
    // raster engine's fast paths (through the view's flipped, scaled transform with
    // antialiasing, this took more of a frame than all the bodies of a 820-box pyramid).
    const QTransform toDevice = painter->worldTransform();
    painter->save();
    painter->resetTransform();
    painter->setRenderHint(QPainter::Antialiasing, false);
    const QRect device = toDevice.mapRect(rect).toAlignedRect();
    painter->fillRect(device, theme::worldBackground());
    // A light grid, 1 m apart (10 m when zoomed far out), so that distances can be read.
    const double step = zoom() < 12 ? 10.0 : (zoom() > 400 ? 0.1 : 1.0);
    painter->setPen(QPen(theme::worldGrid(), 0));
    const double x0 = std::floor(rect.left() / step) * step;
    const double y0 = std::floor(rect.top() / step) * step;
    for (double x = x0; x <= rect.right(); x += step) {
        const int px = qRound(toDevice.map(QPointF(x, 0)).x());
        painter->drawLine(px, device.top(), px, device.bottom());
    }
    for (double y = y0; y <= rect.bottom(); y += step) {
        const int py = qRound(toDevice.map(QPointF(0, y)).y());
        painter->drawLine(device.left(), py, device.right(), py);
    }
    painter->restore();
}

int WorldView::worldCount() const
{
    return static_cast<int>(m_controller.variantLabels().size());
}

bool WorldView::stoppedWorld(int world) const
{
    const physics::World& w = world == 0 ? m_controller.world() : m_controller.variant(world - 1);
    return w.divergence().has_value();
}

QString WorldView::legendLine(int world) const
{
    const QString name = m_controller.variantLabels().value(world);
    const physics::World& w = world == 0 ? m_controller.world() : m_controller.variant(world - 1);
    // A stopped world gets one short line, readable from the back of the room; the numbers
    // (how far the energy grew, which body) are in legendDetail, the line's tooltip.
    if (const auto& d = w.divergence()) {
        const QString time = QLocale().toString(d->time, 'g', 3);
        if (d->kind == physics::Divergence::Kind::EnergyGrowth)
            return tr("%1 — blew up at t = %2 s").arg(name, time);
        return tr("%1 — stopped at t = %2 s: %3").arg(name, time, divergenceShort(*d));
    }
    return world == 0 ? tr("%1 (solid)").arg(name) : tr("%1 (outline)").arg(name);
}

QString WorldView::legendDetail(int world) const
{
    const QString name = m_controller.variantLabels().value(world);
    const physics::World& w = world == 0 ? m_controller.world() : m_controller.variant(world - 1);
    if (const auto& d = w.divergence())
        return world == 0 ? tr("%1 (solid): %2").arg(name, divergenceLabel(*d))
                          : tr("%1 (outline): %2").arg(name, divergenceLabel(*d));
    return legendLine(world);
}

bool WorldView::viewportEvent(QEvent* event)
{
    if (event->type() == QEvent::ToolTip) {
        // The legend's short lines: the full diagnosis of a stopped world.
        const auto* help = static_cast<QHelpEvent*>(event);
        const std::vector<QRect> lines = legendLayout();
        for (int i = 0; i < static_cast<int>(lines.size()); ++i) {
            const QRect box = lines[static_cast<std::size_t>(i)].adjusted(-30, -1, 3, 1);
            if (box.contains(help->pos())) {
                QToolTip::showText(help->globalPos(), legendDetail(i), viewport(), box);
                return true;
            }
        }
        QToolTip::hideText();
        event->ignore();
        return true;
    }
    return QGraphicsView::viewportEvent(event);
}

void WorldView::drawForeground(QPainter* painter, const QRectF&)
{
    // A scale bar in screen space, bottom left: a round length of about 120 px.
    painter->save();
    painter->resetTransform();
    const double metres = 120.0 / zoom();
    const double exp10 = std::pow(10.0, std::floor(std::log10(metres)));
    double nice = exp10;
    for (double m : {1.0, 2.0, 5.0})
        if (m * exp10 <= metres)
            nice = m * exp10;
    const int len = static_cast<int>(nice * zoom());
    const QPoint o(16, viewport()->height() - 18);
    painter->setPen(QPen(theme::worldText(), 2));
    painter->drawLine(o, o + QPoint(len, 0));
    painter->drawLine(o + QPoint(0, -5), o + QPoint(0, 5));
    painter->drawLine(o + QPoint(len, -5), o + QPoint(len, 5));
    const QFont f = legendFont();
    painter->setFont(f);
    const QString label = nice >= 1 ? tr("%1 m").arg(QLocale().toString(nice))
                                    : tr("%1 cm").arg(QLocale().toString(nice * 100));
    painter->drawText(o + QPoint(len + 8, 5), label);
    const QFontMetrics fm(legendFont());

    // Which colour is which world, when worlds are compared; a stopped one says why. Each line
    // on a box of the background's colour: the grid (or a body) behind it does not lower its
    // contrast.
    const std::vector<QRect> lines = legendLayout();
    for (int i = 0; i < static_cast<int>(lines.size()); ++i) {
        const QRect& box = lines[static_cast<std::size_t>(i)];
        painter->fillRect(box.adjusted(-30, -1, 3, 1), theme::worldLabelBox());
        painter->fillRect(QRect(14, box.top() + 2, 22, fm.ascent() - 4), plotColor(i));
        painter->setPen(stoppedWorld(i) ? theme::worldAlertText() : theme::worldText());
        painter->drawText(box, Qt::TextWordWrap, legendLine(i));
    }
    // Beside each stopped ghost, in a box of the background's colour (it may lie over bodies
    // or off the view, so it is kept inside), below the one before where they would meet.
    const std::vector<QRect> labels = stoppedLabelRects();
    int k = 0;
    for (int v = 0; v < m_controller.variantCount(); ++v) {
        if (!m_controller.variant(v).divergence() || !ghostOf(v))
            continue;
        const QRect& box = labels[static_cast<std::size_t>(k++)];
        painter->fillRect(box, theme::worldLabelBox());
        painter->setPen(theme::worldAlertText());
        painter->drawText(box, Qt::AlignCenter, stoppedLabel(v));
        // A cross over the frozen body: this one no longer moves.
        const QPoint c = mapFromScene(ghostOf(v)->sceneBoundingRect().center());
        const int r = std::max(6, fm.ascent() / 2);
        painter->setPen(QPen(theme::worldAlertText(), theme::lineWidth(2.5)));
        painter->drawLine(c + QPoint(-r, -r), c + QPoint(r, r));
        painter->drawLine(c + QPoint(-r, r), c + QPoint(r, -r));
    }
    painter->restore();
}

QFont WorldView::legendFont() const
{
    QFont f = font();
    f.setPointSizeF(f.pointSizeF() * 1.1);
    return f;
}

std::vector<QRect> WorldView::legendLayout() const
{
    const QFontMetrics fm(legendFont());
    const int width = std::max(120, viewport()->width() - 56);
    std::vector<QRect> out;
    int y = 12;
    for (int i = 0; i < worldCount(); ++i) {
        const QRect box =
            fm.boundingRect(QRect(42, y, width, 10000), Qt::TextWordWrap, legendLine(i));
        out.push_back(box);
        y = box.bottom() + 3;
    }
    return out;
}

int WorldView::legendHeight() const
{
    const std::vector<QRect> lines = legendLayout();
    return lines.empty() ? 0 : lines.back().bottom() + 4;
}

int WorldView::stoppedCount() const
{
    int n = m_controller.world().divergence() ? 1 : 0;
    for (int v = 0; v < m_controller.variantCount(); ++v)
        n += m_controller.variant(v).divergence() ? 1 : 0;
    return n;
}

const BodyItem* WorldView::ghostOf(int variant) const
{
    const auto ghost = std::find_if(m_ghosts.begin(), m_ghosts.end(),
                                    [variant](const Ghost& g) { return g.variant == variant; });
    return ghost == m_ghosts.end() ? nullptr : ghost->item;
}

QString WorldView::stoppedLabel(int variant) const
{
    return tr("%1 stopped").arg(m_controller.variantLabels().value(variant + 1));
}

std::vector<QRect> WorldView::stoppedLabelRects() const
{
    const QFontMetrics fm(legendFont());
    const QRect inside = viewport()->rect().adjusted(4, legendHeight(), -4, -30);
    std::vector<QRect> out;
    for (int v = 0; v < m_controller.variantCount(); ++v) {
        const BodyItem* ghost = ghostOf(v);
        if (!m_controller.variant(v).divergence() || !ghost)
            continue;
        QRect box = fm.boundingRect(stoppedLabel(v)).adjusted(-4, -2, 4, 2);
        const QPoint at = mapFromScene(ghost->sceneBoundingRect().topRight());
        box.moveTopLeft(at + QPoint(6, -box.height()));
        box.moveLeft(std::clamp(box.left(), inside.left(),
                                std::max(inside.left(), inside.right() - box.width())));
        box.moveTop(std::clamp(box.top(), inside.top(),
                               std::max(inside.top(), inside.bottom() - box.height())));
        // Stacked below any label it would meet (a ghost that flew off is pinned to an edge,
        // where the others are too).
        for (bool moved = true; moved;) {
            moved = false;
            for (const QRect& other : out)
                if (box.intersects(other)) {
                    box.moveTop(other.bottom() + 3);
                    moved = true;
                }
        }
        out.push_back(box);
    }
    return out;
}

} // namespace rigidlab::ui
