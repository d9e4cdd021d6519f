// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A live plot of the lab window: a QCustomPlot with a title, labelled axes with units, a
// legend, and series that either read a value out of each Sample of a SampleBuffer or are fed
// point by point (appendPoint). The widget drains its source about 30 times a second, right
// after a frame of the run when told of frames (frameAdvanced), else on a timer of its own,
// and replots, queued, only when something changed; the simulation never waits for it. A
// replot hands each graph its points decimated to the pixel columns (prepareGraphs), and
// the value axes follow niceRange (plot_range.h): what it costs and what it shows do not
// depend on rounding noise.
//
// Memory stays bounded however long the run (see PlotSeries): in window mode the points older
// than the window (plus a margin) are dropped; in both modes a series that grows past the
// point budget is thinned. Dragging or zooming the plot pauses following the run (data keeps
// arriving); "Follow" (button, double-click, context menu) resumes it.
//
// While the run is shorter than the window, the time axis fits it (rounded up a little, at
// least kMinTimeSpan): a lesson step of 3 s is drawn across the plot, not in its first third.
// Then the axis scrolls.
//
// Time travel (rewind) keeps the points: those up to the chosen moment are drawn as usual, the
// axis follows that moment, and the run's future as it was stays drawn faded and dotted (the
// "ghost", see PlotSeries) until the run, going on from there, overwrites it. A mark in that
// future is faded too, and goes when the new branch passes it.

#include "plots/plot_export.h"
#include "plots/plot_series.h"
#include "simulation/sample_buffer.h"

#include <QColor>
#include <QElapsedTimer>
#include <QList>
#include <QPointF>
#include <QPointer>
#include <QString>
#include <QWidget>

#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

class QAction;
class QCustomPlot;
class QCPAxis;
class QCPGraph;
class QCPItemLine;
class QCPItemText;
class QCPTextElement;
class QTimer;
class QToolButton;

namespace rigidlab::ui {

/// What the time axis shows while following the run.
enum class RangeMode {
    Window,  ///< the last windowSeconds() of the run, scrolling
    WholeRun ///< everything since the start (thinned to the point budget)
};

class PlotWidget : public QWidget {
    Q_OBJECT

public:
    static constexpr int kDefaultPointBudget = 20000;     ///< points per series
    static constexpr int kMaxMarks = 50;                  ///< vertical marks kept at most
    static constexpr double kDefaultWindowSeconds = 10.0; ///< [s]
    static constexpr int kRefreshIntervalMs = 33;         ///< drain and replot at ~30 Hz
    /// The shortest time axis while the run is shorter than the window [s].
    static constexpr double kMinTimeSpan = 1.0;
    /// After going back on the timeline, this fraction of the window shows what came after
    /// the chosen moment (the ghost), where there is any.
    static constexpr double kGhostLookahead = 0.25;

    explicit PlotWidget(const QString& title, QWidget* parent = nullptr);
    ~PlotWidget() override;

    QString title() const;
    /// Shows or hides the title on screen (a dock may already show it); exports always show it.
    void setTitleShown(bool shown);
    bool titleShown() const { return m_titleShown; }
    /// A second line under the title for handouts ("lesson, step, integrator, dt"); it may
    /// hold a line break. Shown in exports only, unless setCaptionShown(true).
    void setCaption(const QString& caption);
    QString caption() const { return m_captionText; }
    void setCaptionShown(bool shown);
    bool captionShown() const { return m_captionShown; }
    /// The caption's text colour: grey in the window, black in presentation mode.
    QColor captionColour() const;

    /// What the plot's data is of, for the names its exports propose: the scene's title, or
    /// the lesson's and its step ("Energy drift, step 2").
    void setExportContext(const QString& context) { m_exportContext = context; }
    QString exportContext() const { return m_exportContext; }
    /// The file name an export dialog proposes: the context, the plot's title and the
    /// language, safe on a Windows share and a USB stick ("welcome_energy_en.csv").
    QString proposedFileName(ExportFormat format) const;

