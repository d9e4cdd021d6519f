// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/scene_catalog.h"

#include "format/scene_loader.h"

#include <QDir>
#include <QFileInfo>

namespace rigidlab::lessons {

std::vector<SceneEntry> scenesIn(const QString& folder, bool own)
{
    std::vector<SceneEntry> entries;
    if (folder.isEmpty())
        return entries;
    for (const QFileInfo& info :
         QDir(folder).entryInfoList({QStringLiteral("*.json")}, QDir::Files, QDir::Name)) {
        const SceneLoadResult r = loadSceneFile(info.absoluteFilePath());
        const QString title = r.ok && !r.scene.title.isEmpty() ? r.scene.title : info.baseName();
        entries.push_back({info.absoluteFilePath(), title, own});
    }
    return entries;
}

} // namespace rigidlab::lessons
