#include "sat_panel.h"

#include "simulation_controller.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPainter>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace rigidlab::ui {

namespace {

const QColor kColorA(0x2f, 0x6d, 0xb5);
const QColor kColorB(0xd9, 0x6c, 0x1e);
const QColor kGap(0x2e, 0x9d, 0x4a);
const QColor kOverlap(0xc6, 0x28, 0x28);

QPointF qt(const physics::Vec2& v)
{
    return {v.x(), v.y()};
}

QString num(double v)
{
    return QString::number(v, 'f', 3);
}

QPen pen(QColor c, double w, Qt::PenStyle s = Qt::SolidLine)
{
    QPen p(c, w, s);
    p.setCosmetic(true);
    p.setCapStyle(Qt::FlatCap);
    return p;
}

} // namespace

SatOverlayItem::SatOverlayItem(const SatPanel& panel) : m_panel(panel)
{
    setZValue(20);
    setAcceptedMouseButtons(Qt::NoButton);
}

QRectF SatOverlayItem::boundingRect() const
{
    return QRectF(-1e5, -1e5, 2e5, 2e5);
}

void SatOverlayItem::paintHulls(QPainter* p, double px) const
{
    // A body whose outline was not convex is handled as its convex hull (the seed's
    // caveat): shade the area the hull adds, where contacts are found wrongly.
    const auto& scene = m_panel.controller().scene();
    const auto& world = m_panel.controller().world();
    for (std::size_t i = 0; i < scene.originalVertices.size() && i < world.bodies().size(); ++i) {
        const auto& original = scene.originalVertices[i];
        if (original.empty())
            continue;
        const physics::Body& b = world.bodies()[i];
        const physics::Transform xf = b.transform();
        QPolygonF hull, outline;
        for (const auto& v : b.shape.polygon.vertices)
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
    p->setRenderHint(QPainter::Antialiasing);
    paintHulls(p, px);
    if (!m_panel.active())
        return;
    const physics::SatResult& r = m_panel.result();
    const int shown = std::min<int>(m_panel.shown(), static_cast<int>(r.axes.size()));
    if (shown <= 0)
        return;
    const physics::SatAxis& ax = r.axes[static_cast<std::size_t>(shown - 1)];
    const physics::Vec2 n = ax.axis;
    const physics::Vec2 t(-n.y(), n.x());

    // The axis is drawn as a line beside both shapes: through a point past them along t.
    const auto& world = m_panel.controller().world();
    double tMax = -1e300, sMid = 0.0;
    int count = 0;
    for (const physics::Body& b : world.bodies()) {
        if (b.shape.type != physics::ShapeType::Polygon)
            continue;
        const physics::Transform xf = b.transform();
        for (const auto& v : b.shape.polygon.vertices) {
            const physics::Vec2 w = xf.apply(v);
            tMax = std::max(tMax, t.dot(w));
            sMid += n.dot(w);
            ++count;
        }
    }
    if (count == 0)
        return;
    sMid /= count;
    const double lineT = tMax + 40 * px; // 40 px beside the shapes
    auto onAxis = [&](double s, double offset) { return qt(s * n + (lineT + offset) * t); };
    const double reach = 1e3;
    p->setPen(pen(QColor(90, 90, 90), 1.5, Qt::DashLine));
    p->drawLine(onAxis(sMid - reach, 0), onAxis(sMid + reach, 0));

    // The projections: A's interval just before the line, B's just after it.
    p->setPen(pen(kColorA, 7.0));
    p->drawLine(onAxis(ax.minA, -8 * px), onAxis(ax.maxA, -8 * px));
    p->setPen(pen(kColorB, 7.0));
    p->drawLine(onAxis(ax.minB, 8 * px), onAxis(ax.maxB, 8 * px));
    // The gap or the overlap between them, on the line.
    const double lo = std::max(ax.minA, ax.minB), hi = std::min(ax.maxA, ax.maxB);
    p->setPen(pen(ax.overlap < 0 ? kGap : kOverlap, 4.0));
    p->drawLine(onAxis(std::min(lo, hi), 0), onAxis(std::max(lo, hi), 0));
    // Thin lines from the interval ends back across the shapes.
    p->setPen(pen(QColor(120, 120, 120, 140), 1.0, Qt::DotLine));
    for (double s : {ax.minA, ax.maxA, ax.minB, ax.maxB})
        p->drawLine(onAxis(s, 0), qt(s * n + (lineT - 1e3 * px) * t));
    // The edge the axis comes from, thick, in its polygon's colour.
    {
        const physics::Body& owner = world.body(ax.owner == 0 ? m_panel.bodyA() : m_panel.bodyB());
        const auto& v = owner.shape.polygon.vertices;
        const physics::Transform xf = owner.transform();
        const std::size_t e = static_cast<std::size_t>(ax.edge);
        p->setPen(pen(ax.owner == 0 ? kColorA : kColorB, 5.0));
        p->drawLine(qt(xf.apply(v[e])), qt(xf.apply(v[(e + 1) % v.size()])));
    }

    // Verdict geometry, once every axis has been shown.
    if (shown == static_cast<int>(r.axes.size()) && r.intersects) {
        p->setPen(pen(kOverlap, 2.5));
        for (int i = 0; i < r.manifold.pointCount; ++i) {
            const QPointF c = qt(r.manifold.points[static_cast<std::size_t>(i)].point);
            p->setBrush(kOverlap);
            p->drawEllipse(c, 5 * px, 5 * px);
            const QPointF tip = c + qt(r.normal) * (50 * px);
            p->drawLine(c, tip);
            const QPointF u = qt(r.normal), v(-u.y(), u.x());
            p->drawLine(tip, tip - 10 * px * u + 5 * px * v);
            p->drawLine(tip, tip - 10 * px * u - 5 * px * v);
        }
    }
}

SatPanel::SatPanel(SimulationController& controller, QWidget* parent)
    : QWidget(parent), m_controller(controller), m_overlay(new SatOverlayItem(*this)),
      m_verdict(new QLabel(this)), m_table(new QTableWidget(0, 5, this)),
      m_summary(new QLabel(this)), m_prev(new QPushButton(tr("◀ Previous axis"), this)),
      m_next(new QPushButton(tr("Next axis ▶"), this)),
      m_all_button(new QPushButton(tr("All"), this))
{
    setMinimumWidth(440);
    auto* layout = new QVBoxLayout(this);
    QFont f = m_verdict->font();
    f.setBold(true);
    f.setPointSizeF(f.pointSizeF() * 1.15);
    m_verdict->setFont(f);
    m_verdict->setWordWrap(true);
    layout->addWidget(m_verdict);
    m_table->setHorizontalHeaderLabels(
        {tr("axis from"), tr("A on axis [m]"), tr("B on axis [m]"), tr("overlap [m]"), tr("")});
    m_table->verticalHeader()->setVisible(false);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    layout->addWidget(m_table, 1);
    m_summary->setWordWrap(true);
    layout->addWidget(m_summary);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_prev);
    buttons->addWidget(m_next);
    buttons->addWidget(m_all_button);
    layout->addLayout(buttons);
    auto* hint = new QLabel(tr("Drag a polygon to move it; Q and E turn the selected one."), this);
    hint->setWordWrap(true);
    hint->setStyleSheet(QStringLiteral("color: #555;"));
    layout->addWidget(hint);
    connect(m_prev, &QPushButton::clicked, this, &SatPanel::previousAxis);
    connect(m_next, &QPushButton::clicked, this, &SatPanel::nextAxis);
    connect(m_all_button, &QPushButton::clicked, this, &SatPanel::showAll);
    connect(&m_controller, &SimulationController::worldChanged, this, &SatPanel::refresh);
    refresh();
}

