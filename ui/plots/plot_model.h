// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a live plot shows, apart from how it is drawn (PlotWidget) and how it is saved
// (PlotExporter): its series and their points, the samples drained from the run, the time
// window, time travel, the marks, the value scales and the CSV column heads. It knows no
// widget and no QCustomPlot, so a test can feed it and read it back alone.
//
// Memory stays bounded however long the run (see PlotSeries): in window mode the points older
// than the window (plus a margin) are dropped; in both modes a series that grows past the
// point budget is thinned. A view paused on older points (setHeldFrom) keeps them.
//
// While the run is shorter than the window, the time axis fits it (rounded up a little, at
// least kMinTimeSpan): a lesson step of 3 s is drawn across the plot, not in its first third.
// Then the axis scrolls (followedRange).
//
// Time travel (rewind) keeps the points: those up to the chosen moment are the series' points,
// and the run's future as it was is the series' ghost until the run, going on from there,
// overwrites it. A mark in that future is a ghost too, and goes when the new branch passes it.

#include "plots/plot_series.h"
#include "simulation/sample_buffer.h"

#include <QObject>
#include <QPointF>
#include <QString>

#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

namespace rigidlab::ui {

/// What the time axis shows while following the run.
enum class RangeMode {
    Window,  ///< the last windowSeconds() of the run, scrolling
    WholeRun ///< everything since the start (thinned to the point budget)
};

/// A span of time [s] or of values [unit of the axis].
struct PlotRange {
    double lower = 0;
    double upper = 0;
};

/// A vertical mark at t [s] with a short label ("RK4", "dt = 5 ms"), where the integrator or
/// the step changed mid-run.
struct PlotMark {
    double t = 0;       ///< [s]
    QString text;       ///< its own label, before the view merges neighbours'
    bool ghost = false; ///< after the moment the timeline went back to
};

/// How a value axis fits what is shown.
struct ValueFit {
    PlotRange range;
    int labelDigits = 0; ///< significant digits the tick labels need (linear axis only)
    /// Per series: above the axis, left out of it (true only for series of that axis).
    std::vector<bool> offScale;
};

class PlotModel : public QObject {
    Q_OBJECT

public:
    static constexpr int kDefaultPointBudget = 20000;     ///< points per series
    static constexpr int kMaxMarks = 50;                  ///< marks kept at most
    static constexpr double kDefaultWindowSeconds = 10.0; ///< [s]
    /// The shortest time axis while the run is shorter than the window [s].
    static constexpr double kMinTimeSpan = 1.0;
    /// After going back on the timeline, this fraction of the window shows what came after
    /// the chosen moment (the ghost), where there is any.
    static constexpr double kGhostLookahead = 0.25;
    /// With off-scale clipping, a series more than this many times larger than the next one
    /// goes off the top of its axis.
    static constexpr double kOffScaleRatio = 100.0;

    explicit PlotModel(QObject* parent = nullptr);

    // The series.

    /// A series read from every sample drained (`value` set), or fed with appendPoint()
    /// only (one energy curve per integrator, say). Returns its index.
    int addSeries(const QString& name, PlotSeries::SampleValue value, YAxis axis = YAxis::Left);
    /// Adds (t [s], value) to a series fed point by point. A t not later than the series'
    /// last point restarts the series there (the points at and after t are dropped).
    /// Non-finite values make a gap.
    void appendPoint(int series, double t, double value);
    int seriesCount() const { return static_cast<int>(m_series.size()); }
    const PlotSeries& series(int series) const { return m_series.at(series); }
    /// The name it was added with (a lesson file's code name, "euler").
    QString seriesName(int series) const;
    /// The series' name in words as the legend gives it (the name until one is set).
    void setSeriesLegend(int series, const QString& legend);
    QString seriesLegend(int series) const;
    QString seriesUnit(int series) const;
    /// The head of a series' CSV column, the same as the command line's for that quantity
    /// (lessons/export/csv_columns.h: "E_k [J]").
    void setSeriesColumn(int series, const QString& head);
    /// The head of its CSV column: the one set, else its name (or, with `legendNames`, its
    /// legend) and unit: "euler [J]".
    QString csvHead(int series, bool legendNames) const;
    /// What the series' quantity is worth in the scene (its axis' valueScale): a value below
    /// its noise floor is written as 0 (lessons/export/noise_floor.h).
    double seriesScale(int series) const;

    /// The points of a series as (t [s], value), oldest first; those with t in `within` alone
    /// if given.
    std::vector<QPointF> points(int series, std::optional<PlotRange> within = {}) const;
    /// The ghost points of a series: the run's future as it was before rewind().
    std::vector<QPointF> ghostPoints(int series) const;
    int pointCount(int series) const;
    int pointCount() const; ///< over all series

    // The value axes.

