// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where the export dialogs open: the folder the user last exported into (remembered in
// QSettings across runs), else the user's documents folder. One place for the plot export
// (PlotWidget's menu, the Export menu) and the lesson export (a step's plots into a folder).

#include <QString>

namespace rigidlab::ui {

/// The QSettings key of the folder last exported into.
inline constexpr char kExportFolderKey[] = "exportFolder";

/// The folder last exported into, if it still exists; else the documents folder (the home
/// folder where there is none).
QString exportFolder();
/// Remembers `folder` (a file's path gives its folder) for the next export dialog.
void rememberExportFolder(const QString& folderOrFile);

} // namespace rigidlab::ui
