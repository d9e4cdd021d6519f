// SPDX-License-Identifier: GPL-3.0-or-later
// WorldView: its bodies kept in step with the controller's worlds, selection and dragging.
// Its other parts: world_view_zoom.cpp, world_view_paint.cpp (grid, legend, stopped labels).
#include "view/world_view.h"

#include "common/theme.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "view/bodies_item.h"
#include "view/body_item.h"
#include "view/scene_narrator.h"

#include <QMouseEvent>
#include <QScrollBar>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace rigidlab::ui {

namespace {

/// Whether a body at p is a sane sight in the view showing `shown` (anywhere, before the
/// view has a size).
bool inSight(const QRectF& shown, const physics::Vec2& p)
{
    return std::isfinite(p.x()) && std::isfinite(p.y()) &&
           (shown.isEmpty() || shown.contains(QPointF(p.x(), p.y())));
}

} // namespace

WorldView::WorldView(SimulationController& controller, QWidget* parent)
    : QGraphicsView(parent), m_controller(controller), m_run(controller),
      m_scene(new QGraphicsScene(this))
{
    m_scene->setSceneRect(-1e5, -1e5, 2e5, 2e5);
    m_scene->setItemIndexMethod(QGraphicsScene::NoIndex); // items move every frame
    setScene(m_scene);
    m_overlays = new OverlayItem(m_controller);
    m_overlays->setFrozenPose(
        [this](int world, physics::BodyId body) { return frozenPose(world, body); });
    m_scene->addItem(m_overlays);
    m_bodiesItem = new BodiesItem;
    m_scene->addItem(m_bodiesItem);
    setRenderHint(QPainter::Antialiasing);
    setViewportUpdateMode(QGraphicsView::FullViewportUpdate);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setTransformationAnchor(QGraphicsView::AnchorUnderMouse);
    setDragMode(QGraphicsView::NoDrag);
    setMinimumSize(320, 240);
    setTransform(QTransform::fromScale(100, -100)); // y up
    setFocusPolicy(Qt::StrongFocus);
    m_narrator = new SceneNarrator(m_controller, *this);
    viewport()->setAccessibleName(tr("Scene drawing"));
    connect(&m_controller, &SimulationController::sceneLoaded, this, &WorldView::rebuild);
    connect(&m_controller, &SimulationController::worldChanged, this, &WorldView::syncPoses);
    connect(&m_controller, &SimulationController::rewound, this,
            [this] { m_overlays->clearTrails(); });
    rebuild();
}

WorldView::~WorldView()
{
    // The bodies' items are not the scene's but these members': the scene outlives them a
    // little (a child of the view), so its painter lets go of them first.
    m_bodiesItem->setBodies({});
}

std::vector<const BodyItem*> WorldView::ghostItems(int variant) const
{
    std::vector<const BodyItem*> out;
    for (const Ghost& g : m_ghosts)
        if (g.variant == variant)
            out.push_back(g.item.get());
    return out;
}

const BodyItem* WorldView::itemFor(int id) const
{
    return id >= 0 && id < static_cast<int>(m_items.size()) ? m_items[static_cast<size_t>(id)].get()
                                                            : nullptr;
}

int WorldView::bodyAt(const QPoint& viewPos) const
{
    // Topmost first, as painted: the selected body over all (BodiesItem paints it last),
    // then a moving body over the ground, a later body over an earlier.
    const QPointF at = mapToScene(viewPos);
    if (const BodyItem* chosen = itemFor(m_selected); chosen && chosen->containsScenePoint(at))
        return m_selected;
    const BodyItem* hit = nullptr;
    for (const auto& item : m_items)
        if (item->containsScenePoint(at) && (!hit || item->zValue() >= hit->zValue()))
            hit = item.get();
    return hit ? hit->bodyId() : -1;
}

/// From this many bodies on, the scene is a crowd (WorldView::m_crowded).
constexpr std::size_t kManyBodies = 300;

