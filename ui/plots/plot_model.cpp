// SPDX-License-Identifier: GPL-3.0-or-later
// PlotModel's series, their points and the samples they are taken from, the value axes'
// scales and fit, and the CSV column heads. Time (the window, time travel, the marks):
// plot_model_time.cpp.

#include "plots/plot_model.h"

#include "plots/plot_range.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace rigidlab::ui {

PlotModel::PlotModel(QObject* parent) : QObject(parent) {}

int PlotModel::addSeries(const QString& name, PlotSeries::SampleValue value, YAxis axis)
{
    m_series.emplace_back(name, axis, std::move(value));
    return seriesCount() - 1;
}

void PlotModel::appendPoint(int series, double t, double value)
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
    announceMarks();
}

void PlotModel::appendTo(PlotSeries& series, double t, double value)
{
    // A gap in the curve rather than an infinite axis range.
    const double v = std::isfinite(value) ? value : std::numeric_limits<double>::quiet_NaN();
    series.append(t, v, m_pointBudget);
    m_latestT = m_latestT ? std::max(*m_latestT, t) : t;
    m_changed = true;
}

QString PlotModel::seriesName(int series) const
{
    return m_series.at(series).name();
}

void PlotModel::setSeriesLegend(int series, const QString& legend)
{
    m_series.at(series).setLegend(legend);
}

QString PlotModel::seriesLegend(int series) const
{
    return m_series.at(series).legend();
}

QString PlotModel::seriesUnit(int series) const
{
    return unit(m_series.at(series).axis());
}

void PlotModel::setSeriesColumn(int series, const QString& head)
{
    m_series.at(series).setColumn(head);
}

QString PlotModel::csvHead(int series, bool legendNames) const
{
    const PlotSeries& s = m_series.at(series);
    if (!s.column().isEmpty())
        return s.column();
    const QString unit = seriesUnit(series);
    const QString name = legendNames ? s.legend() : s.name();
    return unit.isEmpty() ? name : QStringLiteral("%1 [%2]").arg(name, unit);
}

double PlotModel::seriesScale(int series) const
{
    return valueScale(m_series.at(series).axis());
}

std::vector<QPointF> PlotModel::points(int series, std::optional<PlotRange> within) const
{
    const std::vector<PlotPoint>& kept = m_series.at(series).points();
    std::vector<QPointF> out;
    out.reserve(kept.size());
    for (const PlotPoint& p : kept)
        if (!within || (p.t >= within->lower && p.t <= within->upper))
            out.emplace_back(p.t, p.v);
    return out;
}

std::vector<QPointF> PlotModel::ghostPoints(int series) const
{
    std::vector<QPointF> out;
    for (const PlotPoint& p : m_series.at(series).ghost())
        out.emplace_back(p.t, p.v);
    return out;
}

int PlotModel::pointCount(int series) const
{
    return m_series.at(series).size();
}

int PlotModel::pointCount() const
{
    int n = 0;
    for (const PlotSeries& s : m_series)
        n += s.size();
    return n;
}

void PlotModel::setUnit(YAxis axis, const QString& unit)
{
    m_unit[side(axis)] = unit;
}

QString PlotModel::unit(YAxis axis) const
{
    return m_unit[side(axis)];
}

void PlotModel::setValueScale(YAxis axis, double scale)
{
    m_valueScaleOf[side(axis)] = {};
    m_valueScale[side(axis)] = std::isfinite(scale) && scale > 0 ? scale : 0.0;
    m_changed = true;
}

void PlotModel::setValueScale(YAxis axis, PlotSeries::SampleValue scale)
{
    m_valueScaleOf[side(axis)] = std::move(scale);
    m_changed = true;
}

double PlotModel::valueScale(YAxis axis) const
{
    return m_valueScale[side(axis)];
}

void PlotModel::setMinimumSpan(YAxis axis, double fraction)
{
    m_minimumSpan[side(axis)] = std::isfinite(fraction) && fraction > 0 ? fraction : 0.0;
    m_changed = true;
}

std::optional<ValueFit> PlotModel::fitValues(YAxis axis, PlotRange keys, bool log,
                                             const std::vector<bool>& shown,
                                             bool clipOffScale) const
{
    struct Extent {
        std::size_t series;
        double lo, hi, magnitude;
    };
    std::vector<Extent> extents;
    for (std::size_t i = 0; i < m_series.size(); ++i) {
        const PlotSeries& series = m_series[i];
        if (series.axis() != axis || (i < shown.size() && !shown[i]))
            continue;
        double lo = 0, hi = 0;
        if (!series.valueRange(keys.lower, keys.upper, log, lo, hi))
            continue;
        extents.push_back({i, lo, hi, std::max(std::abs(lo), std::abs(hi))});
    }
    if (extents.empty())
        return std::nullopt;
    // A compared run that blew up (1e10 J beside 1000 J) would flatten the runs that survive
    // to a line at 0: the axis fits the survivors, and the runs beyond kOffScaleRatio times
    // them go off the top.
    ValueFit fit;
    fit.offScale.assign(m_series.size(), false);
    if (clipOffScale && !log) {
        std::sort(extents.begin(), extents.end(),
                  [](const Extent& a, const Extent& b) { return a.magnitude < b.magnitude; });
        const double floor = std::max(valueScale(axis), kMinMagnitude);
        std::size_t kept = 1;
        while (kept < extents.size() &&
               extents[kept].magnitude <=
                   kOffScaleRatio * std::max(extents[kept - 1].magnitude, floor))
            ++kept;
        for (std::size_t k = kept; k < extents.size(); ++k)
            fit.offScale[extents[k].series] = true;
        extents.resize(kept);
    }
    double lowest = extents.front().lo, highest = extents.front().hi;
    for (const Extent& e : extents) {
        lowest = std::min(lowest, e.lo);
        highest = std::max(highest, e.hi);
    }
    if (log) {
        fit.range = {lowest / 2, highest * 2};
        return fit;
    }
    // Rounding noise is drawn flat, and the ticks always read differently (plot_range.h).
    const AxisRange range = niceRange(lowest, highest, valueScale(axis), m_minimumSpan[side(axis)]);
    fit.range = {range.lower, range.upper};
    fit.labelDigits = range.labelDigits;
    return fit;
}

void PlotModel::setSource(const SampleBuffer* source)
{
    m_source = source;
    m_cursor = 0; // readSince() starts at the oldest sample still in the ring
}

int PlotModel::takeSamples()
{
    if (!m_source)
        return 0;
    int taken = 0;
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
    announceMarks();
    return taken;
}

bool PlotModel::takeChanged()
{
    return std::exchange(m_changed, false);
}

} // namespace rigidlab::ui
