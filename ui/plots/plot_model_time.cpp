// SPDX-License-Identifier: GPL-3.0-or-later
// PlotModel and time: the window kept and followed, time travel (going back keeps the points;
// the run's old future stays as the ghost, see PlotSeries, until a new branch overwrites it),
// and the marks, which scroll out, and go ghost and back with the points.

#include "plots/plot_model.h"

#include "plots/plot_range.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace rigidlab::ui {

namespace {

/// In window mode points are kept this fraction of the window longer than shown, so a
/// curve enters from the left edge instead of starting inside the plot.
constexpr double kWindowMargin = 0.1;
/// Smallest time span [s] shown in whole-run mode, so a single point has an axis.
constexpr double kMinWholeRunSpan = 1e-3;

} // namespace

void PlotModel::rewind(double t)
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
    for (PlotMark& mark : m_marks) {
        const bool ghost = mark.t > t;
        if (ghost != mark.ghost) {
            mark.ghost = ghost;
            m_marksTouched = true;
        }
    }
    // The controller sends a sample at t next: it replaces the point there.
    if (m_lastSampleT)
        m_lastSampleT = t;
    updateLatest();
    if (any)
        m_latestT = t; // "now" is the moment gone to, even with no point there
    m_changed = true;
    announceMarks();
}

void PlotModel::setTimelineStart(double t)
{
    m_timelineStart = std::isfinite(t) ? std::optional(t) : std::nullopt;
}

void PlotModel::clear()
{
    for (PlotSeries& series : m_series)
        series.clear();
    m_marksTouched = m_marksTouched || !m_marks.empty();
    m_marks.clear();
    m_lastSampleT.reset();
    m_latestT.reset();
    m_heldFrom.reset();
    m_changed = true;
    announceMarks();
}

void PlotModel::setRangeMode(RangeMode mode)
{
    if (mode == m_rangeMode)
        return;
    m_rangeMode = mode;
    applyWindow();
}

void PlotModel::setWindowSeconds(double seconds)
{
    Q_ASSERT(std::isfinite(seconds) && seconds > 0);
    if (!std::isfinite(seconds) || seconds <= 0)
        return;
    m_windowSeconds = seconds;
    applyWindow();
}

void PlotModel::setPointBudget(int points)
{
    m_pointBudget = std::max(points, 16);
}

void PlotModel::setHeldFrom(std::optional<double> t)
{
    const bool following = !t && m_heldFrom;
    m_heldFrom = t;
    if (following)
        applyWindow();
}

std::optional<double> PlotModel::ghostEnd() const
{
    std::optional<double> end;
    for (const PlotSeries& series : m_series)
        if (!series.ghost().empty())
            end = std::max(end.value_or(series.ghost().back().t), series.ghost().back().t);
    return end;
}

std::optional<PlotRange> PlotModel::followedRange(bool log) const
{
    if (!m_latestT)
        return std::nullopt;
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
        const double upper = std::max(end, first + span);
        return PlotRange{upper - span, upper};
    }
    if (log) // a log axis (work against precision): a third of a decade beyond the points
        return PlotRange{first / 2, *m_latestT * 2};
    const double end = std::max(*m_latestT, ghost.value_or(*m_latestT));
    return PlotRange{first, first + std::max(end - first, kMinWholeRunSpan)};
}

double PlotModel::timeSpan(double run) const
{
    if (!(run < m_windowSeconds))
        return m_windowSeconds;
    // Rounded up to a twentieth-ish round step: the axis grows in small jumps, and the run
    // fills at least 19/20 of it.
    const double step = niceStep(std::max(run, kMinTimeSpan), 20);
    const double rounded = std::ceil(run / step - 1e-9) * step;
    return std::clamp(rounded, std::min(kMinTimeSpan, m_windowSeconds), m_windowSeconds);
}

void PlotModel::overwriteGhostMarks(double t)
{
    for (std::size_t i = m_marks.size(); i-- > 0;)
        if (m_marks[i].ghost && m_marks[i].t <= t)
            removeMark(i);
}

void PlotModel::dropFrom(double t)
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
    m_changed = true;
}

void PlotModel::updateLatest()
{
    m_latestT.reset();
    for (const PlotSeries& series : m_series)
        if (!series.isEmpty())
            m_latestT = m_latestT ? std::max(*m_latestT, series.lastKey()) : series.lastKey();
}

void PlotModel::applyWindow()
{
    trimToWindow();
    m_changed = true;
    announceMarks();
}

void PlotModel::trimToWindow()
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
    if (m_heldFrom) {
        cutoff = std::min(cutoff, *m_heldFrom);
        keepFloor = std::min(keepFloor, *m_heldFrom);
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

void PlotModel::addMark(double t, const QString& label)
{
    if (!std::isfinite(t))
        return;
    const auto at = std::upper_bound(m_marks.begin(), m_marks.end(), t,
                                     [](double time, const PlotMark& m) { return time < m.t; });
    m_marks.insert(at, PlotMark{t, label, false});
    m_marksTouched = true;
    while (m_marks.size() > static_cast<std::size_t>(kMaxMarks))
        removeMark(0);
    applyWindow();
}

void PlotModel::removeMark(std::size_t index)
{
    m_marks.erase(m_marks.begin() + static_cast<std::ptrdiff_t>(index));
    m_marksTouched = true;
    m_changed = true;
}

void PlotModel::announceMarks()
{
    if (std::exchange(m_marksTouched, false))
        emit marksChanged();
}

} // namespace rigidlab::ui