    /// Labels a value axis "quantity [unit]"; the unit also heads the CSV columns.
    void setYAxisLabel(const QString& quantity, const QString& unit, YAxis axis = YAxis::Left);
    QString yAxisUnit(YAxis axis) const;
    /// What the quantity on a value axis is worth in the scene, in its unit: a variation below
    /// a billionth of it is rounding noise, drawn flat (see niceRange in plot_range.h). Fixed,
    /// or read from each sample drained (the scene's momentum, say). Unset, it is 0.
    void setValueScale(YAxis axis, double scale);
    void setValueScale(YAxis axis, PlotSeries::SampleValue scale);
    double valueScale(YAxis axis) const;
    /// Keeps a value axis at least this fraction of the quantity's magnitude tall (see
    /// niceRange); 0, the default, fits the data however small its variation.
    void setMinimumSpan(YAxis axis, double fraction);

    /// A series that reads its value from every sample of the source. Returns its index.
    /// Series on the right axis are drawn dashed, and say so in the legend.
    int addSeries(const QString& name, const QColor& color, PlotSeries::SampleValue value,
                  YAxis axis = YAxis::Left);
    /// A series fed with appendPoint() only (one energy curve per integrator, say).
    int addSeries(const QString& name, const QColor& color, YAxis axis = YAxis::Left);
    /// Adds (t [s], value) to a series. A t not later than the series' last point restarts
    /// the series there (the points at and after t are dropped). Non-finite values make a gap.
    void appendPoint(int series, double t, double value);

    int seriesCount() const { return static_cast<int>(m_series.size()); }
    /// The series' name in the legend (the CSV keeps the name it was added with).
    void setSeriesLegend(int series, const QString& legend);
    /// Whether the value axis leaves that series out, above it: it grew more than
    /// kOffScaleRatio times the others (a compared run that blew up), and its legend says
    /// "↑ off scale".
    bool offScale(int series) const;
    /// Lets series go off the top of the value axis as above (off by default: in one run's
    /// plot, 1e-16 beside 1 is no runaway).
    void setOffScaleClipping(bool on);
    /// A series more than this many times larger than the next one goes off the top.
    static constexpr double kOffScaleRatio = 100.0;
    /// Draws a series in this pen style, its line `widthFactor` times as wide as the others
    /// (its colour stays), on screen, in presentation mode and in exports.
    void setSeriesPen(int series, Qt::PenStyle style, double widthFactor = 1.0);
    /// The graph that draws a series, for styling (pen, scatter); owned by plot().
    QCPGraph* graph(int series) const;
    QString seriesName(int series) const;
    /// The series' name as the legend gives it (setSeriesLegend), without "(right axis)".
    QString seriesLegend(int series) const;
    QString seriesUnit(int series) const;
    /// The head of a series' CSV column, the same as the command line's for that quantity
    /// (lessons/export/csv_columns.h: "E_k [J]"); unset, its name and unit: "euler [J]".
    void setSeriesColumn(int series, const QString& head);
    QString seriesColumn(int series) const;
    /// What the series' quantity is worth in the scene (its axis' valueScale): a value below
    /// its noise floor is written as 0 (lessons/export/noise_floor.h).
    double seriesScale(int series) const;
    /// The points of the series with t in the time axis' range as shown [s].
    std::vector<QPointF> visiblePoints(int series) const;
    /// The points of a series as (t [s], value), oldest first.
    std::vector<QPointF> points(int series) const;
    int pointCount(int series) const;
    int pointCount() const; ///< over all series

    /// The buffer to drain (not owned; nullptr detaches). Reading starts at its oldest sample.
    void setSource(const SampleBuffer* source);
    /// Takes what is new in the source, and brings the view up to date if anything changed
    /// (ranges, queued replot). The timer calls it; tests may too. Returns the samples taken.
    /// A sample not later than the previous one means the run went back: the points from its
    /// time on are dropped.
    int drain();

    void setRangeMode(RangeMode mode);
    RangeMode rangeMode() const { return m_rangeMode; }
    void setWindowSeconds(double seconds);
    double windowSeconds() const { return m_windowSeconds; } ///< [s]
    void setPointBudget(int points);
    int pointBudget() const { return m_pointBudget; }

    bool isFollowing() const { return m_following; }
    void setFollowing(bool following);

