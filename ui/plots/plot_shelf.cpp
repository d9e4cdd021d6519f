// SPDX-License-Identifier: GPL-3.0-or-later
#include "plots/plot_shelf.h"

#include "plots/plot_widget.h"

#include <qcustomplot.h>

#include <QBoxLayout>
#include <QTabBar>

#include <algorithm>

namespace rigidlab::ui {

QSize plotDataArea(const PlotWidget& plot)
{
    return plot.plot()->axisRect()->rect().size();
}

QSize plotSizeFor(const PlotWidget& plot, const QSize& data)
{
    // What is not data (title, legend, tick labels, axis titles) keeps its size as the plot
    // grows; a plot not laid out yet lays itself out first.
    QCustomPlot* custom = plot.plot();
    if (custom->axisRect()->rect().isEmpty() && !custom->size().isEmpty())
        custom->replot(QCustomPlot::rpImmediateRefresh);
    const QSize around = plot.size() - plotDataArea(plot);
    return data + around.expandedTo(QSize(0, 0));
}

PlotShelf::PlotShelf(QWidget* parent)
    : QWidget(parent), m_tabs(new QTabBar(this)),
      m_plotsLayout(new QBoxLayout(QBoxLayout::TopToBottom))
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    m_tabs->setObjectName(QStringLiteral("plotShelfTabs"));
    m_tabs->setExpanding(false);
    m_tabs->setElideMode(Qt::ElideNone);
    m_tabs->setAccessibleName(tr("Plots"));
    m_tabs->hide();
    layout->addWidget(m_tabs);
    layout->addLayout(m_plotsLayout, 1);
    connect(m_tabs, &QTabBar::currentChanged, this, [this](int index) {
        if (m_arrangement != Arrangement::Tabs)
            return;
        for (std::size_t i = 0; i < m_plots.size(); ++i)
            m_plots[i]->setVisible(m_shown[i] && static_cast<int>(i) == index);
    });
}

void PlotShelf::addPlot(PlotWidget* plot, const QString& tab)
{
    plot->setParent(this);
    m_plots.push_back(plot);
    m_shown.push_back(true);
    m_plotsLayout->addWidget(plot, 1);
    m_tabs->addTab(tab);
    m_tabs->setTabToolTip(m_tabs->count() - 1, plot->title());
    apply(m_arrangement);
}

void PlotShelf::setPlotShown(PlotWidget* plot, bool shown)
{
    const auto at = std::find(m_plots.begin(), m_plots.end(), plot);
    if (at == m_plots.end())
        return;
    const auto i = static_cast<std::size_t>(at - m_plots.begin());
    m_shown[i] = shown;
    m_tabs->setTabVisible(static_cast<int>(i), shown);
    apply(m_arrangement);
    arrange();
}

void PlotShelf::arrange()
{
    if (m_arranging)
        return;
    const int n = static_cast<int>(std::count(m_shown.begin(), m_shown.end(), true));
    if (n < 2)
        return apply(Arrangement::Column);
    // Each plot's least size, from one laid out now (they share their fonts and style).
    const PlotWidget* shown = m_plots.front();
    for (const PlotWidget* p : m_plots)
        if (p->isVisible())
            shown = p;
    const QSize least = plotSizeFor(*shown, kLeastDataArea);
    const int gaps = (n - 1) * std::max(0, m_plotsLayout->spacing());
    if (width() >= n * least.width() + gaps)
        apply(Arrangement::Row);
    else if (height() >= n * least.height() + gaps)
        apply(Arrangement::Column);
    else
        apply(Arrangement::Tabs);
}

void PlotShelf::apply(Arrangement arrangement)
{
    m_arranging = true;
    m_arrangement = arrangement;
    const bool tabs = arrangement == Arrangement::Tabs;
    m_plotsLayout->setDirection(arrangement == Arrangement::Row ? QBoxLayout::LeftToRight
                                                                : QBoxLayout::TopToBottom);
    m_tabs->setVisible(tabs);
    // The tab in front is one of a plot shown.
    const int current = m_tabs->currentIndex();
    if (current >= 0 && !m_shown[static_cast<std::size_t>(current)]) {
        const auto first = std::find(m_shown.begin(), m_shown.end(), true);
        if (first != m_shown.end())
            m_tabs->setCurrentIndex(static_cast<int>(first - m_shown.begin()));
    }
    for (std::size_t i = 0; i < m_plots.size(); ++i)
        m_plots[i]->setVisible(m_shown[i] &&
                               (!tabs || static_cast<int>(i) == m_tabs->currentIndex()));
    m_arranging = false;
}

void PlotShelf::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    if (!m_arranging)
        arrange();
}

} // namespace rigidlab::ui
