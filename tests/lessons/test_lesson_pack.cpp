// SPDX-License-Identifier: GPL-3.0-or-later
// A lesson in one file (.rlesson, lessons/format/RLESSON_FORMAT.md): every shipped lesson packs,
// loads through the lesson loader with the same steps and the same scenes (compared field by
// field) as from its folder, and survives unpack → pack byte for byte; damaged files are
// refused in one line naming the file and the place; the scenes inside are the only ones read;
// and rigidlab-cli lesson pack / unpack / --validate / --export work on it as on a folder.

#include "build_paths.h"
#include "format/data_dirs.h"
#include "format/lesson.h"
#include "format/lesson_catalog.h"
#include "format/lesson_pack.h"
#include "format/scene_compare.h"

#include "cli_run.h"
#include "test_files.h"
#include "test_main.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QtTest>

#include "question_kinds.h"
#include <functional>

using rigidlab::test::choiceOf;

using namespace rigidlab;
using rigidlab::test::filesUnder;
using rigidlab::test::writeFile;

class TestLessonPack : public QObject {
    Q_OBJECT
private slots:
    void shippedLessonsPack_data();
    void shippedLessonsPack();
    void infoRoundTrips();
    void refusesDamaged_data();
    void refusesDamaged();
    void refusesSceneNameWithLineBreak();
    void readsNoSceneFromDisk();
    void listedWithAuthorAndDate();
    void cliPacksValidatesExports_data();
    void cliPacksValidatesExports();
    void cliRefusals();
    void cliOneLanguageLessons_data();
    void cliOneLanguageLessons();
};

namespace {

const QString kLessonsDir = rigidlab::test::sourcePath(u"/lessons/lessons");

QStringList shippedLessons()
{
    return QDir(kLessonsDir).entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
}

/// restitution.json packed, as a JSON object to damage.
QJsonObject packedRestitution()
{
    const lessons::LessonPackResult r =
        lessons::packLesson(QDir(kLessonsDir).filePath(QStringLiteral("restitution.json")));
    if (!r.ok)
        qFatal("restitution.json does not pack: %s", qPrintable(r.error));
    return QJsonDocument::fromJson(lessons::lessonPackBytes(r.pack)).object();
}

using rigidlab::test::runCli;
using Run = rigidlab::test::CliRun;

} // namespace

void TestLessonPack::shippedLessonsPack_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("language");
    for (const QString& file : shippedLessons())
        for (const char* language : {"en", "cs"})
            QTest::newRow(qPrintable(file + u' ' + QLatin1String(language)))
                << file << QString::fromLatin1(language);
    QVERIFY(shippedLessons().size() >= 6);
}

void TestLessonPack::shippedLessonsPack()
{
    QFETCH(QString, file);
    QFETCH(QString, language);
    const lessons::LessonLoadOptions options{language};
    const lessons::LessonLoadResult folder =
        lessons::loadLessonFile(QDir(kLessonsDir).filePath(file), options);
    QVERIFY2(folder.ok, qPrintable(folder.error));

    const lessons::LessonPackResult packed = lessons::packLesson(QDir(kLessonsDir).filePath(file));
    QVERIFY2(packed.ok, qPrintable(packed.error));
    const QByteArray bytes = lessons::lessonPackBytes(packed.pack);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString packPath = dir.filePath(QFileInfo(file).completeBaseName() + ".rlesson");
    QVERIFY(writeFile(packPath, bytes));

    // Read by the same loader as the folder lesson: the same lesson, scene for scene.
    const lessons::LessonLoadResult one = lessons::loadLessonFile(packPath, options);
    QVERIFY2(one.ok, qPrintable(one.error));
    QCOMPARE(one.lesson.title, folder.lesson.title);
    QCOMPARE(one.lesson.summary, folder.lesson.summary);
    QCOMPARE(one.lesson.goals, folder.lesson.goals);
    QCOMPARE(one.lesson.steps.size(), folder.lesson.steps.size());
    for (std::size_t i = 0; i < one.lesson.steps.size(); ++i) {
        const lessons::LessonStep& a = one.lesson.steps[i];
        const lessons::LessonStep& b = folder.lesson.steps[i];
        QCOMPARE(a.title, b.title);
        QCOMPARE(a.text, b.text);
        QCOMPARE(a.plots, b.plots);
        QCOMPARE(a.panels, b.panels);
        QCOMPARE(a.questions.size(), b.questions.size());
        for (std::size_t q = 0; q < a.questions.size(); ++q) { // a choice's options too
            QCOMPARE(a.questions[q].kind.index(), b.questions[q].kind.index());
            if (const auto* choice = a.questions[q].as<lessons::ChoiceQuestion>()) {
                QCOMPARE(choice->choices, choiceOf(b.questions[q]).choices);
                QCOMPARE(choice->answer, choiceOf(b.questions[q]).answer);
            }
        }
        QCOMPARE(a.exportTime, b.exportTime);
        const QString difference = lessons::sceneDifference(a.scene, b.scene);
        QVERIFY2(difference.isEmpty(),
                 qPrintable(QStringLiteral("step %1: %2").arg(i + 1).arg(difference)));
    }
    QCOMPARE(one.warnings.size(), folder.warnings.size());

    // Unpacked into a folder of its own and packed again: the same bytes.
    QStringList written;
    const QString unpackDir = dir.filePath(QStringLiteral("unpacked"));
    const QString error =
        lessons::unpackLesson(packed.pack, unpackDir, QFileInfo(file).completeBaseName(), written);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QCOMPARE(written.size(), static_cast<qsizetype>(packed.pack.scenes.size()) + 1);
    const lessons::LessonPackResult again = lessons::packLesson(written.back());
    QVERIFY2(again.ok, qPrintable(again.error));
    QCOMPARE(lessons::lessonPackBytes(again.pack), bytes);
    // A .rlesson packed again (what Save does to an opened one): the same bytes.
    const lessons::LessonPackResult resaved = lessons::packLesson(packPath);
    QVERIFY2(resaved.ok, qPrintable(resaved.error));
    QCOMPARE(lessons::lessonPackBytes(resaved.pack), bytes);
}

