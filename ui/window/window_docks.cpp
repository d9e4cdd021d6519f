// SPDX-License-Identifier: GPL-3.0-or-later
// WindowLayout's docks: the lesson, the panels, the plots, each under its lesson name.
#include "window/window_layout.h"

#include "common/accessible_names.h"
#include "common/dock_names.h"
#include "common/step_part_names.h"
#include "common/theme.h"
#include "plots/plot_table.h"
#include "plots/plot_widget.h"
#include "window/dock_tabs.h"

#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QMainWindow>
#include <QScrollArea>
#include <QVBoxLayout>

#include <algorithm>
#include <string_view>
#include <utility>

namespace rigidlab::ui {

namespace {

/// Text read by a class from the back of the room: `panel` and the widgets in it that chose a
/// size of their own (a title, the step's text) grow by theme::kReadingFontScale.
void enlargeForReading(QWidget& panel)
{
    for (QWidget* w : panel.findChildren<QWidget*>())
        if (w->testAttribute(Qt::WA_SetFont)) {
            QFont f = w->font();
            f.setPointSizeF(f.pointSizeF() * theme::kReadingFontScale);
            w->setFont(f);
            w->setProperty(kReadingSizeProperty, true);
        }
    QFont f = panel.font();
    f.setPointSizeF(f.pointSizeF() * theme::kReadingFontScale);
    panel.setFont(f);
    panel.setProperty(kReadingSizeProperty, true);
}

} // namespace

WindowLayout::WindowLayout(QMainWindow& window, const Panels& panels)
    : QObject(&window), m_window(window)
{
    window.setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks);
    // Short dock titles, whole on their tabs; the full ones in tooltips.
    keepDockTabsWhole(window);
    buildLessonDock(panels);
    // The panels a lesson step may show, each under the lesson format's name, its full title
    // the one the lesson editor lists it by.
    const auto panelDock = [this](std::string_view name, QWidget* panel,
                                  Scrolling scrolling = Scrolling::InDock) {
        const StepPartName& part = stepPanel(name);
        return addDock(QLatin1String(part.name), panel, Qt::RightDockWidgetArea,
                       stepPartText(part.title), scrolling);
    };
    panelDock("controls", panels.controls);
    panelDock("inspector", panels.inspector);
    for (PlotWidget* plot : panels.plots) {
        const PlotRow* row = findPlot(plot->objectName());
        Q_ASSERT(row); // made by its row (makeWorldPlot)
        // Small enough that the plots fit beside the world on a 1024×768 projector.
        plot->setMinimumSize(180, 150);
        plot->setTitleShown(false); // the dock shows it
        addDock(plot->objectName(), plot, Qt::RightDockWidgetArea, plotTitle(*row));
    }
    for (const auto& [name, panel] : {std::pair<std::string_view, QWidget*>{"sat", panels.sat},
                                      {"bounces", panels.bounces},
                                      {"collision", panels.collision}})
        panelDock(name, panel)->hide();
    // The work-precision sweep, hidden until asked for (View menu).
    addDock(QStringLiteral("error"), panels.error, Qt::BottomDockWidgetArea)->hide();
    panelDock("measurement", panels.measurement, Scrolling::Own)->hide();
    m_compareDock = new QDockWidget(&window);
    nameDock(*m_compareDock, QStringLiteral("compareDock"));
    setFullTitle(*m_compareDock, m_compareDock->windowTitle());
    window.addDockWidget(Qt::RightDockWidgetArea, m_compareDock);
    keepFocusInSight(*m_compareDock);
    m_compareDock->hide();
}

QDockWidget* WindowLayout::addDock(const QString& name, QWidget* w, int area, const QString& full,
                                   Scrolling scrolling)
{
    auto* dock = new QDockWidget(&m_window);
    nameDock(*dock, name + QStringLiteral("Dock"));
    const QString title = dock->windowTitle();
    setFullTitle(*dock, full.isEmpty() ? title : full);
    // Lists as narrow as a short name: a long entry ("Dormand-Prince 5(4), adaptive") must not
    // widen the side column on a small projector.
    for (QComboBox* box : w->findChildren<QComboBox*>()) {
        box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        box->setMinimumContentsLength(8);
    }
    if (qobject_cast<PlotWidget*>(w) || scrolling == Scrolling::Own) {
        dock->setWidget(w);
    } else {
        // A panel taller or wider than its dock scrolls instead of being cut.
        auto* scroll = new QScrollArea(dock);
        scroll->setWidgetResizable(true);
        scroll->setFrameShape(QFrame::NoFrame);
        scroll->setWidget(w);
        nameScrollArea(*scroll, title);
        dock->setWidget(scroll);
    }
    m_window.addDockWidget(static_cast<Qt::DockWidgetArea>(area), dock);
    m_docks.insert(name, dock);
    keepFocusInSight(*dock);
    // Its plots, first seen when its tab comes to the front (a measurement imported), as
    // tall as every plot shown.
    connect(dock, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible)
            fitPlotHeightSoon();
    });
    showWhenAsked(*dock);
    return dock;
}

void WindowLayout::buildLessonDock(const Panels& panels)
{
    QDockWidget* lessonDock =
        addDock(QStringLiteral("lesson"), panels.lesson, Qt::LeftDockWidgetArea);
    enlargeForReading(*panels.lesson);
    // The step's questions and Back, Next, Restart and Export stay in sight below the lesson,
    // which scrolls.
    auto* box = new QWidget(lessonDock);
    auto* column = new QVBoxLayout(box);
    column->setContentsMargins(0, 0, 0, 4);
    column->addWidget(lessonDock->widget(), 1);
    column->addWidget(panels.lessonNavigation);
    lessonDock->setWidget(box);
}

void WindowLayout::showWhenAsked(QDockWidget& dock)
{
    // Ticked in the View menu: in front of the docks it shares tabs with, in a column wide
    // enough to read it.
    connect(dock.toggleViewAction(), &QAction::triggered, this, [this, d = &dock](bool on) {
        if (!on)
            return;
        d->raise();
        fitSideColumns();
    });
}

QDockWidget* WindowLayout::dock(const QString& name) const
{
    if (const PlotRow* plot = findPlot(name); plot && !plot->inWindow())
        return m_compareDock; // the compared worlds' plots share one dock
    return m_docks.value(name, nullptr);
}

void WindowLayout::raiseFirst(QList<QDockWidget*> docks) const
{
    // Its table first (its numbers are what the questions ask about), then the first plot it
    // lists (its text talks about it), then the controls, which the student finds by their tab.
    const auto rank = [this](QDockWidget* d) {
        for (const char* table : {"sat", "bounces", "collision"})
            if (d == m_docks.value(QLatin1String(table)))
                return 0;
        return d == m_docks.value(QStringLiteral("controls")) ||
                       d == m_docks.value(QStringLiteral("inspector"))
                   ? 2
                   : 1;
    };
    std::stable_sort(docks.begin(), docks.end(),
                     [&](QDockWidget* a, QDockWidget* b) { return rank(a) < rank(b); });
    // The first of each tab group: the table, the plot and the controls each have a place.
    QList<QDockWidget*> raisedWith;
    for (QDockWidget* d : docks) {
        const QList<QDockWidget*> tabs = m_window.tabifiedDockWidgets(d);
        if (std::any_of(tabs.begin(), tabs.end(),
                        [&](QDockWidget* t) { return raisedWith.contains(t); }))
            continue;
        d->raise();
        raisedWith << d;
    }
}

} // namespace rigidlab::ui
