// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/dock_tabs.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QEvent>
#include <QHelpEvent>
#include <QMainWindow>
#include <QTabBar>
#include <QTimer>
#include <QToolTip>
#include <QVariant>

namespace rigidlab::ui {

namespace {

const char* const kFullTitle = "fullTitle";

/// Whole titles: a tab bar that must not scroll or elide is as wide as all its tabs, and the
/// dock column makes room for it.
void keepWhole(QTabBar& bar)
{
    bar.setElideMode(Qt::ElideNone);
    bar.setUsesScrollButtons(false);
    bar.setExpanding(false);
}
/// The keeper's object name, by which a dock finds its window's keeper (the keeper has no
/// meta-object of its own, so findChild<DockTabKeeper*> would take any child for it).
const char* const kKeeperName = "rigidlabDockTabKeeper";

/// Lets the window's dock tab bars show whole titles, and the full ones as tooltips. The
/// window makes its tab bars as docks are tabbed (eliding their text): they are set up once
/// polished, after the window has made them.
class DockTabKeeper : public QObject {
public:
    explicit DockTabKeeper(QMainWindow& window) : QObject(&window), m_window(window)
    {
        setObjectName(QLatin1String(kKeeperName));
    }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (watched == &m_window && event->type() == QEvent::ChildPolished) {
            auto* child = static_cast<QChildEvent*>(event)->child();
            if (auto* bar = qobject_cast<QTabBar*>(child)) {
                keepWhole(*bar);
                bar->installEventFilter(this);
                bar->setFocusPolicy(bar->count() > 0 ? Qt::TabFocus : Qt::NoFocus);
            }
        } else if ((watched == &m_window && event->type() == QEvent::LayoutRequest) ||
                   (qobject_cast<QTabBar*>(watched) &&
                    (event->type() == QEvent::Show || event->type() == QEvent::Resize ||
                     event->type() == QEvent::Move || event->type() == QEvent::Paint))) {
            // The window keeps tab bars it no longer uses: without tabs, not a Tab stop with
            // nothing to say. (Once the window is done moving docks: it empties bars later.)
            // Only the focus policy changes. Such a bar is not hidden: the window shows every
            // tab bar of a tabbed area whenever it has laid out its docks, and hiding one asks
            // for a layout, so the two would hide and show it without end, a flood of events
            // for a screen reader. The window moves an empty bar out of its sight instead.
            if (!m_focusUpdatePending) {
                m_focusUpdatePending = true;
                QTimer::singleShot(0, this, [this] {
                    m_focusUpdatePending = false;
                    for (QTabBar* bar :
                         m_window.findChildren<QTabBar*>(QString(), Qt::FindDirectChildrenOnly)) {
                        // Nor one the window moved out of sight.
                        const bool seen =
                            bar->count() > 0 && m_window.rect().intersects(bar->geometry());
                        bar->setFocusPolicy(seen ? Qt::TabFocus : Qt::NoFocus);
                    }
                });
            }
        } else if (event->type() == QEvent::ToolTip) {
            if (auto* bar = qobject_cast<QTabBar*>(watched))
                return showTabTip(*bar, static_cast<QHelpEvent&>(*event));
            if (auto* dock = qobject_cast<QDockWidget*>(watched))
                return showTitleTip(*dock, static_cast<QHelpEvent&>(*event));
        }
        return QObject::eventFilter(watched, event);
    }

private:
    bool showTabTip(QTabBar& bar, const QHelpEvent& help)
    {
        const int tab = bar.tabAt(help.pos());
        if (tab < 0)
            return false;
        for (const QDockWidget* dock : m_window.findChildren<QDockWidget*>())
            if (dock->windowTitle() == bar.tabText(tab)) {
                QToolTip::showText(help.globalPos(), fullTitle(*dock), &bar);
                return true;
            }
        return false;
    }

    static bool showTitleTip(QDockWidget& dock, const QHelpEvent& help)
    {
        // Over the title bar only: the panel's own widgets keep their tooltips.
        const QWidget* content = dock.widget();
        if (!content || help.pos().y() >= content->geometry().top())
            return false;
        QToolTip::showText(help.globalPos(), fullTitle(dock), &dock);
        return true;
    }

    bool m_focusUpdatePending = false;
    QMainWindow& m_window;
};

} // namespace

void setFullTitle(QDockWidget& dock, const QString& title)
{
    dock.setProperty(kFullTitle, title);
    // The title bar's tooltip: every dock gets the filter of its window's keeper.
    if (QObject* keeper = dock.parent()
                              ? dock.parent()->findChild<QObject*>(QLatin1String(kKeeperName),
                                                                   Qt::FindDirectChildrenOnly)
                              : nullptr)
        dock.installEventFilter(keeper);
}

QString fullTitle(const QDockWidget& dock)
{
    const QString full = dock.property(kFullTitle).toString();
    return full.isEmpty() ? dock.windowTitle() : full;
}

void keepDockTabsWhole(QMainWindow& window)
{
    auto* keeper = new DockTabKeeper(window);
    window.installEventFilter(keeper);
    // The tab bars made already.
    for (QTabBar* bar : window.findChildren<QTabBar*>(QString(), Qt::FindDirectChildrenOnly)) {
        keepWhole(*bar);
        bar->installEventFilter(keeper);
    }
}

void keepFocusInSight(QDockWidget& dock)
{
    QObject::connect(&dock, &QDockWidget::visibilityChanged, &dock,
                     [d = &dock](bool) { showContentIfInSight(*d); });
}

void showContentIfInSight(QDockWidget& dock)
{
    QWidget* content = dock.widget();
    if (!content || dock.isHidden())
        return;
    // A dock behind another's tab is moved off the window's left or top edge, not hidden.
    const QRect r = dock.geometry();
    const bool behind = dock.isWindow() ? false : (r.right() < 0 || r.bottom() < 0);
    if (content->isHidden() == behind)
        return;
    const bool hadFocus = content->isAncestorOf(QApplication::focusWidget());
    // Hidden, the content keeps its place in the dock's layout: a dock shrunk to its title
    // bar would cap the height of the whole tab group (to its minimum) and leave the column's
    // height to the other docks.
    QSizePolicy policy = content->sizePolicy();
    policy.setRetainSizeWhenHidden(true);
    content->setSizePolicy(policy);
    content->setVisible(!behind);
    if (behind && hadFocus && dock.parentWidget())
        dock.parentWidget()->setFocus(Qt::OtherFocusReason);
}

void focusWhenAsked(QDockWidget& dock)
{
    QObject::connect(dock.toggleViewAction(), &QAction::triggered, &dock, [d = &dock](bool on) {
        if (!on)
            return;
        QTimer::singleShot(0, d, [d] {
            if (!d->isVisible() || !d->widget())
                return;
            // Its first control that takes Tab, or the panel itself.
            QWidget* first = d->widget();
            for (QWidget* w : d->widget()->findChildren<QWidget*>())
                if ((w->focusPolicy() & Qt::TabFocus) && w->isVisibleTo(d) && w->isEnabled()) {
                    first = w;
                    break;
                }
            first->setFocus(Qt::ShortcutFocusReason);
        });
    });
}

} // namespace rigidlab::ui
