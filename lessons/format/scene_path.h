// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where a lesson's scene file is: the one place that resolves a step's "scene" path and
// decides whether the lab may read it (lessons/LESSON_FORMAT.md, "Scene files").
//
// A path is relative to the lesson's folder and, once resolved, must stay inside the lesson's
// root: the data folder when the lesson sits in a data folder's lessons/ (a folder holding
// scenes/ and lessons/, as the shipped data and the user's own do), so that
// "../scenes/pendulum.json" reaches the shared scenes; otherwise the lesson's folder itself, so
// that a lesson someone sends cannot make the lab read files elsewhere on the machine.

#include <QString>

namespace rigidlab::lessons {

/// The folder a lesson in `lessonFolder` (absolute) may read scene files from.
QString lessonRoot(const QString& lessonFolder);

struct ScenePathResult {
    bool ok = false;
    QString error;        ///< what is wrong with the path, for the loader's `FILE: PLACE: ` prefix
    QString readPath;     ///< what to read: the resolved path, links followed when it exists
    QString absolutePath; ///< the path as written, made absolute (links kept)
};

/// Checks and resolves `relative`, a step's "scene", for a lesson in `lessonFolder`.
ScenePathResult resolveScenePath(const QString& lessonFolder, const QString& relative);

} // namespace rigidlab::lessons
