// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the classroom tests share: the window shown as a screen of a given size shows it, and
// checks that every control is in reach and no text overlaps another.

#include "common/theme.h"
#include "editor/edit_tools.h"
#include "lesson_player/lesson_player.h"
#include "panels/sat_panel.h"
#include "plots/plot_widget.h"
#include "shipped_lessons.h"
#include "simulation/simulation_controller.h"
#include "view/body_item.h"
#include "view/sat_overlay.h"
#include "view/world_view.h"
#include "window/main_window.h"

#include "format/lesson.h"

#include <qcustomplot.h>

#include <QAbstractButton>
#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QStatusBar>
#include <QTabBar>
#include <QTableWidget>
#include <QTextBrowser>
#include <QToolBar>
#include <QtTest>

namespace rigidlab::test::classroom {

using rigidlab::ui::MainWindow;

/// A classroom projector's screen, the smallest the lab is made for [px].
inline constexpr QSize kProjector(1024, 768);

/// "x,y WxH", for messages.
inline QString rectText(const QRect& r)
{
    return QStringLiteral("%1,%2 %3x%4").arg(r.x()).arg(r.y()).arg(r.width()).arg(r.height());
}

inline bool interactive(const QWidget* w)
{
    return qobject_cast<const QAbstractButton*>(w) || qobject_cast<const QLineEdit*>(w) ||
           qobject_cast<const QComboBox*>(w) || qobject_cast<const QAbstractSlider*>(w) ||
           qobject_cast<const QAbstractSpinBox*>(w) || qobject_cast<const QTableWidget*>(w);
}

/// Where `w` can be reached in the window: its own rectangle, or, inside a scroll area, the
/// part of the scroll area that shows it (scrolling brings it there).
inline QRect reachableRect(const QWidget* w, const QWidget* window)
{
    for (const QWidget* p = w->parentWidget(); p && p != window; p = p->parentWidget())
        if (const auto* scroll = qobject_cast<const QScrollArea*>(p))
            if (scroll->widget() && scroll->widget()->isAncestorOf(w))
                return QRect(scroll->viewport()->mapTo(window, QPoint(0, 0)),
                             scroll->viewport()->size());
    return QRect(w->mapTo(window, QPoint(0, 0)), w->size());
}

/// Every visible interactive widget of the window lies inside it (scroll areas count as
/// reachable); returns what does not, described.
inline QStringList outside(const MainWindow& window)
{
    QStringList out;
    const QRect inside = window.rect();
    for (const QWidget* w : window.findChildren<QWidget*>()) {
        if (!w->isVisible() || !interactive(w) || w->window() != &window)
            continue;
        if (w->objectName() == QLatin1String("qt_toolbar_ext_button"))
            continue;
        // A dock behind another in a tab group is reached through its tab.
        bool behindTab = false;
        for (const QWidget* p = w; p && p != &window; p = p->parentWidget())
            if (qobject_cast<const QDockWidget*>(p) && p->visibleRegion().isEmpty())
                behindTab = true;
        if (behindTab)
            continue;
        const QRect r = reachableRect(w, &window);
        if (r.isEmpty() || !inside.contains(r))
            out << QStringLiteral("%1 \"%2\" at (%3,%4 %5x%6)")
                       .arg(QString::fromLatin1(w->metaObject()->className()),
                            w->property("text").toString() + QLatin1Char(' ') +
                                (w->parentWidget() ? w->parentWidget()->objectName() : QString()))
                       .arg(r.x())
                       .arg(r.y())
                       .arg(r.width())
                       .arg(r.height());
    }
    return out;
}

/// Pairs of visible text-bearing widgets of the lesson panel that overlap.
inline QStringList overlapping(const QWidget& panel)
{
    QList<const QWidget*> texts;
    for (const QWidget* w : panel.findChildren<QWidget*>())
        if (w->isVisible() &&
            (qobject_cast<const QLabel*>(w) || qobject_cast<const QAbstractButton*>(w) ||
             qobject_cast<const QLineEdit*>(w) || qobject_cast<const QComboBox*>(w)))
            texts << w;
    QStringList out;
    for (int i = 0; i < texts.size(); ++i)
        for (int j = i + 1; j < texts.size(); ++j) {
            const QWidget* a = texts[i];
            const QWidget* b = texts[j];
            if (a->isAncestorOf(b) || b->isAncestorOf(a))
                continue;
            const QRect ra(a->mapTo(&panel, QPoint(0, 0)), a->size());
            const QRect rb(b->mapTo(&panel, QPoint(0, 0)), b->size());
            if (ra.intersects(rb))
                out << QStringLiteral("\"%1\" and \"%2\"")
                           .arg(a->property("text").toString().left(30),
                                b->property("text").toString().left(30));
        }
    return out;
}

/// The widgets whose minimum size is the largest, for a message.
inline QString largestMinimums(const QWidget& window)
{
    QList<const QWidget*> all;
    for (const QWidget* w : window.findChildren<QWidget*>())
        if (w->isVisible())
            all << w;
    std::sort(all.begin(), all.end(), [](const QWidget* a, const QWidget* b) {
        return a->minimumSizeHint().height() > b->minimumSizeHint().height();
    });
    QStringList out;
    for (int i = 0; i < std::min<qsizetype>(8, all.size()); ++i)
        out << QStringLiteral("%1(%2) %3x%4")
                   .arg(QString::fromLatin1(all[i]->metaObject()->className()),
                        all[i]->objectName())
                   .arg(all[i]->minimumSizeHint().width())
                   .arg(all[i]->minimumSizeHint().height());
    return out.join(QStringLiteral(", "));
}

/// Where the frame of window `w` (the window manager's decoration included) leaves a screen
/// of size `screen`, said with the widgets that hold it large; empty when it lies inside. A
/// window 1143 px wide on a 1024-pixel projector hides its right-hand docks.
inline QString frameOutside(const QWidget& w, const QSize& screen)
{
    const QRect frame = w.frameGeometry();
    if (QRect(QPoint(0, 0), screen).contains(frame))
        return QString();
    return QStringLiteral("the window's frame %1 leaves the %2x%3 screen (least size %4x%5: %6)")
        .arg(rectText(frame))
        .arg(screen.width())
        .arg(screen.height())
        .arg(w.minimumSizeHint().width())
        .arg(w.minimumSizeHint().height())
        .arg(largestMinimums(w));
}

struct DockPlace {
    QString name;
    bool hidden = false;
    Qt::DockWidgetArea area = Qt::NoDockWidgetArea;
    QRect geometry;
};

inline QList<DockPlace> dockPlaces(const MainWindow& w)
{
    QList<DockPlace> out;
    for (QDockWidget* d : w.findChildren<QDockWidget*>())
        out << DockPlace{d->objectName(), d->isHidden(), w.dockWidgetArea(d), d->geometry()};
    return out;
}

inline bool samePlaces(const QList<DockPlace>& a, const QList<DockPlace>& b)
{
    constexpr int kSlackPx = 4;
    if (a.size() != b.size())
        return false;
    for (qsizetype i = 0; i < a.size(); ++i) {
        if (a[i].name != b[i].name || a[i].hidden != b[i].hidden || a[i].area != b[i].area)
            return false;
        // Hidden, or behind another's tab (moved off the window): no place to compare.
        const auto away = [](const QRect& r) { return r.right() < 0 || r.bottom() < 0; };
        if (a[i].hidden || (away(a[i].geometry) && away(b[i].geometry)))
            continue;
        const QRect& p = a[i].geometry;
        const QRect& q = b[i].geometry;
        if (std::abs(p.x() - q.x()) > kSlackPx || std::abs(p.y() - q.y()) > kSlackPx ||
            std::abs(p.width() - q.width()) > kSlackPx ||
            std::abs(p.height() - q.height()) > kSlackPx)
            return false;
    }
    return true;
}

inline QString describe(const QList<DockPlace>& now, const QList<DockPlace>& before)
{
    QStringList out;
    for (qsizetype i = 0; i < std::min(now.size(), before.size()); ++i)
        out << QStringLiteral("%1: %2,%3 %4x%5 (was %6,%7 %8x%9)")
                   .arg(now[i].name)
                   .arg(now[i].geometry.x())
                   .arg(now[i].geometry.y())
                   .arg(now[i].geometry.width())
                   .arg(now[i].geometry.height())
                   .arg(before[i].geometry.x())
                   .arg(before[i].geometry.y())
                   .arg(before[i].geometry.width())
                   .arg(before[i].geometry.height());
    return out.join(QStringLiteral("; "));
}

inline void addSizes()
{
    QTest::addColumn<QSize>("screen");
    QTest::newRow("1024x768") << QSize(1024, 768);
    QTest::newRow("1280x720") << QSize(1280, 720); // also 1920×1080 at QT_SCALE_FACTOR=1.5
    QTest::newRow("1366x768") << QSize(1366, 768);
    QTest::newRow("1920x1080") << QSize(1920, 1080);
}

/// The window as a screen of that size would show it.
inline void showOn(MainWindow& w, const QSize& screen)
{
    w.fitToScreen(QRect(QPoint(0, 0), screen));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QCoreApplication::processEvents();
}

/// The window in presentation mode as a 1024×768 projector shows it (as rigidlab --present
/// --screenshots makes it: full screen is the offscreen platform's own size). Full screen has
/// no frame: the window with its frame covers the screen, as much of it as full screen would.
inline void presentOn(MainWindow& w, const QSize& screen)
{
    showOn(w, screen);
    w.setPresentation(true);
    w.setWindowState(Qt::WindowNoState);
    const QSize frame = w.frameGeometry().size() - w.size();
    w.resize(screen - frame);
    w.move(0, 0); // move() places the frame
    QCoreApplication::processEvents();
}

/// Steps the world until `seconds` of simulated time have passed.
inline void runFor(ui::SimulationController& c, double seconds)
{
    const long long steps = std::llround(seconds / c.world().def().dt);
    for (long long i = 0; i < steps; ++i)
        c.stepForward();
}

} // namespace rigidlab::test::classroom