void TestLessonPack::infoRoundTrips()
{
    const lessons::LessonPackInfo info{QStringLiteral("Jana Nováková"),
                                       QStringLiteral("2026-12-03")};
    const lessons::LessonPackResult packed =
        lessons::packLesson(QDir(kLessonsDir).filePath(QStringLiteral("stacks.json")), info);
    QVERIFY2(packed.ok, qPrintable(packed.error));
    const lessons::LessonPackResult read =
        lessons::readLessonPack(lessons::lessonPackBytes(packed.pack), QStringLiteral("x.rlesson"));
    QVERIFY2(read.ok, qPrintable(read.error));
    QCOMPARE(read.pack.info.author, info.author);
    QCOMPARE(read.pack.info.date, info.date);
    QCOMPARE(read.pack.scenes.size(), packed.pack.scenes.size());
}

void TestLessonPack::refusesDamaged_data()
{
    using Damage = std::function<QByteArray(QJsonObject)>;
    QTest::addColumn<Damage>("damage");
    QTest::addColumn<QString>("expected"); ///< what the one line holds after "FILE: "
    const auto json = [](const QJsonObject& o) { return QJsonDocument(o).toJson(); };
    QTest::newRow("truncated") << Damage([&](QJsonObject o) { return json(o).left(2000); })
                               << QStringLiteral("line ");
    QTest::newRow("empty") << Damage([](QJsonObject) { return QByteArray(); })
                           << QStringLiteral("line 1");
    QTest::newRow("an array") << Damage([](QJsonObject) { return QByteArray("[1]"); })
                              << QStringLiteral("the top level must be an object");
    QTest::newRow("wrong version") << Damage([&](QJsonObject o) {
        o.insert(QStringLiteral("rigidlab-lesson-file"), 2);
        return json(o);
    }) << QStringLiteral("rigidlab-lesson-file: unsupported format version 2");
    QTest::newRow("no version") << Damage([&](QJsonObject o) {
        o.remove(QStringLiteral("rigidlab-lesson-file"));
        return json(o);
    }) << QStringLiteral("rigidlab-lesson-file: missing");
    QTest::newRow("unknown key") << Damage([&](QJsonObject o) {
        o.insert(QStringLiteral("images"), QJsonObject());
        return json(o);
    }) << QStringLiteral("images");
    QTest::newRow("no lesson") << Damage([&](QJsonObject o) {
        o.remove(QStringLiteral("lesson"));
        return json(o);
    }) << QStringLiteral("lesson: required, but missing");
    QTest::newRow("missing scene") << Damage([&](QJsonObject o) {
        QJsonObject scenes = o.value(u"scenes").toObject();
        scenes.remove(QStringLiteral("scenes/two_balls.json"));
        o.insert(QStringLiteral("scenes"), scenes);
        return json(o);
    }) << QStringLiteral("lesson.steps[1].scene: \"scenes/two_balls.json\" is not among");
    QTest::newRow("bad number in a scene") << Damage([&](QJsonObject o) {
        QJsonObject scenes = o.value(u"scenes").toObject();
        QJsonObject scene = scenes.value(u"scenes/four_balls.json").toObject();
        QJsonArray bodies = scene.value(u"bodies").toArray();
        QJsonObject body = bodies[0].toObject();
        body.insert(QStringLiteral("mass"), -1);
        bodies[0] = body;
        scene.insert(QStringLiteral("bodies"), bodies);
        scenes.insert(QStringLiteral("scenes/four_balls.json"), scene);
        o.insert(QStringLiteral("scenes"), scenes);
        return json(o);
    }) << QStringLiteral("scenes[\"scenes/four_balls.json\"].bodies[0].mass: must be a positive");
    QTest::newRow("bad number in the lesson") << Damage([&](QJsonObject o) {
        QJsonObject lesson = o.value(u"lesson").toObject();
        lesson.insert(QStringLiteral("minutes"), 1e9);
        o.insert(QStringLiteral("lesson"), lesson);
        return json(o);
    }) << QStringLiteral("lesson.minutes");
    QTest::newRow("huge number") << Damage([&](QJsonObject o) {
        QByteArray bytes = json(o);
        bytes.replace("\"restitution\": 0.8", "\"restitution\": 1e999");
        return bytes;
    }) << QStringLiteral("line ");
    QTest::newRow("a scene name leaving its folder") << Damage([&](QJsonObject o) {
        QJsonObject scenes = o.value(u"scenes").toObject();
        scenes.insert(QStringLiteral("scenes/../../x.json"), QJsonObject());
        o.insert(QStringLiteral("scenes"), scenes);
        return json(o);
    }) << QStringLiteral("scenes: \"scenes/../../x.json\" is not a scene's name");
    QTest::newRow("a scene not an object") << Damage([&](QJsonObject o) {
        QJsonObject scenes = o.value(u"scenes").toObject();
        scenes.insert(QStringLiteral("scenes/two_balls.json"), 3);
        o.insert(QStringLiteral("scenes"), scenes);
        return json(o);
    }) << QStringLiteral("scenes[\"scenes/two_balls.json\"]: ");
    QTest::newRow("author of two lines") << Damage([&](QJsonObject o) {
        o.insert(QStringLiteral("author"), QStringLiteral("a\nb"));
        return json(o);
    }) << QStringLiteral("author: must be one line");
    QTest::newRow("bad date") << Damage([&](QJsonObject o) {
        o.insert(QStringLiteral("date"), QStringLiteral("2026-13-40"));
        return json(o);
    }) << QStringLiteral("date: must be a date written YYYY-MM-DD");
}

