// SPDX-License-Identifier: GPL-3.0-or-later
#include "plots/plot_widget.h"

#include "common/theme.h"
#include "plots/column_graph.h"
#include "plots/plot_range.h"

#include <qcustomplot.h>

#include <QLocale>
#include <QScopedValueRollback>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rigidlab::ui {

namespace {

// Sizes for a projector at the back of a lecture room, not for a laptop screen.
constexpr double kTitlePt = 14;
constexpr double kCaptionPt = 10;
constexpr double kAxisLabelPt = 12;
constexpr double kTickLabelPt = 11;
constexpr double kLegendPt = 11;
constexpr double kLineWidthPx = 2.0;
/// Presentation mode (theme.h): axis labels readable from the back of a room on a 1024×768
/// projector, ticks and legend a little smaller.
constexpr double kPresentationAxisLabelPt = 18;
constexpr double kPresentationTickLabelPt = 16;
constexpr double kPresentationLegendPt = 16;
constexpr double kPresentationTitlePt = 20;
/// Ticks an axis has at most (QCPAxisTicker's default); fewer where their labels would meet.
constexpr int kTickCount = 5;

/// In window mode points are kept this fraction of the window longer than shown, so a
/// curve enters from the left edge instead of starting inside the plot.
constexpr double kWindowMargin = 0.1;
constexpr int kRightMarginPx = 22; // half a tick label, so "10" is not cut at the edge
/// Smallest time span [s] shown in whole-run mode, so a single point has an axis.
constexpr double kMinWholeRunSpan = 1e-3;
/// A frame may come this much early and still count as the refresh interval passed [ms].
constexpr int kFrameSlackMs = 8;
/// Pixel columns assumed for a plot that was never laid out.
constexpr int kDefaultColumns = 800;
/// Opacity of the ghost: the run's future before the timeline went back.
constexpr double kGhostAlpha = 0.4;

QFont sized(const QFont& base, double pointSize, bool bold = false)
{
    QFont f = base;
    f.setPointSizeF(pointSize);
    f.setBold(bold);
    return f;
}

QString axisText(const QString& quantity, const QString& unit)
{
    return unit.isEmpty() ? quantity : QStringLiteral("%1 [%2]").arg(quantity, unit);
}

} // namespace

