// SPDX-License-Identifier: GPL-3.0-or-later
#include "measure/measurement_panel.h"

#include "common/accessible_names.h"
#include "common/shortcuts.h"
#include "measure/import_dialog.h"
#include "plots/plot_shelf.h"
#include "plots/plot_widget.h"

#include <qcustomplot.h>

#include <QBoxLayout>
#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <iterator>

namespace rigidlab::ui {

namespace {

/// Each plot's least size until the window sets a height of its own
/// (WindowLayout::fitPlotHeight) [px]. Narrow: side by side, the plots' least widths would
/// hold the dock wider than the screen before they go behind tabs.
constexpr QSize kPlotLeast(180, 130);
constexpr double kMarkerPx = 6.0;
/// The controls beside the plots take up to 1/kControlsShare of the panel's width.
constexpr int kControlsShare = 3;

/// Draws a series as markers of `shape` without a line between them.
void asMarkers(PlotWidget& plot, int series, QCPScatterStyle::ScatterShape shape)
{
    QCPGraph* g = plot.graph(series);
    g->setLineStyle(QCPGraph::lsNone);
    g->setScatterStyle(QCPScatterStyle(shape, g->pen().color(), kMarkerPx));
}

} // namespace

MeasurementPanel::MeasurementPanel(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("measurementPanel"));
    m_layout = new QBoxLayout(QBoxLayout::LeftToRight, this);
    m_layout->setContentsMargins(0, 0, 0, 0);
    m_layout->addWidget(buildControls());

    // Side by side, stacked or behind tabs, as the room left keeps each readable.
    m_plots = new PlotShelf(this);
    m_comparison = new PlotWidget(tr("Measured and simulated"), m_plots);
    m_comparison->setAccessibleName(tr("Plot: measured points and the simulated line"));
    m_comparison->model().setRangeMode(RangeMode::WholeRun);
    m_comparison->setMinimumSize(kPlotLeast);
    m_comparison->setTitleShown(false); // the legend names both; exports show the title
    m_comparison->addSeries(tr("measured"), plotColor(0));
    m_comparison->addSeries(tr("simulated"), plotColor(1));
    asMarkers(*m_comparison, kMeasured, QCPScatterStyle::ssCircle);
    m_plots->addPlot(m_comparison, m_comparison->title());

    m_residual = new PlotWidget(tr("Residuals: measured − simulated"), m_plots);
    m_residual->setAccessibleName(tr("Plot: residuals, measured minus simulated"));
    m_residual->model().setRangeMode(RangeMode::WholeRun);
    m_residual->setMinimumSize(kPlotLeast);
    m_residual->setTitleShown(false); // the tab or the check box says what it is
    m_residual->staggerRefresh(1);    // the comparison's is turn 0: not in the same frame
    m_residual->addSeries(tr("measured − simulated"), plotColor(2));
    asMarkers(*m_residual, kResidual, QCPScatterStyle::ssCross);
    m_plots->addPlot(m_residual, tr("Residuals"));
    connect(m_showResiduals, &QCheckBox::toggled, this,
            [this](bool on) { m_plots->setPlotShown(m_residual, on); });
    m_layout->addWidget(m_plots, 1);
    // Arranged for its size now, before it is first shown: the dock keeps the panel's least
    // size even while it is behind another dock's tab, and two plots stacked would hold the
    // window taller than a projector's screen.
    m_plots->arrange();
    clear();
}

