// SPDX-License-Identifier: GPL-3.0-or-later
// A lesson in one file (.rlesson) in the window: opened as a lesson (what File › Open, the
// command line and a double-click do), by drag and drop, refused with its place when damaged,
// and listed among the teacher's own lessons with its author and date.

#include "build_paths.h"
#include "lesson_player/lesson_player.h"
#include "test_files.h"
#include "window/main_window.h"
#include "window/window_drop.h"

#include "format/data_dirs.h"
#include "format/lesson.h"
#include "format/lesson_catalog.h"
#include "format/lesson_pack.h"
#include "format/scene_compare.h"

#include <QAction>
#include <QDir>
#include <QDropEvent>
#include <QMenu>
#include <QMimeData>
#include <QTemporaryDir>
#include <QUrl>
#include <QtTest>

#include "test_main.h"

using namespace rigidlab;
using rigidlab::test::writeFile;
using rigidlab::ui::MainWindow;

namespace {

const QString kLessonsDir = rigidlab::test::sourcePath(u"/lessons/lessons");

/// `lesson` (a shipped lesson's file name) packed into `folder`; its path.
QString packInto(const QString& folder, const QString& lesson,
                 const lessons::LessonPackInfo& info = {})
{
    const lessons::LessonPackResult packed =
        lessons::packLesson(QDir(kLessonsDir).filePath(lesson), info);
    if (!packed.ok)
        return {};
    const QString path = QDir(folder).filePath(QFileInfo(lesson).completeBaseName() + ".rlesson");
    return writeFile(path, lessons::lessonPackBytes(packed.pack)) ? path : QString();
}

QMimeData* filesData(const QStringList& paths)
{
    auto* data = new QMimeData;
    QList<QUrl> urls;
    for (const QString& p : paths)
        urls.append(QUrl::fromLocalFile(p));
    data->setUrls(urls);
    return data;
}

} // namespace

class TestLessonFileWindow : public QObject {
    Q_OBJECT
private slots:
    /// Opened as a lesson, it plays the same steps on the same scenes as its folder.
    void opensAsTheFolderLesson()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString pack = packInto(dir.path(), QStringLiteral("restitution.json"));
        QVERIFY(!pack.isEmpty());
        QVERIFY(lessons::isLessonDocument(pack));
        QVERIFY(lessons::isLessonDocument(QDir(kLessonsDir).filePath("restitution.json")));
        QVERIFY(!lessons::isLessonDocument(
            rigidlab::test::sourcePath(u"/lessons/scenes/welcome.json")));

