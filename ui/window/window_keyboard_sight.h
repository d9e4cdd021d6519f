// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Tab and Shift+Tab stop only on controls a student can see. Qt moves a dock behind another
// dock's tab out of the window (dock_tabs.h hides its content then), but a dock can also lie
// on the window under another one: mid-way through an animated rearrangement, or where a
// layout put two docks in one place. Such a control is visible to Qt and takes the focus, yet
// nobody sees it; the focus ring would be drawn over the dock in front.

class QMainWindow;
class QWidget;

namespace rigidlab::ui {

/// Whether some of `control` shows in its window: its part inside all its parents is not
/// empty and, at one of a few points of it, the window's topmost widget there is `control`,
/// one of its children or one of its parents (not another dock or panel lying over it). A
/// control in a scrolled panel is in sight when the panel's viewport is: it scrolls into view
/// when it takes the focus.
bool inSightInWindow(const QWidget& control);

/// Makes Tab and Shift+Tab in `window` go on past a control that took the focus but is not in
/// sight, to the next one in the same direction that is.
void skipControlsOutOfSight(QMainWindow& window);

} // namespace rigidlab::ui