PlotWidget::PlotWidget(const QString& title, QWidget* parent)
    : QWidget(parent), m_plot(new QCustomPlot(this)), m_followButton(new QToolButton(this)),
      m_timer(new QTimer(this))
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plot);
    setMinimumSize(320, 220);

    const QFont base = font();
    m_plot->setNoAntialiasingOnDrag(true);
    // Tick labels in the window's language, as the fields and tables are (CSV keeps the point).
    m_plot->setLocale(QLocale());

    // Rows of the layout: title, legend (one line, wrapping), then the axes.
    m_title = new QCPTextElement(m_plot, title, sized(base, kTitlePt, true));
    m_plot->plotLayout()->insertRow(0);
    m_plot->plotLayout()->addElement(0, 0, m_title);
    m_plot->axisRect()->insetLayout()->take(m_plot->legend);
    m_plot->plotLayout()->insertRow(1);
    m_plot->plotLayout()->addElement(1, 0, m_plot->legend);
    m_plot->plotLayout()->setRowStretchFactor(0, 0.001);
    m_plot->plotLayout()->setRowStretchFactor(1, 0.001);
    m_caption = new QCPTextElement(m_plot, QString(), sized(base, kCaptionPt));
    m_caption->setTextColor(QColor(0x40, 0x40, 0x40));
    m_plot->legend->setVisible(true);
    m_plot->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    m_plot->legend->setBorderPen(Qt::NoPen);
    m_plot->legend->setFont(sized(base, kLegendPt));
    m_plot->legend->setIconSize(32, 14);
    m_plot->legend->setMargins(QMargins(8, 0, 8, 0));
    m_plot->axisRect()->setMinimumMargins(QMargins(0, 0, kRightMarginPx, 0));

    for (QCPAxis* axis : {m_plot->xAxis, m_plot->yAxis, m_plot->yAxis2}) {
        axis->setLabelFont(sized(base, kAxisLabelPt));
        axis->setTickLabelFont(sized(base, kTickLabelPt));
    }
    m_plot->xAxis->setLabel(tr("time t [s]"));
    m_plot->xAxis->setRange(0, m_windowSeconds);
    m_plot->yAxis2->setVisible(false);

    // Drag and wheel move the time axis and every value axis; doing so pauses following.
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    const QList<QCPAxis*> horizontal{m_plot->xAxis};
    const QList<QCPAxis*> vertical{m_plot->yAxis, m_plot->yAxis2};
    m_plot->axisRect()->setRangeDragAxes(horizontal, vertical);
    m_plot->axisRect()->setRangeZoomAxes(horizontal, vertical);
    for (QCPAxis* axis : {m_plot->xAxis, m_plot->yAxis, m_plot->yAxis2})
        connect(axis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this,
                &PlotWidget::onRangeChanged);
    connect(m_plot, &QCustomPlot::mouseDoubleClick, this, &PlotWidget::follow);
    // The graphs get what the axes show, decimated to the pixels, just before each replot.
    connect(m_plot, &QCustomPlot::beforeReplot, this, [this] {
        fitTicks();
        prepareGraphs();
    });

    m_followButton->setText(tr("Follow"));
    m_followButton->setToolTip(tr("Follow the run again (or double-click the plot)"));
    m_followButton->setFont(sized(base, kLegendPt));
    m_followButton->setVisible(false);
    m_followButton->raise();
    connect(m_followButton, &QToolButton::clicked, this, &PlotWidget::follow);

    m_plot->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(m_plot, &QWidget::customContextMenuRequested, this, &PlotWidget::showContextMenu);

    m_timer->setInterval(kRefreshIntervalMs);
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, [this] {
        // While frames come, they drive the drains (frameAdvanced()).
        if (!m_sinceFrame.isValid() || m_sinceFrame.elapsed() > 2 * kRefreshIntervalMs)
            drain();
    });
    // The plots take turns: each starts a third of the interval after the one before, so that
    // their replots fall in different frames of the view instead of all in one.
    static int instances = 0;
    const int phase = (instances++ % 3) * (kRefreshIntervalMs / 3);
    QTimer::singleShot(phase, m_timer, qOverload<>(&QTimer::start));
}

PlotWidget::~PlotWidget() = default;

QString PlotWidget::title() const
{
    return m_title->text();
}

