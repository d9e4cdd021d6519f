// SPDX-License-Identifier: GPL-3.0-or-later
// The scene editor's files: the window's document, New, Save, Save As, unsaved
// changes asked about, Run and Reset from the scene as edited, undo and redo from the Edit menu.
// The dialogs are answered through the window's askers, so no dialog opens.

#include "build_paths.h"
#include "common/shortcuts.h"
#include "editor/edit_tools.h"
#include "editor/scene_document.h"
#include "lesson_player/lesson_player.h"
#include "simulation/simulation_controller.h"
#include "view/body_item.h"
#include "view/world_view.h"
#include "window/language_switch.h"
#include "window/main_window.h"

#include "format/data_dirs.h"
#include "format/scene_compare.h"
#include "format/scene_loader.h"
#include "format/scene_writer.h"

#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QMenu>
#include <QMessageBox>
#include <QPointer>
#include <QTemporaryDir>
#include <QToolBar>
#include <QUndoStack>
#include <QtTest>

#include "test_files.h"
#include "test_main.h"

using namespace rigidlab;
using rigidlab::ui::MainWindow;

using rigidlab::test::readAll;

namespace {

QString shippedScene(const char* name)
{
    return QDir(MainWindow::scenesFolder()).filePath(QLatin1String(name));
}

/// The index of the first dynamic body.
std::size_t firstDynamic(const lessons::Scene& scene)
{
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
        if (scene.bodies[i].type == physics::BodyType::Dynamic)
            return i;
    return scene.bodies.size();
}

/// An edit through the document, as the editor's tools make them: body `i` moved by `by`.
lessons::Scene moveBody(MainWindow& w, std::size_t i, const physics::Vec2& by)
{
    lessons::Scene edited = w.document()->scene();
    edited.bodies[i].position += by;
    w.document()->apply(QStringLiteral("Move"), edited);
    return edited;
}

physics::Vec2 originOf(MainWindow& w, std::size_t i)
{
    return w.controller().world().bodies()[i].origin();
}

} // namespace

class TestEditorFiles : public QObject {
    Q_OBJECT

private slots:
    void cleanup()
    {
        // The user's scenes folder lives in this run's $HOME; each test starts without it.
        QDir(lessons::userDataDir()).removeRecursively();
    }

    // Found by hand: a window closed in Edit mode came back with the editor's tools and docks
    // showing outside it (its saved layout restored them).
    void editorPanelsOnlyInEditMode()
    {
        {
            MainWindow w;
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QVERIFY(w.newScene()); // a new scene opens in Edit mode
            QVERIFY(w.editTools().editing());
            QVERIFY(w.findChild<QToolBar*>(QStringLiteral("editToolbar"))->isVisible());
            QVERIFY(w.findChild<QDockWidget*>(QStringLiteral("historyDock"))->isVisible());
            QVERIFY(w.close()); // its layout is saved as it is
        }
        MainWindow again;
        again.show();
        QVERIFY(QTest::qWaitForWindowExposed(&again));
        QVERIFY(!again.editTools().editing());
        QVERIFY(!again.findChild<QToolBar*>(QStringLiteral("editToolbar"))->isVisible());
        for (const char* dock : {"propertiesDock", "historyDock"})
            QVERIFY2(!again.findChild<QDockWidget*>(QLatin1String(dock))->isVisible(), dock);
        again.editTools().editAction()->trigger();
        QVERIFY(again.findChild<QToolBar*>(QStringLiteral("editToolbar"))->isVisible());
        again.editTools().editAction()->trigger();
    }

    // Found by hand: saved into one's own folder, quit, started again (the welcome scene opens
    // from the shipped folder), and Open started among the shipped scenes.
    void openStartsWhereOwnScenesWere()
    {
        QTemporaryDir dir;
        const QString own = QFileInfo(dir.path()).absoluteFilePath();
        {
            MainWindow w;
            QCOMPARE(w.openScene(shippedScene("ball_drop.json"), true), QString());
            w.setSavePathAsker(
                [&](const QString&) { return dir.filePath(QStringLiteral("mine.json")); });
            QVERIFY(w.saveSceneAs());
            QCOMPARE(w.lastFolder(), own);
        }
        MainWindow again;
        QCOMPARE(again.lastFolder(), own);
        QCOMPARE(again.openScene(shippedScene("welcome.json"), true), QString());
        QCOMPARE(again.lastFolder(), own);
        // A scene opened from another folder of one's own moves it there.
        QTemporaryDir other;
        const QString copy = other.filePath(QStringLiteral("copy.json"));
        QVERIFY(QFile::copy(dir.filePath(QStringLiteral("mine.json")), copy));
        QCOMPARE(again.openScene(copy, true), QString());
        QCOMPARE(again.lastFolder(), QFileInfo(other.path()).absoluteFilePath());
    }