QWidget* MeasurementPanel::buildControls()
{
    // What is chosen and fitted scrolls on its own, so that the plots beside or below it keep
    // their whole height in a short dock.
    m_controls = new QScrollArea(this);
    m_controls->setWidgetResizable(true);
    m_controls->setFrameShape(QFrame::NoFrame);
    m_controls->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    nameScrollArea(*m_controls, tr("Comparison and fit"));
    auto* box = new QWidget(m_controls);
    auto* layout = new QVBoxLayout(box);
    m_source = new QLabel(box);
    m_source->setWordWrap(true);
    m_source->setAccessibleName(tr("Measurement imported"));
    layout->addWidget(m_source);

    auto* form = new QFormLayout;
    m_body = new QComboBox(box);
    m_body->setAccessibleName(tr("Body the measurement is compared with"));
    m_quantity = new QComboBox(box);
    m_quantity->setAccessibleName(tr("Measured quantity compared"));
    form->addRow(tr("&Body:"), m_body);
    form->addRow(tr("&Quantity:"), m_quantity);
    layout->addLayout(form);
    for (QComboBox* list : {m_body, m_quantity})
        connect(list, &QComboBox::currentIndexChanged, this, &MeasurementPanel::choiceChanged);
    m_showResiduals = new QCheckBox(tr("Show &residuals"), box);
    m_showResiduals->setChecked(true);
    layout->addWidget(m_showResiduals);

    m_message = new QLabel(box);
    m_message->setWordWrap(true);
    m_message->setAccessibleName(tr("Why the simulation cannot be compared"));
    m_message->hide();
    layout->addWidget(m_message);
    layout->addWidget(buildFit(*box));
    layout->addStretch(1);
    m_controls->setWidget(box);
    return m_controls;
}

void MeasurementPanel::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    arrange();
}

void MeasurementPanel::arrange()
{
    // The controls beside the plots where both fit across (a wide, short dock under the world
    // on a projector), the fit's choices one under another if only that makes them fit (its
    // large type in presentation mode); else above the plots, across the dock.
    const int plotWidth = plotSizeFor(*m_comparison, kLeastDataArea).width();
    bool beside = false;
    int controlsWidth = 0;
    for (const bool narrow : {false, true}) {
        setFitNarrow(narrow);
        controlsWidth = leastControlsWidth();
        beside = width() >= controlsWidth + m_layout->spacing() + plotWidth;
        if (beside)
            break;
    }
    if (!beside)
        setFitNarrow(false);
    const QBoxLayout::Direction direction =
        beside ? QBoxLayout::LeftToRight : QBoxLayout::TopToBottom;
    if (m_layout->direction() != direction)
        m_layout->setDirection(direction);
    if (beside) {
        // Wider than their least width, up to a third of the panel, where the plots keep
        // room to be read: the fit's result then wraps to fewer lines, and in a short dock
        // (presentation mode's type on a projector) its last line stays in sight.
        const int room = width() - m_layout->spacing() - plotWidth;
        controlsWidth = std::max(controlsWidth, std::min(room, width() / kControlsShare));
        m_controls->setFixedWidth(controlsWidth);
    } else {
        m_controls->setMinimumWidth(0);
        m_controls->setMaximumWidth(QWIDGETSIZE_MAX);
    }
}

void MeasurementPanel::setFitNarrow(bool narrow)
{
    if (narrow == m_fitNarrow)
        return;
    m_fitNarrow = narrow;
    for (int i = 0; i < kFitParameters; ++i) {
        m_fitGrid->removeWidget(m_parameters[i]);
        m_fitGrid->addWidget(m_parameters[i], narrow ? i : i / 2, narrow ? 0 : i % 2);
    }
    m_fitButtons->setDirection(narrow ? QBoxLayout::TopToBottom : QBoxLayout::LeftToRight);
}

int MeasurementPanel::leastControlsWidth() const
{
    // Laid out again as they are placed now (a layout recomputes its sizes when activated).
    QWidget* controls = m_controls->widget();
    m_fitBox->layout()->activate();
    m_fitBox->updateGeometry();
    controls->layout()->activate();
    return controls->minimumSizeHint().width() +
           m_controls->verticalScrollBar()->sizeHint().width();
}

void MeasurementPanel::clear()
{
    // Shown in the View menu (and restored with the layout) before anything is imported.
    m_source->setText(tr("No measurement yet: File › Import measurement… (%1), or drop a CSV "
                         "file on the window.")
                          .arg(controlKeysText("importMeasurement")));
    const QSignalBlocker blockBody(m_body), blockQuantity(m_quantity);
    m_body->clear();
    m_quantity->clear();
    clearPlots();
    m_message->clear();
    m_message->hide();
    showFit(QString(), false);
    showBounceFit(QString(), false);
}

