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

namespace rigidlab::ui {

/// Registers the factory that makes every QLineEdit's interface, those inside spin boxes and
/// of classes derived from it (NumberField) too (once per process). Call it before any field
/// is made: Qt makes a field's interface at its first accessibility event and keeps it
/// (app/gui_main.cpp calls it after making the application, and MainWindow before its parts).
void installLineEditAccessible();

} // namespace rigidlab::ui