    void openingSetsTheDocument()
    {
        MainWindow w;
        const QString path = shippedScene("ball_drop.json");
        QCOMPARE(w.openScene(path, true), QString());
        QCOMPARE(w.document()->path(), path);
        const lessons::SceneLoadResult loaded = lessons::loadSceneFile(path);
        QVERIFY(loaded.ok);
        const QString difference = lessons::sceneDifference(w.document()->scene(), loaded.scene);
        QVERIFY2(difference.isEmpty(), qPrintable(difference));
        QVERIFY(!w.document()->isModified());
        QVERIFY(w.windowTitle().contains(QStringLiteral("ball_drop.json")));
        QVERIFY(w.windowTitle().contains(loaded.scene.title));
        QVERIFY(!w.isWindowModified());
    }

    void runAndResetFromTheSceneAsEdited()
    {
        MainWindow w;
        QCOMPARE(w.openScene(shippedScene("ball_drop.json"), true), QString());
        const std::size_t i = firstDynamic(w.document()->scene());
        QVERIFY(i < w.document()->scene().bodies.size());
        const physics::Vec2 opened = w.document()->scene().bodies[i].position;
        const physics::Vec2 by(0.25, 0.5);
        moveBody(w, i, by);
        // The world is rebuilt from the edit, paused at t = 0.
        QVERIFY(originOf(w, i) == physics::Vec2(opened + by));
        QCOMPARE(w.controller().world().stepCount(), 0LL);
        QVERIFY(w.document()->isModified());
        QVERIFY(w.isWindowModified()); // the "*" of the title
        for (int k = 0; k < 50; ++k)
            w.controller().stepForward();
        QVERIFY(originOf(w, i) != physics::Vec2(opened + by)); // it fell
        w.controller().reset();
        QVERIFY(originOf(w, i) == physics::Vec2(opened + by)); // back to the edit, not the file

        // Edit › Undo and Redo, on their keys.
        auto* undo = w.findChild<QAction*>(QStringLiteral("undo"));
        auto* redo = w.findChild<QAction*>(QStringLiteral("redo"));
        QVERIFY(undo && redo);
        QCOMPARE(undo->shortcut(), QKeySequence(QStringLiteral("Ctrl+Z")));
        QCOMPARE(redo->shortcut(), QKeySequence(QStringLiteral("Ctrl+Shift+Z")));
        auto* edit = w.findChild<QMenu*>(QStringLiteral("editMenu"));
        QVERIFY(edit && edit->actions().contains(undo) && edit->actions().contains(redo));
        QVERIFY(undo->isEnabled());
        undo->trigger();
        QVERIFY(originOf(w, i) == opened);
        QVERIFY(!w.document()->isModified());
        QVERIFY(!w.isWindowModified());
        redo->trigger();
        QVERIFY(originOf(w, i) == physics::Vec2(opened + by));
        QVERIFY(w.isWindowModified());
    }

