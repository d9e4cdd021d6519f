// SPDX-License-Identifier: GPL-3.0-or-later
// PlotWidget's making, its title, caption, axis labels, curves, legend and presentation mode.
// Its other parts: plot_axes.cpp (draining, following, ranges, ticks, off scale),
// plot_marks.cpp, plot_menu.cpp.
#include "plots/plot_widget.h"

#include "common/theme.h"
#include "plots/column_graph.h"
#include "plots/plot_exporter.h"
#include "plots/plot_range.h"
#include "plots/readable_ticker.h"

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
/// The series' markers [px] (plotMarker).
constexpr double kMarkerPx = 7.0;
/// Presentation mode (theme.h): axis labels readable from the back of a room on a 1024×768
/// projector, ticks and legend a little smaller.
constexpr double kPresentationAxisLabelPt = 18;
constexpr double kPresentationTickLabelPt = 16;
constexpr double kPresentationLegendPt = 16;
constexpr double kPresentationTitlePt = 20;
const QColor kCaptionColour(0x40, 0x40, 0x40);
/// QCustomPlot's own grid colour, and the darker one of presentation mode.
const QColor kGridColour(200, 200, 200);
const QColor kPresentationGridColour(0x80, 0x80, 0x80);

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
    : QWidget(parent), m_model(new PlotModel(this)), m_plot(new QCustomPlot(this)),
      m_followButton(new QToolButton(this)), m_timer(new QTimer(this))
{
    m_exporter = new PlotExporter(*this);
    connect(m_model, &PlotModel::marksChanged, this, &PlotWidget::syncMarks);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plot);
    setMinimumSize(320, 220);
    installMenuAndCopy();

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
    m_caption->setTextColor(kCaptionColour);
    m_plot->legend->setVisible(true);
    m_plot->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    m_plot->legend->setBorderPen(Qt::NoPen);
    m_plot->legend->setFont(sized(base, kLegendPt));
    m_plot->legend->setIconSize(32, 14);
    m_plot->legend->setMargins(QMargins(8, 0, 8, 0));
    m_plot->axisRect()->setMinimumMargins(QMargins(0, 0, kRightMarginPx, 0));

    for (QCPAxis* axis : {m_plot->xAxis, m_plot->yAxis, m_plot->yAxis2}) {
        axis->setTicker(QSharedPointer<QCPAxisTicker>(new ReadableTicker));
        axis->setLabelFont(sized(base, kAxisLabelPt));
        axis->setTickLabelFont(sized(base, kTickLabelPt));
    }
    m_plot->xAxis->setLabel(tr("time t [s]"));
    m_plot->xAxis->setRange(0, m_model->windowSeconds());
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

    startRefresh();
}

void PlotWidget::startRefresh()
{
    m_timer->setInterval(kRefreshIntervalMs);
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, [this] {
        // While frames come, they drive the drains (PlotTurns, plot_turns.h).
        if (!m_sinceFrame.isValid() || m_sinceFrame.elapsed() > 2 * kRefreshIntervalMs)
            drain();
    });
    m_timer->start(); // staggerRefresh() moves it to its owner's turn
}

void PlotWidget::staggerRefresh(int turn)
{
    constexpr int kTurns = 3;
    m_refreshPhaseMs = (std::max(0, turn) % kTurns) * (kRefreshIntervalMs / kTurns);
    m_timer->stop();
    QTimer::singleShot(m_refreshPhaseMs, m_timer, qOverload<>(&QTimer::start));
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
    m_model->setUnit(axis, unit);
    axisFor(axis)->setLabel(axisText(quantity, unit));
    if (axis == YAxis::Right) {
        m_plot->yAxis2->setVisible(true);
        m_plot->yAxis2->setTickLabels(true);
    }
}

int PlotWidget::addSeries(const QString& name, const QColor& color, PlotSeries::SampleValue value,
                          YAxis axis)
{
    Q_ASSERT(value);
    m_model->addSeries(name, std::move(value), axis);
    return addCurves(name, color, axis);
}

int PlotWidget::addSeries(const QString& name, const QColor& color, YAxis axis)
{
    m_model->addSeries(name, {}, axis);
    return addCurves(name, color, axis);
}

int PlotWidget::addCurves(const QString& name, const QColor& color, YAxis axis)
{
    auto* graph = new ColumnGraph(m_plot->xAxis, axisFor(axis)); // owned by m_plot
    // Dashed means "read me on the right axis", in the legend as on the curve; else each
    // series has a style of its own, and a marker: told apart without colour.
    const int index = static_cast<int>(m_curves.size());
    graph->setPen(QPen(color, theme::lineWidth(kLineWidthPx),
                       axis == YAxis::Right ? Qt::DashLine : plotPenStyleFor(index)));
    graph->setScatterStyle(QCPScatterStyle(plotMarker(index), color, kMarkerPx));
    graph->setMarkerPhase(index);
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
    m_curves.push_back({graph, ghost});
    fitLegend(m_plot->width());
    return index;
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

void PlotWidget::setSeriesLegend(int series, const QString& legend)
{
    m_model->setSeriesLegend(series, legend);
    const bool right = m_model->series(series).axis() == YAxis::Right;
    graph(series)->setName((right ? tr("%1 (right axis)").arg(legend) : legend) +
                           (offScale(series) ? offScaleMark() : QString()));
    fitLegend(m_plot->width());
    requestReplot();
}

void PlotWidget::setSeriesPen(int series, Qt::PenStyle style, double widthFactor)
{
    Curves& c = m_curves.at(series);
    QPen pen = c.graph->pen();
    const double plain = pen.widthF() / c.widthFactor;
    c.widthFactor = std::isfinite(widthFactor) && widthFactor > 0 ? widthFactor : 1.0;
    pen.setStyle(style);
    pen.setWidthF(plain * c.widthFactor);
    c.graph->setPen(pen);
    requestReplot();
}

QCPGraph* PlotWidget::graph(int series) const
{
    return m_curves.at(series).graph;
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

QColor PlotWidget::captionColour() const
{
    return m_caption->textColor();
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
    fitMarks(); // the top margin follows the tick labels' size
    // Black on white for a washed-out projector: the caption black, the grid dark enough
    // to be seen. The curves keep their colours (and dashes), which tell compared runs apart.
    m_caption->setTextColor(on ? QColor(Qt::black) : kCaptionColour);
    for (QCPAxis* axis : {m_plot->xAxis, m_plot->yAxis}) {
        QPen grid = axis->grid()->pen();
        grid.setColor(on ? kPresentationGridColour : kGridColour);
        grid.setWidthF(on ? 1.0 : 0.0);
        axis->grid()->setPen(grid);
    }
    for (const Curves& curves : m_curves) {
        for (QCPGraph* g :
             {static_cast<QCPGraph*>(curves.graph), static_cast<QCPGraph*>(curves.ghost)}) {
            QPen pen = g->pen();
            pen.setWidthF((on ? theme::lineWidth(kLineWidthPx) : kLineWidthPx) *
                          curves.widthFactor);
            g->setPen(pen);
        }
    }
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

} // namespace rigidlab::ui
