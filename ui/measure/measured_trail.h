// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The measured positions drawn faintly in the scene view as small crosses, where the body
// was seen in the experiment: the lab's own trail (View › Trails) can be laid beside it.

#include <QGraphicsItem>
#include <QPointF>

#include <vector>

namespace rigidlab::ui {

class MeasuredTrailItem : public QGraphicsItem {
public:
    MeasuredTrailItem();

    /// The positions in scene coordinates [m], y up as the view draws them.
    void setPoints(std::vector<QPointF> points);
    const std::vector<QPointF>& points() const { return m_points; }

    /// Half the size of a cross on screen [px].
    static constexpr double kCrossPx = 3.0;

    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    std::vector<QPointF> m_points;
    QRectF m_bounds;
};

} // namespace rigidlab::ui
