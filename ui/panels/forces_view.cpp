// SPDX-License-Identifier: GPL-3.0-or-later
#include "panels/forces_view.h"

#include "common/calm_text.h"
#include "common/number_format.h"

#include <QLabel>
#include <QPainter>
#include <QPainterPath>
#include <QTextDocumentFragment>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace rigidlab::ui {

namespace {

QString num(double v)
{
    return formatReadable(v, 3);
}

QString vec(const physics::Vec2& v)
{
    return ForcesView::tr("(%1, %2)").arg(num(v.x()), num(v.y()));
}

QString nameOf(const physics::ForceTerm& t)
{
    switch (t.kind) {
    case physics::ForceKind::Weight:
        return ForcesView::tr("weight m g");
    case physics::ForceKind::Drag:
        return ForcesView::tr("drag");
    case physics::ForceKind::Spring:
        return ForcesView::tr("spring %1").arg(t.index + 1);
    case physics::ForceKind::Applied:
        return ForcesView::tr("your pull");
    case physics::ForceKind::Gravitation:
        return ForcesView::tr("gravitation");
    }
    return {};
}

} // namespace

/// The free-body diagram: the body's outline around its centre of mass, an arrow per force at
/// its point of action and the sum at the centre, each numbered as in the table.
class ForceDiagram : public QWidget {
public:
    explicit ForceDiagram(QWidget* parent) : QWidget(parent) { setMinimumHeight(170); }
    void show(const physics::ForceBreakdown& forces, const physics::Body& body)
    {
        m_forces = forces;
        m_body = body;
        update();
    }

protected:
    void paintEvent(QPaintEvent*) override
    {
        QPainter p(this);
        p.setRenderHint(QPainter::Antialiasing);
        p.fillRect(rect(), palette().base());
        if (m_forces.terms.empty())
            return;
        // Lengths: the body's reach and the points of action fill a fifth of the height and
        // the largest force is drawn a quarter of it long, so that every arrow and its label
        // stay inside.
        double reach = 1e-3, largest = std::max(m_forces.force.norm(), 1e-12);
        for (const physics::ForceTerm& t : m_forces.terms) {
            reach = std::max(reach, (t.point - m_body.position).norm());
            largest = std::max(largest, t.force.norm());
        }
        const QPointF centre = rect().center();
        const double metre = height() / 5.0 / reach;
        const double newton = height() / 4.0 / largest;
        const auto at = [&](const physics::Vec2& world) {
            const physics::Vec2 d = world - m_body.position;
            return centre + QPointF(d.x() * metre, -d.y() * metre);
        };
        drawOutline(p, at);
        int n = 0;
        for (const physics::ForceTerm& t : m_forces.terms)
            arrow(p, at(t.point), t.force * newton, QString::number(++n), 1.5);
        arrow(p, centre, m_forces.force * newton, QStringLiteral("ΣF"), 3.0);
    }

private:
    template <typename At> void drawOutline(QPainter& p, At at)
    {
        p.setPen(QPen(palette().text().color(), 1, Qt::DashLine));
        p.setBrush(Qt::NoBrush);
        const physics::Transform xf = m_body.transform();
        if (const physics::Polygon* poly = m_body.shape.asPolygon()) {
            QPolygonF outline;
            for (const physics::Vec2& v : poly->vertices)
                outline << at(xf.apply(v));
            p.drawPolygon(outline);
        } else if (const physics::Circle* c = m_body.shape.asCircle()) {
            const QPointF mid = at(xf.apply(c->center));
            const double r =
                (at(m_body.position + physics::Vec2(c->radius, 0)) - at(m_body.position)).x();
            p.drawEllipse(mid, r, r);
        }
        p.drawEllipse(at(m_body.position), 2.5, 2.5);
    }
    void arrow(QPainter& p, const QPointF& from, const physics::Vec2& length, const QString& label,
               double width)
    {
        const QPointF to = from + QPointF(length.x(), -length.y());
        p.setPen(QPen(palette().text().color(), width));
        p.drawLine(from, to);
        const double len = std::hypot(length.x(), length.y());
        if (len > 1) {
            const QPointF u(length.x() / len, -length.y() / len), side(-u.y(), u.x());
            const double head = std::min(8.0, len / 2);
            p.drawLine(to, to - head * u + head / 2 * side);
            p.drawLine(to, to - head * u - head / 2 * side);
        }
        p.drawText(to + QPointF(3, -3), label);
    }

