// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// rigidlab-cli run as a user runs it: a separate process, its exit status, what it printed and
// how long it took. Tests that run it are added with USES_CLI (tests/CMakeLists.txt), so that the
// program is built before them.

#include "build_paths.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QProcess>
#include <QString>
#include <QStringList>

#include <functional>

namespace rigidlab::test {

struct CliRun {
    int exitCode = -1;   ///< -1 when it crashed or did not finish in time
    bool crashed = true; ///< ended by a signal, or did not finish in time
    QByteArray out;
    QByteArray err;
    qint64 milliseconds = 0; ///< wall time
};

/// Runs `program` with `arguments`, killed after 300 s; `inChild` (optional) runs in the child
/// before the program starts (a resource limit).
inline CliRun runProgram(const QString& program, const QStringList& arguments,
                         const std::function<void()>& inChild = {})
{
    QProcess process;
    if (inChild)
        process.setChildProcessModifier(inChild);
    QElapsedTimer clock;
    clock.start();
    process.start(program, arguments);
    CliRun run;
    if (!process.waitForFinished(300'000)) {
        process.kill();
        process.waitForFinished();
        return run;
    }
    run.milliseconds = clock.elapsed();
    run.crashed = process.exitStatus() != QProcess::NormalExit;
    run.exitCode = run.crashed ? -1 : process.exitCode();
    run.out = process.readAllStandardOutput();
    run.err = process.readAllStandardError();
    return run;
}

/// rigidlab-cli with `arguments`.
inline CliRun runCli(const QStringList& arguments, const std::function<void()>& inChild = {})
{
    return runProgram(cliPath(), arguments, inChild);
}

} // namespace rigidlab::test
