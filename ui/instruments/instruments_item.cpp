// SPDX-License-Identifier: GPL-3.0-or-later
#include "instruments/instruments_item.h"

#include "instruments/instruments_panel.h"
#include "simulation/run_view.h"
#include "view/world_view.h"

#include <QApplication>
#include <QGraphicsScene>
#include <QMouseEvent>
#include <QPainter>
#include <QTabWidget>

#include <cmath>
#include <numbers>

namespace rigidlab::ui {

namespace {

/// Ends within this many pixels of the pointer are grabbed; ends dropped this close snap [px].
constexpr double kGrabPx = 10.0;
const QColor kInk(170, 60, 0); // a warm brown: apart from the bodies' palette

/// Painting in device pixels: world points are mapped with the view's transform, so that
/// text stays upright in a view whose y goes up.
struct Device {
    QTransform toDevice;
    QPointF at(const physics::Vec2& v) const { return toDevice.map(QPointF(v.x(), v.y())); }
};

void handle(QPainter& p, const QPointF& c)
{
    p.setBrush(Qt::white);
    p.drawEllipse(c, 4.5, 4.5);
    p.setBrush(Qt::NoBrush);
}

/// Text on a light plate, so that it reads over bodies and the grid.
void label(QPainter& p, const QPointF& at, const QString& text)
{
    const QFontMetricsF fm(p.font());
    QRectF box = fm.boundingRect(QRectF(0, 0, 400, 400), Qt::AlignLeft, text);
    box.moveTopLeft(at + QPointF(8, 8));
    box.adjust(-3, -2, 3, 2);
    p.save();
    p.setPen(QPen(kInk, 1));
    p.setBrush(QColor(255, 255, 255, 225));
    p.drawRect(box);
    p.setPen(Qt::black);
    p.drawText(box.adjusted(3, 2, -3, -2), Qt::AlignLeft, text);
    p.restore();
}

} // namespace

InstrumentsItem::InstrumentsItem(const InstrumentsPanel& panel, const RunView& run)
    : m_panel(panel), m_run(run)
{
    setZValue(1000); // over the bodies and overlays
}

QRectF InstrumentsItem::boundingRect() const
{
    // The instruments may be anywhere in the world the view shows.
    return {-1e5, -1e5, 2e5, 2e5};
}

void InstrumentsItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*)
{
    painter->save();
    const QTransform toDevice = painter->worldTransform();
    painter->resetTransform();
    painter->setRenderHint(QPainter::Antialiasing);
    // Each paint function maps with the transform saved here.
    m_device = toDevice;
    // The open tab's instrument, and the stopwatch's line while it has one.
    paintStopwatchLine(*painter);
    switch (m_panel.tabs()->currentIndex()) {
    case InstrumentsPanel::RulerTab:
        paintRuler(*painter);
        break;
    case InstrumentsPanel::ProtractorTab:
        paintProtractor(*painter);
        break;
    case InstrumentsPanel::ProbeTab:
        paintProbe(*painter);
        break;
    default:
        break;
    }
    painter->restore();
}

void InstrumentsItem::paintRuler(QPainter& p) const
{
    const Device d{m_device};
    const QPointF a = d.at(m_panel.rulerStart()), b = d.at(m_panel.rulerEnd());
    p.setPen(QPen(kInk, 2));
    p.drawLine(a, b);
    // Ticks across the ends, like a tape's.
    const QLineF line(a, b);
    if (line.length() > 0) {
        const QPointF n = QPointF(-line.dy(), line.dx()) / line.length() * 6.0;
        p.drawLine(a - n, a + n);
        p.drawLine(b - n, b + n);
    }
    handle(p, a);
    handle(p, b);
    label(p, (a + b) / 2, InstrumentsPanel::tr("ruler: %1").arg(m_panel.rulerText()));
}

void InstrumentsItem::paintProtractor(QPainter& p) const
{
    const Device d{m_device};
    physics::Vec2 vertex = m_panel.protractorVertex();
    physics::Vec2 armA = m_panel.protractorArmA(), armB = m_panel.protractorArmB();
    const physics::World& w = m_run.world();
    const int id = m_panel.protractorBody();
    if (m_panel.protractorMode() == InstrumentsPanel::ProtractorMode::Body) {
        if (id < 0 || id >= static_cast<int>(w.bodies().size()))
            return;
        // The body's turn: from the horizontal to its own x axis, at its centre.
        const physics::Body& b = w.body(id);
        vertex = b.position;
        armA = vertex + physics::Vec2(1, 0);
        armB = vertex + physics::Vec2(std::cos(b.angle), std::sin(b.angle));
    }
    const QPointF v = d.at(vertex), a = d.at(armA), b = d.at(armB);
    const bool lines = m_panel.protractorMode() == InstrumentsPanel::ProtractorMode::Lines;
    p.setPen(QPen(kInk, 2, lines ? Qt::SolidLine : Qt::DashLine));
    const QLineF la(v, a), lb(v, b);
    const double r = 30.0;
    // In body mode the arms are drawn 60 px long whatever the zoom.
    p.drawLine(v, lines ? a : v + (a - v) / std::max(1e-9, la.length()) * 60.0);
    p.drawLine(v, lines ? b : v + (b - v) / std::max(1e-9, lb.length()) * 60.0);
    if (la.length() > 0 && lb.length() > 0) {
        // Qt's angles run counter-clockwise on screen, in 1/16 of a degree.
        const double startDeg = la.angle();
        double span = lb.angle() - startDeg;
        while (span > 180)
            span -= 360;
        while (span < -180)
            span += 360;
        p.drawArc(QRectF(v - QPointF(r, r), v + QPointF(r, r)), qRound(startDeg * 16),
                  qRound(span * 16));
    }
    if (lines) {
        handle(p, v);
        handle(p, a);
        handle(p, b);
    }
    label(p, v, InstrumentsPanel::tr("angle: %1").arg(m_panel.protractorText()));
}