QWidget* MeasurementPanel::buildFit(QWidget& parent)
{
    auto* box = new QGroupBox(tr("Fit to the measurement"), &parent);
    m_fitBox = box;
    auto* layout = new QVBoxLayout(box);
    const QString names[kFitParameters] = {tr("e (res&titution)"), tr("&μ (friction)"),
                                           tr("initial v&x"), tr("initial v&y")};
    const QString full[kFitParameters] = {
        tr("Fit the coefficient of restitution e"), tr("Fit the friction coefficient μ"),
        tr("Fit the initial velocity vx"), tr("Fit the initial velocity vy")};
    // Two by two, or one under another (setFitNarrow).
    m_fitGrid = new QGridLayout;
    for (int i = 0; i < kFitParameters; ++i) {
        m_parameters[i] = new QCheckBox(names[i], box);
        m_parameters[i]->setAccessibleName(full[i]);
        m_fitGrid->addWidget(m_parameters[i], i / 2, i % 2);
    }
    layout->addLayout(m_fitGrid);
    m_parameters[0]->setChecked(true);
    m_fitButtons = new QBoxLayout(QBoxLayout::LeftToRight);
    m_fit = new QPushButton(tr("F&it"), box);
    m_fit->setAccessibleName(tr("Fit the ticked parameters to the measurement"));
    m_apply = new QPushButton(tr("&Apply to scene"), box);
    m_apply->setAccessibleName(tr("Apply the fitted values to the scene (can be undone)"));
    m_apply->setEnabled(false);
    // While a fit runs: a busy bar (a fit cannot say how many runs it will need) and Cancel.
    m_cancelFit = new QPushButton(tr("Cancel fit"), box);
    m_cancelFit->setAccessibleName(tr("Cancel the fit that is running"));
    m_cancelFit->hide();
    m_fitProgress = new QProgressBar(box);
    m_fitProgress->setRange(0, 0);
    m_fitProgress->setTextVisible(false);
    m_fitProgress->setAccessibleName(tr("Fit running"));
    m_fitProgress->hide();
    m_fitButtons->addWidget(m_fit);
    m_fitButtons->addWidget(m_cancelFit);
    m_fitButtons->addWidget(m_apply);
    layout->addLayout(m_fitButtons);
    layout->addWidget(m_fitProgress);
    m_fitResult = new QLabel(box);
    m_fitResult->setWordWrap(true);
    m_fitResult->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
    m_fitResult->setAccessibleName(tr("Fitted values"));
    layout->addWidget(m_fitResult);
    m_bounceResult = new QLabel(box);
    m_bounceResult->setWordWrap(true);
    m_bounceResult->setTextInteractionFlags(Qt::TextSelectableByMouse |
                                            Qt::TextSelectableByKeyboard);
    m_bounceResult->setAccessibleName(tr("e from the bounce times"));
    m_bounceResult->hide();
    layout->addWidget(m_bounceResult);
    m_applyBounce = new QPushButton(tr("Apply &e from the bounce times"), box);
    m_applyBounce->setAccessibleName(m_applyBounce->text().remove(QLatin1Char('&')));
    m_applyBounce->hide();
    layout->addWidget(m_applyBounce);
    connect(m_fit, &QPushButton::clicked, this, &MeasurementPanel::fitRequested);
    connect(m_cancelFit, &QPushButton::clicked, this, &MeasurementPanel::cancelFitRequested);
    connect(m_apply, &QPushButton::clicked, this, &MeasurementPanel::applyRequested);
    connect(m_applyBounce, &QPushButton::clicked, this, &MeasurementPanel::applyBounceRequested);
    return box;
}

void MeasurementPanel::setSource(const QString& text)
{
    m_source->setText(text);
}

