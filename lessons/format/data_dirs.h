// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where RigidLab's shipped scenes and lessons are, and where a user keeps their own.
//
// The shipped data is found, in this order: the folder named by the environment variable
// RIGIDLAB_DATA_DIR; DATADIR/rigidlab beside an installed program (PREFIX/bin/rigidlab finds
// PREFIX/share/rigidlab); the source tree's lessons/ folder, for a program run from its build
// folder (compiled in only when RIGIDLAB_BUILD_TREE_DATA is on, the default; packages turn it
// off). Each data folder holds scenes/ and lessons/.

#include <QString>

namespace rigidlab::lessons {

/// The shipped data folder, or an empty string when none is found.
QString shippedDataDir();
/// shippedDataDir()/scenes.
QString shippedScenesDir();
/// shippedDataDir()/lessons.
QString shippedLessonsDir();

/// The user's own data folder: GenericDataLocation/rigidlab (~/.local/share/rigidlab on Linux,
/// as the man page says), the same for the window and rigidlab-cli whatever their application
/// names. It may not exist yet.
QString userDataDir();
/// The user's own scenes and lessons: userDataDir()'s scenes/ and lessons/. The window and
/// `rigidlab-cli lessons` list them beside the shipped ones, marked as the user's own.
QString userScenesDir();
QString userLessonsDir();

/// Keeps the user's settings in a file on every system: on Windows an INI file,
/// %APPDATA%\RigidLab\RigidLab.ini, rather than the registry (elsewhere the native format is
/// that file already, ~/.config/RigidLab/RigidLab.conf). The window's --screenshots points the
/// settings at a folder of their own, which only a file allows. Called by both programs before
/// any QSettings is made.
void useSettingsFiles();

} // namespace rigidlab::lessons
