// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What Edit mode draws over the world: the grid, the selected body's outline and rotate
// handle and velocity arrow, overlapping bodies, the shape, pin or spring being drawn with its
// size, and where the pointer snaps to another body.

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
    /// The selected body's velocity arrow (editor/velocity_arrow.h), its speed while dragged.
    void paintVelocity(QPainter* painter, double zoom) const;
    static void drawSnapMarker(QPainter* painter, const Snap& snap, double zoom);

    const EditTools& m_tools;
};

} // namespace rigidlab::ui
