// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Files the tests write for themselves (a broken scene or lesson, a file to overwrite), and
// the files a folder holds (what an export or an unpacked lesson wrote).

#include <QByteArray>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QString>
#include <QStringList>

namespace rigidlab::test {

/// The file's bytes, or nothing when it cannot be read.
inline QByteArray readAll(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

/// Writes `contents` to `path` (made or truncated); false if the file could not be written.
inline bool writeFile(const QString& path, const QByteArray& contents)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(contents) == contents.size();
}

/// The files under `folder` and its subfolders, relative to it, sorted.
inline QStringList filesUnder(const QString& folder)
{
    QStringList files;
    QDirIterator it(folder, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext())
        files.append(QDir(folder).relativeFilePath(it.next()));
    files.sort();
    return files;
}

} // namespace rigidlab::test
