// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the SAT panel draws in the world view: the axis being shown as a line beside both
// shapes, each shape's projection interval on it, the gap or overlap between them (bold, in a
// colour of its own, labelled with its length), and at the end the contact normal and points.
// The geometry is computed in one place (SatOverlayItem::geometry) so that painting, the
// bounding rect, the view's fit and the tests all use the same numbers.
//
//              gap 0.14 m                       label, beyond B's interval
//          ════════            B's interval     8 px past the line
//   - - - - - - - ▬▬▬ - - - - - - - - - - -     the axis (dashed), the gap/overlap on it
//    ════════════                               A's interval, 8 px before the line
//         :        :                            guides back across the shapes
//       [shapes]                                the line lies 40 px beside them

#include "rigidlab/physics/sat.h"

#include <QCoreApplication>
#include <QFont>
#include <QGraphicsItem>
#include <QLineF>
#include <QRectF>
#include <QString>

#include <functional>

namespace rigidlab::ui {

class SatViewModel;

class SatOverlayItem : public QGraphicsItem {
    Q_DECLARE_TR_FUNCTIONS(SatOverlayItem)
public:
    enum { Type = UserType + 40 };

    /// Everything drawn for the axis being shown, in scene (world) coordinates [m], for a
    /// view showing `px` metres per pixel (offsets and text are sized in pixels).
    struct Geometry {
        bool valid = false;
        QLineF axisLine;      ///< the axis, a little longer than both projections
        QLineF projectionA;   ///< A's interval [minA, maxA] on the axis, on A's side of the line
        QLineF projectionB;   ///< B's interval, on the other side
        QLineF span;          ///< the gap or overlap between the intervals, on the line
        bool gap = false;     ///< whether `span` is a gap (the axis separates)
        QString label;        ///< its length, what this axis is, and the verdict at the end
        QRectF labelRect;     ///< where the label's box is drawn
        bool contact = false; ///< the contact normal and points are drawn (overlap, at the end)
        QRectF shapes;        ///< both shapes' outlines
        QRectF drawn;         ///< everything above (shapes included)
    };

    /// Draws what `model` holds; the model outlives the item or detach() is called first.
    explicit SatOverlayItem(const SatViewModel& model);
    ~SatOverlayItem() override;
    /// Called when the item is deleted (by its scene, when the scene goes first).
    void setOnDestroyed(std::function<void()> f) { m_onDestroyed = std::move(f); }
    /// From now on the item draws nothing and reads nothing of the model (whose controller
    /// or itself is being destroyed while the item may still be asked for its bounds).
    void detach()
    {
        prepareGeometryChange();
        m_detached = true;
    }
    int type() const override { return Type; }
    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

    /// The geometry for a view at `px` metres per pixel.
    Geometry geometry(double px) const;
    /// The font of the view showing the item (larger in presentation mode).
    QFont viewFont() const;
    /// The geometry in the view that shows this item now (for tests and the panel's fit).
    Geometry geometry() const { return geometry(pixelSize()); }
    /// Metres per pixel of the first view showing the scene (0.01 without one).
    double pixelSize() const;
    /// Call before the data drawn changes (the panel that changes the model does).
    void dataChanging() { prepareGeometryChange(); }

private:
    void paintHulls(QPainter* painter, double px) const;
    QRectF hullRect() const;
    const SatViewModel& m_model;
    std::function<void()> m_onDestroyed;
    bool m_detached = false;
};

} // namespace rigidlab::ui
