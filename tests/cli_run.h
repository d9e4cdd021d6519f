// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// rigidlab-cli run as a process by a test: its exit, its output, and how long it took. The
// test's CMake target names the program (RIGIDLAB_CLI) and depends on it.

#include <QByteArray>
#include <QElapsedTimer>
#include <QProcess>
#include <QStringList>

#include <functional>

namespace rigidlab::test {

struct CliRun {
    int exitCode = -1;
    bool crashed = true; ///< or did not finish in time
    QByteArray out;
    QByteArray err;
    qint64 milliseconds = 0; ///< wall time
};

/// Runs rigidlab-cli with `arguments`; `inChild` (optional) runs in the child before the
/// program starts (a resource limit).
inline CliRun runCli(const QStringList& arguments, const std::function<void()>& inChild = {})
{
    QProcess process;
    if (inChild)
        process.setChildProcessModifier(inChild);
    QElapsedTimer clock;
    clock.start();
    process.start(QStringLiteral(RIGIDLAB_CLI), arguments);
    CliRun run;
    if (!process.waitForFinished(300'000)) {
        process.kill();
        process.waitForFinished();
        return run;
    }
    run.milliseconds = clock.elapsed();
    run.crashed = process.exitStatus() != QProcess::NormalExit;
    run.exitCode = process.exitCode();
    run.out = process.readAllStandardOutput();
    run.err = process.readAllStandardError();
    return run;
}

} // namespace rigidlab::test
