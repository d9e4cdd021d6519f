// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/data_dirs.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>

namespace rigidlab::lessons {

namespace {

/// A data folder has both of its subfolders.
bool isDataDir(const QString& dir)
{
    return !dir.isEmpty() && QFileInfo(QDir(dir).filePath(QStringLiteral("scenes"))).isDir() &&
           QFileInfo(QDir(dir).filePath(QStringLiteral("lessons"))).isDir();
}

} // namespace

QString shippedDataDir()
{
    const QString env = qEnvironmentVariable("RIGIDLAB_DATA_DIR");
    if (!env.isEmpty())
        return isDataDir(env) ? QDir(env).canonicalPath() : QString();
    if (QCoreApplication::instance()) {
        // RIGIDLAB_DATA_FROM_BIN: the installed data folder relative to the installed
        // programs, e.g. "../share/rigidlab" (computed by CMake from GNUInstallDirs).
        const QString installed = QDir(QCoreApplication::applicationDirPath())
                                      .filePath(QStringLiteral(RIGIDLAB_DATA_FROM_BIN));
        if (isDataDir(installed))
            return QDir(installed).canonicalPath();
    }
#ifdef RIGIDLAB_SOURCE_DATA
    if (isDataDir(QStringLiteral(RIGIDLAB_SOURCE_DATA)))
        return QStringLiteral(RIGIDLAB_SOURCE_DATA);
#endif
    return QString();
}

QString shippedScenesDir()
{
    const QString data = shippedDataDir();
    return data.isEmpty() ? QString() : QDir(data).filePath(QStringLiteral("scenes"));
}

QString shippedLessonsDir()
{
    const QString data = shippedDataDir();
    return data.isEmpty() ? QString() : QDir(data).filePath(QStringLiteral("lessons"));
}

QString userDataDir()
{
    // Not AppDataLocation: that folder is named after the organisation and the application,
    // which differ between the window and rigidlab-cli (and the tests). The user's folder
    // mirrors the installed one, DATADIR/rigidlab.
    return QDir(QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation))
        .filePath(QStringLiteral("rigidlab"));
}

QString userScenesDir()
{
    return QDir(userDataDir()).filePath(QStringLiteral("scenes"));
}

QString userLessonsDir()
{
    return QDir(userDataDir()).filePath(QStringLiteral("lessons"));
}

void useSettingsFiles()
{
#ifdef Q_OS_WIN
    QSettings::setDefaultFormat(QSettings::IniFormat);
#endif
}

} // namespace rigidlab::lessons
