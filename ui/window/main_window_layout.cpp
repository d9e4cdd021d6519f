// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow's arrangement for the screen it is on, and presentation mode: what a teacher
// projecting the lab at 1024×768 in a bright room, and a student on a small laptop, need.
//
// The rules, in order: the window never opens larger than the screen's available area; the
// world view keeps at least half of the width; the lesson text and the world win over the
// plots (on a small screen the plots share one tabbed dock and the tables another); every
// panel scrolls rather than being cut. The layout is remembered per screen size, so a laptop
// and the classroom projector each keep their own.

#include "window/main_window.h"

#include "panels/error_panel.h"

#include "common/theme.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"
#include "window/window_names.h"

#include <QApplication>
#include <QDockWidget>
#include <QGraphicsScene>
#include <QScreen>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>

#include <algorithm>

namespace rigidlab::ui {

namespace {

/// The window's size where the screen allows it [px].
constexpr QSize kPreferredSize(1500, 920);
/// On a screen smaller than this the plots are tabbed rather than stacked [px].
constexpr QSize kRoomy(1600, 1000);
/// The share of the window's width each side column takes at most; together they leave the
/// world at least half. The lesson's column wins over the plots'.
constexpr double kLeftShare = 0.27;
constexpr double kRightShare = 0.21;
/// The side columns' widths where there is room [px].
constexpr int kLeftWidth = 400;
constexpr int kRightWidth = 480;

QString sizeKey(const QSize& size)
{
    return QStringLiteral("layout/%1x%2/").arg(size.width()).arg(size.height());
}

/// Black on white, strong selection: survives a washed-out projector.
QPalette highContrastPalette()
{
    QPalette p;
    for (const auto role : {QPalette::Window, QPalette::Base, QPalette::Button,
                            QPalette::AlternateBase, QPalette::ToolTipBase})
        p.setColor(role, Qt::white);
    for (const auto role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText,
                            QPalette::ToolTipText, QPalette::BrightText})
        p.setColor(role, Qt::black);
    p.setColor(QPalette::Highlight, QColor(0, 60, 170));
    p.setColor(QPalette::HighlightedText, Qt::white);
    p.setColor(QPalette::PlaceholderText, QColor(70, 70, 70));
    p.setColor(QPalette::Disabled, QPalette::WindowText, QColor(90, 90, 90));
    p.setColor(QPalette::Disabled, QPalette::Text, QColor(90, 90, 90));
    p.setColor(QPalette::Disabled, QPalette::ButtonText, QColor(90, 90, 90));
    return p;
}

} // namespace

QRect MainWindow::availableScreenArea() const
{
    const QScreen* s = screen() ? screen() : QGuiApplication::primaryScreen();
    return s ? s->availableGeometry() : QRect(QPoint(0, 0), kPreferredSize);
}

void MainWindow::fitToScreen(const QRect& available)
{
    m_screenArea = available;
    // The frame the window manager adds (known once the window is shown) counts too.
    const QSize frame = isVisible() ? frameGeometry().size() - this->size() : QSize(0, 0);
    const QSize size = kPreferredSize.boundedTo(available.size() - frame);
    if (!isFullScreen() && !isMaximized()) {
        resize(size);
        move(available.topLeft() + QPoint((available.width() - size.width()) / 2,
                                          (available.height() - size.height()) / 2));
    }
    arrangeDocks(available.size(), size.width());
    if (QDockWidget* error = m_docks.value(QStringLiteral("errorDock")))
        ErrorPanel::placeDock(*error, available, m_compact);
}

