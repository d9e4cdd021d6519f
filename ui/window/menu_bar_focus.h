// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The menu bar takes the keyboard only when the student asks for it (Alt alone, pressed and
// released) and then always shows where it is. Qt arms its menu bar when Alt goes down and
// opens it for the keyboard when Alt comes up with nothing in between; a chord's Alt
// (Alt+→ for the next step) could still open it when its key events come back late or again
// (a screen reader's bridge hands key events back after it has seen them), leaving the focus
// in the menu bar with no title highlighted: Tab then walked the menu titles until Esc.

class QMainWindow;

namespace rigidlab::ui {

/// Watches `window`'s menu bar: when it takes the focus at the end of an Alt chord, or holds
/// the focus with no title highlighted, the focus goes back where it was (as Esc does).
void keepMenuBarFocusVisible(QMainWindow& window);

} // namespace rigidlab::ui
