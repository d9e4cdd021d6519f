// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The window's toolbars by keyboard. Qt keeps toolbar buttons out of the Tab order (each
// would be a stop on the way to the panels); a key (F10, kControls' "focusToolbar") puts the
// focus on the first button of the top toolbar instead. There the arrows move: Left and Right
// along a toolbar, Up and Down to the toolbar above or below (the scene editor's tools, in
// Edit mode), Home and End to its first and last button; Space or Enter presses the button;
// Escape takes the focus back where it was.

#include <QObject>
#include <QPointer>

class QKeyEvent;
class QMainWindow;
class QToolBar;
class QToolButton;
class QWidget;

namespace rigidlab::ui {

class ToolbarKeys : public QObject {
public:
    /// Escape takes the focus back where it was, or to `home` (the scene).
    ToolbarKeys(QMainWindow& window, QWidget& home);

    /// Puts the focus on the first button of the window's first toolbar shown at the top
    /// (remembering where it was, for Escape).
    void enter();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    /// The toolbars shown at the window's top, top to bottom.
    QList<QToolBar*> rows() const;
    /// The buttons of `bar` that can be pressed, left to right.
    static QList<QToolButton*> buttons(const QToolBar& bar);
    void focusButton(QToolButton* button);
    bool key(QToolButton& button, const QKeyEvent& key);
    /// Whether `key` is one the toolbar takes (before the window's shortcuts).
    static bool isToolbarKey(const QKeyEvent& key);

    QMainWindow& m_window;
    QWidget& m_home;
    QPointer<QWidget> m_before; ///< where the focus was before enter()
};

} // namespace rigidlab::ui
