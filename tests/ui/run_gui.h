// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Runs the rigidlab binary (build_paths.h; tests/ui/CMakeLists.txt builds it first) as a user would
// from a shell: the tests of its command line.

#include "build_paths.h"

#include <QProcess>
#include <QProcessEnvironment>
#include <QString>
#include <QStringList>

namespace rigidlab::test {

/// The environment with Qt's offscreen platform: no display needed.
inline QProcessEnvironment offscreenEnvironment()
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    return env;
}

/// Runs rigidlab with `args` in `env`; its exit status, or -1 if it crashed or hung.
inline int runGui(const QStringList& args, const QProcessEnvironment& env, QString& out,
                  QString& err)
{
    QProcess p;
    p.setProcessEnvironment(env);
    p.start(rigidlab::test::guiPath(), args);
    if (!p.waitForFinished(60000)) {
        p.kill();
        p.waitForFinished();
        return -1;
    }
    out = QString::fromLocal8Bit(p.readAllStandardOutput());
    err = QString::fromLocal8Bit(p.readAllStandardError());
    return p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
}

} // namespace rigidlab::test
