// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// rigidlab-cli run as a user runs it: a separate process, its exit status and what it printed.
// Tests that link it define RIGIDLAB_CLI (the program's path, from CMake).

#include <QByteArray>
#include <QProcess>
#include <QString>
#include <QStringList>

namespace rigidlab::test {

struct CliRun {
    int exitCode = -1;   ///< -1 when it did not finish in time or crashed
    bool crashed = true; ///< ended by a signal, or did not finish in time
    QByteArray out;
    QByteArray err;
};

/// Runs `program` with `arguments`, waiting at most `timeoutMs` (killed after that).
inline CliRun runProgram(const QString& program, const QStringList& arguments,
                         int timeoutMs = 120'000)
{
    QProcess process;
    process.start(program, arguments);
    CliRun run;
    if (!process.waitForFinished(timeoutMs)) {
        process.kill();
        process.waitForFinished();
        return run;
    }
    run.crashed = process.exitStatus() != QProcess::NormalExit;
    run.exitCode = run.crashed ? -1 : process.exitCode();
    run.out = process.readAllStandardOutput();
    run.err = process.readAllStandardError();
    return run;
}

#ifdef RIGIDLAB_CLI
/// rigidlab-cli with `arguments`.
inline CliRun runCli(const QStringList& arguments)
{
    return runProgram(QStringLiteral(RIGIDLAB_CLI), arguments);
}
#endif

} // namespace rigidlab::test