void MeasurementPanel::setChoices(const std::vector<BodyChoice>& bodies,
                                  const std::vector<measure::Quantity>& quantities)
{
    const QSignalBlocker blockBody(m_body), blockQuantity(m_quantity);
    const QString body = m_body->currentData().toString();
    const int quantity = m_quantity->currentData().toInt();
    m_body->clear();
    for (const BodyChoice& b : bodies)
        m_body->addItem(b.label, b.id);
    m_body->setCurrentIndex(std::max(0, m_body->findData(body)));
    m_quantity->clear();
    for (const measure::Quantity q : quantities)
        m_quantity->addItem(quantityText(q), static_cast<int>(q));
    // The same quantity as before, else the height (what a dropped ball is filmed for).
    int index = m_quantity->findData(quantity);
    if (index < 0)
        index = m_quantity->findData(static_cast<int>(measure::Quantity::Y));
    m_quantity->setCurrentIndex(std::max(0, index));
    m_fit->setEnabled(!quantities.empty() && !bodies.empty());
}

int MeasurementPanel::body() const
{
    return m_body->currentIndex();
}

void MeasurementPanel::setBody(int index)
{
    m_body->setCurrentIndex(index);
}

measure::Quantity MeasurementPanel::quantity() const
{
    return m_quantity->currentIndex() < 0
               ? measure::Quantity::Ignored
               : static_cast<measure::Quantity>(m_quantity->currentData().toInt());
}

void MeasurementPanel::showComparison(const measure::Series& measured,
                                      const std::vector<double>& lineT,
                                      const std::vector<double>& lineValue,
                                      const std::vector<double>& residuals, const QString& error)
{
    clearPlots();
    m_message->setText(error);
    m_message->setVisible(!error.isEmpty());
    // The quantity's symbol (x, y, vx, ...): a long name would not fit a short plot's side.
    const QString symbol = measure::quantityName(measured.quantity);
    const QString unit = quantityUnit(measured.quantity);
    m_comparison->setYAxisLabel(symbol, unit);
    m_residual->setYAxisLabel(QStringLiteral("Δ") + symbol, unit);
    for (std::size_t i = 0; i < measured.t.size(); ++i)
        m_comparison->model().appendPoint(kMeasured, measured.t[i], measured.value[i]);
    if (!error.isEmpty())
        return;
    for (std::size_t i = 0; i < lineT.size(); ++i)
        m_comparison->model().appendPoint(kSimulated, lineT[i], lineValue[i]);
    for (std::size_t i = 0; i < residuals.size(); ++i)
        m_residual->model().appendPoint(kResidual, measured.t[i], residuals[i]);
    m_comparison->drain();
    m_residual->drain();
}

void MeasurementPanel::clearPlots()
{
    m_comparison->clear();
    m_residual->clear();
    for (const int series : m_otherSeries)
        m_comparison->graph(series)->removeFromLegend();
    m_othersShown = 0;
    m_comparison->setSeriesLegend(kMeasured, tr("measured"));
}

