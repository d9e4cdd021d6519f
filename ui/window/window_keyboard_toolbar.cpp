// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/window_keyboard_toolbar.h"

#include <QAction>
#include <QApplication>
#include <QKeyEvent>
#include <QMainWindow>
#include <QToolBar>
#include <QToolButton>

#include <algorithm>

namespace rigidlab::ui {

ToolbarKeys::ToolbarKeys(QMainWindow& window, QWidget& home)
    : QObject(&window), m_window(window), m_home(home)
{
}

QList<QToolBar*> ToolbarKeys::rows() const
{
    QList<QToolBar*> bars;
    for (QToolBar* bar : m_window.findChildren<QToolBar*>())
        if (bar->isVisible() && m_window.toolBarArea(bar) == Qt::TopToolBarArea &&
            !buttons(*bar).isEmpty())
            bars << bar;
    std::stable_sort(bars.begin(), bars.end(),
                     [](const QToolBar* a, const QToolBar* b) { return a->y() < b->y(); });
    return bars;
}

QList<QToolButton*> ToolbarKeys::buttons(const QToolBar& bar)
{
    QList<QToolButton*> list;
    for (QAction* a : bar.actions())
        if (auto* b = qobject_cast<QToolButton*>(bar.widgetForAction(a));
            b && b->isVisible() && b->isEnabled())
            list << b;
    return list;
}

void ToolbarKeys::enter()
{
    const QList<QToolBar*> bars = rows();
    if (bars.isEmpty())
        return;
    QWidget* now = QApplication::focusWidget();
    if (!now || !bars.first()->isAncestorOf(now))
        m_before = now;
    focusButton(buttons(*bars.first()).first());
}

void ToolbarKeys::focusButton(QToolButton* button)
{
    if (!button)
        return;
    // Toolbar buttons take no focus by Tab or click; given it by key, they keep these keys.
    button->removeEventFilter(this);
    button->installEventFilter(this);
    button->setFocus(Qt::ShortcutFocusReason);
}

bool ToolbarKeys::isToolbarKey(const QKeyEvent& key)
{
    if (key.modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier))
        return false;
    switch (key.key()) {
    case Qt::Key_Left:
    case Qt::Key_Right:
    case Qt::Key_Up:
    case Qt::Key_Down:
    case Qt::Key_Home:
    case Qt::Key_End:
    case Qt::Key_Escape:
    case Qt::Key_Return:
    case Qt::Key_Enter:
    case Qt::Key_Space:
        return true;
    default:
        return false;
    }
}

bool ToolbarKeys::eventFilter(QObject* watched, QEvent* event)
{
    auto* button = qobject_cast<QToolButton*>(watched);
    if (!button || !button->hasFocus())
        return false;
    if (event->type() == QEvent::ShortcutOverride &&
        isToolbarKey(*static_cast<QKeyEvent*>(event))) {
        event->accept(); // a key press for the button, not Play, Step or Back
        return true;
    }
    if (event->type() == QEvent::KeyPress)
        return key(*button, *static_cast<QKeyEvent*>(event));
    if (event->type() == QEvent::FocusOut)
        button->removeEventFilter(this);
    return false;
}

bool ToolbarKeys::key(QToolButton& button, const QKeyEvent& key)
{
    if (!isToolbarKey(key))
        return false;
    const QList<QToolBar*> bars = rows();
    const auto row = std::find_if(bars.begin(), bars.end(),
                                  [&](const QToolBar* b) { return b->isAncestorOf(&button); });
    if (row == bars.end())
        return false;
    const QList<QToolButton*> list = buttons(**row);
    const qsizetype at = std::max<qsizetype>(0, list.indexOf(&button));
    const qsizetype n = list.size();
    switch (key.key()) {
    case Qt::Key_Left:
        focusButton(list[(at + n - 1) % n]);
        return true;
    case Qt::Key_Right:
        focusButton(list[(at + 1) % n]);
        return true;
    case Qt::Key_Home:
        focusButton(list.first());
        return true;
    case Qt::Key_End:
        focusButton(list.last());
        return true;
    case Qt::Key_Up:
    case Qt::Key_Down: {
        const qsizetype r = row - bars.begin() + (key.key() == Qt::Key_Down ? 1 : -1);
        if (r >= 0 && r < bars.size())
            focusButton(buttons(*bars[r]).first());
        return true;
    }
    case Qt::Key_Escape:
        if (m_before && m_before->isVisible())
            m_before->setFocus(Qt::ShortcutFocusReason);
        else
            m_home.setFocus(Qt::ShortcutFocusReason);
        return true;
    default: // Space, Return, Enter
        button.click();
        return true;
    }
}

} // namespace rigidlab::ui
