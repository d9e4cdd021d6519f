// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Names for what Qt leaves unnamed to a screen reader, one rule each.

#include <QString>

class QScrollArea;

namespace rigidlab::ui {

/// Names a panel's scroll area and its scroll bars after the panel ("Controls", "Scroll
/// Controls"), and keeps it out of the Tab order: its fields are Tab stops, and scroll into
/// view when they take the focus (common/shortcuts_guard.h).
void nameScrollArea(QScrollArea& area, const QString& name);

} // namespace rigidlab::ui
