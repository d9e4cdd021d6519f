// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Writing scene files (format v1, lessons/SCENE_FORMAT.md): what the scene editor saves. The
// file reads back (scene_loader.h) to an equal Scene: every number is written with the decimal
// point as the shortest text that reads back to the same double, a box is written as a box,
// a polygon that the loader replaced by its hull with the vertices the file gave, and texts
// in several languages keep all of them.

#include "format/scene.h"

#include <QByteArray>
#include <QString>

namespace rigidlab::lessons {

/// The scene as a scene file, UTF-8 JSON. Texts: when `titles` (or `descriptions`) is not
/// empty its languages are written, with `title` in the language shown (`language`, else
/// English) so that a title edited without setSceneTitle is saved too; otherwise `title` is
/// written as a plain string.
QByteArray sceneToJson(const Scene& scene);

/// An editor's new title or description of `scene`: the text shown, and in `titles` (or
/// `descriptions`) the language it is shown in (`language`, else English), the others kept.
void setSceneTitle(Scene& scene, const QString& text);
void setSceneDescription(Scene& scene, const QString& text);

/// Writes the scene to `path` atomically (atomic_file.h). Returns empty on success, else one
/// line saying why it could not be written.
QString saveScene(const QString& path, const Scene& scene);

} // namespace rigidlab::lessons