    void saveAsAndReopen()
    {
        MainWindow w;
        const QString shipped = shippedScene("pendulum.json");
        const QByteArray shippedBytes = readAll(shipped);
        QCOMPARE(w.openScene(shipped, true), QString());
        lessons::Scene edited = moveBody(w, firstDynamic(w.document()->scene()), {0.1, -0.05});
        lessons::setSceneTitle(edited, QStringLiteral("My pendulum"));
        edited.colours.assign(edited.bodies.size(), QStringLiteral("#3060c0"));
        w.document()->apply(QStringLiteral("Properties"), edited);

        QTemporaryDir dir;
        const QString target = dir.filePath(QStringLiteral("my_pendulum.json"));
        QStringList suggested;
        w.setSavePathAsker([&](const QString& s) {
            suggested << s;
            return target;
        });
        // Save on a shipped scene: it is not overwritten, Save As asks where.
        auto* save = w.findChild<QAction*>(QStringLiteral("saveScene"));
        QVERIFY(save);
        QCOMPARE(save->shortcut(), QKeySequence(QStringLiteral("Ctrl+S")));
        save->trigger();
        QCOMPARE(suggested.size(), 1);
        QCOMPARE(QFileInfo(suggested[0]).absolutePath(),
                 QFileInfo(lessons::userScenesDir()).absoluteFilePath());
        QCOMPARE(QFileInfo(suggested[0]).fileName(), QStringLiteral("pendulum.json"));
        QCOMPARE(readAll(shipped), shippedBytes);
        QVERIFY(QFile::exists(target));
        QCOMPARE(w.document()->path(), target);
        QVERIFY(!w.document()->isModified());
        QVERIFY(!w.isWindowModified());
        QVERIFY2(w.windowTitle().contains(QStringLiteral("My pendulum (my_pendulum.json)")),
                 qPrintable(w.windowTitle()));

        // Saved again: to the same file, without asking.
        moveBody(w, firstDynamic(edited), {0.0, 0.01});
        edited = w.document()->scene();
        QVERIFY(w.saveScene());
        QCOMPARE(suggested.size(), 1);

        MainWindow again;
        QCOMPARE(again.openScene(target, true), QString());
        const QString difference = lessons::sceneDifference(again.document()->scene(), edited);
        QVERIFY2(difference.isEmpty(), qPrintable(difference));
    }

    void savedScenesListedAsYourOwn()
    {
        MainWindow w;
        QVERIFY(!w.findChild<QMenu*>(QStringLiteral("ownScenes")));
        QVERIFY(w.newScene());
        w.setSavePathAsker([](const QString& s) {
            return QFileInfo(s).absolutePath() + QStringLiteral("/ramp"); // no suffix given
        });
        auto* saveAs = w.findChild<QAction*>(QStringLiteral("saveSceneAs"));
        QVERIFY(saveAs);
        QCOMPARE(saveAs->shortcut(), QKeySequence(QStringLiteral("Ctrl+Shift+S")));
        saveAs->trigger();
        const QString path = QDir(lessons::userScenesDir()).filePath(QStringLiteral("ramp.json"));
        QVERIFY(QFile::exists(path));
        auto* own = w.findChild<QMenu*>(QStringLiteral("ownScenes"));
        QVERIFY(own);
        QCOMPARE(own->actions().size(), 1);
        QCOMPARE(own->actions().front()->text(), MainWindow::tr("New scene"));
    }

    void shippedSceneNeverOverwritten()
    {
        MainWindow w;
        const QString shipped = shippedScene("ball_drop.json");
        const QByteArray bytes = readAll(shipped);
        QCOMPARE(w.openScene(shipped, true), QString());
        moveBody(w, firstDynamic(w.document()->scene()), {0.5, 0});
        w.setSavePathAsker([&](const QString&) { return shipped; });
        QVERIFY(!w.saveSceneAs());
        QCOMPARE(readAll(shipped), bytes);
        QVERIFY2(w.lastError().contains(QStringLiteral("comes with RigidLab")),
                 qPrintable(w.lastError()));
        QVERIFY(w.document()->isModified());
        auto* box = w.findChild<QMessageBox*>(QStringLiteral("saveErrorBox"));
        QVERIFY(box);
        box->close();
    }

    void failedSaveSaysWhy()
    {
        MainWindow w;
        QVERIFY(w.newScene());
        QTemporaryDir dir;
        const QString target = dir.filePath(QStringLiteral("no/such/folder/x.json"));
        w.setSavePathAsker([&](const QString&) { return target; });
        QVERIFY(!w.saveScene());
        QVERIFY2(w.lastError().contains(target), qPrintable(w.lastError()));
        QVERIFY(w.document()->path().isEmpty());
        auto* box = w.findChild<QMessageBox*>(QStringLiteral("saveErrorBox"));
        QVERIFY(box);
        QVERIFY(box->text().contains(target));
        box->close();
    }