void MainWindow::arrangeDocks(const QSize& screen, int windowWidth)
{
    const bool compact = screen.width() < kRoomy.width() || screen.height() < kRoomy.height();
    m_compact = compact;
    // The plots stacked one above the other where the screen is tall enough, else one tabbed
    // dock; the tables (SAT, bounces, collision) likewise share a tabbed dock below them.
    QList<QDockWidget*> plots;
    for (const PlotNames& plot : kPlotNames)
        plots << m_docks.value(QLatin1String(plot.name));
    plots << m_compareDock;
    // On a small screen the lesson has the left column to itself (its text, questions and
    // buttons need the height); the controls and the inspector join the plots' tabs.
    QDockWidget* lesson = m_docks.value(QStringLiteral("lesson"));
    const QList<QDockWidget*> settings{m_docks.value(QStringLiteral("controls")),
                                       m_docks.value(QStringLiteral("inspector"))};
    for (QDockWidget* d : settings)
        if (dockWidgetArea(d) != (compact ? Qt::RightDockWidgetArea : Qt::LeftDockWidgetArea))
            addDockWidget(compact ? Qt::RightDockWidgetArea : Qt::LeftDockWidgetArea, d);
    if (compact) {
        plots << settings;
    } else {
        splitDockWidget(lesson, settings.first(), Qt::Vertical);
        tabifyDockWidget(settings.first(), settings.last());
        settings.first()->raise();
    }
    QList<QDockWidget*> tables;
    for (const char* name : {"sat", "bounces", "collision"})
        tables << m_docks.value(QLatin1String(name));
    for (QDockWidget* d : plots + tables)
        if (dockWidgetArea(d) != Qt::RightDockWidgetArea)
            addDockWidget(Qt::RightDockWidgetArea, d);
    if (compact) {
        // One tab group for the right column: the tab a step raises has all the height.
        for (QDockWidget* d : plots.mid(1) + tables)
            tabifyDockWidget(plots.first(), d);
    } else {
        for (int i = 1; i < plots.size(); ++i)
            splitDockWidget(plots[i - 1], plots[i], Qt::Vertical);
        splitDockWidget(plots.last(), tables.first(), Qt::Vertical);
        for (int i = 1; i < tables.size(); ++i)
            tabifyDockWidget(tables.first(), tables[i]);
    }
    plots.first()->raise();
    fitSideColumns(windowWidth);
}

void MainWindow::fitSideColumns(int windowWidth)
{
    const int left = std::min(kLeftWidth, static_cast<int>(kLeftShare * windowWidth));
    const int right = std::min(kRightWidth, static_cast<int>(kRightShare * windowWidth));
    QList<QDockWidget*> leftDocks, rightDocks;
    for (QDockWidget* d : findChildren<QDockWidget*>()) {
        if (d->isHidden())
            continue;
        if (dockWidgetArea(d) == Qt::LeftDockWidgetArea)
            leftDocks << d;
        else if (dockWidgetArea(d) == Qt::RightDockWidgetArea)
            rightDocks << d;
    }
    if (!leftDocks.isEmpty())
        resizeDocks({leftDocks.first()}, {left}, Qt::Horizontal);
    if (!rightDocks.isEmpty())
        resizeDocks({rightDocks.first()}, {right}, Qt::Horizontal);
}

void MainWindow::saveLayout(QSettings& s) const
{
    const QString key = sizeKey(m_screenArea.size());
    if (m_presentation) {
        // Presentation mode is for the moment: the layout to remember is the one before it.
        s.setValue(key + QStringLiteral("geometry"), m_normalGeometry);
        s.setValue(key + QStringLiteral("state"), m_normalState);
    } else {
        s.setValue(key + QStringLiteral("geometry"), saveGeometry());
        s.setValue(key + QStringLiteral("state"), saveState());
    }
}

void MainWindow::restoreLayout(const QSettings& s)
{
    const QRect available = availableScreenArea();
    fitToScreen(available);
    const QString key = sizeKey(available.size());
    if (!s.contains(key + QStringLiteral("state")))
        return;
    restoreGeometry(s.value(key + QStringLiteral("geometry")).toByteArray());
    restoreState(s.value(key + QStringLiteral("state")).toByteArray());
    // Never larger than the screen, whatever was saved (the screen may have shrunk).
    if (!isMaximized() && !isFullScreen() &&
        (width() > available.width() || height() > available.height()))
        resize(size().boundedTo(available.size()));
}