void WorldView::rebuild()
{
    m_bodiesItem->setBodies({});
    m_items.clear();
    m_itemPoses.clear(); // another scene's bodies: their poses are no cache for these
    m_ghosts.clear();
    const bool comparing = !m_controller.variantLabels().isEmpty();
    m_selected = -1;
    const auto& bodies = m_controller.world().bodies();
    m_crowded = bodies.size() >= kManyBodies;
    int colour = 0;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const physics::Body& b = bodies[i];
        const int kind = b.type == physics::BodyType::Static      ? 1
                         : b.type == physics::BodyType::Kinematic ? 2
                                                                  : 0;
        // When worlds are compared, each has one colour, the same as its plot curve.
        QColor fill = kind == 1 ? QColor(Qt::gray) : comparing ? plotColor(0) : bodyColor(colour++);
        // The scene's own colour for the body, where it gives one ("colour": "#rrggbb").
        if (const QString own = m_controller.scene().colourOf(i); !own.isEmpty() && !comparing)
            fill = QColor::fromString(own);
        m_items.push_back(std::make_unique<BodyItem>(static_cast<int>(i), b.shape, kind, fill));
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
            auto item =
                std::make_unique<BodyItem>(static_cast<int>(i), vb[i].shape, 3, plotColor(v + 1));
            item->setZValue(vb[i].moves() ? 2 : 1.5);
            m_ghosts.push_back({v, static_cast<int>(i), std::move(item), physics::Transform()});
        }
    }
    applyMinimumBodySize();
    paintBodiesInOrder();
    m_overlays->clearTrails();
    m_drawnRunning.clear();
    syncPoses();
    if (m_fitOnRebuild) {
        m_autoFit = true;
        fitScene();
    }
    emit bodySelected(-1);
}

void WorldView::paintBodiesInOrder()
{
    // The order the scene painted the bodies' own items in: by their z (the ground, the
    // moving bodies, the compared worlds' ground, their moving bodies), then as added.
    std::vector<const BodyItem*> order;
    for (const auto& item : m_items)
        order.push_back(item.get());
    for (const Ghost& g : m_ghosts)
        order.push_back(g.item.get());
    std::stable_sort(order.begin(), order.end(), [](const BodyItem* a, const BodyItem* b) {
        return a->zValue() < b->zValue();
    });
    m_bodiesItem->setBodies(std::move(order));
    m_bodiesItem->setAntialiased(!m_crowded);
}

void WorldView::syncPoses()
{
    // A stopped world stays drawn, frozen where it last was in sight while it ran (in the
    // steps before it diverged its bodies may already fly far off): not gone, and its last
    // sane pose.
    const QRectF shown = mapToScene(viewport()->rect()).boundingRect();
    m_drawnRunning.resize(static_cast<std::size_t>(m_controller.variantCount()) + 1, false);
    syncMainPoses(shown);
    syncGhostPoses(shown);
    followContent();
    m_bodiesItem->update();
    m_overlays->refresh();
}

void WorldView::syncMainPoses(const QRectF& shown)
{
    const physics::World& main = m_controller.world();
    const bool mainFrozen = main.divergence() && m_drawnRunning[0];
    // A body that stands where it was drawn last keeps that pose: no sine and no cosine for the
    // ground or a resting pile.
    const bool known = m_itemPoses.size() == m_items.size();
    std::vector<Pose> poses(m_items.size());
    bool mainSane = !main.divergence();
    for (std::size_t i = 0; i < m_items.size(); ++i) {
        poses[i] = m_controller.drawPose(static_cast<physics::BodyId>(i),
                                         known ? &m_itemPoses[i] : nullptr);
        mainSane = mainSane && inSight(shown, poses[i].origin);
    }
    const bool keep = mainSane || !m_drawnRunning[0];
    if (keep)
        m_itemPoses.swap(poses);
    const std::vector<Pose>& drawn =
        keep || (mainFrozen && m_itemPoses.size() == poses.size()) ? m_itemPoses : poses;
    for (std::size_t i = 0; i < m_items.size(); ++i)
        m_items[i]->setPose(drawn[i].origin.x(), drawn[i].origin.y(), drawn[i].angle,
                            drawn[i].rotation);
    m_drawnRunning[0] = m_drawnRunning[0] || mainSane;
}

