// SPDX-License-Identifier: GPL-3.0-or-later
// WindowLayout's arrangement for the screen it is on: what a teacher projecting the lab at
// 1024×768 in a bright room, and a student on a small laptop, need.
//
// The rules, in order: the window never opens larger than the screen's available area; the
// world view keeps at least half of the width; every panel a lesson step shows is in sight
// (panels share tabs only with panels of their kind, and each kind has its own place in the
// column); the lesson text and the world win over the plots; every panel scrolls rather than
// being cut. The layout is remembered per screen size, so a laptop and the classroom
// projector each keep their own.

#include "window/window_layout.h"

#include "panels/error_panel.h"
#include "plots/plot_shelf.h"
#include "plots/plot_table.h"
#include "plots/plot_widget.h"
#include "window/dock_tabs.h"
#include "window/window_names.h"

#include <QDataStream>
#include <QDockWidget>
#include <QGuiApplication>
#include <QLayout>
#include <QMainWindow>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QTabBar>
#include <QTableWidget>
#include <QTimer>

#include <qcustomplot.h>

#include <algorithm>
#include <array>
#include <numeric>

namespace rigidlab::ui {

namespace {

/// The window's size where the screen allows it [px].
constexpr QSize kPreferredSize(1500, 920);
/// On a screen smaller than this the plots are tabbed rather than stacked [px].
constexpr QSize kRoomy(1600, 1000);
/// The share of the window's width each side column takes at most; together they leave the
/// world at least half.
constexpr double kLeftShare = 0.26;
constexpr double kRightShare = 0.22;
/// How the right column's height is shared on a small screen, by kind: the controls and the
/// inspector (the most rows), the tables (the plots have their place under the world; their
/// weight counts only where they are in the column).
constexpr std::array<int, 3> kCompactHeightWeights{5, 4, 4};
/// The same in presentation mode, where the type is large; the controls and tables scroll.
constexpr std::array<int, 3> kPresentationHeightWeights{3, 3, 5};
/// A plot's least height where the room is not short [px].
constexpr int kPlotMinimumHeight = 150;
/// The side columns' widths where there is room [px].
constexpr int kLeftWidth = 400;
constexpr int kRightWidth = 480;

QString sizeKey(const QSize& size)
{
    return QStringLiteral("layout/%1x%2/").arg(size.width()).arg(size.height());
}

/// The error dock's object name in layouts saved before it was named once ("errorDock"):
/// restoreState() finds a dock by its object name.
const QString kOldErrorDockName = QStringLiteral("errorDockDock");

/// Whether a state saved by QMainWindow::saveState() names a dock `name`: the name as its
/// QDataStream writes it, its length before it, so that a longer name does not count.
bool stateNames(const QByteArray& state, const QString& name)
{
    QByteArray written;
    QDataStream out(&written, QIODevice::WriteOnly);
    out << name;
    return state.contains(written);
}

} // namespace

QRect WindowLayout::availableScreenArea() const
{
    const QScreen* s = m_window.screen() ? m_window.screen() : QGuiApplication::primaryScreen();
    return s ? s->availableGeometry() : QRect(QPoint(0, 0), kPreferredSize);
}

void WindowLayout::fitToScreen(const QRect& available)
{
    m_screenArea = available;
    // The frame the window manager adds (known once the window is shown) counts too.
    const QSize frame =
        m_window.isVisible() ? m_window.frameGeometry().size() - m_window.size() : QSize(0, 0);
    const QSize size = kPreferredSize.boundedTo(available.size() - frame);
    const bool sized = !m_window.isFullScreen() && !m_window.isMaximized();
    if (sized) {
        m_window.resize(size);
        // move() places the frame: centred with it.
        const QSize outer = size + frame;
        m_window.move(available.topLeft() + QPoint((available.width() - outer.width()) / 2,
                                                   (available.height() - outer.height()) / 2));
    }
    arrangeDocks(available.size());
    // While the docks were put back one row each, their minimum heights added up and may have
    // grown the window past the screen; tabbed, they fit again.
    m_window.layout()->activate();
    if (sized)
        m_window.resize(size);
    if (QDockWidget* error = m_docks.value(QStringLiteral("error")))
        ErrorPanel::placeDock(*error, available, m_compact);
}

void WindowLayout::arrangeDocks(const QSize& screen)
{
    m_compact = screen.width() < kRoomy.width() || screen.height() < kRoomy.height();
    QList<QDockWidget*> plots;
    for (const PlotRow& row : kPlotRows) // the window's own plots, in the table's order
        if (row.inWindow())
            plots << m_docks.value(plotName(row));
    plots << m_compareDock;
    // An imported measurement is plotted: its dock shares the plots' place (a lesson step
    // that shows it beside a table keeps the table in sight).
    if (QDockWidget* measurement = m_docks.value(QStringLiteral("measurement")))
        plots << measurement;
    const QList<QDockWidget*> settings{m_docks.value(QStringLiteral("controls")),
                                       m_docks.value(QStringLiteral("inspector"))};
    QList<QDockWidget*> tables;
    for (const char* name : {"sat", "bounces", "collision"})
        tables << m_docks.value(QLatin1String(name));
    // Each dock is put back at the end of its side, one row each, in order (this also takes
    // it out of any tab group an earlier arrangement made: splitting a dock that shares tabs
    // would only add a tab), then the docks of a kind are tabbed together.
    QList<QDockWidget*> left{m_docks.value(QStringLiteral("lesson"))};
    QList<QList<QDockWidget*>> groups;
    if (m_compact) {
        // On a small screen the lesson has the left column to itself (its text, questions and
        // buttons need the height). The right column has a place for each kind, top to
        // bottom: the controls and the inspector, the tables. A step's panel is never behind
        // a plot's tab, and a place with nothing shown takes no room. The plots, tabbed, go
        // under the world and the right column, as wide as both: in a column a fifth of
        // 1024 px wide their data area was too small to read (fitPlotHeight()).
        groups = {settings, tables, plots};
    } else {
        // The controls and the inspector under the lesson; the plots stacked one above the
        // other on the right, the tables (SAT, bounces, collision) below them.
        left << settings;
        for (QDockWidget* plot : plots)
            groups << QList<QDockWidget*>{plot};
        groups << tables;
    }
    // On a small screen the bottom area lies under the world and the right column, the lesson
    // beside it keeping the whole height; else it spans the window (the work-precision sweep).
    m_window.setCorner(Qt::BottomLeftCorner,
                       m_compact ? Qt::LeftDockWidgetArea : Qt::BottomDockWidgetArea);
    m_window.setCorner(Qt::BottomRightCorner, Qt::BottomDockWidgetArea);
    for (QDockWidget* d : left)
        m_window.addDockWidget(Qt::LeftDockWidgetArea, d);
    for (const QList<QDockWidget*>& group : groups)
        for (QDockWidget* d : group)
            m_window.addDockWidget(m_compact && group == plots ? Qt::BottomDockWidgetArea
                                                               : Qt::RightDockWidgetArea,
                                   d);
    if (left.contains(settings.first()))
        m_window.tabifyDockWidget(settings.first(), settings.last());
    for (const QList<QDockWidget*>& group : groups)
        for (int i = 1; i < group.size(); ++i)
            m_window.tabifyDockWidget(group.first(), group.at(i));
    m_rightGroups = m_compact ? groups : QList<QList<QDockWidget*>>();
    settings.first()->raise();
    plots.first()->raise();
    fitSideColumns();
}

void WindowLayout::keepingSize(const std::function<void()>& change)
{
    const QSize before = m_window.size();
    change();
    if (m_window.isMaximized() || m_window.size() == before)
        return;
    m_window.layout()->activate();
    if (m_window.minimumSizeHint().boundedTo(before) == m_window.minimumSizeHint())
        m_window.resize(before);
}

void WindowLayout::regroup()
{
    for (const QList<QDockWidget*>& group : std::as_const(m_rightGroups)) {
        QDockWidget* first = nullptr;
        for (QDockWidget* d : group) {
            if (d->isHidden())
                continue;
            if (!first)
                first = d;
            else if (!m_window.tabifiedDockWidgets(first).contains(d))
                m_window.tabifyDockWidget(first, d);
        }
    }
}

void WindowLayout::fitSideColumns()
{
    const int windowWidth = m_window.width();
    const int left = std::min(kLeftWidth, static_cast<int>(kLeftShare * windowWidth));
    const int right = std::min(kRightWidth, static_cast<int>(kRightShare * windowWidth));
    QList<QDockWidget*> leftDocks, rightDocks;
    for (QDockWidget* d : m_window.findChildren<QDockWidget*>()) {
        if (d->isHidden())
            continue;
        if (m_window.dockWidgetArea(d) == Qt::LeftDockWidgetArea)
            leftDocks << d;
        else if (m_window.dockWidgetArea(d) == Qt::RightDockWidgetArea)
            rightDocks << d;
    }
    if (!leftDocks.isEmpty())
        m_window.resizeDocks({leftDocks.first()}, {left}, Qt::Horizontal);
    if (!rightDocks.isEmpty())
        m_window.resizeDocks({rightDocks.first()}, {right}, Qt::Horizontal);
    // Once the docks have their places: those behind a tab take no keyboard focus.
    QTimer::singleShot(0, this, [this] {
        for (QDockWidget* d : m_window.findChildren<QDockWidget*>())
            showContentIfInSight(*d);
        // Likewise the tab bars the window keeps aside, out of sight, for later tab groups.
        for (QTabBar* bar :
             m_window.findChildren<QTabBar*>(QString(), Qt::FindDirectChildrenOnly)) {
            const QRect r = bar->geometry();
            bar->setFocusPolicy(r.right() < 0 || r.bottom() < 0 ? Qt::NoFocus : Qt::TabFocus);
        }
        // A dock shown again may come back as a column of its own beside its kind's tabs,
        // past the window's edge: back into its tab group.
        for (const QList<QDockWidget*>& group : std::as_const(m_rightGroups))
            for (QDockWidget* d : group)
                if (!d->isHidden() && d->geometry().right() >= m_window.width()) {
                    regroup();
                    break;
                }
        shareColumnHeight();
        fitPlotHeight();
        scrollTablesToData();
    });
}

void WindowLayout::scrollTablesToData()
{
    // A table panel's description above its table may fill a short dock (presentation mode's
    // type): the dock scrolls so that as much of the table as fits is in sight, its head
    // first, and the description only as far as room is left.
    for (const char* name : {"sat", "bounces", "collision"}) {
        QDockWidget* dock = m_docks.value(QLatin1String(name));
        auto* scroll = dock ? qobject_cast<QScrollArea*>(dock->widget()) : nullptr;
        if (!scroll || dock->isHidden() || !scroll->widget())
            continue;
        const auto* table = scroll->widget()->findChild<QTableWidget*>();
        if (!table || !table->isVisible())
            continue;
        const int top = table->mapTo(scroll->widget(), QPoint(0, 0)).y();
        const int bottom = top + table->height();
        const int needed = std::max(0, bottom - scroll->viewport()->height());
        QScrollBar* bar = scroll->verticalScrollBar();
        if (bar->value() < std::min(top, needed))
            bar->setValue(std::min(top, needed));
    }
}

void WindowLayout::fitPlotHeight()
{
    // The plots under the world (a small screen) at least as tall as keeps a readable data
    // area, kLeastDataArea, with their legends and axis titles above and below it: as their
    // least height, which the window keeps whatever else is shown. Again whenever one's size
    // changes (a legend wraps to more rows in less width, presentation mode's type).
    for (PlotWidget* plot : m_window.findChildren<PlotWidget*>()) {
        QDockWidget* dock = nullptr;
        for (QWidget* p = plot->parentWidget(); p && !dock; p = p->parentWidget())
            dock = qobject_cast<QDockWidget*>(p);
        if (!dock || !plot->isVisible())
            continue;
        plot->installEventFilter(this);
        int least = kPlotMinimumHeight;
        // Plots one above the other in a shelf have each its least height already (the shelf
        // stacks them only then); their least heights added up would hold the dock that tall.
        const auto* shelf = qobject_cast<const PlotShelf*>(plot->parentWidget());
        const bool stacked = shelf && shelf->arrangement() == PlotShelf::Arrangement::Column;
        if (m_compact && !stacked && m_window.dockWidgetArea(dock) == Qt::BottomDockWidgetArea) {
            plot->plot()->replot(QCustomPlot::rpImmediateRefresh); // laid out at its size now
            least = std::max(least, plotSizeFor(*plot, kLeastDataArea).height());
        }
        if (plot->minimumHeight() != least)
            plot->setMinimumHeight(least);
    }
}

void WindowLayout::relaxPlotHeights()
{
    for (PlotWidget* plot : m_window.findChildren<PlotWidget*>())
        plot->setMinimumHeight(std::min(plot->minimumHeight(), kPlotMinimumHeight));
}

void WindowLayout::fitPlotHeightSoon()
{
    if (m_plotFitPending)
        return;
    m_plotFitPending = true;
    QTimer::singleShot(0, this, [this] {
        m_plotFitPending = false;
        fitPlotHeight();
    });
}

bool WindowLayout::eventFilter(QObject* watched, QEvent* event)
{
    if (event->type() == QEvent::Resize && qobject_cast<PlotWidget*>(watched))
        fitPlotHeightSoon();
    return QObject::eventFilter(watched, event);
}

void WindowLayout::shareColumnHeight()
{
    // On a small screen the right column's kinds share its height by their weights: the
    // controls are not squeezed to a few rows by a plot, nor a plot by a table. Each kind by
    // its dock in front.
    QList<QList<QDockWidget*>> groups;
    QList<int> weights;
    int total = 0;
    for (qsizetype g = 0; g < m_rightGroups.size(); ++g) {
        QList<QDockWidget*> group;
        QList<QDockWidget*> kind = m_rightGroups[g];
        // The scene editor's Properties and History are tabs beside the inspector: settings
        // too, though the layout did not place them. Uncounted, they kept whatever height an
        // earlier step left (a lesson's editor step after steps that showed only a table: the
        // Properties squeezed to a few rows under a half-empty collision table).
        if (g == 0)
            for (const char* name : {"propertiesDock", "historyDock"})
                if (auto* editor = m_window.findChild<QDockWidget*>(QLatin1String(name),
                                                                    Qt::FindDirectChildrenOnly))
                    kind << editor;
        for (QDockWidget* d : kind)
            if (!d->isHidden() && d->geometry().right() >= 0 && d->geometry().bottom() >= 0 &&
                m_window.dockWidgetArea(d) == Qt::RightDockWidgetArea)
                group << d;
        if (group.isEmpty())
            continue;
        total += group.first()->height();
        groups << group;
        weights << (m_presentation ? kPresentationHeightWeights
                                   : kCompactHeightWeights)[static_cast<std::size_t>(g)];
    }
    if (groups.size() < 2)
        return;
    // In pixels that add up to the column's height as it is: resizeDocks() fits the sizes it
    // is given into the column, and sizes adding up to more are cut from the last dock (the
    // plots) down to its minimum, while the rest goes to an expanding table.
    const int weightSum = std::accumulate(weights.begin(), weights.end(), 0);
    QList<QDockWidget*> front;
    QList<int> heights;
    for (qsizetype g = 0; g < groups.size(); ++g) {
        front << groups[g].first();
        heights << total * weights[g] / weightSum;
    }
    m_window.resizeDocks(front, heights, Qt::Vertical);
}

void WindowLayout::save(QSettings& s) const
{
    const QString key = sizeKey(m_screenArea.size());
    if (m_presentation) {
        // Presentation mode is for the moment: the layout to remember is the one before it.
        s.setValue(key + QStringLiteral("geometry"), m_normalGeometry);
        s.setValue(key + QStringLiteral("state"), m_normalState);
    } else {
        s.setValue(key + QStringLiteral("geometry"), m_window.saveGeometry());
        s.setValue(key + QStringLiteral("state"), m_window.saveState());
    }
}

void WindowLayout::restore(const QSettings& s)
{
    const QRect available = availableScreenArea();
    fitToScreen(available);
    const QString key = sizeKey(available.size());
    if (!s.contains(key + QStringLiteral("state")))
        return;
    m_window.restoreGeometry(s.value(key + QStringLiteral("geometry")).toByteArray());
    const QByteArray state = s.value(key + QStringLiteral("state")).toByteArray();
    // A layout saved under the error dock's old name: the dock answers to it while the layout
    // is restored, and goes where the teacher had put it, not back to its first place.
    QDockWidget* error = m_docks.value(QStringLiteral("error"));
    const QString name = error ? error->objectName() : QString();
    const bool oldName = error && stateNames(state, kOldErrorDockName);
    if (oldName)
        error->setObjectName(kOldErrorDockName);
    m_window.restoreState(state);
    if (oldName)
        error->setObjectName(name);
    // Never larger than the screen, whatever was saved (the screen may have shrunk).
    if (!m_window.isMaximized() && !m_window.isFullScreen() &&
        (m_window.width() > available.width() || m_window.height() > available.height()))
        m_window.resize(m_window.size().boundedTo(available.size()));
}

void WindowLayout::windowShown()
{
    QTimer::singleShot(0, this, &WindowLayout::keepFrameOnScreen);
}

void WindowLayout::windowMoved()
{
    // A window manager (openbox) frames the window after it is shown, and moves it as it does:
    // only then is the frame known.
    keepFrameOnScreen();
}

void WindowLayout::keepFrameOnScreen()
{
    if (m_screenArea.isEmpty() || m_presentation || m_window.isFullScreen() ||
        m_window.isMaximized() || !m_window.isVisible())
        return;
    // The window and its frame together within the screen's available area: else the status
    // bar (paused, drift, the solver that ran) lies below a 1024×768 projector's edge.
    const QRect outer = m_window.frameGeometry();
    const QSize frame = outer.size() - m_window.size();
    if (frame == m_frameFitted || m_screenArea.contains(outer))
        return;
    m_frameFitted = frame;
    fitToScreen(m_screenArea);
}

void WindowLayout::windowResized()
{
    if (m_presentation && m_window.isFullScreen())
        fitSideColumns();
    if (m_restoreStatePending && !m_presentation && !m_window.isFullScreen()) {
        m_restoreStatePending = false;
        restoreNormalState();
    }
}

} // namespace rigidlab::ui