    /// The timeline went to t [s] (back or forward): the points after t become the ghost,
    /// drawn faded, or ghost points up to t come back; the time axis follows t (a plot
    /// dragged aside follows again). What the source holds from before is drained first.
    void rewind(double t);
    /// The ghost points of a series: the run's future as it was before rewind().
    std::vector<QPointF> ghostPoints(int series) const;
    /// The earliest time the timeline can go back to [s]: window mode keeps the points from
    /// there on (within the point budget), so that going back shows them. NaN (the default)
    /// keeps only the window.
    void setTimelineStart(double t);
    /// New scene or reset: drops all points and marks, keeps the series, follows again.
    void clear();
    /// A dashed vertical line at t [s] with a short label ("RK4", "dt = 5 ms"), where the
    /// integrator or the step changed mid-run. Marks that scroll out are dropped, and at most
    /// kMaxMarks are kept.
    void addMark(double t, const QString& label);
    int markCount() const { return static_cast<int>(m_marks.size()); }
    /// The label drawn for the index-th mark (oldest first); hidden where merged into a
    /// neighbour's or out of view.
    QCPItemText* markLabel(int index) const
    {
        return m_marks.at(static_cast<std::size_t>(index)).label;
    }
    /// Whether the index-th mark lies in the ghost (after the moment gone back to).
    bool markIsGhost(int index) const { return m_marks.at(static_cast<std::size_t>(index)).ghost; }
    /// Stacks and merges the marks' labels for a plot `widthPx` wide (the widget's width on
    /// screen; the export's while exporting). Labels that would overlap go on rows above one
    /// another (at most kMarkRows); marks closer than kMergePx share one label.
    void fitMarks(int widthPx = 0);
    static constexpr int kMarkRows = 3;
    static constexpr double kMergePx = 6.0;

    /// An action the plot's context menu offers after its own (Graph of bodies…); not owned.
    void addMenuAction(QAction* action) { m_menuActions << action; }

    /// The underlying plot, for export and styling. It stays owned by this widget.
    QCustomPlot* plot() const { return m_plot; }
    /// Hands each graph its points decimated to `columns` pixel columns of the time axis
    /// shown (see PlotSeries::draw); 0 takes the plot's width on screen. Every replot does
    /// this first; an export does it for the export's width.
    void prepareGraphs(int columns = 0);
    /// Wraps the legend into as many columns as fit `widthPx` (the widget's width on screen;
    /// the export size while exporting).
    /// In presentation mode its text also shrinks (to the plain size at least) until it takes
    /// one line or at most a fifth of the plot's height.
    void fitLegend(int widthPx);

    /// Presentation mode: larger titles, axis labels (18 pt) and legend, curves at least
    /// theme::kPresentationMinLinePx wide.
    void setPresentation(bool on);
    bool presentation() const { return m_presentation; }

public slots:
    void follow() { setFollowing(true); }
    /// The run advanced a frame: drains now if the refresh interval has passed. A plot told
    /// of every frame drains right after one, so that its replot does not land on the next
    /// frame's deadline; its own timer then only stands in while no frames come (a paused
    /// run).
    void frameAdvanced();
    /// Asks for a file name, then exports; a failure is shown in a message box. Returns the
    /// file written, or an empty string. The dialog opens in the folder last exported into
    /// (else Documents) with a name proposed from the export context, the plot's title and
    /// the language; a CSV's dialect is one of its filters, the window's by default, and a
    /// change is remembered.
    QString exportInteractively(rigidlab::ui::ExportFormat format);
    /// Puts the data shown (the series over the time axis' range) on the clipboard as
    /// tab-separated text in the language's number format (Ctrl+C).
    void copyData();

signals:
    void followingChanged(bool following);
    void rangeModeChanged(rigidlab::ui::RangeMode mode);
    void exported(const QString& path);

protected:
    void resizeEvent(QResizeEvent* event) override;
    void showEvent(QShowEvent* event) override;

private:
    /// The axis rect's right margin: half a tick label, so "10" is not cut at the edge [px].
    static constexpr int kRightMarginPx = 22;
    /// Marks the series of `axis` that go off the top of it (true in `offScale`), in the
    /// legend.
    void setOffScale(YAxis axis, const std::vector<bool>& offScale);
    QString offScaleMark() const;
    struct Mark {
        double t = 0;                 ///< [s]
        QString text;                 ///< its own label, before merging
        bool ghost = false;           ///< after the moment the timeline went back to
        QCPItemLine* line = nullptr;  ///< owned by m_plot
        QCPItemText* label = nullptr; ///< owned by m_plot
    };

