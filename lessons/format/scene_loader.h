// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reading scene files (format v1, lessons/SCENE_FORMAT.md). Everything is checked; the first
// problem found comes back as one line `FILE: PLACE: what is wrong`, where PLACE is a JSON
// path (`bodies[2].shape.radius`) or, for broken JSON, `line L, column C`.

#include "format/languages.h"
#include "format/limits.h"
#include "format/scene.h"

#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <QStringList>

namespace rigidlab::lessons {

/// The scene format version this loader reads (the value of the key "rigidlab").
inline constexpr int kSceneFormatVersion = 1;

/// Limits that keep a mistyped or hostile file from taking the machine down.
inline constexpr qint64 kMaxSceneFileBytes = 8 * 1024 * 1024;
inline constexpr int kMaxBodies = 10000;
inline constexpr int kMaxSprings = 10000;
inline constexpr int kMaxJoints = 10000;
inline constexpr int kMaxPolygonVertices = 64;
inline constexpr int kMaxBodyIdLength = 64;
/// A body's "label", in each language [characters].
inline constexpr int kMaxBodyLabelLength = 80;
// The ranges of settings live in limits.h, with every other range; these names are kept short.
inline constexpr int kMaxIterations = static_cast<int>(limits::kIterations.max);
inline constexpr double kMinDt = limits::kDt.min; ///< [s]
inline constexpr double kMaxDt = limits::kDt.max; ///< [s]

struct SceneLoadResult {
    bool ok = false;
    QString error;        ///< one line when !ok: `FILE: PLACE: what is wrong`
    QStringList warnings; ///< lines in the same form; the scene loaded all the same
    Scene scene;          ///< complete when ok
};

/// How a scene is read.
struct SceneLoadOptions {
    /// The language its title and description are kept in (languages.h); a text without it
    /// is English.
    QString language = lessonLanguage();
};

/// Reads and checks a scene file. The path as given names the file in messages. The title and
/// description are checked in every language they have, whichever is kept; a scene with a text
/// in the object form warns of each text that lacks a shipped language, like a lesson.
SceneLoadResult loadSceneFile(const QString& path, const SceneLoadOptions& options = {});

/// Checks scene JSON held in memory; `sourceName` names it in messages.
SceneLoadResult loadSceneJson(const QByteArray& bytes, const QString& sourceName,
                              const SceneLoadOptions& options = {});

/// Checks a scene already parsed (a document whose top level holds "rigidlab").
SceneLoadResult loadSceneObject(const QJsonObject& root, const QString& sourceName,
                                const SceneLoadOptions& options = {});

} // namespace rigidlab::lessons
