// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Every body of the view painted by one graphics item, in one pass over the bodies' poses.
// One item each made the scene set up a transform, a bounding box, a style option and a
// painter state for every body in every frame: with the 5,050 boxes of the base-100 pyramid
// that was most of the frame (docs/performance.md, "In the window"). The bodies' own items
// (body_item.h) stay outside the scene and keep the geometry for picking and the screen
// reader. A body two or three pixels across is drawn as a dot (level of detail); the
// selected one always whole, over the others.

#include <QGraphicsItem>

#include <vector>

namespace rigidlab::ui {

class BodyItem;

class BodiesItem : public QGraphicsItem {
public:
    enum { Type = UserType + 2 };
    BodiesItem();

    int type() const override { return Type; }
    /// The bodies to paint, in the order they are painted (the later over the earlier). The
    /// items belong to the view and must outlive their use here.
    void setBodies(std::vector<const BodyItem*> inOrder);
    /// Smooth edges (the default). A scene of hundreds of bodies draws them without: each is
    /// a few pixels across, and antialiasing them took a large part of a frame.
    void setAntialiased(bool on);
    bool antialiased() const { return m_antialiased; }

    /// The whole scene: bodies may be anywhere, and the view repaints all of itself anyway.
    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    /// One body drawn in full in its frame; `toDevice` maps the scene [m] to the device.
    static void paintWhole(QPainter& painter, const BodyItem& body, const QTransform& toDevice);

    std::vector<const BodyItem*> m_bodies;
    bool m_antialiased = true;
};

} // namespace rigidlab::ui
