// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/sat_overlay.h"

#include "common/theme.h"
#include "simulation/run_view.h"
#include "view/sat_view_model.h"

#include <QFontMetricsF>
#include <QGraphicsScene>
#include <QGraphicsView>
#include <QLocale>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace rigidlab::ui {

namespace {

// Sizes on screen [px]: the line lies this far beside the shapes, each interval this far
// off the line, drawn this thick; the gap or overlap is drawn bolder than 4 px, to stand out from
// the intervals.
constexpr double kLineOffset = 40.0;
constexpr double kIntervalOffset = 8.0;
constexpr double kIntervalWidth = 7.0;
constexpr double kSpanWidth = 6.0;
constexpr double kLabelPadding = 4.0;
constexpr double kLabelSlack = 4.0; ///< [px]
constexpr double kArrowLength = 50.0;
/// Labels wrap at this width [px], so that they fit beside the shapes in a narrow view.
constexpr double kLabelWidth = 150.0;
constexpr int kLabelFlags = Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap;

QPointF qt(const physics::Vec2& v)
{
    return {v.x(), v.y()};
}

QPen pen(QColor c, double w, Qt::PenStyle s = Qt::SolidLine)
{
    QPen p(c, w, s);
    p.setCosmetic(true);
    p.setCapStyle(Qt::FlatCap);
    return p;
}

/// The view's font, bold. Measured and painted with the same, fully resolved font: QPainter
/// resolves a default QFont() against the view's, which presentation mode makes 1.5 times
/// larger, and a box measured with the application's font then cut the label's end ("m").
QFont labelFont(const QFont& viewFont)
{
    QFont f = viewFont;
    f.setBold(true);
    return f;
}

/// The scene rect of a text box of `text` whose side nearest `anchor` touches it, placed
/// from the anchor along the unit scene direction `dir`, for a view at px metres per pixel
/// (y up in the scene, down on screen).
QRectF labelBox(const QString& text, const QFont& font, const QPointF& anchor, const QPointF& dir,
                double px)
{
    const QSizeF size =
        QFontMetricsF(font).boundingRect(QRectF(0, 0, kLabelWidth, 1e4), kLabelFlags, text).size() +
        // A little slack: text painted on the screen may lay out a pixel wider than measured
        // here, and its last word ("m") then wrapped onto a line the box had no room for.
        QSizeF(2 * kLabelPadding + kLabelSlack, 2 * kLabelPadding);
    // The box's half extent along dir, so that its centre sits that far past the anchor.
    const double d =
        0.5 * size.width() * std::abs(dir.x()) + 0.5 * size.height() * std::abs(dir.y());
    const QPointF centre = anchor + d * px * dir;
    const QSizeF world = size * px;
    return QRectF(centre - QPointF(world.width(), world.height()) / 2, world);
}

void drawLabel(QPainter* p, const QString& text, const QFont& font, const QRectF& sceneRect,
               const QColor& colour)
{
    const QRectF device = p->worldTransform().mapRect(sceneRect);
    p->save();
    p->resetTransform();
    p->setPen(pen(colour, 1.0));
    p->setBrush(theme::worldLabelBox());
    p->drawRect(device);
    p->setFont(font);
    p->drawText(device.adjusted(kLabelPadding, kLabelPadding, -kLabelPadding, -kLabelPadding),
                kLabelFlags, text);
    p->restore();
}

QRectF lineRect(const QLineF& l, double halfWidth)
{
    return QRectF(l.p1(), l.p2())
        .normalized()
        .adjusted(-halfWidth, -halfWidth, halfWidth, halfWidth);
}

/// The polygon's vertices, or none for another kind of shape: the overlay draws polygons only,
/// and a new scene may be in place before the panel is told its new pair.
const std::vector<physics::Vec2>& polygonVertices(const physics::Shape& shape)
{
    static const std::vector<physics::Vec2> kNone;
    const physics::Polygon* polygon = shape.asPolygon();
    return polygon ? polygon->vertices : kNone;
}

} // namespace

SatOverlayItem::SatOverlayItem(const SatViewModel& model) : m_model(model)
{
    setZValue(20);
    setAcceptedMouseButtons(Qt::NoButton);
}

SatOverlayItem::~SatOverlayItem()
{
    if (m_onDestroyed)
        m_onDestroyed();
}

double SatOverlayItem::pixelSize() const
{
    if (scene() && !scene()->views().isEmpty()) {
        const double s = std::abs(scene()->views().first()->transform().m11());
        if (s > 1e-9 && std::isfinite(s))
            return 1.0 / s;
    }
    return 0.01;
}

QFont SatOverlayItem::viewFont() const
{
    return scene() && !scene()->views().isEmpty() ? scene()->views().constFirst()->font() : QFont();
}

