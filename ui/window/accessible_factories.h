// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The interfaces a screen reader is given for the window's own kinds of widget, all installed
// in one place: every text field's (common/line_edit_accessible.h), every tab bar's
// (common/tab_bar_accessible.h), every scroll bar's (common/scroll_bar_accessible.h), the
// plots' (plots/plot_accessible.h), the scene view's (view/world_view_accessible.h) and the
// announcer's (common/announcer.h).
//
// Qt makes a widget's interface at its first accessibility event, often while the widget is
// being built, and keeps it: a factory installed after a widget exists never reaches that
// widget. And QApplication installs Qt's own factory as it is made, so ours must come after
// it (Qt asks the factories installed last first).

namespace rigidlab::ui {

/// Installs the window's accessibility factories (once per process; later calls do nothing).
/// Call it after the QApplication is made and before any widget: app/gui_main.cpp does, and
/// MainWindow before its parts, for the windows a test makes.
void installAccessibleFactories();

} // namespace rigidlab::ui
