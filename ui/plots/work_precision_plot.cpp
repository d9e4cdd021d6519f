// SPDX-License-Identifier: GPL-3.0-or-later
#include "plots/work_precision_plot.h"

#include <qcustomplot.h>

#include <QLocale>

#include <algorithm>
#include <cmath>

namespace rigidlab::ui {

namespace {

/// Pixels between a point and its order label.
constexpr double kLabelGap = 6.0;

} // namespace

WorkPrecisionPlot::WorkPrecisionPlot(QWidget* parent) : PlotWidget(tr("Error vs run time"), parent)
{
    model().setRangeMode(RangeMode::WholeRun);
    model().setPointBudget(1000);
    QCustomPlot* p = plot();
    for (QCPAxis* axis : {p->xAxis, p->yAxis}) {
        axis->setScaleType(QCPAxis::stLogarithmic);
        QSharedPointer<QCPAxisTickerLog> ticker(new QCPAxisTickerLog);
        axis->setTicker(ticker);
        axis->setNumberFormat(QStringLiteral("eb"));
        axis->setNumberPrecision(0);
    }
    p->xAxis->setLabel(tr("CPU time of the run [s]"));
    // Short enough to stand whole beside a plot 300 px tall.
    setYAxisLabel(tr("final position error"), QStringLiteral("m"));
    setMinimumHeight(kMinPlotHeight);
    // The order labels are placed in pixels once the layout is known, before each drawing.
    connect(p, &QCustomPlot::afterLayout, this, &WorkPrecisionPlot::arrangeLabels);
    p->xAxis->setRange(1e-5, 1);
    p->yAxis->setRange(1e-12, 1);
}

void WorkPrecisionPlot::setProblem(const QString& problem)
{
    m_problem = problem;
    if (auto* title = qobject_cast<QCPTextElement*>(plot()->plotLayout()->element(0, 0)))
        title->setText(tr("Error vs run time: %1").arg(problem));
    clear();
    for (auto& [integrator, label] : m_labels)
        label->setVisible(false);
    for (const auto& [integrator, series] : m_series)
        redraw(integrator);
}

void WorkPrecisionPlot::clearRows()
{
    m_rows.clear();
    clear();
    for (auto& [integrator, label] : m_labels)
        label->setVisible(false);
}

void WorkPrecisionPlot::setRows(const std::vector<lessons::SweepRow>& rows)
{
    clearRows();
    for (const lessons::SweepRow& r : rows)
        addRow(r);
}

int WorkPrecisionPlot::seriesFor(const QString& integrator)
{
    const auto it = m_series.find(integrator);
    if (it != m_series.end())
        return it->second;
    const int colour = static_cast<int>(lessons::sweepIntegratorNames().indexOf(integrator));
    const QColor color = plotColor(std::max(colour, 0));
    const int index = addSeries(integrator, color);
    QCPGraph* graph = PlotWidget::graph(index);
    // Boost.Odeint's lines dashed, so that each pair (rk4, dopri5) reads as ours against theirs.
    const bool library = integrator.startsWith(QLatin1String("odeint-"));
    graph->setPen(QPen(color, 2.0, library ? Qt::DashLine : Qt::SolidLine));
    graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, color, color, 6));
    auto* label = new QCPItemText(plot());
    label->position->setType(QCPItemPosition::ptAbsolute);
    label->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
    label->setClipToAxisRect(true);
    label->setColor(color);
    label->setPadding(QMargins(2, 1, 2, 1));
    label->setBrush(QBrush(QColor(255, 255, 255, 220))); // readable over the lines
    label->setVisible(false);
    m_labels[integrator] = label;
    m_series[integrator] = index;
    return index;
}

void WorkPrecisionPlot::addRow(const lessons::SweepRow& row)
{
    m_rows.push_back(row);
    if (m_problem.isEmpty())
        setProblem(row.problem);
    if (row.problem == m_problem)
        redraw(row.integrator);
}

QString WorkPrecisionPlot::orderLabel(const QString& integrator) const
{
    const auto it = m_labels.find(integrator);
    return it == m_labels.end() || !it->second->visible() ? QString() : it->second->text();
}