    physics::ForceBreakdown m_forces;
    physics::Body m_body;
};

QString forcesTableText(const physics::ForceBreakdown& forces, const physics::Body& body)
{
    QString html = QStringLiteral("<table cellpadding=\"2\"><tr><th>#</th><th>") +
                   ForcesView::tr("force") + QStringLiteral("</th><th>") + ForcesView::tr("F [N]") +
                   QStringLiteral("</th><th>") + ForcesView::tr("acts at r [m]") +
                   QStringLiteral("</th><th>") + ForcesView::tr("τ = r × F [N·m]") +
                   QStringLiteral("</th></tr>");
    int n = 0;
    for (const physics::ForceTerm& t : forces.terms)
        html += QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td><td>%4</td><td>%5</td></tr>")
                    .arg(++n)
                    .arg(nameOf(t).toHtmlEscaped(), vec(t.force), vec(t.point - body.position),
                         num(t.torque));
    html += QStringLiteral("<tr><td><b>Σ</b></td><td><b>%1</b></td><td><b>%2</b></td><td>%3</td>"
                           "<td><b>%4</b></td></tr></table>")
                .arg(ForcesView::tr("the accumulators"), vec(forces.force), vec({0, 0}),
                     num(forces.torque));
    if (body.mass > 0 && body.inertia > 0)
        html += QStringLiteral("<p>") +
                ForcesView::tr("a = F / m = %1 m/s², α = τ / I = %2 rad/s²")
                    .arg(vec(forces.force / body.mass), num(forces.torque / body.inertia)) +
                QStringLiteral("</p>");
    return html;
}

ForcesView::ForcesView(QWidget* parent)
    : QWidget(parent), m_toggle(new QToolButton(this)), m_diagram(new ForceDiagram(this)),
      m_table(new QLabel(this))
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_toggle->setText(tr("Forces on this body"));
    m_toggle->setCheckable(true);
    m_toggle->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_toggle->setArrowType(Qt::RightArrow);
    m_toggle->setAccessibleName(tr("Show the forces on this body"));
    m_diagram->setAccessibleName(tr("Free-body diagram"));
    m_table->setWordWrap(true);
    m_table->setTextFormat(Qt::RichText);
    m_table->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
    m_table->setAccessibleName(tr("Forces and their sums"));
    layout->addWidget(m_toggle);
    layout->addWidget(m_diagram);
    layout->addWidget(m_table);
    connect(m_toggle, &QToolButton::toggled, this, &ForcesView::setOpen);
    setOpen(false);
    showNone();
}

void ForcesView::setOpen(bool open)
{
    m_toggle->setChecked(open);
    m_toggle->setArrowType(open ? Qt::DownArrow : Qt::RightArrow);
    m_diagram->setVisible(open);
    m_table->setVisible(open);
}

QString ForcesView::text() const
{
    return m_table->text();
}

void ForcesView::showBody(const physics::World& world, physics::BodyId id)
{
    const physics::Body& body = world.body(id);
    const physics::ForceBreakdown forces = physics::forceBreakdown(world, id);
    m_diagram->show(forces, body);
    if (forces.terms.empty()) {
        m_table->setText(tr("No force acts on this body."));
        return;
    }
    const QString html = forcesTableText(forces, body);
    m_table->setText(html);
    // The diagram says in words what it draws: the table's numbers, at the calm rate (they
    // change with every frame of a run: 55 descriptions a second buried the focus a reader
    // was to say).
    setCalmAccessibleDescription(*m_diagram, QTextDocumentFragment::fromHtml(html).toPlainText());
}

void ForcesView::showNone()
{
    m_diagram->show({}, {});
    m_table->setText(tr("Click a body to see the forces on it."));
}

} // namespace rigidlab::ui
