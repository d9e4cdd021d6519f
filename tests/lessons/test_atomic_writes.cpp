// SPDX-License-Identifier: GPL-3.0-or-later
// Every file the lab writes is written whole or not at all: a write that fails (a full disk,
// simulated by a file size limit that stops root as well; a missing or read-only folder)
// leaves the previous file as it was, leaves no temporary file behind, and says why.
// In process (writeFileAtomically, runScene) and through rigidlab-cli (run, error-vs-time,
// stress, bench --export, lesson --export). The window's writers are in tests/ui.

#include "build_paths.h"
#include "format/atomic_file.h"
#include "format/scene_loader.h"
#include "run/scene_run.h"

#include "cli_run.h"
#include "file_size_limit.h"
#include "test_files.h"
#include "test_main.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <sys/resource.h>
#include <unistd.h>

#include <csignal>

using namespace rigidlab;

using rigidlab::test::FileSizeLimit;
using rigidlab::test::readAll;
using rigidlab::test::writeFile;

namespace {

const QString kCli = rigidlab::test::cliPath();
const QString kSource = rigidlab::test::sourcePath();
const QByteArray kPrevious = "the previous file, which must survive\n";
/// Enough for a header or two, far too little for any real output [bytes].
constexpr rlim_t kLimit = 200;

/// Every entry of a folder, hidden ones (temporary files) included, recursively.
QStringList entries(const QString& dir)
{
    QStringList out;
    const QDir d(dir);
    for (const QString& name :
         d.entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot, QDir::Name)) {
        out << name;
        if (QFileInfo(d.filePath(name)).isDir())
            for (const QString& inner : entries(d.filePath(name)))
                out << name + u'/' + inner;
    }
    return out;
}

/// rigidlab-cli with a file size limit in the child only.
rigidlab::test::CliRun runCliLimited(const QStringList& arguments)
{
    return rigidlab::test::runCli(arguments, [] {
        std::signal(SIGXFSZ, SIG_IGN); // kept across exec: writes fail with EFBIG instead
        rlimit limited{};
        getrlimit(RLIMIT_FSIZE, &limited);
        limited.rlim_cur = kLimit;
        setrlimit(RLIMIT_FSIZE, &limited);
    });
}

} // namespace