SatOverlayItem::Geometry SatOverlayItem::geometry(double px) const
{
    Geometry g;
    if (m_detached || !m_model.active())
        return g;
    const physics::SatResult& r = m_model.result();
    const int total = static_cast<int>(r.axes.size());
    const int shown = std::min(m_model.shown(), total);
    if (shown <= 0)
        return g;
    // The ids are checked against the world: a new scene may be in place before the panel
    // is told its new pair.
    const auto& world = m_model.run().world();
    for (const int id : {m_model.bodyA(), m_model.bodyB()})
        if (id < 0 || id >= static_cast<int>(world.bodies().size()) ||
            polygonVertices(world.body(id).shape).empty())
            return g;
    const int index = shown - 1;
    const physics::SatAxis& ax = r.axes[static_cast<std::size_t>(index)];
    const physics::Vec2 n = ax.axis;
    const physics::Vec2 t(-n.y(), n.x());

    // The line lies beside the two shapes tested (not the rest of the scene), past their
    // farthest point along t.
    double tMax = -1e300;
    for (const int id : {m_model.bodyA(), m_model.bodyB()}) {
        const physics::Body& b = world.body(id);
        const physics::Transform xf = b.transform();
        for (const auto& v : polygonVertices(b.shape)) {
            const physics::Vec2 w = xf.apply(v);
            tMax = std::max(tMax, t.dot(w));
            g.shapes |= QRectF(qt(w), QSizeF(1e-9, 1e-9));
        }
    }
    const double lineT = tMax + kLineOffset * px;
    auto onAxis = [&](double s, double offsetPx) {
        return qt(s * n + (lineT + offsetPx * px) * t);
    };
    const double sLo = std::min(ax.minA, ax.minB), sHi = std::max(ax.maxA, ax.maxB);
    const double reach = 0.1 * (sHi - sLo) + 20 * px;
    g.axisLine = QLineF(onAxis(sLo - reach, 0), onAxis(sHi + reach, 0));
    g.projectionA = QLineF(onAxis(ax.minA, -kIntervalOffset), onAxis(ax.maxA, -kIntervalOffset));
    g.projectionB = QLineF(onAxis(ax.minB, kIntervalOffset), onAxis(ax.maxB, kIntervalOffset));
    const double lo = std::max(ax.minA, ax.minB), hi = std::min(ax.maxA, ax.maxB);
    g.span = QLineF(onAxis(std::min(lo, hi), 0), onAxis(std::max(lo, hi), 0));
    g.gap = ax.overlap < 0;
    g.valid = true;

    const QLocale locale;
    g.label = (g.gap ? tr("gap %1 m") : tr("overlap %1 m"))
                  .arg(locale.toString(std::abs(ax.overlap), 'f', 2));
    const bool complete = shown == total;
    if (index == r.separatingAxis)
        g.label += QLatin1Char('\n') + tr("separating axis: no collision");
    else if (complete && r.intersects && index == r.leastAxis)
        g.label += QLatin1Char('\n') + tr("least overlap: this is the contact normal");
    else if (complete && r.intersects)
        // One box for everything, so that it fits beside the shapes in a narrow view.
        g.label += QLatin1Char('\n') +
                   tr("least overlap: axis %1, the contact normal (arrow)").arg(r.leastAxis + 1);
    const QPointF mid = onAxis(0.5 * (lo + hi), kIntervalOffset + kIntervalWidth / 2 + 6);
    g.labelRect = labelBox(g.label, labelFont(viewFont()), mid, qt(t), px);

    g.drawn = g.shapes | lineRect(g.axisLine, 2 * px) |
              lineRect(g.projectionA, kIntervalWidth / 2 * px) |
              lineRect(g.projectionB, kIntervalWidth / 2 * px) | g.labelRect;
    if (complete && r.intersects && r.manifold.pointCount > 0) {
        const QPointF normal = qt(r.normal);
        QRectF arrows;
        for (int i = 0; i < r.manifold.pointCount; ++i) {
            const QPointF c = qt(r.manifold.points[static_cast<std::size_t>(i)].point);
            arrows |= QRectF(c, c + normal * (kArrowLength * px)).normalized();
        }
        g.drawn |= arrows.adjusted(-6 * px, -6 * px, 6 * px, 6 * px);
        g.contact = true;
    }
    return g;
}

QRectF SatOverlayItem::hullRect() const
{
    QRectF box;
    if (m_detached)
        return box;
    const auto& scene = m_model.run().scene();
    const auto& world = m_model.run().world();
    for (std::size_t i = 0; i < scene.originalVertices.size() && i < world.bodies().size(); ++i) {
        if (scene.originalVertices[i].empty())
            continue;
        const physics::Body& b = world.bodies()[i];
        const physics::Transform xf = b.transform();
        for (const auto& v : polygonVertices(b.shape))
            box |= QRectF(qt(xf.apply(v)), QSizeF(1e-9, 1e-9));
    }
    return box;
}

QRectF SatOverlayItem::boundingRect() const
{
    const double px = pixelSize();
    const QRectF box = geometry(px).drawn | hullRect();
    // Room for the pens' widths and the text's antialiasing.
    return box.isNull() ? box : box.adjusted(-8 * px, -8 * px, 8 * px, 8 * px);
}

