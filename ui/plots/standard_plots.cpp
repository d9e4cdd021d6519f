// SPDX-License-Identifier: GPL-3.0-or-later
// The plots of the lab window, each a few lines over PlotWidget; and the palette they share.
// The plots are declared in plot_table.h (made by their rows), the palette in plot_widget.h.

#include "plots/plot_table.h"
#include "plots/plot_widget.h"

#include "export/csv_columns.h"

#include <algorithm>
#include <iterator>
#include <utility>

namespace rigidlab::ui {

QColor plotColor(int index)
{
    // Okabe & Ito's hues, each darkened as a whole (its red, green and blue scaled alike, so
    // the hue stays) until it has at least 3:1 against the plots' white and the world's
    // background (WCAG 1.4.11), and until any two stay apart for a student with deuteranopia
    // or protanopia: at least 15 CIELAB ΔE (1976) after Machado, Oliveira and Fernandes'
    // (2009) simulation at full severity, and at least 23 with normal colour vision
    // (tests/ui/test_colours checks both, and every shipped plot). The six hues first (the
    // bodies' colours, bodyColor), ink last.
    // Colour is never alone: each series also has its own line style and marker
    // (plotPenStyleFor, plotMarker).
    static const QColor palette[] = {
        {0x00, 0x5D, 0x92}, // blue, 6.8:1 on the world's background
        {0xAF, 0x4D, 0x00}, // vermilion, 5.2:1
        {0x00, 0x82, 0x5E}, // bluish green, 4.7:1
        {0xAB, 0x66, 0x8C}, // reddish purple, 4.0:1
        {0xBD, 0x82, 0x00}, // orange, 3.2:1
        {0x47, 0x94, 0xBF}, // sky blue, 3.2:1
        {0x20, 0x20, 0x20}, // ink, 16:1
    };
    const int n = static_cast<int>(std::size(palette));
    return palette[((index % n) + n) % n];
}

Qt::PenStyle plotPenStyle(int index)
{
    // Solid first, then dashes that leave gaps for the curves drawn before to show through.
    static const Qt::PenStyle styles[] = {Qt::SolidLine, Qt::DashLine, Qt::DotLine, Qt::DashDotLine,
                                          Qt::DashDotDotLine};
    const int n = static_cast<int>(std::size(styles));
    return styles[((index % n) + n) % n];
}

Qt::PenStyle plotPenStyleFor(int index)
{
    // Dashed is kept for the right axis (and the dotted ghost is faint): the left-axis series
    // go solid, dash-dot, dash-dot-dot, then dotted.
    static const Qt::PenStyle styles[] = {Qt::SolidLine, Qt::DashDotLine, Qt::DashDotDotLine,
                                          Qt::DotLine};
    const int n = static_cast<int>(std::size(styles));
    return styles[((index % n) + n) % n];
}

double plotPenWidthFactor(int index, int count)
{
    // 0.4 of a line more per curve drawn over it: 2 px lines at 4.4, 3.6, 2.8 and 2 px for
    // four worlds, wide enough that each shows on both sides of the next.
    return 1.0 + 0.4 * std::max(count - 1 - index, 0);
}

PlotWidget* makeEnergyPlot(QWidget* parent)
{
    auto* plot = new PlotWidget(PlotWidget::tr("Energy"), parent);
    plot->setYAxisLabel(PlotWidget::tr("energy E"), QStringLiteral("J"));
    plot->model().setValueScale(YAxis::Left, [](const Sample& s) { return s.energyScale; });
    using lessons::CsvColumn;
    const int kinetic = plot->addSeries(PlotWidget::tr("kinetic"), plotColor(1),
                                        [](const Sample& s) { return s.kinetic; });
    const int potential = plot->addSeries(PlotWidget::tr("potential"), plotColor(0),
                                          [](const Sample& s) { return s.potential; });
    const int total = plot->addSeries(PlotWidget::tr("total"), plotColor(6),
                                      [](const Sample& s) { return s.total; });
    // The energy balance: what contacts, friction, drag and dampers took since the start, and
    // the total with it added back, which stays at the starting energy but for the drift.
    const int dissipated = plot->addSeries(PlotWidget::tr("dissipated"), plotColor(2),
                                           [](const Sample& s) { return s.dissipated; });
    const int balance = plot->addSeries(PlotWidget::tr("total + dissipated"), plotColor(4),
                                        [](const Sample& s) { return s.total + s.dissipated; });
    // The CSV heads the command line's diagnostics use for the same quantities.
    for (const auto& [series, column] :
         {std::pair{kinetic, CsvColumn::Kinetic}, std::pair{potential, CsvColumn::Potential},
          std::pair{total, CsvColumn::Total}, std::pair{dissipated, CsvColumn::Dissipated},
          std::pair{balance, CsvColumn::TotalDissipated}})
        plot->model().setSeriesColumn(series, lessons::csvColumnHead(column));
    // With nothing dissipated it lies on the total: dashed, so that both stay visible.
    plot->setSeriesPen(balance, plotPenStyle(1));
    return plot;
}

PlotWidget* makeMomentumPlot(QWidget* parent)
{
    auto* plot = new PlotWidget(PlotWidget::tr("Momentum"), parent);
    plot->setYAxisLabel(PlotWidget::tr("p"), QStringLiteral("kg m/s"));
    plot->setYAxisLabel(PlotWidget::tr("L"), QStringLiteral("kg m²/s"), YAxis::Right);
    plot->model().setValueScale(YAxis::Left, [](const Sample& s) { return s.momentumScale; });
    plot->model().setValueScale(YAxis::Right,
                                [](const Sample& s) { return s.angularMomentumScale; });
    plot->model().setMinimumSpan(YAxis::Left, kConservedMinimumSpan);
    plot->model().setMinimumSpan(YAxis::Right, kConservedMinimumSpan);
    const int px =
        plot->addSeries(QStringLiteral("px"), plotColor(0), [](const Sample& s) { return s.px; });
    const int py =
        plot->addSeries(QStringLiteral("py"), plotColor(1), [](const Sample& s) { return s.py; });
    const int l = plot->addSeries(
        QStringLiteral("L"), plotColor(2), [](const Sample& s) { return s.angularMomentum; },
        YAxis::Right);
    plot->model().setSeriesColumn(px, lessons::csvColumnHead(lessons::CsvColumn::Px));
    plot->model().setSeriesColumn(py, lessons::csvColumnHead(lessons::CsvColumn::Py));
    plot->model().setSeriesColumn(l, lessons::csvColumnHead(lessons::CsvColumn::AngularMomentum));
    return plot;
}

PlotWidget* makeDriftPlot(QWidget* parent)
{
    auto* plot = new PlotWidget(PlotWidget::tr("Energy drift"), parent);
    // The numerical error alone: the energy that contacts, friction, drag and dampers took is
    // added back, since losing it is physics, not error.
    // The axis says what it is in a word (a plot in a narrow column has no room for the
    // formula, (E + E_dissipated − E₀)/|E₀|, which the README and the lesson give).
    plot->setYAxisLabel(PlotWidget::tr("drift"), QStringLiteral("%"));
    plot->model().setValueScale(YAxis::Left, kDriftScalePercent);
    const int drift = plot->addSeries(PlotWidget::tr("energy drift (numerical error)"),
                                      plotColor(3), [](const Sample& s) { return s.driftPercent; });
    plot->model().setSeriesColumn(drift, lessons::csvColumnHead(lessons::CsvColumn::DriftPercent));
    return plot;
}

} // namespace rigidlab::ui
