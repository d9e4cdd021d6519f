// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// rigidlab-cli as a user meets it: run as a process, judged by its exit status, its output
// and the files it leaves (or must not leave). One executable: its usage and refusals
// (test_cli.cpp), and what its commands write (test_cli_runs.cpp). Shared helpers here.

#include "build_paths.h"
#include "cli_run.h"
#include "test_files.h"

#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QTest>

namespace rigidlab::test::cli {

using rigidlab::test::readAll;
using rigidlab::test::writeFile;

using rigidlab::test::readAll;
using rigidlab::test::writeFile;

inline const QString kScenesDir = rigidlab::test::sourcePath(u"/lessons/scenes");

inline QString scene(const char* name)
{
    return QDir(kScenesDir).filePath(QLatin1StringView(name) + QStringLiteral(".json"));
}

/// The files in a directory, hidden ones (temporary files) included.
inline QStringList filesIn(const QString& dir)
{
    return QDir(dir).entryList(QDir::Files | QDir::Hidden | QDir::NoDotAndDotDot);
}

inline constexpr const char* kBall =
    R"({"id": "ball", "shape": {"type": "circle", "radius": 0.1}})";

} // namespace rigidlab::test::cli

class TestCli : public QObject {
    Q_OBJECT

private slots:
    void help();
    void usageErrors_data();
    void usageErrors();
    void badInput_data();
    void badInput();
    void shippedScenesValidate_data();
    void shippedScenesValidate();
    void validateWarns();
    void lessonLanguages();
    void runWritesHeaders();
    void runIsByteIdentical();
    void runSummary();
    void runFailsOnUnwritableOutput();
    void runStopsOnNonFinite();
    void satOutput();
    void satArray();
    void runProfile();
    void bench();
    void benchExportNamesTheSolver_data();
    void benchExportNamesTheSolver();
    void lessonsListsOwn();
};
