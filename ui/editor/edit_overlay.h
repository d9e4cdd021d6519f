// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What Edit mode draws over the world: the grid, the selected body's outline and rotate
// handle and velocity arrow, overlapping bodies, and the shape, pin or spring being drawn with its
// size.

#include <QGraphicsItem>

namespace rigidlab::ui {

class EditTools;

class EditOverlay : public QGraphicsItem {
public:
    explicit EditOverlay(const EditTools& tools);

    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    /// The selected body's velocity arrow (editor/velocity_arrow.h), its speed while dragged.
    void paintVelocity(QPainter* painter, double zoom) const;

    const EditTools& m_tools;
};

} // namespace rigidlab::ui