void PlotWidget::setTitleShown(bool shown)
{
    m_titleShown = shown;
    // A hidden layout element still takes its row: squeeze the row to nothing as well.
    m_title->setVisible(shown);
    m_title->setMaximumSize(QWIDGETSIZE_MAX, shown ? QWIDGETSIZE_MAX : 0);
    m_title->setMinimumSize(0, 0);
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void PlotWidget::setCaption(const QString& caption)
{
    m_captionText = caption;
    m_caption->setText(caption);
    setCaptionShown(m_captionShown);
}

void PlotWidget::setCaptionShown(bool shown)
{
    m_captionShown = shown;
    // The caption's row exists only while it is shown, so that the screen layout is the
    // same as without a caption: a hidden element would still take its row's spacing.
    QCPLayoutGrid* layout = m_plot->plotLayout();
    const bool inLayout = layout->hasElement(1, 0) && layout->element(1, 0) == m_caption;
    const bool wanted = shown && !m_captionText.isEmpty();
    if (wanted && !inLayout) {
        layout->insertRow(1);
        layout->addElement(1, 0, m_caption);
        layout->setRowStretchFactor(1, 0.001);
    } else if (!wanted && inLayout) {
        layout->take(m_caption);
        layout->simplify();
    }
    m_caption->setVisible(wanted);
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

QCPAxis* PlotWidget::axisFor(YAxis axis) const
{
    return axis == YAxis::Left ? m_plot->yAxis : m_plot->yAxis2;
}

void PlotWidget::setYAxisLabel(const QString& quantity, const QString& unit, YAxis axis)
{
    (axis == YAxis::Left ? m_leftUnit : m_rightUnit) = unit;
    axisFor(axis)->setLabel(axisText(quantity, unit));
    if (axis == YAxis::Right) {
        m_plot->yAxis2->setVisible(true);
        m_plot->yAxis2->setTickLabels(true);
    }
}

QString PlotWidget::yAxisUnit(YAxis axis) const
{
    return axis == YAxis::Left ? m_leftUnit : m_rightUnit;
}

void PlotWidget::setValueScale(YAxis axis, double scale)
{
    const std::size_t i = axis == YAxis::Left ? 0 : 1;
    m_valueScaleOf[i] = {};
    m_valueScale[i] = std::isfinite(scale) && scale > 0 ? scale : 0.0;
    m_dirty = true;
}

void PlotWidget::setValueScale(YAxis axis, PlotSeries::SampleValue scale)
{
    m_valueScaleOf[axis == YAxis::Left ? 0 : 1] = std::move(scale);
    m_dirty = true;
}

void PlotWidget::setMinimumSpan(YAxis axis, double fraction)
{
    m_minimumSpan[axis == YAxis::Left ? 0 : 1] =
        std::isfinite(fraction) && fraction > 0 ? fraction : 0.0;
    m_dirty = true;
}

double PlotWidget::valueScale(YAxis axis) const
{
    return m_valueScale[axis == YAxis::Left ? 0 : 1];
}

int PlotWidget::addSeries(const QString& name, const QColor& color, PlotSeries::SampleValue value,
                          YAxis axis)
{
    Q_ASSERT(value);
    return addGraph(name, color, std::move(value), axis);
}

int PlotWidget::addSeries(const QString& name, const QColor& color, YAxis axis)
{
    return addGraph(name, color, {}, axis);
}

int PlotWidget::addGraph(const QString& name, const QColor& color, PlotSeries::SampleValue value,
                         YAxis axis)
{
    auto* graph = new ColumnGraph(m_plot->xAxis, axisFor(axis)); // owned by m_plot
    // Dashed means "read me on the right axis", in the legend as on the curve.
    graph->setPen(QPen(color, theme::lineWidth(kLineWidthPx),
                       axis == YAxis::Right ? Qt::DashLine : Qt::SolidLine));
    graph->setName(axis == YAxis::Right ? tr("%1 (right axis)").arg(name) : name);
    if (axis == YAxis::Right) {
        m_plot->yAxis2->setVisible(true);
        m_plot->yAxis2->setTickLabels(true);
    }
    // The run's future before the timeline went back: the same colour, faded, dotted, and
    // not in the legend (it is that series, as it was).
    auto* ghost = new ColumnGraph(m_plot->xAxis, axisFor(axis)); // owned by m_plot
    QColor faded = color;
    faded.setAlphaF(kGhostAlpha);
    ghost->setPen(QPen(faded, theme::lineWidth(kLineWidthPx), Qt::DotLine));
    ghost->setName(tr("%1 (before going back)").arg(graph->name()));
    ghost->removeFromLegend();
    m_series.emplace_back(graph, name, axis, std::move(value));
    m_series.back().setGhostGraph(ghost);
    fitLegend(m_plot->width());
    return seriesCount() - 1;
}

void PlotWidget::fitLegend(int widthPx)
{
    QCPLegend* legend = m_plot->legend;
    if (legend->itemCount() == 0)
        return;
    if (!m_presentation) {
        wrapLegend(widthPx);
        return;
    }
    // Presentation mode: the largest legend text, from its own size down to the window's
    // plain one, that leaves the curves the plot's height: one line, or at most a fifth of
    // the plot (a narrow dock on a 1024-pixel projector would otherwise stack five lines).
    const QFont base = font();
    for (double pt = kPresentationLegendPt;; pt -= 1) {
        legend->setFont(sized(base, pt));
        const int rows = wrapLegend(widthPx);
        const int height = rows * (QFontMetrics(legend->font()).height() + legend->rowSpacing());
        int widest = 0;
        for (int i = 0; i < legend->itemCount(); ++i)
            if (const QCPAbstractLegendItem* item = legend->item(i))
                widest = std::max(widest, item->minimumOuterSizeHint().width());
        const bool fits = widest <= widthPx - legend->margins().left() - legend->margins().right();
        if ((fits && (rows <= 1 || height <= m_plot->height() / 5)) || pt <= kLegendPt)
            break;
    }
}

int PlotWidget::wrapLegend(int widthPx)
{
    // As many legend columns as fit the width; more entries wrap to a second line rather
    // than being cut off.
    QCPLegend* legend = m_plot->legend;
    const int count = legend->itemCount();
    std::vector<int> widths;
    for (int i = 0; i < count; ++i) {
        // Once wrapped, the grid may hold empty cells: item() is null there.
        const QCPAbstractLegendItem* item = legend->item(i);
        widths.push_back(item ? item->minimumOuterSizeHint().width() : 0);
    }
    const QMargins margins = legend->margins();
    const int available = widthPx - margins.left() - margins.right();
    int columns = count;
    for (; columns > 1; --columns) {
        int total = (columns - 1) * legend->columnSpacing();
        for (int c = 0; c < columns; ++c) {
            int widest = 0;
            for (int i = c; i < count; i += columns)
                widest = std::max(widest, widths[static_cast<std::size_t>(i)]);
            total += widest;
        }
        if (total <= available)
            break;
    }
    if (columns != legend->wrap() || legend->columnCount() > columns) {
        legend->setWrap(columns);
        legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true);
    }
    return (count + columns - 1) / columns;
}

void PlotWidget::fitTicks()
{
    // No more ticks than their labels have room for, a blank of one line's height between
    // two: on a narrow plot with presentation-sized labels, "0 2 4 6 8 10" ran together.
    for (QCPAxis* axis : {m_plot->xAxis, m_plot->yAxis, m_plot->yAxis2}) {
        if (!axis->visible() || !axis->tickLabels() || !axis->ticker())
            continue;
        const QFontMetrics fm(axis->tickLabelFont());
        const bool horizontal = axis->orientation() == Qt::Horizontal;
        int label = fm.height();
        if (horizontal) {
            label = fm.horizontalAdvance(QStringLiteral("00.0"));
            for (const QString& text : axis->tickVectorLabels())
                label = std::max(label, fm.horizontalAdvance(text));
        }
        const QRect area = axis->axisRect()->rect();
        const int length = horizontal ? area.width() : area.height();
        if (length <= 0)
            continue;
        // The ticker makes about tickCount + 1 intervals of a round size, sometimes a little
        // shorter than asked for: one tick fewer than would just fit.
        const int fit = length / (label + fm.height()) - 1;
        axis->ticker()->setTickCount(std::clamp(fit, 2, kTickCount));
    }
}

bool PlotWidget::offScale(int series) const
{
    return series >= 0 && static_cast<std::size_t>(series) < m_offScale.size() &&
           m_offScale[static_cast<std::size_t>(series)];
}

void PlotWidget::setOffScaleClipping(bool on)
{
    m_offScaleClipping = on;
    updateRanges();
    requestReplot();
}

QString PlotWidget::offScaleMark() const
{
    return tr(" ↑ off scale");
}

void PlotWidget::setOffScale(YAxis axis, const std::vector<bool>& offScale)
{
    m_offScale.resize(m_series.size(), false);
    bool changed = false;
    for (std::size_t i = 0; i < m_series.size() && i < offScale.size(); ++i) {
        if (m_series[i].axis() != axis) // the other axis's series keep their mark
            continue;
        if (m_offScale[i] == offScale[i])
            continue;
        m_offScale[i] = offScale[i];
        QCPGraph* g = m_series[i].graph();
        QString name = g->name();
        if (offScale[i])
            name += offScaleMark();
        else if (name.endsWith(offScaleMark()))
            name.chop(offScaleMark().size());
        g->setName(name);
        changed = true;
    }
    if (changed)
        fitLegend(m_plot->width());
}

void PlotWidget::setSeriesLegend(int series, const QString& legend)
{
    const PlotSeries& s = m_series.at(series);
    s.graph()->setName((s.axis() == YAxis::Right ? tr("%1 (right axis)").arg(legend) : legend) +
                       (offScale(series) ? offScaleMark() : QString()));
    fitLegend(m_plot->width());
    requestReplot();
}

void PlotWidget::setSeriesPen(int series, Qt::PenStyle style, double widthFactor)
{
    PlotSeries& s = m_series.at(series);
    QPen pen = s.graph()->pen();
    const double plain = pen.widthF() / s.widthFactor();
    s.setWidthFactor(std::isfinite(widthFactor) && widthFactor > 0 ? widthFactor : 1.0);
    pen.setStyle(style);
    pen.setWidthF(plain * s.widthFactor());
    s.graph()->setPen(pen);
    requestReplot();
}

QCPGraph* PlotWidget::graph(int series) const
{
    return m_series.at(series).graph();
}

QString PlotWidget::seriesName(int series) const
{
    return m_series.at(series).name();
}

QString PlotWidget::seriesUnit(int series) const
{
    return yAxisUnit(m_series.at(series).axis());
}

std::vector<QPointF> PlotWidget::points(int series) const
{
    const std::vector<PlotPoint>& kept = m_series.at(series).points();
    std::vector<QPointF> out;
    out.reserve(kept.size());
    for (const PlotPoint& p : kept)
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

void PlotWidget::setRangeMode(RangeMode mode)
{
    if (mode == m_rangeMode)
        return;
    m_rangeMode = mode;
    trimToWindow();
    m_dirty = true;
    emit rangeModeChanged(mode);
}

void PlotWidget::setWindowSeconds(double seconds)
{
    Q_ASSERT(std::isfinite(seconds) && seconds > 0);
    if (!std::isfinite(seconds) || seconds <= 0)
        return;
    m_windowSeconds = seconds;
    trimToWindow();
    m_dirty = true;
}

void PlotWidget::setPointBudget(int points)
{
    m_pointBudget = std::max(points, 16);
}

void PlotWidget::setFollowing(bool following)
{
    if (following == m_following)
        return;
    m_following = following;
    m_followButton->setVisible(!following);
    if (following) {
        trimToWindow();
        m_dirty = true;
    }
    emit followingChanged(following);
}

void PlotWidget::onRangeChanged()
{
    updateMarkLabels();
    if (m_settingRanges)
        return;
    // Changed by the user (drag, wheel) or by a caller: stop following, show the new range.
    setFollowing(false);
    requestReplot();
}

void PlotWidget::updateRanges()
{
    if (!m_following || !m_latestT)
        return;
    QScopedValueRollback<bool> guard(m_settingRanges, true);

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
        m_plot->xAxis->setRange(std::max(end, first + span), span, Qt::AlignRight);
    } else if (m_plot->xAxis->scaleType() == QCPAxis::stLogarithmic) {
        // A log axis (work against precision): a third of a decade beyond the points.
        m_plot->xAxis->setRange(first / 2, *m_latestT * 2);
    } else {
        const double end = std::max(*m_latestT, ghost.value_or(*m_latestT));
        m_plot->xAxis->setRange(first, first + std::max(end - first, kMinWholeRunSpan));
    }
    fitValueAxis(YAxis::Left);
    fitValueAxis(YAxis::Right);
}

double PlotWidget::timeSpan(double run) const
{
    if (!(run < m_windowSeconds))
        return m_windowSeconds;
    // Rounded up to a twentieth-ish round step: the axis grows in small jumps, and the run
    // fills at least 19/20 of it.
    const double step = niceStep(std::max(run, kMinTimeSpan), 20);
    const double rounded = std::ceil(run / step - 1e-9) * step;
    return std::clamp(rounded, std::min(kMinTimeSpan, m_windowSeconds), m_windowSeconds);
}

void PlotWidget::fitValueAxis(YAxis axis)
{
    const QCPRange keys = m_plot->xAxis->range();
    QCPAxis* valueAxis = axisFor(axis);
    const bool log = valueAxis->scaleType() == QCPAxis::stLogarithmic;
    struct Extent {
        std::size_t series;
        double lo, hi, magnitude;
    };
    std::vector<Extent> extents;
    for (std::size_t i = 0; i < m_series.size(); ++i) {
        const PlotSeries& series = m_series[i];
        if (series.axis() != axis || !series.graph()->visible())
            continue;
        double lo = 0, hi = 0;
        if (!series.valueRange(keys.lower, keys.upper, log, lo, hi))
            continue;
        extents.push_back({i, lo, hi, std::max(std::abs(lo), std::abs(hi))});
    }
    if (extents.empty())
        return;
    // A compared run that blew up (1e10 J beside 1000 J) would flatten the runs that survive
    // to a line at 0: the axis fits the survivors, and the runs beyond kOffScaleRatio times
    // them go off the top, said so in the legend.
    std::vector<bool> offScale(m_series.size(), false);
    if (m_offScaleClipping && !log) {
        std::sort(extents.begin(), extents.end(),
                  [](const Extent& a, const Extent& b) { return a.magnitude < b.magnitude; });
        const double floor = std::max(valueScale(axis), kMinMagnitude);
        std::size_t kept = 1;
        while (kept < extents.size() &&
               extents[kept].magnitude <=
                   kOffScaleRatio * std::max(extents[kept - 1].magnitude, floor))
            ++kept;
        for (std::size_t k = kept; k < extents.size(); ++k)
            offScale[extents[k].series] = true;
        extents.resize(kept);
    }
    setOffScale(axis, offScale);
    double lowest = extents.front().lo, highest = extents.front().hi;
    for (const Extent& e : extents) {
        lowest = std::min(lowest, e.lo);
        highest = std::max(highest, e.hi);
    }
    if (log) {
        valueAxis->setRange(lowest / 2, highest * 2);
        return;
    }
    // Rounding noise is drawn flat, and the ticks always read differently (plot_range.h).
    const AxisRange range =
        niceRange(lowest, highest, valueScale(axis), m_minimumSpan[axis == YAxis::Left ? 0 : 1]);
    valueAxis->setNumberPrecision(range.labelDigits);
    valueAxis->setRange(range.lower, range.upper);
}

void PlotWidget::prepareGraphs(int columns)
{
    if (columns <= 0)
        columns = m_plot->width() > 0 ? m_plot->width() : kDefaultColumns;
    const QCPRange keys = m_plot->xAxis->range();
    const bool log = m_plot->xAxis->scaleType() == QCPAxis::stLogarithmic;
    for (const PlotSeries& series : m_series) {
        series.ghostGraph()->setVisible(series.graph()->visible());
        series.draw(keys.lower, keys.upper, columns, log);
    }
}

void PlotWidget::requestReplot()
{
    if (isVisible())
        m_plot->replot(QCustomPlot::rpQueuedReplot);
    else
        m_replotWhenShown = true;
}

void PlotWidget::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    if (m_replotWhenShown) {
        m_replotWhenShown = false;
        m_plot->replot(QCustomPlot::rpQueuedReplot);
    }
}