    void newSceneIsEmptyWithAGround()
    {
        MainWindow w;
        QCOMPARE(w.openScene(shippedScene("ball_drop.json"), true), QString());
        auto* newAction = w.findChild<QAction*>(QStringLiteral("newScene"));
        QVERIFY(newAction);
        QCOMPARE(newAction->shortcut(), QKeySequence(QStringLiteral("Ctrl+N")));
        newAction->trigger();
        const lessons::Scene& scene = w.document()->scene();
        QVERIFY(w.document()->path().isEmpty());
        QVERIFY(!w.document()->isModified());
        lessons::Scene defaults = scene;
        defaults.world = physics::WorldDef{};
        QCOMPARE(lessons::sceneDifference(scene, defaults), QString()); // the default world
        QCOMPARE(scene.bodies.size(), std::size_t{1});
        QCOMPARE(scene.bodies[0].type, physics::BodyType::Static);
        QVERIFY(scene.springs.empty() && scene.joints.empty());
        QCOMPARE(w.controller().world().bodies().size(), std::size_t{1});
        // Save on a new scene asks where, suggesting a name from its title.
        int asked = 0;
        QString suggested;
        w.setSavePathAsker([&](const QString& s) {
            ++asked;
            suggested = s;
            return QString(); // cancelled
        });
        QVERIFY(!w.saveScene());
        QCOMPARE(QFileInfo(suggested).fileName(), QStringLiteral("new_scene.json"));
        QCOMPARE(asked, 1);
    }

    void unsavedChangesAsked()
    {
        MainWindow w;
        w.show();
        QCOMPARE(w.openScene(shippedScene("ball_drop.json"), true), QString());
        const lessons::Scene edited = moveBody(w, firstDynamic(w.document()->scene()), {0.5, 0});
        int asked = 0;
        int answer = QMessageBox::Cancel;
        w.setUnsavedAsker([&] {
            ++asked;
            return answer;
        });
        const auto keptEdit = [&] {
            return w.document()->isModified() &&
                   lessons::sceneDifference(w.document()->scene(), edited).isEmpty() &&
                   w.controller().scene().title == edited.title;
        };
        // Cancel keeps the edited scene: opening another scene, a lesson, New, closing.
        QVERIFY(!w.openScene(shippedScene("two_balls.json"), true).isEmpty());
        QCOMPARE(asked, 1);
        QVERIFY(keptEdit());
        const QString lesson = w.lessonPlayer().firstLessonPath();
        QVERIFY(!lesson.isEmpty());
        QVERIFY(!w.openLesson(lesson, true).isEmpty());
        QCOMPARE(asked, 2);
        QVERIFY(!w.lessonPlayer().lesson());
        QVERIFY(keptEdit());
        QVERIFY(!w.newScene());
        QCOMPARE(asked, 3);
        QVERIFY(keptEdit());
        QVERIFY(!w.close());
        QCOMPARE(asked, 4);
        QVERIFY(w.isVisible());
        QVERIFY(keptEdit());

        // Save: written first (here to a file of one's own), then the other scene opens.
        QTemporaryDir dir;
        const QString target = dir.filePath(QStringLiteral("kept.json"));
        w.setSavePathAsker([&](const QString&) { return target; });
        answer = QMessageBox::Save;
        QCOMPARE(w.openScene(shippedScene("two_balls.json"), true), QString());
        QCOMPARE(asked, 5);
        const lessons::SceneLoadResult kept = lessons::loadSceneFile(target);
        QVERIFY2(kept.ok, qPrintable(kept.error));
        QCOMPARE(lessons::sceneDifference(kept.scene, edited), QString());
        QVERIFY(w.document()->path().endsWith(QStringLiteral("two_balls.json")));

        // Discard: the edit is dropped; an unmodified scene asks nothing.
        moveBody(w, firstDynamic(w.document()->scene()), {0.5, 0});
        answer = QMessageBox::Discard;
        QVERIFY(w.newScene());
        QCOMPARE(asked, 6);
        QVERIFY(!w.document()->isModified());
        QVERIFY(w.close());
        QCOMPARE(asked, 6);
    }