void SatPanel::setBodies(int a, int b)
{
    const int n = static_cast<int>(m_controller.world().bodies().size());
    auto polygon = [&](int id) {
        return id >= 0 && id < n &&
               m_controller.world().body(id).shape.type == physics::ShapeType::Polygon;
    };
    m_a = polygon(a) && polygon(b) ? a : -1;
    m_b = m_a >= 0 ? b : -1;
    m_shown = 1;
    m_all = false;
    refresh();
}

void SatPanel::nextAxis()
{
    m_all = false;
    m_shown = std::min<int>(m_shown + 1, static_cast<int>(m_result.axes.size()));
    updateTable();
}

void SatPanel::previousAxis()
{
    m_all = false;
    m_shown = std::max(1, m_shown - 1);
    updateTable();
}

void SatPanel::showAll()
{
    m_all = true;
    updateTable();
}

void SatPanel::refresh()
{
    if (!active()) {
        m_result = physics::SatResult{};
        updateTable();
        return;
    }
    const physics::Body& a = m_controller.world().body(m_a);
    const physics::Body& b = m_controller.world().body(m_b);
    m_result = physics::satPolygons(a.shape.polygon, a.transform(), b.shape.polygon, b.transform());
    updateTable();
}

void SatPanel::updateTable()
{
    const auto& axes = m_result.axes;
    const int total = static_cast<int>(axes.size());
    if (m_all)
        m_shown = total;
    m_shown = std::clamp(m_shown, std::min(1, total), total);
    m_table->setRowCount(m_shown);
    const auto& bodies = m_controller.world().bodies();
    auto name = [&](int owner) {
        const int id = owner == 0 ? m_a : m_b;
        return id >= 0 ? QString::fromStdString(bodies[static_cast<std::size_t>(id)].name)
                       : QString();
    };
    for (int i = 0; i < m_shown; ++i) {
        const physics::SatAxis& ax = axes[static_cast<std::size_t>(i)];
        const QStringList cells{tr("%1, edge %2").arg(name(ax.owner)).arg(ax.edge),
                                QStringLiteral("[%1, %2]").arg(num(ax.minA), num(ax.maxA)),
                                QStringLiteral("[%1, %2]").arg(num(ax.minB), num(ax.maxB)),
                                ax.overlap < 0 ? tr("gap %1").arg(num(-ax.overlap))
                                               : num(ax.overlap),
                                i == m_result.separatingAxis ? tr("separates: stop")
                                : i == m_result.leastAxis && m_shown == total ? tr("least overlap")
                                                                              : QString()};
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            if (i == m_shown - 1)
                item->setBackground(QColor(255, 244, 200));
            m_table->setItem(i, c, item);
        }
    }
    m_prev->setEnabled(active() && m_shown > 1);
    m_next->setEnabled(active() && m_shown < total);
    m_all_button->setEnabled(active() && m_shown < total);
    if (!active()) {
        m_verdict->setText(tr("No pair of polygons to test."));
        m_summary->clear();
    } else if (m_shown < total) {
        m_verdict->setText(
            tr("Axis %1 of %2 tested so far: no separating axis yet.").arg(m_shown).arg(total));
        m_summary->setText(summary());
    } else if (!m_result.intersects) {
        m_verdict->setText(tr("Separated: axis %1 has a gap, so the test stops there.")
                               .arg(m_result.separatingAxis + 1));
        m_summary->setText(summary());
    } else {
        m_verdict->setText(tr("Overlapping: no axis separates them."));
        m_summary->setText(summary());
    }
    m_overlay->update();
}