void MeasurementPanel::showOtherFiles(const QString& comparedFile,
                                      const std::vector<FileSeries>& others)
{
    // Each file's markers in a shape of their own beside the circles compared; a series once
    // added stays (a plot keeps its series), out of the legend while no file needs it.
    constexpr QCPScatterStyle::ScatterShape kShapes[] = {
        QCPScatterStyle::ssTriangle, QCPScatterStyle::ssSquare, QCPScatterStyle::ssDiamond,
        QCPScatterStyle::ssTriangleInverted};
    constexpr int kFirstColour = 3; // after the measured, simulated and residual series
    while (m_otherSeries.size() < others.size()) {
        const auto k = static_cast<int>(m_otherSeries.size());
        const int series = m_comparison->addSeries(QString(), plotColor(kFirstColour + k));
        asMarkers(*m_comparison, series, kShapes[k % std::size(kShapes)]);
        m_otherSeries.push_back(series);
    }
    for (std::size_t k = 0; k < m_otherSeries.size(); ++k) {
        const int series = m_otherSeries[k];
        if (k >= others.size()) {
            m_comparison->graph(series)->removeFromLegend();
            continue;
        }
        const FileSeries& other = others[k];
        m_comparison->graph(series)->addToLegend();
        m_comparison->setSeriesLegend(series, other.file);
        m_comparison->model().setSeriesColumn(
            series,
            QStringLiteral("%1 [%2]").arg(other.file, m_comparison->model().seriesUnit(series)));
        for (std::size_t i = 0; i < other.series.t.size(); ++i)
            m_comparison->model().appendPoint(series, other.series.t[i], other.series.value[i]);
    }
    // Named by its file too where there are others, and what it is used for.
    m_comparison->setSeriesLegend(
        kMeasured, others.empty() ? tr("measured") : tr("%1 (fit, residuals)").arg(comparedFile));
    m_comparison->drain();
    if (others.size() != m_othersShown) {
        m_othersShown = others.size();
        emit legendChanged();
    }
}

std::vector<PlotWidget*> MeasurementPanel::plotsShown() const
{
    if (m_showResiduals->isChecked())
        return {m_comparison, m_residual};
    return {m_comparison};
}

std::vector<int> MeasurementPanel::fitChoices() const
{
    std::vector<int> chosen;
    for (int i = 0; i < kFitParameters; ++i)
        if (m_parameters[i]->isChecked())
            chosen.push_back(i);
    return chosen;
}

void MeasurementPanel::setFitChoice(int parameter, bool on)
{
    m_parameters[parameter]->setChecked(on);
}

void MeasurementPanel::showFit(const QString& text, bool applicable)
{
    const bool focus = m_cancelFit->hasFocus();
    m_fitProgress->hide();
    m_cancelFit->hide();
    m_fit->show();
    if (focus)
        m_fit->setFocus(); // the keyboard stays where the fit was asked for
    m_fitResult->setText(text);
    m_apply->setEnabled(applicable);
    arrange(); // Fit back in place of Cancel
    showResultsSoon();
}

void MeasurementPanel::showResultsSoon()
{
    // A result below the fold of a short dock (a 1024×768 projector) is missed: once laid out,
    // the controls scroll down to the last line of the results, then, if they are taller than
    // the dock, back to their first line.
    QTimer::singleShot(0, this, [this] {
        if (m_fitResult->text().isEmpty() && m_bounceResult->isHidden())
            return;
        for (QWidget* last :
             {static_cast<QWidget*>(m_applyBounce), static_cast<QWidget*>(m_bounceResult),
              static_cast<QWidget*>(m_fitResult)})
            if (!last->isHidden()) {
                m_controls->ensureWidgetVisible(last, 0, 0);
                break;
            }
        if (!m_fitResult->text().isEmpty())
            m_controls->ensureWidgetVisible(m_fitResult, 0, 0);
    });
}

void MeasurementPanel::showFitRunning(int runs)
{
    const bool focus = m_fit->hasFocus();
    m_fitProgress->show();
    m_cancelFit->show();
    m_fit->hide();
    if (focus)
        m_cancelFit->setFocus();
    m_apply->setEnabled(false);
    m_fitResult->setText(tr("Fitting… %n run(s) of the model so far", nullptr, runs));
    arrange(); // Cancel in place of Fit
}

bool MeasurementPanel::fitRunning() const
{
    return !m_cancelFit->isHidden();
}

void MeasurementPanel::showBounceFit(const QString& text, bool applicable)
{
    m_bounceResult->setText(text);
    m_bounceResult->setVisible(!text.isEmpty());
    m_applyBounce->setVisible(!text.isEmpty());
    m_applyBounce->setEnabled(applicable);
    arrange();
    showResultsSoon();
}

QString MeasurementPanel::fitText() const
{
    return m_fitResult->text();
}

QString MeasurementPanel::bounceFitText() const
{
    return m_bounceResult->text();
}

} // namespace rigidlab::ui
