// SPDX-License-Identifier: GPL-3.0-or-later
// PlotWidget's axes: the time range (a window that follows, or the whole run), the value
// axes fitted to what is shown, their ticks, and what is off scale.

#include "plots/plot_widget.h"

#include "plots/column_graph.h"
#include "plots/plot_range.h"

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
/// Smallest time span [s] shown in whole-run mode, so a single point has an axis.
constexpr double kMinWholeRunSpan = 1e-3;
/// Pixel columns assumed for a plot that was never laid out.
constexpr int kDefaultColumns = 800;

} // namespace

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
    m_offScale.resize(m_series.size(), false);
    bool changed = false;
    for (std::size_t i = 0; i < m_series.size() && i < offScale.size(); ++i) {
        if (m_series[i].axis() != axis) // the other axis's series keep their mark
            continue;
        if (m_offScale[i] == offScale[i])
            continue;
        m_offScale[i] = offScale[i];
        QCPGraph* g = m_series[i].graph();
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

void PlotWidget::setRangeMode(RangeMode mode)
{
    if (mode == m_rangeMode)
        return;
    m_rangeMode = mode;
    trimToWindow();
    m_dirty = true;
    emit rangeModeChanged(mode);
}

void PlotWidget::setWindowSeconds(double seconds)
{
    Q_ASSERT(std::isfinite(seconds) && seconds > 0);
    if (!std::isfinite(seconds) || seconds <= 0)
        return;
    m_windowSeconds = seconds;
    trimToWindow();
    m_dirty = true;
}

void PlotWidget::setPointBudget(int points)
{
    m_pointBudget = std::max(points, 16);
}

void PlotWidget::setFollowing(bool following)
{
    if (following == m_following)
        return;
    m_following = following;
    m_followButton->setVisible(!following);
    if (following) {
        trimToWindow();
        m_dirty = true;
    }
    emit followingChanged(following);
}

void PlotWidget::onRangeChanged()
{
    updateMarkLabels();
    if (m_settingRanges)
        return;
    // Changed by the user (drag, wheel) or by a caller: stop following, show the new range.
    setFollowing(false);
    requestReplot();
}

void PlotWidget::updateRanges()
{
    if (!m_following || !m_latestT)
        return;
    QScopedValueRollback<bool> guard(m_settingRanges, true);

    double first = *m_latestT;
    for (const PlotSeries& series : m_series)
        if (!series.isEmpty())
            first = std::min(first, series.firstKey());
    const std::optional<double> ghost = ghostEnd();

    if (m_rangeMode == RangeMode::Window) {
        // Gone back on the timeline: the moment chosen, and a little of the old future after
        // it. Until a whole window has run, the axis fits the run, from the left edge.
        double end = *m_latestT;
        if (ghost)
            end = std::max(end, std::min(*ghost, end + kGhostLookahead * m_windowSeconds));
        // The span is the whole run's, the old future's too: scrubbing does not zoom.
        const double span = timeSpan(std::max(end, ghost.value_or(end)) - first);
        m_plot->xAxis->setRange(std::max(end, first + span), span, Qt::AlignRight);
    } else if (m_plot->xAxis->scaleType() == QCPAxis::stLogarithmic) {
        // A log axis (work against precision): a third of a decade beyond the points.
        m_plot->xAxis->setRange(first / 2, *m_latestT * 2);
    } else {
        const double end = std::max(*m_latestT, ghost.value_or(*m_latestT));
        m_plot->xAxis->setRange(first, first + std::max(end - first, kMinWholeRunSpan));
    }
    fitValueAxis(YAxis::Left);
    fitValueAxis(YAxis::Right);
}

double PlotWidget::timeSpan(double run) const
{
    if (!(run < m_windowSeconds))
        return m_windowSeconds;
    // Rounded up to a twentieth-ish round step: the axis grows in small jumps, and the run
    // fills at least 19/20 of it.
    const double step = niceStep(std::max(run, kMinTimeSpan), 20);
    const double rounded = std::ceil(run / step - 1e-9) * step;
    return std::clamp(rounded, std::min(kMinTimeSpan, m_windowSeconds), m_windowSeconds);
}

void PlotWidget::fitValueAxis(YAxis axis)
{
    const QCPRange keys = m_plot->xAxis->range();
    QCPAxis* valueAxis = axisFor(axis);
    const bool log = valueAxis->scaleType() == QCPAxis::stLogarithmic;
    struct Extent {
        std::size_t series;
        double lo, hi, magnitude;
    };
    std::vector<Extent> extents;
    for (std::size_t i = 0; i < m_series.size(); ++i) {
        const PlotSeries& series = m_series[i];
        if (series.axis() != axis || !series.graph()->visible())
            continue;
        double lo = 0, hi = 0;
        if (!series.valueRange(keys.lower, keys.upper, log, lo, hi))
            continue;
        extents.push_back({i, lo, hi, std::max(std::abs(lo), std::abs(hi))});
    }
    if (extents.empty())
        return;
    // A compared run that blew up (1e10 J beside 1000 J) would flatten the runs that survive
    // to a line at 0: the axis fits the survivors, and the runs beyond kOffScaleRatio times
    // them go off the top, said so in the legend.
    std::vector<bool> offScale(m_series.size(), false);
    if (m_offScaleClipping && !log) {
        std::sort(extents.begin(), extents.end(),
                  [](const Extent& a, const Extent& b) { return a.magnitude < b.magnitude; });
        const double floor = std::max(valueScale(axis), kMinMagnitude);
        std::size_t kept = 1;
        while (kept < extents.size() &&
               extents[kept].magnitude <=
                   kOffScaleRatio * std::max(extents[kept - 1].magnitude, floor))
            ++kept;
        for (std::size_t k = kept; k < extents.size(); ++k)
            offScale[extents[k].series] = true;
        extents.resize(kept);
    }
    setOffScale(axis, offScale);
    double lowest = extents.front().lo, highest = extents.front().hi;
    for (const Extent& e : extents) {
        lowest = std::min(lowest, e.lo);
        highest = std::max(highest, e.hi);
    }
    if (log) {
        valueAxis->setRange(lowest / 2, highest * 2);
        return;
    }
    // Rounding noise is drawn flat, and the ticks always read differently (plot_range.h).
    const AxisRange range =
        niceRange(lowest, highest, valueScale(axis), m_minimumSpan[axis == YAxis::Left ? 0 : 1]);
    valueAxis->setNumberPrecision(range.labelDigits);
    valueAxis->setRange(range.lower, range.upper);
}

void PlotWidget::prepareGraphs(int columns)
{
    if (columns <= 0)
        columns = m_plot->width() > 0 ? m_plot->width() : kDefaultColumns;
    const QCPRange keys = m_plot->xAxis->range();
    const bool log = m_plot->xAxis->scaleType() == QCPAxis::stLogarithmic;
    for (const PlotSeries& series : m_series) {
        series.ghostGraph()->setVisible(series.graph()->visible());
        series.draw(keys.lower, keys.upper, columns, log);
    }
}

} // namespace rigidlab::ui
