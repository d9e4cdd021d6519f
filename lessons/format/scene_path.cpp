// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/scene_path.h"

#include "format/json_reader.h"

#include <QDir>
#include <QFileInfo>

namespace rigidlab::lessons {

using detail::FileMessages;

namespace {

/// `path` lies strictly below `folder` (both clean and absolute).
bool isBelow(const QString& path, const QString& folder)
{
    const QString inside = folder.endsWith(u'/') ? folder : folder + u'/';
    return path.startsWith(inside);
}

ScenePathResult failure(const QString& what)
{
    ScenePathResult result;
    result.error = what;
    return result;
}

} // namespace

QString lessonRoot(const QString& lessonFolder)
{
    const QDir folder(QDir::cleanPath(lessonFolder));
    if (folder.dirName() == QStringLiteral("lessons")) {
        const QString data = QDir::cleanPath(folder.absoluteFilePath(QStringLiteral("..")));
        if (QFileInfo(QDir(data).filePath(QStringLiteral("scenes"))).isDir())
            return data;
    }
    return folder.absolutePath();
}

ScenePathResult resolveScenePath(const QString& lessonFolder, const QString& relative)
{
    if (relative.isEmpty())
        return failure(FileMessages::tr("must name a scene file, got an empty path"));
    if (relative.contains(u'\\'))
        return failure(FileMessages::tr("use '/' between folders, got \"%1\"").arg(relative));
    if (QDir::isAbsolutePath(relative) || relative.startsWith(u'/') ||
        (relative.size() >= 2 && relative[1] == u':'))
        return failure(
            FileMessages::tr("must be a path relative to the lesson's folder, got \"%1\"")
                .arg(relative));
    for (const QChar c : relative) {
        if (c.unicode() < 0x20 || c.unicode() == 0x7f)
            return failure(FileMessages::tr("must not hold control characters"));
    }
    const QString folder = QDir::cleanPath(QFileInfo(lessonFolder).absoluteFilePath());
    const QString root = lessonRoot(folder);
    const QString rootName = root == folder ? FileMessages::tr("the lesson's folder")
                                            : FileMessages::tr("the data folder (scenes/ and "
                                                               "lessons/)");
    const QString path = QDir::cleanPath(QDir(folder).filePath(relative));
    if (!isBelow(path, root))
        return failure(FileMessages::tr("must not leave %1, got \"%2\"").arg(rootName, relative));
    // A symbolic link inside the root could still point out of it. What is read is the
    // resolved path itself, checked to be a plain file below the root: a link swapped after
    // the check cannot redirect the read, and a named pipe or a device cannot block or feed it.
    ScenePathResult result;
    result.absolutePath = path;
    result.readPath = path;
    const QString canonicalRoot = QFileInfo(root).canonicalFilePath();
    const QString canonical = QFileInfo(path).canonicalFilePath();
    if (!canonical.isEmpty()) {
        if (canonicalRoot.isEmpty() || !isBelow(canonical, canonicalRoot))
            return failure(FileMessages::tr("\"%1\" leads out of %2 (through a symbolic link)")
                               .arg(relative, rootName));
        if (!QFileInfo(canonical).isFile())
            return failure(FileMessages::tr("\"%1\" is not a plain file").arg(relative));
        result.readPath = canonical;
    }
    result.ok = true;
    return result;
}

} // namespace rigidlab::lessons