void WorkPrecisionPlot::redraw(const QString& integrator)
{
    std::vector<const lessons::SweepRow*> rows;
    for (const lessons::SweepRow& r : m_rows)
        if (r.problem == m_problem && r.integrator == integrator && r.error > 0 &&
            std::isfinite(r.error) && r.seconds > 0 && std::isfinite(r.seconds))
            rows.push_back(&r);
    const int series = seriesFor(integrator);
    // A series takes increasing times: feed it sorted; its first point restarts it.
    std::sort(rows.begin(), rows.end(),
              [](const auto* a, const auto* b) { return a->seconds < b->seconds; });
    if (rows.empty())
        return;
    for (const lessons::SweepRow* r : rows)
        model().appendPoint(series, r->seconds, r->error);
    // The observed order at the most accurate point, or why there is none.
    QCPItemText* label = m_labels[integrator];
    const auto best = std::min_element(
        rows.begin(), rows.end(), [](const auto* a, const auto* b) { return a->error < b->error; });
    label->setText(orderText(integrator));
    m_anchors[integrator] = QPointF((*best)->seconds, (*best)->error);
    label->setVisible(true);
    drain();
}

QString WorkPrecisionPlot::orderText(const QString& integrator) const
{
    if (const std::optional<double> order = lessons::observedOrder(m_rows, m_problem, integrator))
        return tr("p = %1").arg(QLocale().toString(*order, 'f', 1));
    switch (lessons::orderGap(m_rows, m_problem, integrator)) {
    case lessons::OrderGap::TooFewRuns:
        return tr("order: needs a second run");
    case lessons::OrderGap::RoundOff:
        return tr("no order: error at round-off");
    case lessons::OrderGap::TooLarge:
        return tr("no order: error too large");
    case lessons::OrderGap::None:
        break;
    }
    return QString();
}

void WorkPrecisionPlot::arrangeLabels()
{
    // Each label starts beside its point, inside the axis rectangle; then, from the top down,
    // a label that would cover the one above moves below it, and the stack moves up again
    // where it ran out at the bottom. Labels never overlap while the rectangle has the height.
    QCPAxisRect* rect = plot()->axisRect();
    const QRect area = rect->rect();
    struct Placed {
        QString integrator;
        QCPItemText* label;
        QRectF box;
    };
    std::vector<Placed> placed;
    for (const auto& [integrator, label] : m_labels) {
        const auto anchor = m_anchors.find(integrator);
        if (!label->visible() || anchor == m_anchors.end())
            continue;
        const QFontMetrics fm(label->font());
        const QMargins pad = label->padding();
        const QSizeF size(fm.horizontalAdvance(label->text()) + pad.left() + pad.right(),
                          fm.height() + pad.top() + pad.bottom());
        const double px = plot()->xAxis->coordToPixel(anchor->second.x());
        const double py = plot()->yAxis->coordToPixel(anchor->second.y());
        QPointF topLeft(px + kLabelGap, py - size.height() / 2);
        if (topLeft.x() + size.width() > area.right())
            topLeft.setX(px - kLabelGap - size.width()); // the other side of its point
        topLeft.setX(std::clamp(topLeft.x(), double(area.left()),
                                std::max(double(area.left()), area.right() - size.width())));
        topLeft.setY(std::clamp(topLeft.y(), double(area.top()),
                                std::max(double(area.top()), area.bottom() - size.height())));
        placed.push_back({integrator, label, QRectF(topLeft, size)});
    }
    std::sort(placed.begin(), placed.end(),
              [](const Placed& a, const Placed& b) { return a.box.top() < b.box.top(); });
    for (std::size_t i = 1; i < placed.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (placed[i].box.intersects(placed[j].box))
                placed[i].box.moveTop(placed[j].box.bottom() + 1);
    for (std::size_t i = placed.size(); i-- > 0;) {
        const double limit =
            i + 1 < placed.size() ? placed[i + 1].box.top() - 1 : double(area.bottom());
        if (placed[i].box.bottom() > limit)
            placed[i].box.moveBottom(limit);
    }
    m_labelBoxes.clear();
    for (const Placed& p : placed) {
        p.label->position->setCoords(p.box.topLeft());
        m_labelBoxes[p.integrator] = p.box;
    }
}

} // namespace rigidlab::ui