void TestLessonPack::refusesDamaged()
{
    QFETCH(std::function<QByteArray(QJsonObject)>, damage);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("damaged.rlesson"));
    QVERIFY(writeFile(path, damage(packedRestitution())));
    const lessons::LessonLoadResult r = lessons::loadLessonFile(path);
    QVERIFY(!r.ok);
    QVERIFY2(
        r.error.startsWith(path + QStringLiteral(": ") + expected),
        qPrintable(QStringLiteral("got: %1\nexpected: %2: %3...").arg(r.error, path, expected)));
    QVERIFY2(!r.error.contains(u'\n'), qPrintable(r.error));
}

void TestLessonPack::refusesSceneNameWithLineBreak()
{
    // A pattern's $ also matches before a final line break: a key "scenes/x.json\n" passed
    // validate, and unpack wrote a file name with a line break that pack then refused.
    QJsonObject o = packedRestitution();
    QJsonObject scenes = o.value(u"scenes").toObject();
    scenes.insert(QStringLiteral("scenes/x.json\n"), QJsonObject());
    o.insert(QStringLiteral("scenes"), scenes);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("newline.rlesson"));
    QVERIFY(writeFile(path, QJsonDocument(o).toJson()));
    const lessons::LessonLoadResult r = lessons::loadLessonFile(path);
    QVERIFY(!r.ok);
    QCOMPARE(r.error.section(QStringLiteral(" (scenes/NAME.json"), 0, 0),
             path + QStringLiteral(": scenes: \"scenes/x.json\\n\" is not a scene's name in a "
                                   "lesson file"));
}