    /// The unit of the quantity on a value axis; it also heads the CSV columns.
    void setUnit(YAxis axis, const QString& unit);
    QString unit(YAxis axis) const;
    /// What the quantity on a value axis is worth in the scene, in its unit: a variation below
    /// a billionth of it is rounding noise, drawn flat (see niceRange in plot_range.h). Fixed,
    /// or read from the last sample of each drain (the scene's momentum, say). Unset, it is 0.
    void setValueScale(YAxis axis, double scale);
    void setValueScale(YAxis axis, PlotSeries::SampleValue scale);
    /// Keeps a value axis at least this fraction of the quantity's magnitude tall (see
    /// niceRange); 0, the default, fits the data however small its variation.
    void setMinimumSpan(YAxis axis, double fraction);
    /// The range of `axis` for the times `keys` (on a log axis if `log`), over the series
    /// of that axis that are shown (`shown[i]`, all if shorter). With `clipOffScale`, series
    /// kOffScaleRatio times larger than the rest (a compared run that blew up) are left out,
    /// above it. Nothing if no shown series has a value there.
    std::optional<ValueFit> fitValues(YAxis axis, PlotRange keys, bool log,
                                      const std::vector<bool>& shown, bool clipOffScale) const;

    // The run: samples, time, travel.

    /// The buffer to drain (not owned; nullptr detaches). Reading starts at its oldest sample.
    void setSource(const SampleBuffer* source);
    /// Takes what is new in the source into the series fed by samples. A sample not later than
    /// the previous one means the run went back: the points from its time on are dropped.
    /// Returns the samples taken.
    int takeSamples();
    /// The timeline went to t [s] (back or forward): the points after t become the ghost,
    /// or ghost points up to t come back. What the source holds from before is taken first.
    void rewind(double t);
    /// The earliest time the timeline can go back to [s]: window mode keeps the points from
    /// there on (within the point budget), so that going back shows them. NaN (the default)
    /// keeps only the window.
    void setTimelineStart(double t);
    /// Drops all points and marks; keeps the series.
    void clear();

    void setRangeMode(RangeMode mode);
    RangeMode rangeMode() const { return m_rangeMode; }
    void setWindowSeconds(double seconds);
    double windowSeconds() const { return m_windowSeconds; } ///< [s]
    void setPointBudget(int points);
    int pointBudget() const { return m_pointBudget; }
    /// A view paused on older times shows from t [s] on: the points from there stay (within
    /// the point budget). Nothing: it follows the run again, and what is older than the
    /// window goes.
    void setHeldFrom(std::optional<double> t);

    /// The latest time over all series, or the moment gone back to [s].
    std::optional<double> latest() const { return m_latestT; }
    /// The time axis of a view following the run (on a log axis if `log`); nothing before
    /// the first point.
    std::optional<PlotRange> followedRange(bool log) const;

    // The marks.

    /// A mark at t [s]. Marks older than what is kept are dropped, and at most kMaxMarks kept.
    void addMark(double t, const QString& label);
    /// Sorted by t.
    const std::deque<PlotMark>& marks() const { return m_marks; }
    int markCount() const { return static_cast<int>(m_marks.size()); }
    bool markIsGhost(int index) const { return m_marks.at(static_cast<std::size_t>(index)).ghost; }

    /// Whether anything shown changed since the last call (points, marks, scales, modes).
    bool takeChanged();

signals:
    /// Marks came, went or changed between the run and its ghost.
    void marksChanged();

private:
    void appendTo(PlotSeries& series, double t, double value);
    std::optional<double> ghostEnd() const;
    void overwriteGhostMarks(double t); // the new branch reached t: older ghost marks go
    void dropFrom(double t);            // the run went back to t: drop points at and after t
    void trimToWindow();
    /// What shows changed (the window, what is followed, a mark): trims to the window, redraws
    /// and tells the marks' watchers.
    void applyWindow();
    void updateLatest();
    void removeMark(std::size_t index);
    void announceMarks(); // emits marksChanged() once after an operation that touched them
    double timeSpan(double run) const; // the time axis for a run this long in window mode
    double valueScale(YAxis axis) const;
    static std::size_t side(YAxis axis) { return axis == YAxis::Left ? 0 : 1; }

    std::vector<PlotSeries> m_series;
    std::deque<PlotMark> m_marks;                          ///< sorted by t
    std::array<QString, 2> m_unit;                         ///< left, right
    std::array<double, 2> m_valueScale{};                  ///< left, right [unit of the axis]
    std::array<PlotSeries::SampleValue, 2> m_valueScaleOf; ///< left, right; may be empty
    std::array<double, 2> m_minimumSpan{};                 ///< left, right; see niceRange

    const SampleBuffer* m_source = nullptr;
    std::uint64_t m_cursor = 0;
    std::optional<double> m_lastSampleT;   ///< [s] time of the last sample taken
    std::optional<double> m_latestT;       ///< [s] see latest()
    std::optional<double> m_timelineStart; ///< [s] see setTimelineStart()
    std::optional<double> m_heldFrom;      ///< [s] see setHeldFrom()

    RangeMode m_rangeMode = RangeMode::Window;
    double m_windowSeconds = kDefaultWindowSeconds; ///< [s]
    int m_pointBudget = kDefaultPointBudget;
    bool m_changed = false;      ///< see takeChanged()
    bool m_marksTouched = false; ///< see announceMarks()
};

} // namespace rigidlab::ui