void SatOverlayItem::paintHulls(QPainter* p, double px) const
{
    // A body whose outline was not convex is handled as its convex hull (the paper's
    // caveat): shade the area the hull adds, where contacts are found wrongly.
    const auto& scene = m_model.run().scene();
    const auto& world = m_model.run().world();
    for (std::size_t i = 0; i < scene.originalVertices.size() && i < world.bodies().size(); ++i) {
        const auto& original = scene.originalVertices[i];
        if (original.empty())
            continue;
        const physics::Body& b = world.bodies()[i];
        const physics::Transform xf = b.transform();
        QPolygonF hull, outline;
        for (const auto& v : polygonVertices(b.shape))
            hull << qt(xf.apply(v));
        for (const auto& v : original)
            outline << qt(xf.apply(v));
        QPainterPath wrong;
        wrong.addPolygon(hull);
        QPainterPath inside;
        inside.addPolygon(outline);
        wrong = wrong.subtracted(inside);
        QBrush hatch(QColor(200, 30, 30, 150), Qt::FDiagPattern);
        hatch.setTransform(QTransform::fromScale(px, px));
        p->setPen(Qt::NoPen);
        p->setBrush(hatch);
        p->drawPath(wrong);
        p->setBrush(Qt::NoBrush);
        p->setPen(pen(QColor(30, 30, 30), 2.0, Qt::DashLine));
        p->drawPolygon(outline);
    }
}

void SatOverlayItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*)
{
    const double px = 1.0 / std::max(1e-9, std::abs(p->worldTransform().m11()));
    if (m_detached)
        return;
    p->setRenderHint(QPainter::Antialiasing);
    paintHulls(p, px);
    const Geometry g = geometry(px);
    if (!g.valid)
        return;
    const physics::SatResult& r = m_model.result();
    const int shown = std::min<int>(m_model.shown(), static_cast<int>(r.axes.size()));
    const physics::SatAxis& ax = r.axes[static_cast<std::size_t>(shown - 1)];
    const QPointF n = qt(ax.axis), t(-n.y(), n.x());

    p->setPen(pen(theme::satAxis(), 1.5, Qt::DashLine));
    p->drawLine(g.axisLine);
    p->setPen(pen(theme::satProjectionA(), kIntervalWidth));
    p->drawLine(g.projectionA);
    p->setPen(pen(theme::satProjectionB(), kIntervalWidth));
    p->drawLine(g.projectionB);
    // Guides from the interval ends back across the shapes.
    p->setPen(pen(QColor(120, 120, 120, 140), 1.0, Qt::DotLine));
    const double back = QPointF::dotProduct(g.axisLine.p1() - g.shapes.center(), t) +
                        0.5 * (g.shapes.width() + g.shapes.height());
    for (const QPointF& e :
         {g.projectionA.p1(), g.projectionA.p2(), g.projectionB.p1(), g.projectionB.p2()})
        p->drawLine(e, e - back * t);
    // The gap or overlap, bold, with ticks at its ends so that a short one still shows.
    const QColor spanColour = g.gap ? theme::satGap() : theme::satOverlap();
    p->setPen(pen(spanColour, kSpanWidth));
    p->drawLine(g.span);
    const QPointF tick = t * (2 * kIntervalOffset * px);
    p->setPen(pen(spanColour, 2.0));
    p->drawLine(g.span.p1() - tick, g.span.p1() + tick);
    p->drawLine(g.span.p2() - tick, g.span.p2() + tick);
    // The edge the axis comes from, thick, in its polygon's colour.
    {
        const auto& world = m_model.run().world();
        const physics::Body& owner = world.body(ax.owner == 0 ? m_model.bodyA() : m_model.bodyB());
        const auto& v = polygonVertices(owner.shape);
        const physics::Transform xf = owner.transform();
        const std::size_t e = static_cast<std::size_t>(ax.edge);
        if (e < v.size()) {
            p->setPen(pen(ax.owner == 0 ? theme::satProjectionA() : theme::satProjectionB(), 5.0));
            p->drawLine(qt(xf.apply(v[e])), qt(xf.apply(v[(e + 1) % v.size()])));
        }
    }

    // Verdict geometry, once every axis has been shown.
    if (g.contact) {
        p->setPen(pen(theme::satOverlap(), 2.5));
        const QPointF u = qt(r.normal), v(-u.y(), u.x());
        for (int i = 0; i < r.manifold.pointCount; ++i) {
            const QPointF c = qt(r.manifold.points[static_cast<std::size_t>(i)].point);
            p->setBrush(theme::satOverlap());
            p->drawEllipse(c, 5 * px, 5 * px);
            const QPointF tip = c + u * (kArrowLength * px);
            p->drawLine(c, tip);
            p->drawLine(tip, tip - 10 * px * u + 5 * px * v);
            p->drawLine(tip, tip - 10 * px * u - 5 * px * v);
        }
    }
    drawLabel(p, g.label, labelFont(viewFont()), g.labelRect, spanColour);
}

} // namespace rigidlab::ui
