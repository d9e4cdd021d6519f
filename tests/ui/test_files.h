// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Files the window tests write for themselves: a broken scene or lesson, a file to overwrite.

#include <QByteArray>
#include <QFile>
#include <QString>

namespace rigidlab::test {

/// Writes `contents` to `path` (made or truncated); false if the file could not be written.
inline bool writeFile(const QString& path, const QByteArray& contents)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(contents) == contents.size();
}

} // namespace rigidlab::test