        MainWindow w;
        w.show();
        QCOMPARE(w.openLesson(pack, true), QString());
        const lessons::Lesson* lesson = w.lessonPlayer().lesson();
        QVERIFY(lesson);
        const lessons::Lesson folder =
            lessons::loadLessonFile(QDir(kLessonsDir).filePath("restitution.json")).lesson;
        QCOMPARE(lesson->steps.size(), folder.steps.size());
        for (std::size_t i = 0; i < folder.steps.size(); ++i) {
            w.lessonPlayer().goToStep(static_cast<int>(i));
            QCOMPARE(w.lessonPlayer().stepIndex(), static_cast<int>(i));
            const QString difference =
                lessons::sceneDifference(lesson->steps[i].scene, folder.steps[i].scene);
            QVERIFY2(difference.isEmpty(), qPrintable(difference));
        }
    }

    /// A damaged file is refused with its place; the window keeps what it had.
    void damagedIsRefused()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString bad = dir.filePath(QStringLiteral("bad.rlesson"));
        QVERIFY(writeFile(bad, "{\"rigidlab-lesson-file\": 7, \"lesson\": {}}"));
        MainWindow w;
        w.show();
        const QString error = w.openLesson(bad, true);
        QVERIFY2(error.startsWith(bad + QStringLiteral(": rigidlab-lesson-file: ")),
                 qPrintable(error));
        QVERIFY(!w.lessonPlayer().lesson());
    }

    /// A .rlesson or a .json dropped on the window opens; other drops are not taken.
    void dropOpensIt()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString pack = packInto(dir.path(), QStringLiteral("stacks.json"));
        QVERIFY(!pack.isEmpty());
        QCOMPARE(ui::WindowDrop::droppedFile(std::unique_ptr<QMimeData>(filesData({pack})).get()),
                 pack);
        QCOMPARE(
            ui::WindowDrop::droppedFile(std::unique_ptr<QMimeData>(filesData({pack, pack})).get()),
            QString());
        QCOMPARE(ui::WindowDrop::droppedFile(
                     std::unique_ptr<QMimeData>(filesData({dir.filePath("a.png")})).get()),
                 QString());

        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.acceptDrops());
        const std::unique_ptr<QMimeData> data(filesData({pack}));
        const QPoint at = w.rect().center();
        QDragEnterEvent enter(at, Qt::CopyAction, data.get(), Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&w, &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(at, Qt::CopyAction, data.get(), Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&w, &drop);
        QVERIFY(drop.isAccepted());
        QTRY_VERIFY(w.lessonPlayer().lesson() != nullptr);
        QCOMPARE(w.lessonPlayer().lesson()->path, QFileInfo(pack).absoluteFilePath());
    }

    /// A teacher's .rlesson in her lessons folder is listed after the shipped ones, with its
    /// author and date.
    void listedAsOwn()
    {
        QVERIFY(QDir().mkpath(lessons::userLessonsDir()));
        const QString pack = packInto(lessons::userLessonsDir(), QStringLiteral("stacks.json"),
                                      {QStringLiteral("Jana"), QStringLiteral("2026-12-01")});
        QVERIFY(!pack.isEmpty());
        MainWindow w;
        const QStringList paths = w.lessonPlayer().lessonPaths();
        const qsizetype at = paths.indexOf(QFileInfo(pack).absoluteFilePath());
        QVERIFY2(at >= 0, qPrintable(paths.join(u'\n')));
        QCOMPARE(at, paths.size() - 1);
        QVERIFY2(
            w.lessonPlayer().lessonMenuTexts()[at].contains(QStringLiteral("Jana, 2026-12-01")),
            qPrintable(w.lessonPlayer().lessonMenuTexts()[at]));
        QVERIFY(QFile::remove(pack));
    }

    /// A folder added (a shared drive) lists its lessons after the user's own; the Lessons
    /// menu offers to add one, and lists what is added while the window is open.
    void addedFolderListed()
    {
        QTemporaryDir shared;
        QVERIFY(shared.isValid());
        const QString pack = packInto(shared.path(), QStringLiteral("restitution.json"),
                                      {QStringLiteral("Petr"), QString()});
        QVERIFY(!pack.isEmpty());
        MainWindow w;
        const QStringList before = w.lessonPlayer().lessonPaths();
        QVERIFY(!before.contains(QFileInfo(pack).absoluteFilePath()));
        QAction* add = w.findChild<QAction*>(QStringLiteral("addLessonFolder"));
        QVERIFY(add);
        QVERIFY(lessons::addLessonFolder(shared.path()));
        MainWindow again;
        const QStringList after = again.lessonPlayer().lessonPaths();
        QCOMPARE(after.size(), before.size() + 1);
        QCOMPARE(after.back(), QFileInfo(pack).absoluteFilePath());
        // No date in the file: the file's own.
        QVERIFY2(again.lessonPlayer().lessonMenuTexts().back().contains(
                     QStringLiteral("(your own: Petr, %1)")
                         .arg(QFileInfo(pack).lastModified().date().toString(Qt::ISODate))),
                 qPrintable(again.lessonPlayer().lessonMenuTexts().back()));
        // File › Lessons › Stop listing a folder: its lessons leave the list, its files stay.
        auto* lessonsMenu = again.findChild<QMenu*>(QStringLiteral("lessonsMenu"));
        QVERIFY(lessonsMenu);
        emit lessonsMenu->aboutToShow();
        auto* stop = lessonsMenu->findChild<QMenu*>(QStringLiteral("stopListingFolder"));
        QVERIFY(stop);
        QAction* entry = nullptr;
        for (QAction* a : stop->actions())
            if (a->text() ==
                QDir::toNativeSeparators(shared.path()).replace(u'&', QStringLiteral("&&")))
                entry = a;
        QVERIFY2(entry, qPrintable(shared.path()));
        entry->trigger();
        QVERIFY(!lessons::addedLessonFolders().contains(shared.path()));
        QCOMPARE(again.lessonPlayer().lessonPaths(), before);
        QVERIFY(QFile::exists(pack));
        emit lessonsMenu->aboutToShow(); // nothing added: no such entry
        QVERIFY(lessonsMenu->findChild<QMenu*>(QStringLiteral("stopListingFolder")) == nullptr);
    }
};

RIGIDLAB_TEST_MAIN(TestLessonFileWindow)
#include "test_lesson_file_window.moc"
