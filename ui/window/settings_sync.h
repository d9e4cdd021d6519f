// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Writing the window's settings, and saying so when that fails.

class QMainWindow;
class QSettings;

namespace rigidlab::ui {

/// QSettings writes its file atomically (through QSaveFile): a write that fails leaves the
/// previous settings as they were. That it failed is said in the status bar, not lost.
void syncSettings(QSettings& settings, QMainWindow& window);

} // namespace rigidlab::ui
