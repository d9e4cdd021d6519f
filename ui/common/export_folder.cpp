// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/export_folder.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>

namespace rigidlab::ui {

QString exportFolder()
{
    const QString last = QSettings().value(QLatin1String(kExportFolderKey)).toString();
    if (!last.isEmpty() && QFileInfo(last).isDir())
        return last;
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    return QFileInfo(documents).isDir() ? documents : QDir::homePath();
}

void rememberExportFolder(const QString& folderOrFile)
{
    if (folderOrFile.isEmpty())
        return;
    const QFileInfo info(folderOrFile);
    const QString folder = info.isDir() ? info.absoluteFilePath() : info.absolutePath();
    QSettings().setValue(QLatin1String(kExportFolderKey), folder);
}

} // namespace rigidlab::ui