void WorldView::syncGhostPoses(const QRectF& shown)
{
    const std::size_t worlds = m_drawnRunning.size();
    std::vector<bool> sane(worlds, true);
    // Each ghost's placement once a frame (one sine and one cosine), for both passes.
    std::vector<physics::Transform> placed(m_ghosts.size());
    for (std::size_t k = 0; k < m_ghosts.size(); ++k) {
        const Ghost& g = m_ghosts[k];
        const physics::World& vw = m_controller.variant(g.variant);
        placed[k] = vw.body(g.body).transform();
        const physics::Vec2 o = placed[k].p + (g.variant + 1) * m_controller.variantOffset();
        const auto w = static_cast<std::size_t>(g.variant) + 1;
        sane[w] = sane[w] && !vw.divergence() && inSight(shown, o);
    }
    for (std::size_t k = 0; k < m_ghosts.size(); ++k) {
        Ghost& g = m_ghosts[k];
        const physics::World& vw = m_controller.variant(g.variant);
        const auto w = static_cast<std::size_t>(g.variant) + 1;
        const physics::Transform& t = placed[k];
        const physics::Vec2 shift = (g.variant + 1) * m_controller.variantOffset();
        if (sane[w] || !m_drawnRunning[w])
            g.pose = t;
        if (vw.divergence() && m_drawnRunning[w]) {
            const physics::Vec2 o = g.pose.p + shift;
            g.item->setPose(o.x(), o.y(), std::atan2(g.pose.q.s, g.pose.q.c), g.pose.q);
        } else {
            const physics::Vec2 o = t.p + shift;
            g.item->setPose(o.x(), o.y(), vw.body(g.body).angle, t.q);
        }
    }
    for (std::size_t w = 1; w < worlds; ++w)
        m_drawnRunning[w] = m_drawnRunning[w] || sane[w];
}

void WorldView::followContent()
{
    if (const int stopped = stoppedCount(); stopped != m_stoppedCount) {
        // A world stopped: what auto-fit widened to follow it is given back, so that the
        // worlds still running are shown as large as at the start.
        m_stoppedCount = stopped;
        if (m_autoFit && !m_startFit.isEmpty()) {
            m_fitted = m_startFit | (contentRect() & m_fitLimit);
            showRect(m_fitted);
        }
    }
    if (m_autoFit && m_fitOnRebuild && !m_fitted.isEmpty()) {
        // Follow bodies that leave the fitted area, by widening it (within the limit); not
        // while the scene is being edited, where the view holds still under the pen (a body
        // drawn outside the area would make everything jump).
        // Most frames every body lies well inside: said without the exact outlines.
        const QRectF wanted = contentWithin(m_fitted) ? m_fitted & m_fitLimit
                                                      : (m_fitted | contentRect()) & m_fitLimit;
        if (!m_fitted.contains(wanted)) {
            m_fitted |= wanted;
            showRect(m_fitted);
        } else if (legendHeight() != m_legendReserved) {
            showRect(m_fitted); // a world stopped: its legend line grew, the bodies move down
        }
    }
}

std::optional<physics::Transform> WorldView::frozenPose(int world, physics::BodyId body) const
{
    const auto w = static_cast<std::size_t>(world);
    if (w >= m_drawnRunning.size() || !m_drawnRunning[w] || !stoppedWorld(world))
        return std::nullopt;
    if (world == 0) {
        if (body < 0 || static_cast<std::size_t>(body) >= m_itemPoses.size())
            return std::nullopt;
        const Pose& pose = m_itemPoses[static_cast<std::size_t>(body)];
        physics::Transform t;
        t.p = pose.origin;
        t.q = pose.rotation;
        return t;
    }
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
    applyMinimumBodySize(); // in a crowd only the selected body is grown
    m_bodiesItem->update();
    emit bodySelected(m_selected);
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
    const int hit = bodyAt(event->pos());
    if (hit < 0) {
        m_panning = true;
        setCursor(Qt::ClosedHandCursor);
        return;
    }
    selectBody(hit);
    m_autoFit = false; // the view must hold still under the hand that drags
    m_controller.grab(hit, toWorld(event->pos()));
    if (m_controller.grabSpring().body())
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
    if (m_controller.grabSpring().body()) {
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

} // namespace rigidlab::ui
