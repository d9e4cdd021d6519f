// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Keys go to the control that has the focus before any window-wide shortcut: Space presses a
// focused button (not Play), the arrows move within a list, a tab bar, a slider or a field
// (not Step and Back), letters type into a field. Qt asks the focused widget first with a
// ShortcutOverride event; most widgets decline it for these keys, so the guard (an event
// filter on the application) accepts it for them. It also makes Return press a focused
// button, scrolls a control that takes the focus into view inside its scroll area, and keeps
// Tab leaving tables (no keyboard trap, WCAG 2.1.2).
//
// Single-key shortcuts (letters, Space, arrows without a modifier) can be switched off
// (WCAG 2.1.4): setSingleKeyShortcuts removes them from a window's actions and brings them
// back.

#include <QObject>

class QKeyEvent;
class QWidget;

namespace rigidlab::ui {

class ShortcutsGuard : public QObject {
    Q_OBJECT
public:
    /// Installs the guard on the application (once; later calls return the same guard).
    static ShortcutsGuard& install();

    /// Whether the focused `widget` takes `key` itself before the window's shortcuts.
    static bool widgetTakesKey(const QWidget& widget, const QKeyEvent& key);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    explicit ShortcutsGuard(QObject* parent) : QObject(parent) {}
};

/// Whether `keys` is a single key without Ctrl, Alt or Meta (Shift allowed): "S", "Space",
/// "Right", "]".
bool isSingleKey(const class QKeySequence& keys);

/// Takes the single-key shortcuts off every action of `window` (`on` false), or gives them
/// back (`on` true). The actions keep their other keys (Ctrl+S, F11).
void setSingleKeyShortcuts(QWidget& window, bool on);

} // namespace rigidlab::ui