    void languageSwitchKeepsTheEdits()
    {
        auto* w = new MainWindow;
        const QString path = shippedScene("ball_drop.json");
        QCOMPARE(w->openScene(path, true), QString());
        const lessons::Scene edited = moveBody(*w, firstDynamic(w->document()->scene()), {0.3, 0});
        int asked = 0;
        w->setUnsavedAsker([&] {
            ++asked;
            return int(QMessageBox::Cancel);
        });
        QPointer<MainWindow> old = w;
        MainWindow* czech = ui::switchLanguage(w, QStringLiteral("cs"));
        QVERIFY(czech != w);
        QTRY_VERIFY(old.isNull());
        QCOMPARE(asked, 0); // nothing to ask: the edits go along
        QCOMPARE(lessons::sceneDifference(czech->document()->scene(), edited), QString());
        QVERIFY(czech->document()->isModified());
        QCOMPARE(czech->document()->path(), path);
        QVERIFY(czech->documentIsFile());
        // Undo leads back to the file as saved.
        czech->document()->undoStack()->undo();
        QVERIFY(!czech->document()->isModified());
        czech->document()->undoStack()->redo();
        old = czech;
        MainWindow* english = ui::switchLanguage(czech, QStringLiteral("en"));
        QTRY_VERIFY(old.isNull());
        QCOMPARE(lessons::sceneDifference(english->document()->scene(), edited), QString());
        english->document()->undoStack()->setClean();
        delete english;
    }

    void colourFromTheSceneIsDrawn()
    {
        MainWindow w;
        QCOMPARE(w.openScene(shippedScene("ball_drop.json"), true), QString());
        const std::size_t i = firstDynamic(w.document()->scene());
        const QColor before = w.view().itemFor(int(i))->fill();
        lessons::Scene edited = w.document()->scene();
        edited.colours.assign(edited.bodies.size(), QString());
        const QColor wanted(0x12, 0x9a, 0x3c);
        QVERIFY(before != wanted);
        edited.colours[i] = wanted.name(); // "#129a3c"
        w.document()->apply(QStringLiteral("Colour"), edited);
        QCOMPARE(w.view().itemFor(int(i))->fill(), wanted);
        w.document()->undoStack()->undo();
        QCOMPARE(w.view().itemFor(int(i))->fill(), before);
    }

    void lessonStepIsTheDocument()
    {
        MainWindow w;
        const QString lesson = w.lessonPlayer().firstLessonPath();
        QCOMPARE(w.openLesson(lesson, true), QString());
        const lessons::Lesson* opened = w.lessonPlayer().lesson();
        QVERIFY(opened);
        const lessons::Scene& step = opened->steps.front().scene;
        QCOMPARE(lessons::sceneDifference(w.document()->scene(), step), QString());
        QVERIFY(!w.document()->isModified());
        // Save in a lesson never writes over the lesson's files: it asks where.
        int asked = 0;
        w.setSavePathAsker([&](const QString&) {
            ++asked;
            return QString();
        });
        QVERIFY(!w.saveScene());
        QCOMPARE(asked, 1);
    }

    void editInALessonKeepsTheStepsWorlds()
    {
        // A step comparing integrators: an edit rebuilds every compared world from the edit,
        // with the step's settings, not a plain scene.
        MainWindow w;
        QCOMPARE(
            w.openLesson(rigidlab::test::sourcePath(u"/lessons/lessons/energy_drift.json"), true),
            QString());
        const lessons::Lesson* lesson = w.lessonPlayer().lesson();
        QVERIFY(lesson);
        int compared = -1;
        for (std::size_t k = 0; k < lesson->steps.size() && compared < 0; ++k)
            if (lesson->steps[k].compare && lesson->steps[k].compare->count() > 1)
                compared = int(k);
        QVERIFY(compared >= 0);
        w.lessonPlayer().goToStep(compared);
        const int variants = w.controller().variantCount();
        QCOMPARE(variants, lesson->steps[std::size_t(compared)].compare->count() - 1);
        const double dt = w.controller().world().def().dt;
        const std::size_t i = firstDynamic(w.document()->scene());
        QVERIFY(i < w.document()->scene().bodies.size());
        const physics::Vec2 by(0.0, 0.125);
        const physics::Vec2 moved = w.document()->scene().bodies[i].position + by;
        moveBody(w, i, by);
        QCOMPARE(w.controller().variantCount(), variants);
        QCOMPARE(w.controller().world().def().dt, dt); // the step's dt, not the scene's
        QVERIFY(w.controller().world().bodies()[i].origin() == moved);
        for (int v = 0; v < variants; ++v)
            QVERIFY(w.controller().variant(v).bodies()[i].origin() == moved);
        QVERIFY(w.lessonPlayer().lesson()); // still in the lesson
    }
};

RIGIDLAB_TEST_MAIN(TestEditorFiles)
#include "test_editor_files.moc"
