// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/overlays.h"

#include "common/theme.h"

#include "simulation/grab_spring.h"
#include "simulation/run_view.h"

#include "rigidlab/physics/touching.h"

#include <QPainter>
#include <QStyleOptionGraphicsItem>

#include <algorithm>
#include <cmath>

namespace rigidlab::ui {

namespace {

constexpr std::size_t kTrailLength = 600;      // points per body
constexpr double kVelocityArrowSeconds = 0.25; // an arrow shows the distance covered in this

QPointF toQt(const physics::Vec2& v)
{
    return {v.x(), v.y()};
}

QPen cosmeticPen(QColor c, double width, Qt::PenStyle style = Qt::SolidLine)
{
    QPen p(c, theme::lineWidth(width), style);
    p.setCosmetic(true);
    return p;
}

/// An arrow from a to b, its head `head` metres long.
void drawArrow(QPainter* p, QPointF a, QPointF b, double head)
{
    p->drawLine(a, b);
    const QPointF d = b - a;
    const double len = std::hypot(d.x(), d.y());
    if (len < 1e-9)
        return;
    const QPointF u = d / len, n(-u.y(), u.x());
    const double h = std::min(head, 0.4 * len);
    p->drawLine(b, b - h * u + 0.5 * h * n);
    p->drawLine(b, b - h * u - 0.5 * h * n);
}

} // namespace

OverlayItem::OverlayItem(const RunView& run) : m_run(run), m_bounds(-1e5, -1e5, 2e5, 2e5)
{
    setZValue(10);
    setAcceptedMouseButtons(Qt::NoButton);
}

void OverlayItem::setEnabled(Overlay overlay, bool on)
{
    m_on[static_cast<int>(overlay)] = on;
    if (overlay == Overlay::Trails && !on)
        clearTrails();
    update();
}

bool OverlayItem::velocityArrowShown(const physics::Vec2& velocity, double metresPerPixel)
{
    const double lengthPx = velocity.norm() * kVelocityArrowSeconds / metresPerPixel;
    return std::isfinite(lengthPx) && lengthPx >= kMinArrowPixels;
}

void OverlayItem::clearTrails()
{
    m_trails.clear();
    update();
}

void OverlayItem::refresh()
{
    if (isEnabled(Overlay::Trails)) {
        const auto& bodies = m_run.world().bodies();
        m_trails.resize(bodies.size());
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            if (!bodies[i].isDynamic())
                continue;
            const QPointF p = toQt(bodies[i].position);
            auto& trail = m_trails[i];
            if (trail.empty() || trail.back() != p)
                trail.push_back(p);
            while (trail.size() > kTrailLength)
                trail.pop_front();
        }
    }
    update();
}

QRectF OverlayItem::boundingRect() const
{
    return m_bounds;
}

QPolygonF OverlayItem::springZigzag(const QPointF& a, const QPointF& b, double px, double penPx)
{
    QPolygonF zig;
    const QPointF d = b - a;
    const double len = std::hypot(d.x(), d.y());
    zig << a;
    if (len < 1e-9 || !(px > 0)) {
        zig << b;
        return zig;
    }
    const QPointF n(-d.y() / len, d.x() / len);
    // Neighbouring strokes lie a half-turn apart along the spring; steep, each takes a little
    // more than a pen's width of it, so 2.5 pen widths per half-turn leave more than a pen's
    // width of background between them.
    constexpr int kMostTurns = 12;
    constexpr double kHalfTurnPens = 2.5;
    const double lengthPx = len / px;
    const int turns =
        std::clamp(static_cast<int>(lengthPx / (2 * kHalfTurnPens * penPx)), 1, kMostTurns);
    const double amp = std::min(0.08 * len, 12 * px) + std::max(4.0, 2 * penPx) * px;
    for (int i = 1; i < 2 * turns; ++i)
        zig << a + d * (i / (2.0 * turns)) + n * (i % 2 ? amp : -amp);
    zig << b;
    return zig;
}

physics::Transform OverlayItem::drawnTransform(int w, const physics::World& in,
                                               physics::BodyId id) const
{
    if (m_frozen)
        if (const auto frozen = m_frozen(w, id))
            return *frozen;
    return in.body(id).transform();
}

void OverlayItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*)
{
    // Metres per screen pixel, to size markers in pixels.
    const double px = 1.0 / std::max(1e-9, std::abs(p->worldTransform().m11()));
    p->setRenderHint(QPainter::Antialiasing);
    if (isEnabled(Overlay::Trails))
        paintTrails(p);
    if (isEnabled(Overlay::BoundingBoxes))
        paintBoundingBoxes(p);
    if (isEnabled(Overlay::SpringsJoints))
        paintSpringsJoints(p, px);
    if (isEnabled(Overlay::CentresOfMass))
        paintCentresOfMass(p, px);
    if (isEnabled(Overlay::Velocities))
        paintVelocities(p, px);
    if (isEnabled(Overlay::Contacts))
        paintContacts(p, px);
}

void OverlayItem::paintTrails(QPainter* p) const
{
    p->setPen(cosmeticPen(QColor(90, 90, 160, 150), 1.5));
    for (const auto& trail : m_trails) {
        if (trail.size() < 2)
            continue;
        QPolygonF line(trail.begin(), trail.end());
        p->drawPolyline(line);
    }
}

