#pragma once
// One curve of a live plot, kept within a point budget however long the run.
//
// The points live in the QCPGraph's own container: there is no second copy. Two rules keep
// their number bounded:
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

#include "sample_buffer.h"

#include <QString>

#include <functional>

class QCPGraph;

namespace rigidlab::ui {

/// Which value axis a series is drawn against.
enum class YAxis { Left, Right };

class PlotSeries {
public:
    /// Reads the series' value out of a sample; empty for a series fed point by point.
    using SampleValue = std::function<double(const Sample&)>;

    /// `graph` belongs to its QCustomPlot; the series only adapts it.
    PlotSeries(QCPGraph* graph, QString name, YAxis axis, SampleValue value);

    const QString& name() const { return m_name; }
    YAxis axis() const { return m_axis; }
    QCPGraph* graph() const { return m_graph; }
    bool isFedBySamples() const { return static_cast<bool>(m_value); }
    double valueOf(const Sample& s) const { return m_value(s); }

    /// Appends (t [s], value); t must be later than lastKey(). Keeps size() <= budget.
    void append(double t, double value, int budget);
    /// Drops the points with t < `t` [s].
    void removeBefore(double t, int budget);
    /// Drops the points with t > `t` [s].
    void removeAfter(double t, int budget);
    /// Drops the points with t >= `t` [s].
    void removeFrom(double t, int budget);
    void clear();

    int size() const;
    bool isEmpty() const { return size() == 0; }
    double firstKey() const; ///< [s]; the series must not be empty
    double lastKey() const;  ///< [s]; the series must not be empty
    int stride() const { return m_stride; }

private:
    void decimate();
    void afterRemoval(int budget);

    QCPGraph* m_graph = nullptr; ///< owned by the QCustomPlot
    QString m_name;
    YAxis m_axis = YAxis::Left;
    SampleValue m_value;
    int m_stride = 1;                 ///< one incoming point in `stride` is kept
    int m_sinceKept = 0;              ///< incoming points since the last kept one
    bool m_lastIsProvisional = false; ///< the newest point is off the stride
};

} // namespace rigidlab::ui