void TestLessonPack::readsNoSceneFromDisk()
{
    // A scene path that a folder lesson beside the shipped scenes could read is refused in a
    // .rlesson: what it plays is only what it carries.
    QJsonObject o = packedRestitution();
    QJsonObject lesson = o.value(u"lesson").toObject();
    QJsonArray steps = lesson.value(u"steps").toArray();
    QJsonObject step = steps[0].toObject();
    step.insert(QStringLiteral("scene"), QStringLiteral("../scenes/welcome.json"));
    steps[0] = step;
    lesson.insert(QStringLiteral("steps"), steps);
    o.insert(QStringLiteral("lesson"), lesson);
    const QString path = QDir(kLessonsDir).filePath(QStringLiteral("not-written.rlesson"));
    const lessons::LessonLoadResult r = lessons::loadLessonJson(QJsonDocument(o).toJson(), path);
    QVERIFY(!r.ok);
    QVERIFY2(r.error.startsWith(path + QStringLiteral(": lesson.steps[0].scene: "
                                                      "\"../scenes/welcome.json\" is not among")),
             qPrintable(r.error));
}

void TestLessonPack::listedWithAuthorAndDate()
{
    // One in the user's own lessons folder, one in a folder added (a shared drive): both
    // listed after the shipped ones, with the author and date their files give.
    const std::size_t shipped = lessons::shippedLessonsInOrder().size();
    const QString own = lessons::userLessonsDir();
    QVERIFY(QDir().mkpath(own));
    QTemporaryDir shared;
    QVERIFY(shared.isValid());
    const auto packInto = [](const QString& folder, const QString& author) {
        const lessons::LessonPackResult packed =
            lessons::packLesson(QDir(kLessonsDir).filePath(QStringLiteral("restitution.json")),
                                {author, QStringLiteral("2026-11-30")});
        return packed.ok &&
               writeFile(QDir(folder).filePath(author.left(1) + QStringLiteral(".rlesson")),
                         lessons::lessonPackBytes(packed.pack));
    };
    QVERIFY(packInto(own, QStringLiteral("Jana")));
    QVERIFY(packInto(shared.path(), QStringLiteral("Petr")));
    QCOMPARE(lessons::allLessonsInOrder().size(), shipped + 1);
    QVERIFY(lessons::addLessonFolder(shared.path()));
    QVERIFY(!lessons::addLessonFolder(shared.path()));
    const std::vector<lessons::LessonEntry> all = lessons::allLessonsInOrder();
    QCOMPARE(all.size(), shipped + 2);
    QCOMPARE(all[shipped].author, QStringLiteral("Jana"));
    QCOMPARE(all[shipped + 1].author, QStringLiteral("Petr"));
    QVERIFY(all[shipped + 1].own);
    QCOMPARE(all[shipped + 1].date, QStringLiteral("2026-11-30"));
    QVERIFY2(lessons::lessonMenuText(all[shipped + 1], 9)
                 .endsWith(QStringLiteral("(your own: Petr, 2026-11-30)")),
             qPrintable(lessons::lessonMenuText(all[shipped + 1], 9)));
    QVERIFY(lessons::removeLessonFolder(shared.path()));
    QCOMPARE(lessons::allLessonsInOrder().size(), shipped + 1);
    QVERIFY(QFile::remove(QDir(own).filePath(QStringLiteral("J.rlesson"))));
}

void TestLessonPack::cliPacksValidatesExports_data()
{
    QTest::addColumn<QString>("file");
    for (const QString& file : shippedLessons())
        QTest::newRow(qPrintable(file)) << file;
}

void TestLessonPack::cliPacksValidatesExports()
{
    QFETCH(QString, file);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString lesson = QDir(kLessonsDir).filePath(file);
    const QString pack = dir.filePath(QFileInfo(file).completeBaseName() + ".rlesson");
    Run run = runCli(
        {QStringLiteral("lesson"), QStringLiteral("pack"), lesson, QStringLiteral("-o"), pack});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QVERIFY(run.out.startsWith("wrote "));

    run = runCli({QStringLiteral("lesson"), pack, QStringLiteral("--validate")});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QVERIFY2(run.out.startsWith("ok: "), run.out.constData());
    run = runCli({QStringLiteral("validate"), pack});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QVERIFY2(run.out.contains("scenes inside") || run.out.contains("scene inside"),
             run.out.constData());

    // The same plot files, with the same names and the same CSV tables, as from the folder.
    const QString fromFolder = dir.filePath(QStringLiteral("folder"));
    const QString fromPack = dir.filePath(QStringLiteral("pack"));
    run = runCli({QStringLiteral("lesson"), lesson, QStringLiteral("--export"), fromFolder});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    run = runCli({QStringLiteral("lesson"), pack, QStringLiteral("--export"), fromPack});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    const QStringList folderFiles = filesUnder(fromFolder);
    QCOMPARE(filesUnder(fromPack), folderFiles);
    for (const QString& f : folderFiles) {
        if (!f.endsWith(QStringLiteral(".csv")))
            continue;
        QFile a(QDir(fromFolder).filePath(f));
        QFile b(QDir(fromPack).filePath(f));
        QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
        QVERIFY2(a.readAll() == b.readAll(), qPrintable(f));
    }

    // Unpacked and packed again: the same bytes.
    const QString unpacked = dir.filePath(QStringLiteral("unpacked"));
    run = runCli(
        {QStringLiteral("lesson"), QStringLiteral("unpack"), pack, QStringLiteral("-o"), unpacked});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    const QString again = dir.filePath(QStringLiteral("again.rlesson"));
    run = runCli({QStringLiteral("lesson"), QStringLiteral("pack"),
                  QDir(unpacked).filePath(QFileInfo(file).completeBaseName() + ".json"),
                  QStringLiteral("-o"), again});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QFile a(pack);
    QFile b(again);
    QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
    QCOMPARE(b.readAll(), a.readAll());
}

