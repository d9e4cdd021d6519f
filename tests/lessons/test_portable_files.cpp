// SPDX-License-Identifier: GPL-3.0-or-later
// What the lab meets on a teacher's Windows PC, checked here on Linux: files saved with CRLF
// line ends (Notepad, Excel, a lesson mailed through Windows) read the same as with LF, errors
// in them named on the same line; folders and file names with Czech letters ("Měření žáků",
// "Srážka míčků.json") for scenes, runs' traces and lessons in one file; and the settings the
// window writes are the ones rigidlab-cli reads when settings live in an INI file, as on Windows
// (data_dirs.h, useSettingsFiles), not in the system's native store.

#include "build_paths.h"
#include "format/data_dirs.h"
#include "format/lesson.h"
#include "format/lesson_catalog.h"
#include "format/lesson_pack.h"
#include "format/scene_compare.h"
#include "format/scene_loader.h"
#include "measure/measurement.h"
#include "run/scene_run.h"

#include "test_files.h"
#include "test_main.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QSettings>
#include <QTemporaryDir>
#include <QtTest>

using namespace rigidlab;
using rigidlab::test::readAll;
using rigidlab::test::writeFile;

namespace {

/// The same text with Windows' line ends.
QByteArray withCrlf(QByteArray lf)
{
    return lf.replace("\r\n", "\n").replace("\n", "\r\n");
}

QString shipped(const QString& relative)
{
    return QDir(rigidlab::test::sourcePath(u"/lessons")).filePath(relative);
}

} // namespace

class TestPortableFiles : public QObject {
    Q_OBJECT
private slots:
    void crlfScenesReadAsLf_data();
    void crlfScenesReadAsLf();
    void crlfErrorsOnTheSameLine();
    void crlfLessonReadsAsLf();
    void crlfMeasurementsReadAsLf_data();
    void crlfMeasurementsReadAsLf();
    void czechNamesForScenesAndTraces();
    void czechNamesForLessonFiles();
    void settingsInAFileAreSharedWithTheCli();
};

void TestPortableFiles::crlfScenesReadAsLf_data()
{
    QTest::addColumn<QString>("path");
    for (const char* name : {"scenes/ball_drop.json", "scenes/newtons_cradle.json",
                             "scenes/sat_non_convex.json", "scenes/spring_oscillator.json"})
        QTest::newRow(name) << shipped(QLatin1String(name));
}

void TestPortableFiles::crlfScenesReadAsLf()
{
    QFETCH(QString, path);
    const QByteArray lf = readAll(path);
    QVERIFY2(!lf.isEmpty() && !lf.contains('\r'), qPrintable(path));
    const lessons::SceneLoadResult a = lessons::loadSceneJson(lf, path);
    const lessons::SceneLoadResult b = lessons::loadSceneJson(withCrlf(lf), path);
    QVERIFY2(a.ok, qPrintable(a.error));
    QVERIFY2(b.ok, qPrintable(b.error));
    const QString difference = lessons::sceneDifference(a.scene, b.scene);
    QVERIFY2(difference.isEmpty(), qPrintable(difference));
    QCOMPARE(b.warnings, a.warnings);
}

void TestPortableFiles::crlfErrorsOnTheSameLine()
{
    // A comma missing at the end of line 3: the message names line 4 either way (a CR is no
    // line of its own).
    const QByteArray lf = "{\n  \"rigidlab\": 1,\n  \"title\": \"x\"\n  \"bodies\": []\n}\n";
    const lessons::SceneLoadResult a = lessons::loadSceneJson(lf, QStringLiteral("broken.json"));
    const lessons::SceneLoadResult b =
        lessons::loadSceneJson(withCrlf(lf), QStringLiteral("broken.json"));
    QVERIFY(!a.ok);
    QVERIFY(!b.ok);
    QVERIFY2(a.error.contains(QLatin1String("4")), qPrintable(a.error));
    QCOMPARE(b.error, a.error);
}

