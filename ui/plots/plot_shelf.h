// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Plots shown together in one place (the compared worlds' dock): side by side where each keeps
// its least data area across, one above the other where each keeps it in height, else one at
// a time behind tabs. A plot is never squeezed below what a class reads at 1024×768.

#include <QSize>
#include <QWidget>

#include <vector>

class QBoxLayout;
class QTabBar;

namespace rigidlab::ui {

class PlotWidget;

/// The least area inside a shown plot's axes [px]: its curves readable from the back of a room
/// on a 1024×768 projector.
inline constexpr QSize kLeastDataArea(300, 150);

/// The size `plot` needs for `data` inside its axes [px], with its legend, axis titles and
/// tick labels as they are laid out now.
QSize plotSizeFor(const PlotWidget& plot, const QSize& data);
/// The area inside `plot`'s axes as last laid out [px].
QSize plotDataArea(const PlotWidget& plot);

class PlotShelf : public QWidget {
    Q_OBJECT
public:
    enum class Arrangement { Row, Column, Tabs };

    explicit PlotShelf(QWidget* parent = nullptr);

    /// Adds `plot` (the shelf owns it), named `tab` on its tab when they are one at a time.
    void addPlot(PlotWidget* plot, const QString& tab);
    /// Shows `plot` or leaves it out (its owner's choice): one left out takes no room and has
    /// no tab, and the others are arranged without it.
    void setPlotShown(PlotWidget* plot, bool shown);
    Arrangement arrangement() const { return m_arrangement; }
    /// Arranges the plots for the shelf's size now.
    void arrange();

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void apply(Arrangement arrangement);

    QTabBar* m_tabs;
    QBoxLayout* m_plotsLayout;
    std::vector<PlotWidget*> m_plots;
    std::vector<bool> m_shown; ///< per plot: not left out by setPlotShown()
    Arrangement m_arrangement = Arrangement::Column;
    bool m_arranging = false;
};

} // namespace rigidlab::ui