class TestAtomicWrites : public QObject {
    Q_OBJECT

private slots:
    void writeFileAtomically()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("out.csv"));
        QVERIFY(writeFile(path, kPrevious));
        const QByteArray big(100000, 'x');
        {
            FileSizeLimit limit(kLimit);
            QVERIFY(limit.isActive());
            const QString error = lessons::writeFileAtomically(path, big);
            QVERIFY2(error.startsWith(QStringLiteral("cannot write ") + path + ": "),
                     qPrintable(error));
            QVERIFY2(error.contains(QStringLiteral("File too large")), qPrintable(error));
        }
        QCOMPARE(readAll(path), kPrevious);
        QCOMPARE(entries(dir.path()), QStringList{QStringLiteral("out.csv")});
        // Small enough to sit in Qt's buffer until the end: the final flush fails, and is seen.
        {
            FileSizeLimit limit(10);
            const QString error = lessons::writeFileAtomically(path, QByteArray(1000, 'y'));
            QVERIFY2(error.contains(QStringLiteral("File too large")), qPrintable(error));
        }
        QCOMPARE(readAll(path), kPrevious);
        QCOMPARE(entries(dir.path()), QStringList{QStringLiteral("out.csv")});
        // A folder that is not there.
        const QString missing = dir.filePath(QStringLiteral("no/such/folder/out.csv"));
        QVERIFY(lessons::writeFileAtomically(missing, big)
                    .startsWith(QStringLiteral("cannot write ") + missing + ": "));
        // And when all is well, the new bytes are there.
        QCOMPARE(lessons::writeFileAtomically(path, big), QString());
        QCOMPARE(readAll(path), big);
    }

    void readOnlyFolderKeepsThePreviousFile()
    {
        if (geteuid() == 0)
            QSKIP("running as root: permissions do not stop root (the file size limit tests "
                  "cover the failing write)");
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("out.csv"));
        QVERIFY(writeFile(path, kPrevious));
        const auto readOnly = QFile::ReadOwner | QFile::ExeOwner;
        QVERIFY(QFile::setPermissions(dir.path(), readOnly));
        const QString error = lessons::writeFileAtomically(path, "new");
        QFile::setPermissions(dir.path(), readOnly | QFile::WriteOwner);
        QVERIFY2(error.contains(QStringLiteral("ermission")), qPrintable(error));
        QCOMPARE(readAll(path), kPrevious);
    }

    void runSceneKeepsBothPreviousFiles()
    {
        const lessons::SceneLoadResult loaded =
            lessons::loadSceneFile(kSource + QStringLiteral("/lessons/scenes/ball_drop.json"));
        QVERIFY2(loaded.ok, qPrintable(loaded.error));
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        lessons::RunOptions options;
        options.time = 1.0;
        options.tracePath = dir.filePath(QStringLiteral("trace.csv"));
        options.diagnosticsPath = dir.filePath(QStringLiteral("diagnostics.csv"));
        QVERIFY(writeFile(options.tracePath, kPrevious));
        QVERIFY(writeFile(options.diagnosticsPath, kPrevious));
        {
            FileSizeLimit limit(kLimit);
            QVERIFY(limit.isActive());
            const lessons::RunReport r = lessons::runScene(loaded.scene, options, "ball_drop");
            QCOMPARE(r.status, lessons::RunStatus::OutputError);
            QVERIFY2(r.error.contains(QStringLiteral("File too large")), qPrintable(r.error));
        }
        QCOMPARE(readAll(options.tracePath), kPrevious);
        QCOMPARE(readAll(options.diagnosticsPath), kPrevious);
        QCOMPARE(entries(dir.path()),
                 (QStringList{QStringLiteral("diagnostics.csv"), QStringLiteral("trace.csv")}));
        // Without the limit both are replaced, and nothing else is left.
        const lessons::RunReport r = lessons::runScene(loaded.scene, options, "ball_drop");
        QCOMPARE(r.status, lessons::RunStatus::Ok);
        QVERIFY(readAll(options.tracePath).startsWith(lessons::traceHeader().join(u',').toUtf8()));
        QVERIFY(readAll(options.diagnosticsPath)
                    .startsWith(lessons::diagnosticsHeader().join(u',').toUtf8()));
        QCOMPARE(entries(dir.path()),
                 (QStringList{QStringLiteral("diagnostics.csv"), QStringLiteral("trace.csv")}));
    }

    void cliWritersKeepThePreviousFile_data()
    {
        QTest::addColumn<QStringList>("arguments"); // FILE stands for the output
        QTest::addColumn<QString>("file");          // the output's name in the folder
        const QString ball = kSource + QStringLiteral("/lessons/scenes/ball_drop.json");
        QTest::newRow("run --trace")
            << QStringList{"run", ball, "--time", "1", "--trace", "FILE"} << "trace.csv";
        QTest::newRow("run --diagnostics")
            << QStringList{"run", ball, "--time", "1", "--diagnostics", "FILE"} << "energy.csv";
        QTest::newRow("error-vs-time --csv")
            << QStringList{"error-vs-time", "--problem", "oscillator", "--integrators", "euler",
                           "--points",      "2",         "--csv",      "FILE"}
            << "sweep.csv";
        QTest::newRow("bench --export")
            << QStringList{"bench", "--scene", "pyramid-20", "--export", "FILE"} << "scene.json";
        QTest::newRow("lesson pack")
            << QStringList{"lesson", "pack",
                           kSource + QStringLiteral("/lessons/lessons/stacks.json"), "-o", "FILE"}
            << "stacks.rlesson";
    }
    void cliWritersKeepThePreviousFile()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, file);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(file);
        QVERIFY(writeFile(path, kPrevious));
        arguments.replaceInStrings(QStringLiteral("FILE"), path);
        const rigidlab::test::CliRun run = runCliLimited(arguments);
        QVERIFY(!run.crashed);
        QVERIFY2(run.exitCode == 1, run.err.constData());
        QVERIFY2(run.err.contains("cannot write " + path.toUtf8()), run.err.constData());
        QVERIFY2(run.err.contains("File too large"), run.err.constData());
        QCOMPARE(readAll(path), kPrevious);
        QCOMPARE(entries(dir.path()), QStringList{file});
    }

    void cliLessonExportKeepsThePreviousFiles()
    {
        // The handouts folder: each plot is written whole or not at all, and the run says why.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString lesson = kSource + QStringLiteral("/lessons/lessons/energy_drift.json");
        const QDir out(dir.filePath(QStringLiteral("handouts")));
        QVERIFY(QDir().mkpath(out.path()));
        // A first export without a limit gives the previous files.
        QProcess first;
        first.start(kCli,
                    {QStringLiteral("lesson"), lesson, QStringLiteral("--export"), out.path()});
        QVERIFY(first.waitForFinished(300'000));
        QCOMPARE(first.exitCode(), 0);
        const QStringList before = entries(out.path());
        QVERIFY(before.size() > 4);
        QMap<QString, QByteArray> contents;
        for (const QString& name : before)
            if (QFileInfo(out.filePath(name)).isFile())
                contents[name] = readAll(out.filePath(name));

        const rigidlab::test::CliRun run = runCliLimited(
            {QStringLiteral("lesson"), lesson, QStringLiteral("--export"), out.path()});
        QVERIFY(!run.crashed);
        QVERIFY2(run.exitCode == 1, run.err.constData());
        QVERIFY2(run.err.contains("File too large"), run.err.constData());
        QCOMPARE(entries(out.path()), before);
        for (auto it = contents.cbegin(); it != contents.cend(); ++it)
            QVERIFY2(readAll(out.filePath(it.key())) == it.value(), qPrintable(it.key()));
    }
};

RIGIDLAB_TEST_GUILESS_MAIN(TestAtomicWrites)
#include "test_atomic_writes.moc"
