// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Walks what a screen reader sees of a widget, through QAccessible in process: the same
// question tests/tools and ../shared/tools/atspi_walk.py ask through AT-SPI from outside.

#include <QAccessible>
#include <QAccessibleInterface>
#include <QStringList>
#include <QWidget>

#include <functional>

namespace rigidlab::test {

/// Whether a screen reader stops at this element: a control a student operates, or anything
/// that takes the keyboard focus.
inline bool isInteractive(const QAccessibleInterface& a)
{
    switch (a.role()) {
    case QAccessible::PushButton:
    case QAccessible::CheckBox:
    case QAccessible::RadioButton:
    case QAccessible::ComboBox:
    case QAccessible::SpinBox:
    case QAccessible::EditableText:
    case QAccessible::Slider:
    case QAccessible::MenuItem:
    case QAccessible::PageTab:
    case QAccessible::ListItem:
    case QAccessible::TreeItem:
    case QAccessible::Cell:
    case QAccessible::ScrollBar:
    case QAccessible::ButtonMenu:
    case QAccessible::ButtonDropDown:
    case QAccessible::Link:
        return true;
    default:
        return a.state().focusable;
    }
}

/// Calls `visit` for every element under `root` that is showing (not invisible, not
/// off-screen), with a path of roles and names for messages.
inline void walkShowing(QAccessibleInterface* root,
                        const std::function<void(QAccessibleInterface&, const QString&)>& visit,
                        const QString& path = {}, int depth = 0)
{
    if (!root || !root->isValid() || depth > 40)
        return;
    const QAccessible::State s = root->state();
    if (s.invisible || s.offscreen)
        return;
    const QString here =
        path +
        QStringLiteral("/%1 %2 '%3'")
            .arg(QLatin1String(root->object() ? root->object()->metaObject()->className() : ""))
            .arg(int(root->role()))
            .arg(root->text(QAccessible::Name));
    visit(*root, here);
    for (int i = 0; i < root->childCount(); ++i)
        walkShowing(root->child(i), visit, here, depth + 1);
}

/// The interactive elements showing under `widget` that have no name or no role.
inline QStringList unnamedInteractive(QWidget& widget, int* interactive = nullptr)
{
    QStringList out;
    int count = 0;
    walkShowing(QAccessible::queryAccessibleInterface(&widget), [&](QAccessibleInterface& a,
                                                                    const QString& path) {
        if (!isInteractive(a))
            return;
        ++count;
        if (a.text(QAccessible::Name).trimmed().isEmpty() || a.role() == QAccessible::NoRole)
            out << path;
    });
    if (interactive)
        *interactive = count;
    return out;
}

} // namespace rigidlab::test
