// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A live plot of the lab window, as the user sees it: a QCustomPlot with a title, labelled
// axes with units, a legend, the marks, and the curves of its PlotModel (plot_model.h), which
// holds what is shown. Its PlotExporter (plot_exporter.h) saves it.
//
// The widget drains its model's source about 30 times a second, right after a frame of the
// run when frames come (its turn among the run's plots: plot_turns.h), else on a timer of its
// own, and replots, queued, only when something changed; the simulation never waits for it.
// A replot hands each graph its points decimated to the pixel columns (prepareGraphs), and
// the value axes follow niceRange (plot_range.h): what it costs and what it shows do not
// depend on rounding noise.
//
// Dragging or zooming the plot pauses following the run (data keeps arriving, and the points
// shown stay); "Follow" (button, double-click, context menu) resumes it. Going back on the
// timeline draws the run's future as it was faded and dotted (the ghost), its marks faded too.

#include "plots/plot_model.h"

#include <QColor>
#include <QElapsedTimer>
#include <QList>
#include <QPointer>
#include <QString>
#include <QWidget>

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

class ColumnGraph;
class PlotExporter;

class PlotWidget : public QWidget {
    Q_OBJECT

public:
    static constexpr int kRefreshIntervalMs = 33; ///< drain and replot at ~30 Hz
    /// Mark labels go on at most this many rows above the plot (fitMarks).
    static constexpr int kMarkRows = 3;
    /// Marks closer than this [px] share one label.
    static constexpr double kMergePx = 6.0;

    explicit PlotWidget(const QString& title, QWidget* parent = nullptr);
    ~PlotWidget() override;

    /// What the plot shows: its series, points, time window and marks. Changes to it show at
    /// the next drain().
    PlotModel& model() { return *m_model; }
    const PlotModel& model() const { return *m_model; }
    /// Its export: file names, the export dialog, the clipboard.
    PlotExporter& exporter() const { return *m_exporter; }

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

    /// Labels a value axis "quantity [unit]"; the model takes the unit (CSV heads, words).
    void setYAxisLabel(const QString& quantity, const QString& unit, YAxis axis = YAxis::Left);

    /// A series of the model with its curve: read from every sample drained (`value`), or
    /// fed with model().appendPoint() only. Returns its index. Series on the right axis are
    /// drawn dashed, and say so in the legend; each other has a line style and a marker of
    /// its own, so that none is told by colour alone.
    int addSeries(const QString& name, const QColor& color, PlotSeries::SampleValue value,
                  YAxis axis = YAxis::Left);
    int addSeries(const QString& name, const QColor& color, YAxis axis = YAxis::Left);
    /// The series' name in the legend (the CSV keeps the name it was added with).
    void setSeriesLegend(int series, const QString& legend);
    /// Draws a series in this pen style, its line `widthFactor` times as wide as the others
    /// (its colour stays), on screen, in presentation mode and in exports.
    void setSeriesPen(int series, Qt::PenStyle style, double widthFactor = 1.0);
    /// The graph that draws a series, for styling (pen, scatter); owned by plot().
    QCPGraph* graph(int series) const;
    /// Whether the value axis leaves that series out, above it (see PlotModel::fitValues),
    /// and its legend says "↑ off scale".
    bool offScale(int series) const;
    /// Lets series go off the top of the value axis as above (off by default: in one run's
    /// plot, 1e-16 beside 1 is no runaway).
    void setOffScaleClipping(bool on);
    /// The time axis' range as shown [s].
    PlotRange shownTimes() const;

    /// Takes what is new in the model's source, and brings the view up to date if anything
    /// in the model changed (ranges, queued replot). The timer calls it; tests may too.
    /// Returns the samples taken.
    int drain();
    bool isFollowing() const { return m_following; }
    /// The timeline went to t [s]: the model keeps the points after t as the ghost, drawn
    /// faded, and the time axis follows t (a plot dragged aside follows again).
    void rewind(double t);
    /// New scene or reset: drops all points and marks, keeps the series, follows again.
    void clear();

    /// The label drawn for the model's index-th mark (oldest first); hidden where merged into
    /// a neighbour's or out of view.
    QCPItemText* markLabel(int index) const;
    /// Stacks and merges the marks' labels for a plot `widthPx` wide (the widget's width on
    /// screen; the export's while exporting). Labels that would overlap go on rows above one
    /// another (at most kMarkRows); marks closer than kMergePx share one label.
    void fitMarks(int widthPx = 0);

