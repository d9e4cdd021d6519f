// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One curve of a live plot (the points of PlotModel's series), kept within a point budget
// however long the run. It knows nothing of drawing: the view hands its points to a
// ColumnGraph (column_graph.h), which takes them decimated to the pixels it is drawn on.
//
// Two rules keep the number of points kept bounded:
//  - the owner trims what scrolled out of the window with removeBefore();
//  - a curve that grows past its budget drops every other point, and from then on keeps only
//    one incoming point in `stride`. Thinning the incoming points too keeps the density even
//    along the whole curve; halving the stored points alone would thin the start of a long
//    run again and again while the recent part stays dense.
// Whatever the stride, the newest point is always shown (a "provisional" point that the next
// one replaces unless it falls on the stride), so the end of the curve never lags behind the
// simulation.
//
//   stride 2:   kept   .   kept   .   kept   .   provisional
//               x0     x1  x2     x3  x4     x5  x6 (replaced by x7, kept at x8)
//
// Time travel splits a series in two: the points up to the moment the timeline went back to
// (points(), drawn as usual) and those after it (ghost(), the run's future as it was, drawn
// faded). Going forward on the timeline takes ghost points back; the
// run going on from there overwrites them, so a new branch replaces the old future as it
// is drawn:
//
//   points ______/\____|. . . .          ghost: faded, dashed
//                       t (timeline)

#include "simulation/sample_buffer.h"

#include <QString>

#include <functional>
#include <vector>

namespace rigidlab::ui {

/// Which value axis a series is drawn against.
enum class YAxis { Left, Right };

/// A point of a series: time [s] and value [unit of the series]; a NaN value is a gap.
struct PlotPoint {
    double t = 0;
    double v = 0;
};

class PlotSeries {
public:
    /// Reads the series' value out of a sample; empty for a series fed point by point.
    using SampleValue = std::function<double(const Sample&)>;

    PlotSeries(QString name, YAxis axis, SampleValue value);

    const QString& name() const { return m_name; }
    /// The name in the legend, in words (the name itself until one is set).
    const QString& legend() const { return m_legend.isEmpty() ? m_name : m_legend; }
    void setLegend(QString legend) { m_legend = std::move(legend); }
    /// The head of its column in a CSV ("E_k [J]"); empty: its name and the axis' unit.
    const QString& column() const { return m_column; }
    void setColumn(QString column) { m_column = std::move(column); }
    YAxis axis() const { return m_axis; }
    bool isFedBySamples() const { return static_cast<bool>(m_value); }
    double valueOf(const Sample& s) const { return m_value(s); }

    /// Appends (t [s], value); t must be later than lastKey(). Keeps size() <= budget. The
    /// ghost points up to t are overwritten: dropped.
    void append(double t, double value, int budget);
    /// The timeline went to t [s]: points after t become ghost points, or ghost points up to
    /// t points again.
    void travelTo(double t, int budget);
    /// Drops the points with t < `t` [s].
    void removeBefore(double t, int budget);
    /// Drops the points with t > `t` [s].
    void removeAfter(double t, int budget);
    /// Drops the points with t >= `t` [s].
    void removeFrom(double t, int budget);
    void clear(); ///< the ghost too

    int size() const { return static_cast<int>(m_points.size()); }
    bool isEmpty() const { return m_points.empty(); }
    const std::vector<PlotPoint>& points() const { return m_points; }
    double firstKey() const; ///< [s]; the series must not be empty
    double lastKey() const;  ///< [s]; the series must not be empty
    /// The run's future before the timeline went back, oldest first; all after lastKey().
    const std::vector<PlotPoint>& ghost() const { return m_ghost; }
    int stride() const { return m_stride; }

    /// The lowest and highest finite value of the points and ghost points with t in
    /// [from, to] [s] (only the positive ones if asked, for a log axis). False if none.
    bool valueRange(double from, double to, bool positiveOnly, double& lowest,
                    double& highest) const;

private:
    void decimate();
    void afterRemoval(int budget);

    std::vector<PlotPoint> m_points; ///< sorted by t
    std::vector<PlotPoint> m_ghost;  ///< sorted by t, all after m_points
    QString m_name;
    QString m_legend;
    QString m_column;
    YAxis m_axis = YAxis::Left;
    SampleValue m_value;
    int m_stride = 1;                 ///< one incoming point in `stride` is kept
    int m_sinceKept = 0;              ///< incoming points since the last kept one
    bool m_lastIsProvisional = false; ///< the newest point is off the stride
};

} // namespace rigidlab::ui