void OverlayItem::paintBoundingBoxes(QPainter* p) const
{
    p->setPen(cosmeticPen(QColor(120, 120, 120), 1.0, Qt::DashLine));
    p->setBrush(Qt::NoBrush);
    for (const physics::Body& b : m_run.world().bodies()) {
        const physics::Transform xf = b.transform();
        QRectF box;
        b.shape.visit(physics::Overloaded{[&](const physics::Circle& circle) {
                                              const QPointF c = toQt(xf.apply(circle.center));
                                              const double r = circle.radius;
                                              box = QRectF(c - QPointF(r, r), c + QPointF(r, r));
                                          },
                                          [&](const physics::Polygon& polygon) {
                                              QPolygonF poly;
                                              for (const auto& v : polygon.vertices)
                                                  poly << toQt(xf.apply(v));
                                              box = poly.boundingRect();
                                          }});
        p->drawRect(box);
    }
}

void OverlayItem::paintSpringsJoints(QPainter* p, double px) const
{
    const physics::World& world = m_run.world();
    auto centreOf = [&](int w, const physics::World& in, physics::BodyId id) {
        return drawnTransform(w, in, id).apply(in.body(id).localCenter);
    };
    auto anchor = [&](physics::BodyId id, const physics::Vec2& a) {
        return id == physics::kWorld ? toQt(a) : toQt(drawnTransform(0, world, id).apply(a));
    };
    // The compared worlds' joints too, where their ghosts are drawn.
    for (int v = 0; v < m_run.variantCount(); ++v) {
        const physics::World& vw = m_run.variant(v);
        const physics::Vec2 shift = (v + 1) * m_run.variantOffset();
        auto end = [&](physics::BodyId id, const physics::Vec2& a) {
            return toQt((id == physics::kWorld ? a : drawnTransform(v + 1, vw, id).apply(a)) +
                        shift);
        };
        p->setPen(cosmeticPen(QColor(120, 120, 120), 1.5));
        for (const physics::PinJointDef& j : vw.joints()) {
            const QPointF pin = end(j.a, j.anchorA);
            if (j.a != physics::kWorld)
                p->drawLine(pin, toQt(centreOf(v + 1, vw, j.a) + shift));
            p->drawEllipse(pin, 3 * px, 3 * px);
        }
        for (const physics::SpringDef& sp : vw.springs())
            p->drawLine(end(sp.a, sp.anchorA), end(sp.b, sp.anchorB));
    }
    const QPen springPen = cosmeticPen(QColor(60, 60, 60), 1.5);
    p->setPen(springPen);
    for (const physics::SpringDef& s : world.springs())
        p->drawPolyline(
            springZigzag(anchor(s.a, s.anchorA), anchor(s.b, s.anchorB), px, springPen.widthF()));
    for (const physics::PinJointDef& j : world.joints()) {
        const QPointF pin = anchor(j.a, j.anchorA);
        p->setPen(cosmeticPen(QColor(40, 40, 40), 2.0));
        if (j.a != physics::kWorld)
            p->drawLine(pin, toQt(centreOf(0, world, j.a)));
        if (j.b != physics::kWorld)
            p->drawLine(pin, toQt(centreOf(0, world, j.b)));
        p->setBrush(Qt::white);
        p->drawEllipse(pin, 4 * px, 4 * px);
    }
    physics::Vec2 from, to;
    if (m_run.grabSpring().line(m_run.world(), from, to)) {
        p->setPen(cosmeticPen(QColor(200, 40, 40), 2.0, Qt::DashLine));
        p->drawLine(toQt(from), toQt(to));
    }
}

void OverlayItem::paintCentresOfMass(QPainter* p, double px) const
{
    p->setPen(cosmeticPen(Qt::black, 1.5));
    for (const physics::Body& b : m_run.world().bodies()) {
        if (!b.isDynamic())
            continue;
        // The usual quartered disc.
        const QPointF c = toQt(b.position);
        const double r = 5 * px;
        p->setBrush(Qt::white);
        p->drawEllipse(c, r, r);
        p->setBrush(Qt::black);
        const QRectF box(c - QPointF(r, r), c + QPointF(r, r));
        p->drawPie(box, 0, 90 * 16);
        p->drawPie(box, 180 * 16, 90 * 16);
    }
}

void OverlayItem::paintVelocities(QPainter* p, double px) const
{
    p->setPen(cosmeticPen(QColor(0, 110, 200), 2.0));
    for (const physics::Body& b : m_run.world().bodies()) {
        if (!b.moves() || !velocityArrowShown(b.velocity, px))
            continue;
        const QPointF c = toQt(b.position);
        drawArrow(p, c, c + toQt(b.velocity) * kVelocityArrowSeconds, 10 * px);
    }
}

void OverlayItem::paintContacts(QPainter* p, double px) const
{
    for (const physics::Contact& c : m_run.world().contacts()) {
        for (int i = 0; i < c.manifold.pointCount; ++i) {
            if (!physics::touches(c, i))
                continue; // a point the step looked ahead for: nothing touches there
            const auto& cp = c.manifold.points[static_cast<std::size_t>(i)];
            const QPointF pt = toQt(cp.point);
            p->setPen(cosmeticPen(QColor(200, 30, 30), 2.0));
            drawArrow(p, pt, pt + toQt(c.manifold.normal) * (30 * px), 8 * px);
            p->setBrush(QColor(200, 30, 30));
            p->drawEllipse(pt, 3.5 * px, 3.5 * px);
        }
    }
}

} // namespace rigidlab::ui
