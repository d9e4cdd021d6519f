// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow's docks: the lesson, the panels, the plots, each under its lesson name.
#include "window/main_window.h"

#include "lesson_player/lesson_panels.h"
#include "lesson_player/lesson_player.h"
#include "panels/control_panel.h"
#include "panels/error_panel.h"
#include "panels/inspector_panel.h"
#include "panels/sat_panel.h"
#include "plots/plot_widget.h"
#include "window/dock_tabs.h"
#include "window/window_names.h"

#include <QComboBox>
#include <QDockWidget>
#include <QScrollArea>
#include <QVBoxLayout>

namespace rigidlab::ui {

void MainWindow::buildDocks()
{
    setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks);
    // Short dock titles, whole on their tabs; the full ones in tooltips.
    keepDockTabsWhole(*this);
    auto addDock = [this](const QString& title, const QString& name, QWidget* w,
                          Qt::DockWidgetArea area, const QString& full = QString()) {
        auto* dock = new QDockWidget(title, this);
        dock->setObjectName(name + QStringLiteral("Dock"));
        setFullTitle(*dock, full.isEmpty() ? title : full);
        if (qobject_cast<PlotWidget*>(w)) {
            dock->setWidget(w);
        } else {
            // Lists as narrow as a short name: a long entry ("Dormand-Prince 5(4), adaptive")
            // must not widen the side column on a small projector.
            for (QComboBox* box : w->findChildren<QComboBox*>()) {
                box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
                box->setMinimumContentsLength(8);
            }
            // A panel taller or wider than its dock scrolls instead of being cut.
            auto* scroll = new QScrollArea(dock);
            scroll->setWidgetResizable(true);
            scroll->setFrameShape(QFrame::NoFrame);
            scroll->setWidget(w);
            dock->setWidget(scroll);
        }
        addDockWidget(area, dock);
        m_docks.insert(name, dock);
        return dock;
    };
    QDockWidget* lessonDock =
        addDock(tr("Lesson"), QStringLiteral("lesson"), m_player, Qt::LeftDockWidgetArea);
    {
        // Back, Next, Restart and Export stay in sight below the lesson, which scrolls.
        auto* box = new QWidget(lessonDock);
        auto* column = new QVBoxLayout(box);
        column->setContentsMargins(0, 0, 0, 4);
        column->addWidget(lessonDock->widget(), 1);
        column->addWidget(m_player->takeNavigation());
        lessonDock->setWidget(box);
    }
    addDock(tr("Controls"), QStringLiteral("controls"), m_controls, Qt::LeftDockWidgetArea);
    addDock(tr("Inspector"), QStringLiteral("inspector"), m_inspector, Qt::LeftDockWidgetArea);
    tabifyDockWidget(m_docks.value(QStringLiteral("controls")),
                     m_docks.value(QStringLiteral("inspector")));
    m_docks.value(QStringLiteral("controls"))->raise();
    m_plots[0] = makeEnergyPlot(this);
    m_plots[1] = makeMomentumPlot(this);
    m_plots[2] = makeDriftPlot(this);
    static_assert(kPlotNames.size() == kPlotCount);
    for (int i = 0; i < kPlotCount; ++i) {
        // Small enough that the plots fit beside the world on a 1024×768 projector.
        m_plots[static_cast<size_t>(i)]->setMinimumSize(180, 150);
        m_plots[static_cast<size_t>(i)]->setTitleShown(false); // the dock shows it
        const PlotNames& plot = kPlotNames[static_cast<size_t>(i)];
        addDock(tr(plot.shortTitle), QLatin1String(plot.name), m_plots[static_cast<size_t>(i)],
                Qt::RightDockWidgetArea, tr(plot.title));
    }
    addDock(tr("Axis test", "short for: separating axis test"), QStringLiteral("sat"), m_sat,
            Qt::RightDockWidgetArea, tr("Separating axis test"))
        ->hide();
    addDock(tr("Bounces"), QStringLiteral("bounces"), m_bounces, Qt::RightDockWidgetArea)->hide();
    addDock(tr("Collision"), QStringLiteral("collision"), m_collision, Qt::RightDockWidgetArea)
        ->hide();
    // The work-precision sweep, hidden until asked for (View menu).
    addDock(tr("Error vs run time"), QStringLiteral("errorDock"), new ErrorPanel(this),
            Qt::BottomDockWidgetArea)
        ->hide();
    m_compareDock = new QDockWidget(tr("Side by side"), this);
    m_compareDock->setObjectName(QStringLiteral("compareDock"));
    setFullTitle(*m_compareDock, m_compareDock->windowTitle());
    addDockWidget(Qt::RightDockWidgetArea, m_compareDock);
    m_compareDock->hide();
}

QDockWidget* MainWindow::dock(const QString& name) const
{
    if (name == QLatin1String("compare-energy") || name == QLatin1String("compare-drift"))
        return m_compareDock;
    return m_docks.value(name, nullptr);
}

} // namespace rigidlab::ui