QString SatPanel::summary() const
{
    if (!active())
        return QString();
    const auto& bodies = m_controller.world().bodies();
    const int kA =
        static_cast<int>(bodies[static_cast<std::size_t>(m_a)].shape.polygon.vertices.size());
    const int kB =
        static_cast<int>(bodies[static_cast<std::size_t>(m_b)].shape.polygon.vertices.size());
    const int k = kA + kB;
    QString text = tr("The test needed %1 of at most %2 axes (one per edge, %3 + %4), each "
                      "projecting all %2 vertices: %5 projections, against the paper's worst "
                      "case of (k₁ + k₂)² = %6.")
                       .arg(m_result.axesTested)
                       .arg(k)
                       .arg(kA)
                       .arg(kB)
                       .arg(m_result.axesTested * k)
                       .arg(k * k);
    if (m_result.intersects && m_shown == static_cast<int>(m_result.axes.size())) {
        text += QStringLiteral("\n") +
                tr("Least overlap on axis %1: normal (%2, %3) from A to B, depth %4 m, "
                   "%5 contact point(s) from clipping.")
                    .arg(m_result.leastAxis + 1)
                    .arg(num(m_result.normal.x()), num(m_result.normal.y()), num(m_result.depth))
                    .arg(m_result.manifold.pointCount);
    }
    return text;
}

} // namespace rigidlab::ui