void PlotWidget::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    placeFollowButton();
    fitLegend(m_plot->width());
    fitMarks();
}

void PlotWidget::placeFollowButton()
{
    m_followButton->adjustSize();
    const int margin = 6;
    m_followButton->move(width() - m_followButton->width() - margin, margin);
}

void PlotWidget::setPresentation(bool on)
{
    m_presentation = on;
    const QFont base = font();
    m_title->setFont(sized(base, on ? kPresentationTitlePt : kTitlePt, true));
    m_plot->legend->setFont(sized(base, on ? kPresentationLegendPt : kLegendPt));
    fitLegend(m_plot->width());
    for (QCPAxis* axis : {m_plot->xAxis, m_plot->yAxis, m_plot->yAxis2}) {
        axis->setLabelFont(sized(base, on ? kPresentationAxisLabelPt : kAxisLabelPt));
        axis->setTickLabelFont(sized(base, on ? kPresentationTickLabelPt : kTickLabelPt));
        QPen axisPen = axis->basePen();
        axisPen.setWidthF(on ? 2.0 : 1.0);
        axis->setBasePen(axisPen);
    }
    for (const PlotSeries& series : m_series) {
        for (QCPGraph* g : {static_cast<QCPGraph*>(series.graph()),
                            static_cast<QCPGraph*>(series.ghostGraph())}) {
            QPen pen = g->pen();
            pen.setWidthF((on ? theme::lineWidth(kLineWidthPx) : kLineWidthPx) *
                          series.widthFactor());
            g->setPen(pen);
        }
    }
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

} // namespace rigidlab::ui
