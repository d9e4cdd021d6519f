// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Names for what Qt leaves unnamed to a screen reader, one rule each.

#include <QString>

class QAbstractSpinBox;
class QFormLayout;
class QScrollArea;

namespace rigidlab::ui {

/// Names a panel's scroll area and its scroll bars after the panel ("Controls", "Scroll
/// Controls"), and keeps it out of the Tab order: its fields are Tab stops, and scroll into
/// view when they take the focus (common/shortcuts_guard.h).
void nameScrollArea(QScrollArea& area, const QString& name);

/// A form read in the order it is shown: Tab goes down its rows (not in the order the fields
/// were made), and a list in a row is named by the row's label, its choice being its value
/// (Qt names a list by its choice).
void followRows(QFormLayout& form);

/// Names a spin box by what it holds and the unit it shows after its number, as the window's
/// fields are named by their labels ("Time step dt [ms]"): "Time of the measurement [s]". A
/// reader says the name before the number; the unit then is not left to the number's text.
void nameWithUnit(QAbstractSpinBox& box, const QString& name);

} // namespace rigidlab::ui
