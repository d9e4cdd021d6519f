// SPDX-License-Identifier: GPL-3.0-or-later
// The plots' table (plot_table.h): finding a row, and a plot of one quantity made from its row.

#include "plots/plot_table.h"

#include "plots/plot_widget.h"

#include "format/lesson.h"

#include <QCoreApplication>

#include <cassert>
#include <iterator>

namespace rigidlab::ui {

namespace {

constexpr bool namesInFormatOrder()
{
    if (std::size(kPlotRows) != lessons::kStepPlotNames.size())
        return false;
    for (std::size_t i = 0; i < std::size(kPlotRows); ++i)
        if (kPlotRows[i].name != lessons::kStepPlotNames[i])
            return false;
    return true;
}
// The lesson loader admits the names of lessons::kStepPlotNames: a row for each, in order.
static_assert(namesInFormatOrder(), "one plot row for each of lessons::kStepPlotNames");

QString translated(const char* text)
{
    return QCoreApplication::translate("rigidlab::ui::MainWindow", text);
}

} // namespace

const PlotRow* findPlot(QStringView name)
{
    for (const PlotRow& row : kPlotRows)
        if (name == plotName(row))
            return &row;
    return nullptr;
}

QString plotName(const PlotRow& row)
{
    return QString::fromLatin1(row.name.data(), static_cast<qsizetype>(row.name.size()));
}

QString plotTitle(const PlotRow& row, bool full)
{
    return translated(full || !row.shortTitle ? row.title : row.shortTitle);
}

PlotWidget* makeWorldPlot(const PlotRow& row, QWidget* parent)
{
    assert(row.inWindow()); // the compared worlds are a step's
    PlotWidget* plot = nullptr;
    if (row.make) {
        plot = row.make(parent);
    } else {
        // A plot of one quantity: its row's title, axis and one curve.
        plot = new PlotWidget(plotTitle(row), parent);
        plot->setYAxisLabel(translated(row.quantity), QString::fromUtf8(row.unit));
        plot->addSeries(translated(row.quantity), plotColor(0), row.sample);
    }
    // Found by its name: the window's docks, a step's plots and their files.
    plot->setObjectName(plotName(row));
    return plot;
}

} // namespace rigidlab::ui
