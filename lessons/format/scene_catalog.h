// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The scenes a scene menu lists: those of the shipped folder, and the user's own
// (userScenesDir(), data_dirs.h) in a menu of their own, each by file name.

#include <QString>

#include <vector>

namespace rigidlab::lessons {

/// What a scene menu shows of one scene.
struct SceneEntry {
    QString path;     ///< absolute
    QString title;    ///< the scene's title, or its file name when it has none or does not load
    bool own = false; ///< one of the user's own scenes, not a shipped one
};

/// The scenes (*.json) of `folder` by file name, each marked `own` as given. A scene that does
/// not load is still listed (opening it says what is wrong), under its file name.
std::vector<SceneEntry> scenesIn(const QString& folder, bool own);

} // namespace rigidlab::lessons
