#pragma once
// The teaching overlays, drawn over the bodies from the controller's current state:
// velocity vectors, contact points and normals, bounding boxes, centres of mass, motion
// trails, springs and joints. Each can be switched on and off.

#include "rigidlab/physics/world.h"

#include <QGraphicsItem>

#include <deque>
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

    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    const SimulationController& m_controller;
    bool m_on[kOverlayCount] = {false, false, false, false, false, true};
    std::vector<std::deque<QPointF>> m_trails; ///< bounded, per body
    QRectF m_bounds;
};

} // namespace rigidlab::ui
