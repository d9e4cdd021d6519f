// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/window_keyboard_sight.h"

#include <QAbstractScrollArea>
#include <QApplication>
#include <QKeyEvent>
#include <QMainWindow>
#include <QPointer>

#include <array>
#include <memory>
#include <utility>

namespace rigidlab::ui {

namespace {

/// The part of `widget` inside all its parents, in its window's coordinates.
QRect shownRect(const QWidget& widget)
{
    const QWidget* window = widget.window();
    QRect r(widget.mapTo(window, QPoint()), widget.size());
    for (const QWidget* p = widget.parentWidget(); p && p != window; p = p->parentWidget())
        r &= QRect(p->mapTo(window, QPoint()), p->size());
    return r & window->rect();
}

/// Whether Tab could stop at `w` in `window`, as Qt's walk of the focus chain asks
/// (QWidget::focusNextPrevChild), though it is not in sight.
bool tabStopOutOfSight(const QWidget& w, const QMainWindow& window)
{
    return w.window() == &window && (w.focusPolicy() & Qt::TabFocus) == Qt::TabFocus &&
           w.isVisible() && w.isEnabled() && !w.focusProxy() && !inSightInWindow(w);
}

/// Lets Tab and Shift+Tab pass controls out of sight by: for the moment the key is handled,
/// those controls take no focus, and Qt's own walk of the focus chain (with the focused
/// control's own say over Tab) does the rest. The focus never lands on them, not even for an
/// instant a screen reader would announce.
class SightGuard : public QObject {
public:
    explicit SightGuard(QMainWindow& window) : QObject(&window), m_window(window) {}

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (m_resending || event->type() != QEvent::KeyPress || !watched->isWidgetType())
            return false;
        const auto* key = static_cast<QKeyEvent*>(event);
        if ((key->key() != Qt::Key_Tab && key->key() != Qt::Key_Backtab) ||
            (key->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier)))
            return false;
        auto* focused = static_cast<QWidget*>(watched);
        if (focused->window() != &m_window)
            return false;
        QList<std::pair<QPointer<QWidget>, Qt::FocusPolicy>> held;
        for (QWidget* w : m_window.findChildren<QWidget*>())
            if (w != focused && tabStopOutOfSight(*w, m_window)) {
                held.append({w, w->focusPolicy()});
                w->setFocusPolicy(Qt::NoFocus);
            }
        if (held.isEmpty())
            return false;
        const std::unique_ptr<QEvent> again(event->clone());
        m_resending = true;
        QCoreApplication::sendEvent(watched, again.get());
        m_resending = false;
        for (const auto& [w, policy] : held)
            if (w)
                w->setFocusPolicy(policy);
        event->setAccepted(again->isAccepted());
        return true;
    }

private:
    QMainWindow& m_window;
    bool m_resending = false;
};

} // namespace

bool inSightInWindow(const QWidget& control)
{
    // A control in a scrolled panel comes into view when it takes the focus: the panel's
    // viewport (the outermost, for panels in panels) must be in sight, not the control.
    const QWidget* widget = &control;
    for (const QWidget* p = control.parentWidget(); p; p = p->parentWidget())
        if (const auto* area = qobject_cast<const QAbstractScrollArea*>(p->parentWidget());
            area && area->viewport() == p)
            widget = p;
    const QRect r = shownRect(*widget);
    if (r.isEmpty())
        return false;
    const QWidget* window = widget->window();
    // The middle and four points near the corners: a control partly under another dock is
    // still in sight by the part that shows.
    const int dx = r.width() / 4, dy = r.height() / 4;
    const std::array<QPoint, 5> points{
        r.center(), r.topLeft() + QPoint(dx, dy), r.topRight() + QPoint(-dx, dy),
        r.bottomLeft() + QPoint(dx, -dy), r.bottomRight() + QPoint(-dx, -dy)};
    for (const QPoint& p : points) {
        const QWidget* top = window->childAt(p);
        // The widget, one of its children, or a parent (the widget lets the mouse through).
        if (!top || top == widget || widget->isAncestorOf(top) || top->isAncestorOf(widget))
            return true;
    }
    return false;
}

void skipControlsOutOfSight(QMainWindow& window)
{
    qApp->installEventFilter(new SightGuard(window));
}

} // namespace rigidlab::ui
