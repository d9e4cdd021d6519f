// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Tabs as a screen reader should see them: the current tab is "focused" only while its tab
// bar has the keyboard focus. Qt 6.4 marks the current tab of every tab bar focused, so a
// reader walking the window met several focused tabs (the Controls dock's, the plots', a
// hidden one behind another dock), none of them where the keys go. The interface is Qt's
// otherwise: a page tab list named by its current tab, whose children are its tabs (named by
// their text or accessible tab name, with the press action), then the bar's scroll buttons.

class QAccessibleInterface;
class QObject;
class QString;

namespace rigidlab::ui {

/// The factory of every QTabBar's interface (installed with the window's others,
/// window/accessible_factories.h, before any tab bar is made: Qt keeps the first interface).
QAccessibleInterface* tabBarInterface(const QString& className, QObject* object);

} // namespace rigidlab::ui
