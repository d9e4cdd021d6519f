// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What Edit mode draws over the world: the grid, overlapping bodies, the selected body's
// outline, rotate handle and velocity arrow, the selected spring, what the tool in use draws
// (the shape, pin or spring being drawn, with its size) and where the pointer snaps to
// another body.

#include <QGraphicsItem>

namespace rigidlab::ui {

class EditTools;
struct Snap;

class EditOverlay : public QGraphicsItem {
public:
    explicit EditOverlay(const EditTools& tools);

    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    /// The grid, as dots at its crossings, where snapping puts points.
    void paintGrid(QPainter& painter, const QWidget* widget) const;
    /// Overlapping bodies, shown before the scene runs.
    void paintOverlaps(QPainter& painter) const;
    /// The selected body: its outline, its origin, the rotate handle and the velocity arrow.
    void paintSelectedBody(QPainter& painter, double zoom) const;
    void paintSelectedSpring(QPainter& painter) const;
    static void paintSnapMarker(QPainter& painter, const Snap& snap, double zoom);

    const EditTools& m_tools;
};

} // namespace rigidlab::ui
