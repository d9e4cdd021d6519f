// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A scroll bar as a screen reader should hear it: its value only while it is shown.
//
// A scroll area whose bars are turned off (the scene view follows its bodies by moving its
// own, hidden bars) still moves them, and Qt tells every move to assistive technology as a
// value change. The scene view's two hidden bars told about 80 a second while it followed two
// balls flying apart, and Orca, flooded ("DELUGE"), dropped the announcement that the run had
// paused. Qt 6.4's AT-SPI bridge passes a value change only for an object with a numeric value
// interface ("ValueChanged event and no ValueInterface"): this interface has one only while
// its bar is visible, so a hidden bar's moves reach no reader, and a shown bar is what Qt's is:
// the role of a scroll bar, its value, range and step.

class QAccessibleInterface;
class QObject;
class QString;

namespace rigidlab::ui {

/// The factory of every QScrollBar's interface; installed with the window's others
/// (window/accessible_factories.h) before any scroll bar is made, since Qt makes a widget's
/// interface at its first accessibility event and keeps it.
QAccessibleInterface* scrollBarInterface(const QString& className, QObject* object);

} // namespace rigidlab::ui
