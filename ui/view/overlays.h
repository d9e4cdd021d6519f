// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The teaching overlays, drawn over the bodies from the controller's current state:
// velocity vectors, contact points and normals, bounding boxes, centres of mass, motion
// trails, springs and joints. Each can be switched on and off.

#include "rigidlab/physics/world.h"

#include <QGraphicsItem>
#include <QPolygonF>

#include <deque>
#include <functional>
#include <optional>
#include <vector>

namespace rigidlab::ui {

class RunView;

enum class Overlay { Velocities, Contacts, BoundingBoxes, CentresOfMass, Trails, SpringsJoints };
inline constexpr int kOverlayCount = 6;

class OverlayItem : public QGraphicsItem {
public:
    explicit OverlayItem(const RunView& run);

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

    /// A spring's zigzag from a to b (scene coordinates [m]) for a view at px metres per
    /// pixel, drawn with a pen penPx wide: at most 12 turns, fewer where the spring is short
    /// on screen, so that its coils stay apart even with presentation mode's thick lines
    /// (each half-turn at least 2.5 pen widths along the spring, its amplitude growing
    /// with the pen).
    static QPolygonF springZigzag(const QPointF& a, const QPointF& b, double px, double penPx);

    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    void paintTrails(QPainter* p) const;
    void paintBoundingBoxes(QPainter* p) const;
    /// Springs, pin joints and the grab line, of the main world and the compared ones.
    void paintSpringsJoints(QPainter* p, double px) const;
    void paintCentresOfMass(QPainter* p, double px) const;
    void paintVelocities(QPainter* p, double px) const;
    void paintContacts(QPainter* p, double px) const;
    /// A body's pose as drawn in world w (0 the main one, v + 1 compared world v).
    physics::Transform drawnTransform(int w, const physics::World& in, physics::BodyId id) const;

    const RunView& m_run;
    bool m_on[kOverlayCount] = {false, false, false, false, false, true};
    std::vector<std::deque<QPointF>> m_trails; ///< bounded, per body
    QRectF m_bounds;
    FrozenPose m_frozen;
};

} // namespace rigidlab::ui
