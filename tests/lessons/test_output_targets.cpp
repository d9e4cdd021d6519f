// SPDX-License-Identifier: GPL-3.0-or-later
// What every writer does with what its path holds: a regular file or a missing name is replaced
// whole; a character device or a FIFO is written into and stays what it is (renaming a file
// over /dev/null as root would replace it for the whole machine); a full device says the disk
// is full; a folder is refused in one line that names it.
// As root the devices are private nodes made in a temporary folder (mknod), never the
// machine's own; as an ordinary user, who cannot make them, the machine's /dev/null and
// /dev/full, which such a user cannot replace either.

#include "build_paths.h"
#include "format/atomic_file.h"

#include "cli_run.h"
#include "test_main.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <cstring>

using namespace rigidlab;
using rigidlab::test::CliRun;
using rigidlab::test::runCli;

namespace {

const QString kSource = rigidlab::test::sourcePath();
/// The system's words for a full device (ENOSPC), which the lab may give instead of its own.
const QString kNoSpace = QString::fromLocal8Bit(std::strerror(ENOSPC));

/// The kind of what `path` holds (S_IFCHR, S_IFREG, ...), 0 when nothing is there.
mode_t kindAt(const QString& path)
{
    struct stat st {};
    return ::stat(QFile::encodeName(path).constData(), &st) == 0 ? (st.st_mode & S_IFMT) : 0;
}

/// The memory devices /dev/null (minor 3) and /dev/full (minor 7): a private node in `dir` as
/// root, else the machine's own.
QString memoryDevice(const QTemporaryDir& dir, const char* name, unsigned minor)
{
    if (geteuid() != 0)
        return QStringLiteral("/dev/") + QLatin1String(name);
    const QString path = dir.filePath(QLatin1String(name));
    if (::mknod(QFile::encodeName(path).constData(), S_IFCHR | 0666, makedev(1, minor)) != 0)
        qFatal("mknod %s: %s", qPrintable(path), std::strerror(errno));
    return path;
}

bool fullDisk(const QString& message)
{
    return message.contains(QStringLiteral("disk is full")) || message.contains(kNoSpace);
}

} // namespace

class TestOutputTargets : public QObject {
    Q_OBJECT

private slots:
    void deviceIsWrittenIntoNotReplaced()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString null = memoryDevice(dir, "null", 3);
        QCOMPARE(kindAt(null), mode_t{S_IFCHR});
        QCOMPARE(lessons::writeFileAtomically(null, QByteArray(100000, 'x')), QString());
        QCOMPARE(kindAt(null), mode_t{S_IFCHR});
        QCOMPARE(
            QDir(dir.path())
                .entryList(QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot),
            geteuid() == 0 ? QStringList{QStringLiteral("null")} : QStringList());
    }

    void fullDeviceSaysTheDiskIsFull()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString full = memoryDevice(dir, "full", 7);
        const QString error = lessons::writeFileAtomically(full, "a line\n");
        QVERIFY2(error.startsWith(QStringLiteral("cannot write ") + full + QStringLiteral(": ")),
                 qPrintable(error));
        QVERIFY2(fullDisk(error), qPrintable(error));
        QVERIFY2(!error.contains(QStringLiteral("ermission")), qPrintable(error));
        QCOMPARE(kindAt(full), mode_t{S_IFCHR});
    }

    void fifoIsWrittenInto()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("pipe"));
        QCOMPARE(::mkfifo(QFile::encodeName(path).constData(), 0600), 0);
        // The reading end first (not blocking), so that the writer's open returns at once.
        const int reader = ::open(QFile::encodeName(path).constData(), O_RDONLY | O_NONBLOCK);
        QVERIFY(reader >= 0);
        const QByteArray sent = "t,y\n0,1\n"; // far less than a pipe holds
        QCOMPARE(lessons::writeFileAtomically(path, sent), QString());
        QByteArray got(64, '\0');
        const ssize_t n = ::read(reader, got.data(), got.size());
        ::close(reader);
        QCOMPARE(got.left(static_cast<int>(n)), sent);
        QCOMPARE(kindAt(path), mode_t{S_IFIFO});
    }

    void folderIsRefused()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString folder = dir.filePath(QStringLiteral("out"));
        QVERIFY(QDir().mkpath(folder));
        const QString error = lessons::writeFileAtomically(folder, "x");
        QCOMPARE(error, QStringLiteral("cannot write %1: it is a folder, not a file").arg(folder));
        QCOMPARE(kindAt(folder), mode_t{S_IFDIR});
        QCOMPARE(QDir(folder).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot),
                 QStringList());
    }

    void regularFileIsStillReplacedWhole()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("out.csv"));
        QCOMPARE(lessons::writeFileAtomically(path, "first"), QString());
        QCOMPARE(lessons::writeFileAtomically(path, "second"), QString());
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll(), QByteArray("second"));
        QCOMPARE(kindAt(path), mode_t{S_IFREG});
    }

    void cliRunOntoNull_data()
    {
        QTest::addColumn<QString>("option");
        QTest::newRow("--diagnostics") << "--diagnostics";
        QTest::newRow("--trace") << "--trace";
    }
    void cliRunOntoNull()
    {
        QFETCH(QString, option);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString null = memoryDevice(dir, "null", 3);
        const QString ball = kSource + QStringLiteral("/lessons/scenes/ball_drop.json");
        const CliRun run = runCli({QStringLiteral("run"), ball, QStringLiteral("--time"),
                                   QStringLiteral("1"), option, null});
        QVERIFY2(!run.crashed && run.exitCode == 0, run.err.constData());
        QCOMPARE(kindAt(null), mode_t{S_IFCHR});
    }

    void cliWorksheetOntoFullFails()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString full = memoryDevice(dir, "full", 7);
        const QString lesson = kSource + QStringLiteral("/lessons/lessons/restitution.json");
        const CliRun run =
            runCli({QStringLiteral("lesson"), lesson, QStringLiteral("--worksheet"), full});
        QVERIFY2(!run.crashed && run.exitCode > 0, run.err.constData());
        const QString err = QString::fromUtf8(run.err);
        QVERIFY2(err.contains(full) && fullDisk(err), run.err.constData());
        QCOMPARE(kindAt(full), mode_t{S_IFCHR});
    }

    void cliFolderTargetIsRefused()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString ball = kSource + QStringLiteral("/lessons/scenes/ball_drop.json");
        const CliRun run =
            runCli({QStringLiteral("run"), ball, QStringLiteral("--time"), QStringLiteral("1"),
                    QStringLiteral("--diagnostics"), dir.path()});
        QVERIFY2(!run.crashed && run.exitCode > 0, run.err.constData());
        const QByteArray expected =
            "cannot write " + QFile::encodeName(dir.path()) + ": it is a folder, not a file\n";
        QVERIFY2(run.err.contains(expected), run.err.constData());
        QCOMPARE(kindAt(dir.path()), mode_t{S_IFDIR});
        QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot),
                 QStringList());
    }
};

RIGIDLAB_TEST_GUILESS_MAIN(TestOutputTargets)
#include "test_output_targets.moc"
