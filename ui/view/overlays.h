// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The teaching overlays, drawn over the bodies from the controller's current state:
// velocity vectors, contact points and normals, bounding boxes, centres of mass, motion
// trails, springs and joints. Each can be switched on and off.

#include "rigidlab/physics/world.h"

#include <QGraphicsItem>

#include <deque>
#include <functional>
#include <optional>
#include <vector>

namespace rigidlab::ui {

class SimulationController;

enum class Overlay { Velocities, Contacts, BoundingBoxes, CentresOfMass, Trails, SpringsJoints };
inline constexpr int kOverlayCount = 6;

class OverlayItem : public QGraphicsItem {
public:
    explicit OverlayItem(const SimulationController& controller);

    void setEnabled(Overlay overlay, bool on);
    bool isEnabled(Overlay overlay) const { return m_on[static_cast<int>(overlay)]; }
    /// Reads the current state (after steps): trails grow, the item repaints.
    void refresh();
    void clearTrails();

    /// Shortest velocity arrow drawn [px]: below it the arrow would be a dot whose direction
    /// is noise (a body at rest moves at 1e-19 m/s, in any direction).
    static constexpr double kMinArrowPixels = 3.0;
    /// Whether a body moving at `velocity` [m/s] gets its arrow at this zoom [m per px].
    static bool velocityArrowShown(const physics::Vec2& velocity, double metresPerPixel);

    /// Where a body of a stopped world is drawn (world 0 the main one, v + 1 compared world
    /// v): its pose before it stopped, or nullopt to draw it where it is now. Springs and
    /// joints follow it, instead of reaching for a body flown a billion metres away.
    using FrozenPose = std::function<std::optional<physics::Transform>(int, physics::BodyId)>;
    void setFrozenPose(FrozenPose frozen) { m_frozen = std::move(frozen); }

    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    const SimulationController& m_controller;
    bool m_on[kOverlayCount] = {false, false, false, false, false, true};
    std::vector<std::deque<QPointF>> m_trails; ///< bounded, per body
    QRectF m_bounds;
    FrozenPose m_frozen;
};

} // namespace rigidlab::ui
