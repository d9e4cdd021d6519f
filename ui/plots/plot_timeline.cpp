// SPDX-License-Identifier: GPL-3.0-or-later
// PlotWidget and time travel: going back on the timeline keeps the points, the run's old
// future stays drawn faded (the ghost, see PlotSeries) until a new branch overwrites it. How
// far back the points are kept is trimToWindow's (plot_points.cpp): as far as the timeline goes.

#include "plots/plot_widget.h"

#include <algorithm>
#include <cmath>

namespace rigidlab::ui {

std::vector<QPointF> PlotWidget::ghostPoints(int series) const
{
    std::vector<QPointF> out;
    for (const PlotPoint& p : m_series.at(series).ghost())
        out.emplace_back(p.t, p.v);
    return out;
}

void PlotWidget::rewind(double t)
{
    if (!std::isfinite(t))
        return;
    // What the run sent before it went back belongs to the timeline as it was.
    takeSamples();
    bool any = false;
    for (PlotSeries& series : m_series) {
        series.travelTo(t, m_pointBudget);
        any = any || !series.isEmpty() || !series.ghost().empty();
    }
    for (Mark& mark : m_marks) {
        const bool ghost = mark.t > t;
        if (ghost != mark.ghost) {
            mark.ghost = ghost;
            styleMark(mark);
        }
    }
    // The controller sends a sample at t next: it replaces the point there.
    if (m_lastSampleT)
        m_lastSampleT = t;
    updateLatest();
    if (any)
        m_latestT = t; // "now" is the moment gone to, even with no point there
    // The timeline is where the user looks now: a plot dragged aside follows it again.
    setFollowing(true);
    m_dirty = true;
}

void PlotWidget::setTimelineStart(double t)
{
    m_timelineStart = std::isfinite(t) ? std::optional(t) : std::nullopt;
}

std::optional<double> PlotWidget::ghostEnd() const
{
    std::optional<double> end;
    for (const PlotSeries& series : m_series)
        if (!series.ghost().empty())
            end = std::max(end.value_or(series.ghost().back().t), series.ghost().back().t);
    return end;
}

void PlotWidget::overwriteGhostMarks(double t)
{
    for (std::size_t i = m_marks.size(); i-- > 0;)
        if (m_marks[i].ghost && m_marks[i].t <= t)
            removeMark(i);
}

} // namespace rigidlab::ui