    /// Wraps the legend into columns that fit `widthPx`; returns its rows.
    int wrapLegend(int widthPx);
    /// Fewer ticks on an axis too short for the usual count's labels, so they never overlap.
    void fitTicks();
    int addGraph(const QString& name, const QColor& color, PlotSeries::SampleValue value,
                 YAxis axis);
    void appendTo(PlotSeries& series, double t, double value);
    int takeSamples(); // from the source, without updating the view
    std::optional<double> ghostEnd() const;
    void overwriteGhostMarks(double t); // the new branch reached t: older ghost marks go
    void styleMark(const Mark& mark);
    void dropFrom(double t); // the run went back to t: drop points at and after t
    void trimToWindow();
    void updateLatest();
    void updateRanges();
    void fitValueAxis(YAxis axis);
    void requestReplot();
    void removeMark(std::size_t index);
    void updateMarkLabels();
    double timeSpan(double run) const; // the time axis for a run this long in window mode
    void placeFollowButton();
    void showContextMenu(const QPoint& pos);
    void installMenuAndCopy(); ///< the context menu, and Ctrl+C for copyData()
    void onRangeChanged();
    QCPAxis* axisFor(YAxis axis) const;

    QCustomPlot* m_plot = nullptr; ///< child
    bool m_titleShown = true;
    QCPTextElement* m_title = nullptr;   ///< owned by m_plot's layout
    QCPTextElement* m_caption = nullptr; ///< child of m_plot; in its layout while shown
    QString m_captionText;
    QString m_exportContext;
    bool m_captionShown = false;
    QToolButton* m_followButton = nullptr; ///< child, shown while paused
    QTimer* m_timer = nullptr;             ///< child
    QElapsedTimer m_sinceDrain;            ///< since the last drain
    QElapsedTimer m_sinceFrame;            ///< since the last frameAdvanced()
    std::vector<PlotSeries> m_series;
    std::vector<bool> m_offScale; ///< per series, see offScale()
    bool m_offScaleClipping = false;
    std::deque<Mark> m_marks; ///< sorted by t
    QString m_leftUnit;
    QString m_rightUnit;
    std::array<double, 2> m_valueScale{};                  ///< left, right [unit of the axis]
    std::array<PlotSeries::SampleValue, 2> m_valueScaleOf; ///< left, right; may be empty
    std::array<double, 2> m_minimumSpan{};                 ///< left, right; see niceRange

    const SampleBuffer* m_source = nullptr;
    std::uint64_t m_cursor = 0;
    std::optional<double> m_lastSampleT;   ///< [s] time of the last sample drained
    std::optional<double> m_latestT;       ///< [s] latest time over all series
    std::optional<double> m_timelineStart; ///< [s] see setTimelineStart()
    int m_markStrip = 0;                   ///< [px] room above the axis rect for mark labels

    RangeMode m_rangeMode = RangeMode::Window;
    double m_windowSeconds = kDefaultWindowSeconds; ///< [s]
    int m_pointBudget = kDefaultPointBudget;
    bool m_following = true;
    bool m_presentation = false;
    bool m_dirty = false;         ///< data changed since the last view update
    bool m_settingRanges = false; ///< our own range changes do not pause following
    bool m_replotWhenShown = false;
    QList<QPointer<QAction>> m_menuActions; ///< see addMenuAction
};

// The plots of the lab window and their palette (standard_plots.cpp).

/// A colour for the index-th curve from a palette told apart with any colour vision (it
/// cycles after 7): one energy curve per integrator, say.
QColor plotColor(int index);
/// A pen style for the index-th of curves that may coincide: solid, dashed, dotted, ... (it
/// cycles after 5), so that a curve drawn over another leaves it visible.
Qt::PenStyle plotPenStyle(int index);
/// The line style of a plot's index-th series on the left axis: solid, dash-dot,
/// dash-dot-dot, dotted (dashed is the right axis').
Qt::PenStyle plotPenStyleFor(int index);
/// How much wider than a plain curve the index-th of `count` curves that may coincide is
/// drawn: the first widest, the last plain, so that each shows around the ones drawn over it.
double plotPenWidthFactor(int index, int count);

/// A drift is relative to |E0|: what it is worth is all of it, 100 % (a drift below 1e-7 %
/// is rounding noise).
inline constexpr double kDriftScalePercent = 100.0;

/// A conserved quantity's axis is at least this fraction of its magnitude tall: a change of
/// 1e-4 of it, which the solver makes, shows as a pixel or two, not as a full-height jump.
inline constexpr double kConservedMinimumSpan = 0.02;

// The window's plots (makeEnergyPlot, makeMomentumPlot, makeDriftPlot) are made by their rows
// of the plots' table, plot_table.h, which declares them.

} // namespace rigidlab::ui
