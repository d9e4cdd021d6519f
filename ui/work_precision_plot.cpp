#include "work_precision_plot.h"

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

namespace rigidlab::ui {

WorkPrecisionPlot::WorkPrecisionPlot(QWidget* parent) : PlotWidget(tr("Error vs run time"), parent)
{
    setRangeMode(RangeMode::WholeRun);
    setPointBudget(1000);
    QCustomPlot* p = plot();
    for (QCPAxis* axis : {p->xAxis, p->yAxis}) {
        axis->setScaleType(QCPAxis::stLogarithmic);
        QSharedPointer<QCPAxisTickerLog> ticker(new QCPAxisTickerLog);
        axis->setTicker(ticker);
        axis->setNumberFormat(QStringLiteral("eb"));
        axis->setNumberPrecision(0);
    }
    p->xAxis->setLabel(tr("CPU time of the run [s]"));
    setYAxisLabel(tr("position error at the end"), QStringLiteral("m"));
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
    label->position->setType(QCPItemPosition::ptPlotCoords);
    label->setPositionAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    label->setColor(color);
    label->setPadding(QMargins(6, 0, 0, 0));
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
        appendPoint(series, r->seconds, r->error);
    // The observed order at the most accurate point.
    QCPItemText* label = m_labels[integrator];
    const auto best = std::min_element(
        rows.begin(), rows.end(), [](const auto* a, const auto* b) { return a->error < b->error; });
    const std::optional<double> order = lessons::observedOrder(m_rows, m_problem, integrator);
    label->setText(order ? tr("p = %1").arg(*order, 0, 'f', 1) : tr("p = ?"));
    label->position->setCoords((*best)->seconds, (*best)->error);
    label->setVisible(true);
    drain();
}

} // namespace rigidlab::ui