void MainWindow::setPresentation(bool on)
{
    if (on == m_presentation)
        return;
    if (on) {
        m_normalGeometry = saveGeometry();
        m_normalState = saveState();
        m_normalFont = font();
        m_normalPalette = palette();
        m_normalWasMaximized = isMaximized();
    }
    m_presentation = on;
    theme::setPresentation(on);
    // Widgets that set a font of their own (the lesson's text, titles, hints) do not follow
    // the window's: they grow by the same factor, and get their own fonts back afterwards.
    if (on) {
        for (QWidget* w : findChildren<QWidget*>()) {
            if (!w->testAttribute(Qt::WA_SetFont) || qobject_cast<PlotWidget*>(w) ||
                (w->parentWidget() && qobject_cast<PlotWidget*>(w->parentWidget())))
                continue;
            m_explicitFonts.push_back({QPointer<QWidget>(w), w->font()});
            QFont f = w->font();
            f.setPointSizeF(f.pointSizeF() * theme::kPresentationFontScale);
            w->setFont(f);
        }
    } else {
        for (const auto& [widget, font] : m_explicitFonts)
            if (widget)
                widget->setFont(font);
        m_explicitFonts.clear();
    }
    if (on) {
        QFont f = m_normalFont;
        f.setPointSizeF(f.pointSizeF() * theme::kPresentationFontScale);
        setFont(f);
        setPalette(highContrastPalette());
    } else {
        setFont(m_normalFont);
        setPalette(m_normalPalette);
    }
    for (PlotWidget* plot : findChildren<PlotWidget*>())
        plot->setPresentation(on);
    for (QToolBar* bar : findChildren<QToolBar*>())
        bar->setIconSize(on ? QSize(32, 32) : QSize());
    // Icons alone where there are icons (their tooltips name them), so that every action fits
    // a 1024-pixel projector's width at the larger text instead of hiding behind "»".
    if (auto* bar = findChild<QToolBar*>(QStringLiteral("simulationToolbar")))
        bar->setToolButtonStyle(on ? Qt::ToolButtonIconOnly : Qt::ToolButtonTextBesideIcon);
    // No developer details on a projector.
    setDetailsShown(!on);
    m_view->scene()->update();
    m_view->viewport()->update();
    updateStatus(); // the short status line of presentation mode, or the full one
    if (on) {
        showFullScreen();
    } else {
        if (m_normalWasMaximized)
            showMaximized();
        else
            showNormal();
        // showNormal() gives back the geometry from before full screen (Qt keeps it); the
        // docks take their old places and sizes.
        restoreState(m_normalState);
        // And again once the window has its old size back (resizeEvent): a state restored
        // while it was still full screen keeps the docks in proportion instead.
        m_restoreStatePending = true;
    }
    if (m_presentAction)
        m_presentAction->setChecked(on);
}

void MainWindow::showEvent(QShowEvent* event)
{
    QMainWindow::showEvent(event);
    // The window manager's frame is known once the window is shown: the window and its frame
    // together must fit the screen's available area.
    if (!m_screenArea.isEmpty() && !isFullScreen() && !isMaximized())
        QTimer::singleShot(0, this, [this] {
            const QSize outer = frameGeometry().size();
            if (outer.width() > m_screenArea.width() || outer.height() > m_screenArea.height())
                fitToScreen(m_screenArea);
        });
}

void MainWindow::resizeEvent(QResizeEvent* event)
{
    QMainWindow::resizeEvent(event);
    if (m_restoreStatePending && !m_presentation && !isFullScreen()) {
        m_restoreStatePending = false;
        restoreState(m_normalState);
    }
}

} // namespace rigidlab::ui
