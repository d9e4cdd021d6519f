// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/settings_sync.h"

#include <QCoreApplication>
#include <QDir>
#include <QMainWindow>
#include <QSettings>
#include <QStatusBar>

namespace rigidlab::ui {

void syncSettings(QSettings& settings, QMainWindow& window)
{
    settings.sync();
    if (settings.status() == QSettings::NoError)
        return;
    const QString why =
        QCoreApplication::translate("MainWindow", "Settings not saved: cannot write %1")
            .arg(QDir::toNativeSeparators(settings.fileName()));
    window.statusBar()->showMessage(why, 8000);
    qWarning("%s", qPrintable(why));
}

} // namespace rigidlab::ui