void TestPortableFiles::crlfLessonReadsAsLf()
{
    // The lesson and every scene it names, all with CRLF, in a folder laid out as shipped.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString lessonPath = shipped(QStringLiteral("lessons/restitution.json"));
    const lessons::LessonLoadResult lf = lessons::loadLessonFile(lessonPath);
    QVERIFY2(lf.ok, qPrintable(lf.error));
    QVERIFY(QDir().mkpath(dir.filePath(QStringLiteral("lessons"))));
    QVERIFY(QDir().mkpath(dir.filePath(QStringLiteral("scenes"))));
    const QString copy = dir.filePath(QStringLiteral("lessons/restitution.json"));
    QVERIFY(writeFile(copy, withCrlf(readAll(lessonPath))));
    for (const lessons::LessonStep& step : lf.lesson.steps)
        if (!step.scenePath.isEmpty()) {
            const QString relative = QDir(shipped(QString())).relativeFilePath(step.scenePath);
            QVERIFY2(writeFile(dir.filePath(relative), withCrlf(readAll(step.scenePath))),
                     qPrintable(relative));
        }
    const lessons::LessonLoadResult crlf = lessons::loadLessonFile(copy);
    QVERIFY2(crlf.ok, qPrintable(crlf.error));
    QCOMPARE(crlf.lesson.title, lf.lesson.title);
    QCOMPARE(crlf.lesson.goals, lf.lesson.goals);
    QCOMPARE(crlf.lesson.steps.size(), lf.lesson.steps.size());
    for (std::size_t i = 0; i < lf.lesson.steps.size(); ++i) {
        QCOMPARE(crlf.lesson.steps[i].title, lf.lesson.steps[i].title);
        QCOMPARE(crlf.lesson.steps[i].text, lf.lesson.steps[i].text);
        const QString difference =
            lessons::sceneDifference(crlf.lesson.steps[i].scene, lf.lesson.steps[i].scene);
        QVERIFY2(difference.isEmpty(), qPrintable(QStringLiteral("step %1: ").arg(i) + difference));
    }
}

void TestPortableFiles::crlfMeasurementsReadAsLf_data()
{
    QTest::addColumn<QString>("path");
    for (const char* name :
         {"measure/samples/ball_plain.csv", "measure/samples/ball_tracker.csv",
          "measure/samples/box_phyphox_cs.csv", "measure/samples/box_tracker_cs.txt"})
        QTest::newRow(name) << shipped(QLatin1String(name));
}

void TestPortableFiles::crlfMeasurementsReadAsLf()
{
    QFETCH(QString, path);
    const QByteArray bytes = readAll(path);
    QVERIFY2(!bytes.isEmpty(), qPrintable(path));
    QByteArray lf = bytes;
    lf.replace("\r\n", "\n");
    const measure::TableResult a = measure::readTable(lf, path);
    const measure::TableResult b = measure::readTable(withCrlf(lf), path);
    QVERIFY2(a.ok, qPrintable(a.error));
    QVERIFY2(b.ok, qPrintable(b.error));
    QCOMPARE(b.table.separator, a.table.separator);
    QCOMPARE(b.table.decimalComma, a.table.decimalComma);
    QCOMPARE(b.table.titleLines, a.table.titleLines);
    QCOMPARE(b.table.lines, a.table.lines);
    QCOMPARE(b.table.columns.size(), a.table.columns.size());
    QVERIFY(a.table.rows() > 0);
    for (std::size_t c = 0; c < a.table.columns.size(); ++c) {
        const measure::Column& x = a.table.columns[c];
        const measure::Column& y = b.table.columns[c];
        QCOMPARE(y.name, x.name); // no CR left at the end of the last column's head
        QCOMPARE(y.unit, x.unit);
        QCOMPARE(y.values.size(), x.values.size());
        for (std::size_t r = 0; r < x.values.size(); ++r)
            QVERIFY2(y.values[r] == x.values[r] ||
                         (std::isnan(y.values[r]) && std::isnan(x.values[r])),
                     qPrintable(QStringLiteral("column %1, row %2: %3 with CRLF, %4 with LF")
                                    .arg(c)
                                    .arg(r)
                                    .arg(y.values[r])
                                    .arg(x.values[r])));
    }
}

void TestPortableFiles::czechNamesForScenesAndTraces()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString folder = dir.filePath(QStringLiteral("Měření žáků"));
    QVERIFY(QDir().mkpath(folder));
    const QString scenePath = QDir(folder).filePath(QStringLiteral("Srážka míčků.json"));
    QVERIFY(QFile::copy(shipped(QStringLiteral("scenes/ball_drop.json")), scenePath));
    const lessons::SceneLoadResult loaded = lessons::loadSceneFile(scenePath);
    QVERIFY2(loaded.ok, qPrintable(loaded.error));

    // Twice into the same trace: the second run keeps the first file under a second name
    // while it writes (a hard link, else a copy), and replaces it whole.
    lessons::RunOptions options;
    options.steps = 50;
    options.tracePath = QDir(folder).filePath(QStringLiteral("stopa – pokus č. 1.csv"));
    for (int run = 0; run < 2; ++run) {
        const lessons::RunReport report = lessons::runScene(loaded.scene, options, scenePath);
        QVERIFY2(report.status == lessons::RunStatus::Ok, qPrintable(report.error));
    }
    const QByteArray trace = readAll(options.tracePath);
    QVERIFY2(trace.count('\n') > 50, trace.left(200).constData());
    QCOMPARE(test::filesUnder(folder), QStringList({QStringLiteral("Srážka míčků.json"),
                                                    QStringLiteral("stopa – pokus č. 1.csv")}));
}