    /// An action the plot's context menu offers after its own (Graph of bodies…); not owned.
    void addMenuAction(QAction* action) { m_menuActions << action; }

    /// The underlying plot, for export and styling. It stays owned by this widget.
    QCustomPlot* plot() const { return m_plot; }
    /// Hands each graph its points decimated to `columns` pixel columns of the time axis
    /// shown (see ColumnGraph::setPoints); 0 takes the plot's width on screen. Every replot
    /// does this first; an export does it for the export's width.
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
    /// A frame of the run came. While frames come, the plot drains right after one, when
    /// its turn comes (PlotTurns, plot_turns.h), so that its replot does not land on the next
    /// frame's deadline; its own timer only stands in while no frames come (a paused run).
    void frameCame() { m_sinceFrame.start(); }
    /// The plot is its owner's `turn`-th (0, 1, ...): its own timer starts again a third of
    /// the refresh interval later than the turn before's (turn modulo 3), so that the
    /// owner's plots replot in different frames of the view while no frames come (a paused
    /// run). The owner counts its plots: PlotTurns a window's, a panel its own.
    void staggerRefresh(int turn);
    /// How late this plot's timer started, as staggerRefresh() set it (0 unless told) [ms].
    int refreshPhaseMs() const { return m_refreshPhaseMs; }

signals:
    void followingChanged(bool following);

protected:
    void resizeEvent(QResizeEvent* event) override;
    void showEvent(QShowEvent* event) override;

private:
    /// The axis rect's right margin: half a tick label, so "10" is not cut at the edge [px].
    static constexpr int kRightMarginPx = 22;
    /// The curves of a series: its points, and its ghost (the run's future before going back).
    struct Curves {
        ColumnGraph* graph = nullptr; ///< owned by m_plot
        ColumnGraph* ghost = nullptr; ///< owned by m_plot
        double widthFactor = 1.0;     ///< of the plot's line width
    };
    /// A mark as drawn (the model's mark of the same index).
    struct MarkItems {
        QCPItemLine* line = nullptr;  ///< owned by m_plot
        QCPItemText* label = nullptr; ///< owned by m_plot
    };

    /// Following the run, or paused where the user dragged, zoomed or chose.
    void setFollowing(bool following);
    /// Marks the series of `axis` that go off the top of it (true in `offScale`), in the
    /// legend.
    void setOffScale(YAxis axis, const std::vector<bool>& offScale);
    QString offScaleMark() const;
    /// Wraps the legend into columns that fit `widthPx`; returns its rows.
    int wrapLegend(int widthPx);
    /// Fewer ticks on an axis too short for the usual count's labels, so they never overlap.
    void fitTicks();
    int addCurves(const QString& name, const QColor& color, YAxis axis);
    void updateRanges();
    void fitValueAxis(YAxis axis);
    void requestReplot();
    void syncMarks();    ///< the marks' items made anew from the model's marks
    void startRefresh(); ///< the timer that drains while no frames come
    void placeFollowButton();
    void showContextMenu(const QPoint& pos);
    void installMenuAndCopy(); ///< the context menu, and Ctrl+C for the exporter's copyData()
    void onRangeChanged();
    QCPAxis* axisFor(YAxis axis) const;

    PlotModel* m_model = nullptr;       ///< child
    PlotExporter* m_exporter = nullptr; ///< child
    QCustomPlot* m_plot = nullptr;      ///< child
    bool m_titleShown = true;
    QCPTextElement* m_title = nullptr;   ///< owned by m_plot's layout
    QCPTextElement* m_caption = nullptr; ///< child of m_plot; in its layout while shown
    QString m_captionText;
    bool m_captionShown = false;
    QToolButton* m_followButton = nullptr; ///< child, shown while paused
    QTimer* m_timer = nullptr;             ///< child
    int m_refreshPhaseMs = 0;              ///< see staggerRefresh() [ms]
    QElapsedTimer m_sinceFrame;            ///< since the last frameCame()
    std::vector<Curves> m_curves;          ///< per series of the model
    std::vector<bool> m_offScale;          ///< per series, see offScale()
    bool m_offScaleClipping = false;
    std::vector<MarkItems> m_markItems; ///< per mark of the model
    int m_markStrip = 0;                ///< [px] room above the axis rect for mark labels

    bool m_following = true;
    bool m_presentation = false;
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
