// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/empty_stage.h"

#include "simulation/simulation_controller.h"
#include "view/world_view.h"

#include "run/swept_bounds.h"

#include <QRectF>

namespace rigidlab::ui {

namespace {

/// Whether a moving body of `world`, drawn `shift` [m] away, lies in `shown` [m].
bool movingBodyIn(const physics::World& world, const physics::Vec2& shift, const QRectF& shown)
{
    for (const physics::Body& body : world.bodies())
        if (body.moves() &&
            shown.intersects(lessons::bodyBounds(body).translated(shift.x(), shift.y())))
            return true;
    return false;
}

} // namespace

EmptyStageWatch::EmptyStageWatch(SimulationController& controller, const WorldView& view,
                                 std::function<bool()> watching, std::function<void(double)> tell,
                                 QObject* parent)
    : QObject(parent), m_controller(controller), m_view(view), m_watching(std::move(watching)),
      m_tell(std::move(tell))
{
    connect(&controller, &SimulationController::frameAdvanced, this, &EmptyStageWatch::afterFrame);
}

bool EmptyStageWatch::anyMovingBodyInSight() const
{
    // A view not shown (a window made for a test, never shown) shows nothing to leave.
    if (!m_view.isVisible() || m_view.viewport()->rect().isEmpty())
        return true;
    const QRect pixels = m_view.viewport()->rect();
    const physics::Vec2 a = m_view.worldAt(pixels.topLeft());
    const physics::Vec2 b = m_view.worldAt(pixels.bottomRight());
    const QRectF shown = QRectF(QPointF(a.x(), a.y()), QPointF(b.x(), b.y())).normalized();
    const SimulationController& c = m_controller;
    if (movingBodyIn(c.world(), physics::Vec2::Zero(), shown))
        return true;
    for (int v = 0; v < c.variantCount(); ++v)
        if (movingBodyIn(c.variant(v), (v + 1) * c.variantOffset(), shown))
            return true;
    return false;
}

void EmptyStageWatch::afterFrame()
{
    const double t = m_controller.world().time();
    if (!m_watching()) {
        m_seenAt = -1;
        m_paused = false;
        return;
    }
    // Back before the moment it paused (Reset, a step back, another step): watched again.
    if (m_paused && t < m_pausedAt)
        m_paused = false;
    if (t < m_seenAt)
        m_seenAt = -1;
    if (!m_controller.isRunning() || m_paused)
        return;
    if (anyMovingBodyInSight()) {
        m_seenAt = t;
        return;
    }
    // Only bodies that were seen and left: a scene whose bodies start out of sight (the view
    // panned away) is not emptied by its run.
    if (m_seenAt < 0)
        return;
    m_paused = true;
    m_pausedAt = t;
    m_controller.setRunning(false);
    m_tell(t);
}

} // namespace rigidlab::ui
