// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lessons the lab ships, as the window finds them: what the window tests walk through.

#include "window/main_window.h"

#include <QDir>
#include <QStringList>

namespace rigidlab::test {

inline QStringList shippedLessons()
{
    const QDir dir(ui::MainWindow::lessonsFolder());
    QStringList out;
    for (const QString& f : dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name))
        out << dir.filePath(f);
    return out;
}

} // namespace rigidlab::test
