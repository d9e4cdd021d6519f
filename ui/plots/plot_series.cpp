// SPDX-License-Identifier: GPL-3.0-or-later
#include "plots/plot_series.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace rigidlab::ui {

namespace {

bool earlier(const PlotPoint& p, double t)
{
    return p.t < t;
}

bool later(double t, const PlotPoint& p)
{
    return t < p.t;
}

bool lowestHighest(const std::vector<PlotPoint>& points, double from, double to, bool positiveOnly,
                   double& lowest, double& highest, bool found)
{
    const auto begin = std::lower_bound(points.begin(), points.end(), from, earlier);
    const auto end = std::upper_bound(begin, points.end(), to, later);
    for (auto it = begin; it != end; ++it) {
        if (!std::isfinite(it->v) || (positiveOnly && !(it->v > 0)))
            continue;
        lowest = found ? std::min(lowest, it->v) : it->v;
        highest = found ? std::max(highest, it->v) : it->v;
        found = true;
    }
    return found;
}

} // namespace

PlotSeries::PlotSeries(QString name, YAxis axis, SampleValue value)
    : m_name(std::move(name)), m_axis(axis), m_value(std::move(value))
{
}

double PlotSeries::firstKey() const
{
    Q_ASSERT(!isEmpty());
    return m_points.front().t;
}

double PlotSeries::lastKey() const
{
    Q_ASSERT(!isEmpty());
    return m_points.back().t;
}

void PlotSeries::append(double t, double value, int budget)
{
    Q_ASSERT(isEmpty() || t > lastKey());
    const bool keep = m_points.empty() || m_sinceKept + 1 >= m_stride;

    if (m_lastIsProvisional)
        m_points.back() = {t, value}; // the provisional point moves on with the run
    else
        m_points.push_back({t, value});

    if (keep) {
        m_sinceKept = 0;
        m_lastIsProvisional = false;
    } else {
        ++m_sinceKept;
        m_lastIsProvisional = true;
    }
    if (size() > budget)
        decimate();
    // The new branch overwrites the old future as far as it has come.
    if (!m_ghost.empty() && m_ghost.front().t <= t)
        m_ghost.erase(m_ghost.begin(), std::upper_bound(m_ghost.begin(), m_ghost.end(), t, later));
}

void PlotSeries::travelTo(double t, int budget)
{
    if (!m_points.empty() && t < m_points.back().t) {
        const auto after = std::upper_bound(m_points.begin(), m_points.end(), t, later);
        m_ghost.insert(m_ghost.begin(), after, m_points.end());
        m_points.erase(after, m_points.end());
    } else if (!m_ghost.empty() && m_ghost.front().t <= t) {
        const auto upTo = std::upper_bound(m_ghost.begin(), m_ghost.end(), t, later);
        m_points.insert(m_points.end(), m_ghost.begin(), upTo);
        m_ghost.erase(m_ghost.begin(), upTo);
    } else {
        return;
    }
    m_lastIsProvisional = false; // what is left ends on a point that now counts as kept
    m_sinceKept = 0;
    afterRemoval(budget);
    if (size() > budget)
        decimate();
}

void PlotSeries::decimate()
{
    const std::size_t kept = m_points.size() - (m_lastIsProvisional ? 1 : 0);
    const PlotPoint newest = m_points.back();

    std::size_t out = 0;
    for (std::size_t i = 0; i < kept; i += 2)
        m_points[out++] = m_points[i];

    // With an even count the newest kept point is among the dropped ones: it stays as the
    // provisional end of the curve, and the next kept point comes a whole new stride after
    // the last surviving one.
    const bool lastKeptDropped = kept % 2 == 0;
    if (m_lastIsProvisional || lastKeptDropped)
        m_points[out++] = newest;
    m_points.resize(out);
    if (lastKeptDropped) {
        m_sinceKept += m_stride;
        m_lastIsProvisional = true;
    }
    m_stride *= 2;
}

void PlotSeries::removeBefore(double t, int budget)
{
    m_points.erase(m_points.begin(),
                   std::lower_bound(m_points.begin(), m_points.end(), t, earlier));
    if (isEmpty()) {
        m_lastIsProvisional = false;
        m_sinceKept = 0;
    }
    afterRemoval(budget);
}

void PlotSeries::removeAfter(double t, int budget)
{
    m_points.erase(std::upper_bound(m_points.begin(), m_points.end(), t, later), m_points.end());
    // What is left ends on a point that now counts as kept.
    m_lastIsProvisional = false;
    m_sinceKept = 0;
    afterRemoval(budget);
}

void PlotSeries::removeFrom(double t, int budget)
{
    removeAfter(std::nextafter(t, -std::numeric_limits<double>::infinity()), budget);
}

void PlotSeries::clear()
{
    m_points.clear();
    m_ghost.clear();
    m_stride = 1;
    m_sinceKept = 0;
    m_lastIsProvisional = false;
}

void PlotSeries::afterRemoval(int budget)
{
    // Once few points are left (after a rewind, or scrolling past a burst), new points may
    // come denser again; the old sparse ones scroll out or stay as they are.
    if (m_stride > 1 && size() * 4 < budget)
        m_stride /= 2;
}

bool PlotSeries::valueRange(double from, double to, bool positiveOnly, double& lowest,
                            double& highest) const
{
    const bool found = lowestHighest(m_points, from, to, positiveOnly, lowest, highest, false);
    return lowestHighest(m_ghost, from, to, positiveOnly, lowest, highest, found);
}

} // namespace rigidlab::ui
