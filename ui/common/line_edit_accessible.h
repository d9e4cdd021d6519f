// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A text field's value as a screen reader should hear it when the field takes the focus.
//
// Orca speaks a focused text field as its label, its role and "the line at the caret", which
// it splits by the runs of the field's text attributes (one language a run). Qt 6.4's
// QLineEdit interface answers every offset with an empty run (start = end = the offset), so
// Orca split the field's text into nothing and said "Mass m text." without the 6 it holds,
// for every field of the window (the Inspector's, the Controls', a lesson's answer). This
// interface is Qt's otherwise: the role of editable text, the field's states, its text, caret
// and selection, and editing through it; its one attribute run is the whole text.

class QAccessibleInterface;
class QObject;
class QString;

namespace rigidlab::ui {

/// The factory of every QLineEdit's interface, those inside spin boxes and of classes derived
/// from it (NumberField) too; installed with the window's others (window/accessible_factories.h)
/// before any field is made, since Qt makes a field's interface at its first accessibility
/// event and keeps it.
QAccessibleInterface* lineEditInterface(const QString& className, QObject* object);

} // namespace rigidlab::ui