void TestLessonPack::cliRefusals()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString lesson = QDir(kLessonsDir).filePath(QStringLiteral("stacks.json"));
    // -o must name a .rlesson, and nothing is written otherwise.
    const QString wrong = dir.filePath(QStringLiteral("out.json"));
    Run run = runCli(
        {QStringLiteral("lesson"), QStringLiteral("pack"), lesson, QStringLiteral("-o"), wrong});
    QVERIFY(run.exitCode != 0);
    QVERIFY2(run.err.contains("does not end in .rlesson"), run.err.constData());
    QVERIFY(!QFile::exists(wrong));
    // A damaged pack: one line naming file and place, exit code not 0, nothing unpacked.
    const QString damaged = dir.filePath(QStringLiteral("damaged.rlesson"));
    QVERIFY(writeFile(damaged, QJsonDocument(packedRestitution()).toJson().left(1500)));
    run = runCli({QStringLiteral("lesson"), damaged, QStringLiteral("--validate")});
    QVERIFY(run.exitCode != 0);
    QVERIFY2(run.err.contains(damaged.toUtf8() + ": line "), run.err.constData());
    const QString out = dir.filePath(QStringLiteral("out"));
    run = runCli(
        {QStringLiteral("lesson"), QStringLiteral("unpack"), damaged, QStringLiteral("-o"), out});
    QVERIFY(run.exitCode != 0);
    QVERIFY(!QFileInfo::exists(out));
}

RIGIDLAB_TEST_GUILESS_MAIN(TestLessonPack)
#include "test_lesson_pack.moc"

void TestLessonPack::cliOneLanguageLessons_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("missing"); // the warning's line
    QTest::newRow("czech-only") << QStringLiteral("czech_only.rlesson")
                                << QStringLiteral("no English text (\"en\") in the whole lesson: "
                                                  "it will show in Czech");
    QTest::newRow("english-only") << QStringLiteral("english_only.rlesson")
                                  << QStringLiteral("no Czech text (\"cs\") in the whole lesson: "
                                                    "it will show in English");
}

void TestLessonPack::cliOneLanguageLessons()
{
    // A hand-made lesson in one language validates (exit 0) with one warning saying so, in
    // either --lang, and exports its plots.
    QFETCH(QString, file);
    QFETCH(QString, missing);
    const QString path = rigidlab::test::sourcePath(u"/tests/lessons/data/one_language/") + file;
    const QByteArray warning = missing.toUtf8();
    for (const QString& lang : {QStringLiteral("cs"), QStringLiteral("en")}) {
        const Run run = runCli({QStringLiteral("lesson"), path, QStringLiteral("--validate"),
                                QStringLiteral("--lang"), lang});
        QVERIFY2(run.exitCode == 0, (run.out + run.err).constData());
        QVERIFY2(run.out.startsWith("ok: "), run.out.constData());
        QVERIFY2(run.out.endsWith(", 1 step\n"), run.out.constData()); // not "1 steps"
        QVERIFY2((run.out + run.err).contains(warning), (run.out + run.err).constData());
    }
    QTemporaryDir dir;
    const Run exported =
        runCli({QStringLiteral("lesson"), path, QStringLiteral("--export"), dir.path()});
    QVERIFY2(exported.exitCode == 0, (exported.out + exported.err).constData());
    const QStringList steps = QDir(dir.path()).entryList(QDir::Dirs | QDir::NoDotAndDotDot);
    QCOMPARE(steps.size(), 1);
    for (const char* name : {"energy.png", "energy.pdf", "energy.svg", "energy.csv"})
        QVERIFY2(QFileInfo(QDir(dir.filePath(steps.front())).filePath(QLatin1String(name))).size() >
                     0,
                 name);
}
