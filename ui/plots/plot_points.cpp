// SPDX-License-Identifier: GPL-3.0-or-later
// PlotWidget's points: appended, taken from the controller's samples once a frame, cut back
// on a rewind, cleared, and trimmed to the time window and the point budget.

#include "plots/plot_widget.h"

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rigidlab::ui {

namespace {

/// In window mode points are kept this fraction of the window longer than shown, so a
/// curve enters from the left edge instead of starting inside the plot.
constexpr double kWindowMargin = 0.1;
/// A frame may come this much early and still count as the refresh interval passed [ms].
constexpr int kFrameSlackMs = 8;

} // namespace

std::vector<QPointF> PlotWidget::points(int series) const
{
    const std::vector<PlotPoint>& kept = m_series.at(series).points();
    std::vector<QPointF> out;
    out.reserve(kept.size());
    for (const PlotPoint& p : kept)
        out.emplace_back(p.t, p.v);
    return out;
}

std::vector<QPointF> PlotWidget::visiblePoints(int series) const
{
    const QCPRange shown = m_plot->xAxis->range();
    std::vector<QPointF> out;
    for (const PlotPoint& p : m_series.at(series).points())
        if (p.t >= shown.lower && p.t <= shown.upper)
            out.emplace_back(p.t, p.v);
    return out;
}

int PlotWidget::pointCount(int series) const
{
    return m_series.at(series).size();
}

int PlotWidget::pointCount() const
{
    int n = 0;
    for (const PlotSeries& s : m_series)
        n += s.size();
    return n;
}

void PlotWidget::appendPoint(int series, double t, double value)
{
    PlotSeries& s = m_series.at(series);
    Q_ASSERT(!s.isFedBySamples());
    if (!std::isfinite(t))
        return;
    if (!s.isEmpty() && t <= s.lastKey()) {
        s.removeFrom(t, m_pointBudget);
        updateLatest();
    }
    appendTo(s, t, value);
    overwriteGhostMarks(t);
    trimToWindow();
}

void PlotWidget::appendTo(PlotSeries& series, double t, double value)
{
    // A gap in the curve rather than an infinite axis range.
    const double v = std::isfinite(value) ? value : std::numeric_limits<double>::quiet_NaN();
    series.append(t, v, m_pointBudget);
    m_latestT = m_latestT ? std::max(*m_latestT, t) : t;
    m_dirty = true;
}

void PlotWidget::setSource(const SampleBuffer* source)
{
    m_source = source;
    m_cursor = 0; // readSince() starts at the oldest sample still in the ring
}

void PlotWidget::frameAdvanced()
{
    m_sinceFrame.start();
    // At 60 frames per second, every second frame: ~30 Hz.
    if (!m_sinceDrain.isValid() || m_sinceDrain.elapsed() >= kRefreshIntervalMs - kFrameSlackMs)
        drain();
}

int PlotWidget::drain()
{
    m_sinceDrain.start();
    const int taken = takeSamples();
    if (m_dirty) {
        m_dirty = false;
        updateRanges();
        requestReplot();
    }
    return taken;
}

int PlotWidget::takeSamples()
{
    int taken = 0;
    if (m_source) {
        const std::vector<Sample> samples = m_source->readSince(m_cursor);
        for (const Sample& s : samples) {
            if (!std::isfinite(s.t))
                continue;
            if (m_lastSampleT && s.t <= *m_lastSampleT)
                dropFrom(s.t);
            for (PlotSeries& series : m_series)
                if (series.isFedBySamples())
                    appendTo(series, s.t, series.valueOf(s));
            overwriteGhostMarks(s.t);
            m_lastSampleT = s.t;
            ++taken;
        }
        if (taken > 0) {
            for (std::size_t i = 0; i < m_valueScaleOf.size(); ++i) {
                if (!m_valueScaleOf[i])
                    continue;
                const double scale = m_valueScaleOf[i](samples.back());
                m_valueScale[i] = std::isfinite(scale) && scale > 0 ? scale : 0.0;
            }
            trimToWindow();
        }
    }
    return taken;
}

void PlotWidget::dropFrom(double t)
{
    for (PlotSeries& series : m_series)
        if (!series.isEmpty())
            series.removeFrom(t, m_pointBudget);
    // A mark exactly at t belongs to the new branch of the run (set, then stepped from t).
    // Ghost marks stay until the run passes them (overwriteGhostMarks).
    for (std::size_t i = m_marks.size(); i-- > 0;)
        if (m_marks[i].t > t && !m_marks[i].ghost)
            removeMark(i);
    m_lastSampleT.reset();
    updateLatest();
    m_dirty = true;
}

void PlotWidget::clear()
{
    for (PlotSeries& series : m_series)
        series.clear();
    while (!m_marks.empty())
        removeMark(m_marks.size() - 1);
    m_lastSampleT.reset();
    m_latestT.reset();
    m_dirty = true;
    setFollowing(true);
    QScopedValueRollback<bool> guard(m_settingRanges, true);
    m_plot->xAxis->setRange(0, m_windowSeconds);
}

void PlotWidget::updateLatest()
{
    m_latestT.reset();
    for (const PlotSeries& series : m_series)
        if (!series.isEmpty())
            m_latestT = m_latestT ? std::max(*m_latestT, series.lastKey()) : series.lastKey();
}

void PlotWidget::trimToWindow()
{
    if (m_rangeMode != RangeMode::Window || !m_latestT)
        return;
    const double windowCutoff = *m_latestT - m_windowSeconds * (1 + kWindowMargin);
    double cutoff = windowCutoff;
    // As far back as the timeline goes, so that going back finds the points there; but no
    // more than half the point budget, so that the window itself is never thinned.
    if (m_timelineStart)
        cutoff = std::min(cutoff, *m_timelineStart);
    double keepFloor = windowCutoff; // the budget rule cuts no further than this
    // While paused, what the user is looking at stays; the point budget still bounds it.
    if (!m_following) {
        cutoff = std::min(cutoff, m_plot->xAxis->range().lower);
        keepFloor = std::min(keepFloor, m_plot->xAxis->range().lower);
    }
    const auto half = static_cast<std::size_t>(m_pointBudget / 2);
    for (PlotSeries& series : m_series) {
        double own = cutoff;
        if (m_timelineStart && series.points().size() > half)
            own = std::min(keepFloor,
                           std::max(own, series.points()[series.points().size() - half].t));
        if (!series.isEmpty() && series.firstKey() < own)
            series.removeBefore(own, m_pointBudget);
    }
    while (!m_marks.empty() && m_marks.front().t < cutoff)
        removeMark(0);
}

} // namespace rigidlab::ui