void InstrumentsItem::paintStopwatchLine(QPainter& p) const
{
    const auto& watch = m_panel.stopwatch();
    const instruments::TriggerSpec* spec = nullptr;
    if (watch.start().kind == instruments::Trigger::PassesLine)
        spec = &watch.start();
    else if (watch.stop().kind == instruments::Trigger::PassesLine)
        spec = &watch.stop();
    if (!spec)
        return;
    const Device d{m_device};
    // Across what the view shows: the device's left and right edges.
    const QRect screen = p.viewport();
    const double y = d.at(physics::Vec2(0, spec->lineY)).y();
    p.setPen(QPen(kInk, 1.5, Qt::DashDotLine));
    p.drawLine(QPointF(screen.left(), y), QPointF(screen.right(), y));
    label(p, QPointF(screen.left() + 4, y),
          InstrumentsPanel::tr("stopwatch line, %1").arg(m_panel.stopwatchText()));
}

void InstrumentsItem::paintProbe(QPainter& p) const
{
    const int id = m_panel.probeBody();
    const physics::World& w = m_run.world();
    if (id < 0 || id >= static_cast<int>(w.bodies().size()))
        return;
    const Device d{m_device};
    const QPointF c = d.at(w.body(id).position);
    p.setPen(QPen(kInk, 1.5));
    p.drawLine(c - QPointF(6, 6), c + QPointF(6, 6));
    p.drawLine(c - QPointF(6, -6), c + QPointF(6, -6));
    label(p, c + QPointF(12, 0),
          m_run.scene().bodyLabel(id) + QLatin1Char('\n') + m_panel.probeText());
}

InstrumentsMouse::InstrumentsMouse(InstrumentsPanel& panel, WorldView& view)
    : QObject(&panel), m_panel(panel), m_view(view)
{
    view.viewport()->installEventFilter(this);
}

std::optional<InstrumentsMouse::Handle> InstrumentsMouse::handleAt(const QPoint& viewPos) const
{
    const auto near = [&](const physics::Vec2& p) {
        const QPointF s = m_view.mapFromScene(QPointF(p.x(), p.y()));
        return QLineF(s, QPointF(viewPos)).length() <= kGrabPx;
    };
    // Only the instrument drawn (the open tab's) has ends to grab.
    const int tab = m_panel.tabs()->currentIndex();
    if (tab == InstrumentsPanel::RulerTab && near(m_panel.rulerStart()))
        return Handle::RulerA;
    if (tab == InstrumentsPanel::RulerTab && near(m_panel.rulerEnd()))
        return Handle::RulerB;
    if (tab == InstrumentsPanel::ProtractorTab &&
        m_panel.protractorMode() == InstrumentsPanel::ProtractorMode::Lines) {
        if (near(m_panel.protractorVertex()))
            return Handle::Vertex;
        if (near(m_panel.protractorArmA()))
            return Handle::ArmA;
        if (near(m_panel.protractorArmB()))
            return Handle::ArmB;
    }
    return std::nullopt;
}

void InstrumentsMouse::moveHandle(Handle h, const physics::Vec2& to)
{
    m_panel.setSnapRadius(kGrabPx / std::max(1e-9, m_view.zoom()));
    physics::Vec2 a = m_panel.rulerStart(), b = m_panel.rulerEnd();
    physics::Vec2 v = m_panel.protractorVertex(), pa = m_panel.protractorArmA(),
                  pb = m_panel.protractorArmB();
    switch (h) {
    case Handle::RulerA:
        return m_panel.setRuler(to, b);
    case Handle::RulerB:
        return m_panel.setRuler(a, to);
    case Handle::Vertex:
        return m_panel.setProtractorLines(to, pa, pb);
    case Handle::ArmA:
        return m_panel.setProtractorLines(v, to, pb);
    case Handle::ArmB:
        return m_panel.setProtractorLines(v, pa, to);
    }
}

bool InstrumentsMouse::eventFilter(QObject* watched, QEvent* event)
{
    if (!m_panel.isVisible() || watched != m_view.viewport())
        return false;
    const auto type = event->type();
    if (type != QEvent::MouseButtonPress && type != QEvent::MouseMove &&
        type != QEvent::MouseButtonRelease)
        return false;
    auto* mouse = static_cast<QMouseEvent*>(event);
    const QPoint pos = mouse->position().toPoint();
    const physics::Vec2 at = m_view.worldAt(pos);
    if (type == QEvent::MouseButtonPress && mouse->button() == Qt::LeftButton) {
        if (mouse->modifiers() & Qt::ShiftModifier) {
            // A new ruler, or a new first line of the protractor, from here.
            const bool protractor =
                m_panel.tabs()->currentIndex() == InstrumentsPanel::ProtractorTab;
            if (protractor) {
                m_panel.setProtractorMode(InstrumentsPanel::ProtractorMode::Lines);
                moveHandle(Handle::Vertex, at);
                m_dragging = Handle::ArmA;
            } else {
                moveHandle(Handle::RulerA, at);
                m_dragging = Handle::RulerB;
            }
            moveHandle(*m_dragging, at);
            return true;
        }
        m_dragging = handleAt(pos);
        return m_dragging.has_value(); // else the view grabs, pans or selects as usual
    }
    if (!m_dragging)
        return false;
    moveHandle(*m_dragging, at);
    if (type == QEvent::MouseButtonRelease)
        m_dragging.reset();
    return true;
}

} // namespace rigidlab::ui