void TestPortableFiles::czechNamesForLessonFiles()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString lessonPath = shipped(QStringLiteral("lessons/restitution.json"));
    const lessons::LessonPackResult packed =
        lessons::packLesson(lessonPath, {QStringLiteral("Žofie Řeháková"), QString()});
    QVERIFY2(packed.ok, qPrintable(packed.error));
    const QString folder = dir.filePath(QStringLiteral("Lekce pro 1. ročník"));
    QVERIFY(QDir().mkpath(folder));
    const QString packPath = QDir(folder).filePath(QStringLiteral("Odrazy a srážky.rlesson"));
    QVERIFY(writeFile(packPath, lessons::lessonPackBytes(packed.pack)));
    QVERIFY(lessons::isLessonDocument(packPath));

    const lessons::LessonLoadResult original = lessons::loadLessonFile(lessonPath);
    const lessons::LessonLoadResult fromPack = lessons::loadLessonFile(packPath);
    QVERIFY2(fromPack.ok, qPrintable(fromPack.error));
    QCOMPARE(fromPack.lesson.title, original.lesson.title);
    QCOMPARE(fromPack.lesson.steps.size(), original.lesson.steps.size());

    // Unpacked into a Czech folder, under a Czech name, it loads again.
    QStringList written;
    const QString unpacked = QDir(folder).filePath(QStringLiteral("rozbalená"));
    QCOMPARE(
        lessons::unpackLesson(packed.pack, unpacked, QStringLiteral("Odrazy a srážky"), written),
        QString());
    const lessons::LessonLoadResult again =
        lessons::loadLessonFile(QDir(unpacked).filePath(QStringLiteral("Odrazy a srážky.json")));
    QVERIFY2(again.ok, qPrintable(again.error));
    QCOMPARE(again.lesson.steps.size(), original.lesson.steps.size());

    // Listed among the lessons of its folder (the unpacked one in its own subfolder).
    const std::vector<lessons::LessonEntry> listed = lessons::lessonsInOrder(folder);
    QCOMPARE(listed.size(), std::size_t(1));
    QCOMPARE(listed.front().path, packPath);
    QCOMPARE(listed.front().title, original.lesson.title);
}

void TestPortableFiles::settingsInAFileAreSharedWithTheCli()
{
    // As on Windows: settings in an INI file, which the window's QSettings() and rigidlab-cli's
    // (no organisation of its own) must both use. Before, the CLI read the native store.
    const QSettings::Format before = QSettings::defaultFormat();
    QSettings::setDefaultFormat(QSettings::IniFormat);
    const QString organisation = QCoreApplication::organizationName();
    const QString application = QCoreApplication::applicationName();

    QTemporaryDir shared;
    QVERIFY(shared.isValid());
    QCoreApplication::setOrganizationName(QStringLiteral("RigidLab")); // the window
    QCoreApplication::setApplicationName(QStringLiteral("RigidLab"));
    QVERIFY(lessons::addLessonFolder(shared.path()));
    QCoreApplication::setOrganizationName(QString()); // rigidlab-cli
    QCoreApplication::setApplicationName(QStringLiteral("rigidlab-cli"));
    const QStringList seen = lessons::addedLessonFolders();

    QCoreApplication::setOrganizationName(QStringLiteral("RigidLab"));
    QCoreApplication::setApplicationName(QStringLiteral("RigidLab"));
    lessons::removeLessonFolder(shared.path());
    QCoreApplication::setOrganizationName(organisation);
    QCoreApplication::setApplicationName(application);
    QSettings::setDefaultFormat(before);
    QVERIFY2(seen.contains(shared.path()), qPrintable(seen.join(u',')));
}

RIGIDLAB_TEST_GUILESS_MAIN(TestPortableFiles)
#include "test_portable_files.moc"
