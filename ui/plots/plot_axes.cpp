// SPDX-License-Identifier: GPL-3.0-or-later
// PlotWidget and the run: draining the model, following the newest time (or rewinding with
// it), the time axis and the value axes fitted to what is shown, their ticks, and what is off
// scale.

#include "plots/plot_widget.h"

#include "plots/column_graph.h"

#include <qcustomplot.h>

#include <QFontMetrics>
#include <QLocale>
#include <QScopedValueRollback>
#include <QToolButton>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rigidlab::ui {

namespace {

/// Ticks an axis has at most (QCPAxisTicker's default); fewer where their labels would meet.
constexpr int kTickCount = 5;
/// Pixel columns assumed for a plot that was never laid out.
constexpr int kDefaultColumns = 800;

} // namespace

int PlotWidget::drain()
{
    const int taken = m_model->takeSamples();
    if (m_model->takeChanged()) {
        updateRanges();
        requestReplot();
    }
    return taken;
}

void PlotWidget::rewind(double t)
{
    m_model->rewind(t);
    // The timeline is where the user looks now: a plot dragged aside follows it again.
    if (std::isfinite(t))
        setFollowing(true);
}

void PlotWidget::clear()
{
    m_model->clear();
    for (const Curves& curves : m_curves)
        for (ColumnGraph* g : {curves.graph, curves.ghost}) {
            g->data()->clear();
            g->setColumns({});
        }
    setFollowing(true);
    QScopedValueRollback<bool> guard(m_settingRanges, true);
    m_plot->xAxis->setRange(0, m_model->windowSeconds());
}

PlotRange PlotWidget::shownTimes() const
{
    return {m_plot->xAxis->range().lower, m_plot->xAxis->range().upper};
}

void PlotWidget::fitTicks()
{
    // No more ticks than their labels have room for, a blank of one line's height between
    // two: on a narrow plot with presentation-sized labels, "0 2 4 6 8 10" ran together.
    for (QCPAxis* axis : {m_plot->xAxis, m_plot->yAxis, m_plot->yAxis2}) {
        if (!axis->visible() || !axis->tickLabels() || !axis->ticker())
            continue;
        const QFontMetrics fm(axis->tickLabelFont());
        const bool horizontal = axis->orientation() == Qt::Horizontal;
        int label = fm.height();
        if (horizontal) {
            label = fm.horizontalAdvance(QStringLiteral("00.0"));
            for (const QString& text : axis->tickVectorLabels())
                label = std::max(label, fm.horizontalAdvance(text));
        }
        const QRect area = axis->axisRect()->rect();
        const int length = horizontal ? area.width() : area.height();
        if (length <= 0)
            continue;
        // The ticker makes about tickCount + 1 intervals of a round size, sometimes a little
        // shorter than asked for: one tick fewer than would just fit.
        const int fit = length / (label + fm.height()) - 1;
        axis->ticker()->setTickCount(std::clamp(fit, 2, kTickCount));
    }
}

bool PlotWidget::offScale(int series) const
{
    return series >= 0 && static_cast<std::size_t>(series) < m_offScale.size() &&
           m_offScale[static_cast<std::size_t>(series)];
}

void PlotWidget::setOffScaleClipping(bool on)
{
    m_offScaleClipping = on;
    updateRanges();
    requestReplot();
}

QString PlotWidget::offScaleMark() const
{
    return tr(" ↑ off scale");
}

void PlotWidget::setOffScale(YAxis axis, const std::vector<bool>& offScale)
{
    m_offScale.resize(m_curves.size(), false);
    bool changed = false;
    for (std::size_t i = 0; i < m_curves.size() && i < offScale.size(); ++i) {
        if (m_model->series(static_cast<int>(i)).axis() != axis) // the other axis's keep theirs
            continue;
        if (m_offScale[i] == offScale[i])
            continue;
        m_offScale[i] = offScale[i];
        QCPGraph* g = m_curves[i].graph;
        QString name = g->name();
        if (offScale[i])
            name += offScaleMark();
        else if (name.endsWith(offScaleMark()))
            name.chop(offScaleMark().size());
        g->setName(name);
        changed = true;
    }
    if (changed)
        fitLegend(m_plot->width());
}

void PlotWidget::setFollowing(bool following)
{
    if (following == m_following)
        return;
    m_following = following;
    m_followButton->setVisible(!following);
    // Paused, the points shown stay; following, the model keeps its window again.
    m_model->setHeldFrom(following ? std::nullopt
                                   : std::optional<double>(m_plot->xAxis->range().lower));
    emit followingChanged(following);
}

void PlotWidget::onRangeChanged()
{
    fitMarks();
    if (!m_following)
        m_model->setHeldFrom(m_plot->xAxis->range().lower);
    if (m_settingRanges)
        return;
    // Changed by the user (drag, wheel) or by a caller: stop following, show the new range.
    setFollowing(false);
    requestReplot();
}

void PlotWidget::updateRanges()
{
    if (!m_following)
        return;
    const std::optional<PlotRange> times =
        m_model->followedRange(m_plot->xAxis->scaleType() == QCPAxis::stLogarithmic);
    if (!times)
        return;
    QScopedValueRollback<bool> guard(m_settingRanges, true);
    m_plot->xAxis->setRange(times->lower, times->upper);
    fitValueAxis(YAxis::Left);
    fitValueAxis(YAxis::Right);
}

void PlotWidget::fitValueAxis(YAxis axis)
{
    QCPAxis* valueAxis = axisFor(axis);
    const bool log = valueAxis->scaleType() == QCPAxis::stLogarithmic;
    std::vector<bool> shown;
    for (const Curves& curves : m_curves)
        shown.push_back(curves.graph->visible());
    const std::optional<ValueFit> fit =
        m_model->fitValues(axis, shownTimes(), log, shown, m_offScaleClipping);
    if (!fit)
        return;
    setOffScale(axis, fit->offScale);
    if (!log)
        valueAxis->setNumberPrecision(fit->labelDigits);
    valueAxis->setRange(fit->range.lower, fit->range.upper);
}

void PlotWidget::prepareGraphs(int columns)
{
    if (columns <= 0)
        columns = m_plot->width() > 0 ? m_plot->width() : kDefaultColumns;
    const QCPRange keys = m_plot->xAxis->range();
    const bool log = m_plot->xAxis->scaleType() == QCPAxis::stLogarithmic;
    for (std::size_t i = 0; i < m_curves.size(); ++i) {
        const Curves& curves = m_curves[i];
        const PlotSeries& series = m_model->series(static_cast<int>(i));
        curves.ghost->setVisible(curves.graph->visible());
        curves.graph->setPoints(series.points(), keys.lower, keys.upper, columns, log);
        curves.ghost->setPoints(series.ghost(), keys.lower, keys.upper, columns, log);
    }
}

} // namespace rigidlab::ui
