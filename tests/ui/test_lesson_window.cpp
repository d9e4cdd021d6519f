// SPDX-License-Identifier: GPL-3.0-or-later
// Lessons in the window: every shipped lesson opens, its steps go forward and back, each
// step shows only the panels and plots it names, questions are judged, plots export.

#include "editor/edit_tools.h"
#include "lesson_player/lesson_panels.h"
#include "lesson_player/lesson_player.h"
#include "panels/sat_panel.h"
#include "plots/plot_widget.h"
#include "shipped_lessons.h"
#include "simulation/simulation_controller.h"
#include "test_files.h"
#include "view/body_item.h"
#include "view/world_view.h"
#include "window/main_window.h"

#include "format/data_dirs.h"
#include "format/lesson.h"
#include "run/measurements.h"

#include <QDockWidget>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QMenu>
#include <QSet>
#include <QSettings>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>

#include "question_kinds.h"
#include "test_main.h"

using rigidlab::test::measuredOf;

using namespace rigidlab;
using rigidlab::test::shippedLessons;
using rigidlab::test::writeFile;
using rigidlab::ui::MainWindow;

namespace {

const QStringList kDockNames{QStringLiteral("controls"), QStringLiteral("inspector"),
                             QStringLiteral("energy"),   QStringLiteral("momentum"),
                             QStringLiteral("drift"),    QStringLiteral("sat"),
                             QStringLiteral("bounces"),  QStringLiteral("collision")};

void writeTo(const QString& path, const QByteArray& bytes)
{
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    QCOMPARE(file.write(bytes), bytes.size());
}

/// The window as a 1024×768 projector shows it, with a shipped lesson open.
void openOnProjector(MainWindow& w, const QString& lesson)
{
    w.fitToScreen(QRect(0, 0, 1024, 768));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QCOMPARE(w.openLesson(QDir(MainWindow::lessonsFolder()).filePath(lesson), true), QString());
}

} // namespace

class TestLessonWindow : public QObject {
    Q_OBJECT
private slots:
    /// The window's Export plots writes what `rigidlab-cli lesson --export` writes for a step
    /// (test_lesson_export checks the CLI's side): the plots the step names, each as PNG, PDF,
    /// SVG and CSV, and nothing else.
    void windowExportsTheStepsOwnPlots()
    {
        MainWindow w;
        w.show();
        int steps = 0;
        rigidlab::test::StepWalk walk;
        for (const QString& path : shippedLessons()) {
            QCOMPARE(w.openLesson(path, true), QString());
            const lessons::Lesson& lesson = *w.lessonPlayer().lesson();
            for (int i = 0; i < static_cast<int>(lesson.steps.size()); ++i) {
                if (!walk.visits(lesson.steps[static_cast<size_t>(i)], i))
                    continue;
                ++steps;
                w.lessonPlayer().goToStep(i);
                for (int k = 0; k < 20; ++k)
                    w.controller().stepForward();
                QTemporaryDir dir;
                QVERIFY(dir.isValid());
                QCOMPARE(w.exportStepPlots(dir.path()), QStringList());
                QStringList expected;
                for (const QString& name : lesson.steps[static_cast<size_t>(i)].plots)
                    for (const char* suffix : {".csv", ".pdf", ".png", ".svg"})
                        expected << name + QLatin1String(suffix);
                expected.sort();
                QStringList written = QDir(dir.path()).entryList(QDir::Files | QDir::Hidden);
                written.sort();
                QVERIFY2(written == expected,
                         qPrintable(QStringLiteral("%1 step %2: wrote %3, the step names %4")
                                        .arg(QFileInfo(path).baseName())
                                        .arg(i + 1)
                                        .arg(written.join(u' '), expected.join(u' '))));
            }
        }
        QVERIFY2(steps >= rigidlab::test::atLeast(20, 18), qPrintable(QString::number(steps)));
    }

    /// A step shows its event: it opens paused (the class reads and predicts first), and
    /// once started, at the step's export time, every moving body of every world it runs is
    /// drawn inside the view, at the classroom's 1024×768.
    void everyStepHoldsItsRunAndKeepsItsBodiesInSight()
    {
        MainWindow w;
        w.fitToScreen(QRect(0, 0, 1024, 768));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        int steps = 0;
        QStringList outside; // every body out of sight, of every step, said at the end
        rigidlab::test::visitShippedSteps(w, [&](const QString& path, int index,
                                                 const lessons::LessonStep& step) {
            ++steps;
            const QString where =
                QStringLiteral("%1 step %2").arg(QFileInfo(path).baseName()).arg(index + 1);
            QVERIFY2(!w.controller().isRunning(),
                     qPrintable(where + QStringLiteral(" runs at once")));
            QCOMPARE(w.controller().world().time(), 0.0);
            // Started as the student starts it: the questions that hold the run answered,
            // the editor left, then the steps taken one by one.
            for (int q = 0; q < static_cast<int>(step.questions.size()); ++q)
                if (w.lessonPlayer().heldBack().contains(QStringLiteral("run")))
                    w.lessonPlayer().showMe(q);
            if (step.editor)
                w.editTools().setEditing(false);
            QVERIFY2(!w.lessonPlayer().heldBack().contains(QStringLiteral("run")),
                     qPrintable(where));
            while (w.controller().world().time() < step.exportTime - 1e-9)
                w.controller().stepForward();
            QCoreApplication::processEvents();
            ui::WorldView& view = w.view();
            const QRectF shown = view.mapToScene(view.viewport()->rect()).boundingRect();
            std::vector<std::pair<QString, const ui::BodyItem*>> items;
            const physics::World& world = w.controller().world();
            for (int b = 0; b < static_cast<int>(world.bodies().size()); ++b)
                if (world.body(b).moves())
                    items.emplace_back(QStringLiteral("body %1").arg(b), view.itemFor(b));
            for (int v = 0; v < w.controller().variantCount(); ++v)
                for (const ui::BodyItem* item : view.ghostItems(v))
                    items.emplace_back(QStringLiteral("world %1").arg(v + 2), item);
            QVERIFY2(!items.empty(), qPrintable(where + QStringLiteral(": nothing moves")));
            for (const auto& [name, item] : items) {
                QVERIFY(item);
                const QRectF drawn = item->sceneBox();
                if (!shown.contains(drawn))
                    outside << (QStringLiteral("%1 at t = %2 s: %3 drawn at (%4, %5)–(%6, %7) m, "
                                               "the view shows (%8, %9)–(%10, %11) m")
                                    .arg(where)
                                    .arg(w.controller().world().time())
                                    .arg(name)
                                    .arg(drawn.left())
                                    .arg(drawn.top())
                                    .arg(drawn.right())
                                    .arg(drawn.bottom())
                                    .arg(shown.left())
                                    .arg(shown.top())
                                    .arg(shown.right())
                                    .arg(shown.bottom()));
            }
        });
        QVERIFY2(steps >= rigidlab::test::atLeast(20, 18), qPrintable(QString::number(steps)));
        for (const QString& line : outside)
            qInfo("%s", qPrintable(line)); // the failure message below is cut short
        QVERIFY2(outside.isEmpty(), qPrintable(outside.join(u'\n')));
    }

    /// At 1024×768 the right column's kinds share its height: with the controls and inspector and
    /// the collision table shown (the plots sit under the world at this size), none is squeezed
    /// to a few rows (each has at least a fifth of the column), whatever hides behind their tabs.
    void rightColumnIsShared()
    {
        MainWindow w;
        openOnProjector(w, QStringLiteral("restitution.json"));
        w.lessonPlayer().goToStep(2); // the collision table and two plots
        for (const char* name : {"controls", "inspector", "collision"})
            if (QDockWidget* dock = w.dock(QLatin1String(name)); dock && dock->isHidden())
                dock->toggleViewAction()->trigger(); // as ticked in the View menu
        for (int i = 0; i < 5; ++i)                  // the layout's queued passes
            QCoreApplication::processEvents();
        QList<QDockWidget*> column;
        int total = 0;
        for (QDockWidget* d : w.findChildren<QDockWidget*>())
            if (d->isVisible() && w.dockWidgetArea(d) == Qt::RightDockWidgetArea &&
                d->geometry().right() >= 0 && d->geometry().bottom() >= 0) {
                column << d;
                total += d->height();
            }
        QStringList names;
        for (QDockWidget* d : column)
            names << d->objectName();
        QVERIFY2(column.size() >= 2, qPrintable(names.join(u' ')));
        for (QDockWidget* d : column)
            QVERIFY2(d->height() >= total / 5, qPrintable(QStringLiteral("%1: %2 px of %3")
                                                              .arg(d->objectName())
                                                              .arg(d->height())
                                                              .arg(total)));
    }

    void initTestCase()
    {
        QVERIFY2(shippedLessons().size() >= 5, qPrintable(MainWindow::lessonsFolder()));
    }

    void everyLessonWalksForwardAndBack_data()
    {
        QTest::addColumn<QString>("path");
        for (const QString& p : shippedLessons())
            QTest::newRow(qPrintable(QFileInfo(p).baseName())) << p;
    }
    void everyLessonWalksForwardAndBack()
    {
        QFETCH(QString, path);
        MainWindow w;
        QCOMPARE(w.openLesson(path, true), QString());
        auto& player = w.lessonPlayer();
        QVERIFY(player.lesson());
        const int steps = static_cast<int>(player.lesson()->steps.size());
        QVERIFY(steps >= 1);
        QCOMPARE(player.stepIndex(), 0);
        for (int i = 0; i < steps; ++i) {
            QCOMPARE(player.stepIndex(), i);
            const lessons::LessonStep& step = player.lesson()->steps[static_cast<size_t>(i)];
            // Only what the step names is shown, and not what its questions hold back.
            const QStringList held = player.heldBack();
            for (const QString& name : kDockNames) {
                const bool wanted =
                    (step.panels.contains(name) &&
                     !held.contains(QStringLiteral("panel:") + name)) ||
                    (step.plots.contains(name) && !held.contains(QStringLiteral("plot:") + name));
                QVERIFY2(w.dock(name)->isHidden() == !wanted,
                         qPrintable(QStringLiteral("step %1, %2").arg(i).arg(name)));
            }
            const bool compares = step.plots.contains(QStringLiteral("compare-energy")) ||
                                  step.plots.contains(QStringLiteral("compare-drift"));
            QCOMPARE(w.comparePlot() != nullptr, compares);
            if (step.compare)
                QCOMPARE(w.controller().variantLabels().size(), step.compare->count());
            // The step's scene is loaded and runs.
            QCOMPARE(w.controller().world().bodies().size(), step.scene.bodies.size());
            for (int k = 0; k < 30; ++k)
                w.controller().stepForward();
            for (const physics::Body& b : w.controller().world().bodies())
                QVERIFY(std::isfinite(b.position.x()) && std::isfinite(b.position.y()));
            player.next();
        }
        QCOMPARE(player.stepIndex(), steps - 1); // next() on the last step stays there
        for (int i = steps - 1; i > 0; --i) {
            player.back();
            QCOMPARE(player.stepIndex(), i - 1);
        }
        player.back();
        QCOMPARE(player.stepIndex(), 0);
        // Leaving the lesson brings the plain lab back.
        player.closeLesson();
        for (const QString& name : {QStringLiteral("controls"), QStringLiteral("energy")})
            QVERIFY(!w.dock(name)->isHidden());
        QVERIFY(w.dock(QStringLiteral("sat"))->isHidden());
    }

    void questionsAreJudged()
    {
        // The first apex question of any shipped lesson: answered with the measured value
        // it is right, with a value far off it is not.
        for (const QString& path : shippedLessons()) {
            MainWindow w;
            QCOMPARE(w.openLesson(path, true), QString());
            auto& player = w.lessonPlayer();
            const auto& steps = player.lesson()->steps;
            for (int s = 0; s < static_cast<int>(steps.size()); ++s) {
                const auto& qs = steps[static_cast<size_t>(s)].questions;
                for (int q = 0; q < static_cast<int>(qs.size()); ++q) {
                    player.goToStep(s);
                    w.controller().setRunning(false);
                    player.answer(q, QStringLiteral("1"));
                    QVERIFY2(player.result(q).contains(QStringLiteral("first")) ||
                                 player.result(q).contains(QStringLiteral("Run")),
                             qPrintable(player.result(q)));
                    std::optional<double> value;
                    for (int k = 0; k < 200000 && !value; ++k) {
                        w.controller().stepForward();
                        value = w.controller().lessonWatch().measurements().value(
                            measuredOf(qs[static_cast<size_t>(q)]).measure,
                            steps[static_cast<size_t>(s)].scene);
                    }
                    QVERIFY2(value, qPrintable(qs[static_cast<size_t>(q)].prompt));
                    player.answer(q, QString::number(*value, 'g', 10));
                    QVERIFY2(player.result(q).startsWith(QStringLiteral("Right")),
                             qPrintable(player.result(q)));
                    player.answer(q, QString::number(*value * 3 + 10, 'g', 10));
                    QVERIFY2(player.result(q).startsWith(QStringLiteral("Not quite")),
                             qPrintable(player.result(q)));
                    return; // one real question is enough here; the loader tests judge more
                }
            }
        }
        QSKIP("no shipped lesson has a question");
    }

    void satStepWalksTheAxes()
    {
        for (const QString& path : shippedLessons()) {
            // A window only for a lesson with a SAT step (a window a lesson is slow to build in
            // the sanitizer pass: seven of them before the SAT lesson took over 5 minutes).
            const lessons::LessonLoadResult file = lessons::loadLessonFile(path);
            QVERIFY2(file.ok, qPrintable(file.error));
            if (std::none_of(file.lesson.steps.begin(), file.lesson.steps.end(),
                             [](const lessons::LessonStep& step) { return step.sat.has_value(); }))
                continue;
            MainWindow w;
            QCOMPARE(w.openLesson(path, true), QString());
            auto& player = w.lessonPlayer();
            const auto& steps = player.lesson()->steps;
            for (int s = 0; s < static_cast<int>(steps.size()); ++s) {
                if (!steps[static_cast<size_t>(s)].sat)
                    continue;
                player.goToStep(s);
                ui::SatPanel& sat = w.satPanel();
                QVERIFY(sat.active());
                const int total = static_cast<int>(sat.result().axes.size());
                QVERIFY(total >= 1);
                QCOMPARE(sat.shown(), 1);
                for (int i = 1; i < total; ++i)
                    sat.nextAxis();
                QCOMPARE(sat.shown(), total);
                // What is shown is what the SAT code returned.
                const auto& bodies = w.controller().world().bodies();
                const auto a = steps[static_cast<size_t>(s)].scene.bodyIndex(
                    steps[static_cast<size_t>(s)].sat->first);
                const auto b = steps[static_cast<size_t>(s)].scene.bodyIndex(
                    steps[static_cast<size_t>(s)].sat->second);
                const physics::Polygon* pa = bodies[static_cast<size_t>(*a)].shape.asPolygon();
                const physics::Polygon* pb = bodies[static_cast<size_t>(*b)].shape.asPolygon();
                QVERIFY(pa && pb);
                const physics::SatResult direct =
                    physics::satPolygons(*pa, bodies[static_cast<size_t>(*a)].transform(), *pb,
                                         bodies[static_cast<size_t>(*b)].transform());
                QCOMPARE(sat.result().intersects, direct.intersects);
                QCOMPARE(sat.result().axesTested, direct.axesTested);
                QVERIFY(sat.summary().contains(QString::number(direct.axesTested)));
                return;
            }
        }
        QSKIP("no shipped lesson has a SAT step");
    }

    void stepPlotsExport()
    {
        MainWindow w;
        for (const QString& path : shippedLessons()) {
            QCOMPARE(w.openLesson(path, true), QString());
            const auto& steps = w.lessonPlayer().lesson()->steps;
            for (int s = 0; s < static_cast<int>(steps.size()); ++s) {
                if (steps[static_cast<size_t>(s)].plots.isEmpty())
                    continue;
                w.lessonPlayer().goToStep(s);
                for (int k = 0; k < 200; ++k)
                    w.controller().stepForward();
                QTemporaryDir dir;
                const QStringList errors = w.exportStepPlots(dir.path());
                QVERIFY2(errors.isEmpty(), qPrintable(errors.join(QLatin1Char('\n'))));
                const QStringList pngs = QDir(dir.path()).entryList({QStringLiteral("*.png")});
                QVERIFY(!pngs.isEmpty());
                QVERIFY(!QImage(QDir(dir.path()).filePath(pngs.first())).isNull());
                QCOMPARE(QDir(dir.path()).entryList({QStringLiteral("*.csv")}).size(), pngs.size());
                return;
            }
        }
        QSKIP("no shipped lesson has plots");
    }

    void brokenLessonShowsError()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("broken.json"));
        QVERIFY(writeFile(
            path,
            R"({"rigidlab-lesson": 1, "title": "x", "steps": [{"title": "a", "scene": "../escape.json"}]})"));
        MainWindow w;
        const QString error = w.openLesson(path);
        QVERIFY(error.contains(QStringLiteral("broken.json")));
        QVERIFY(!w.lessonPlayer().lesson());
    }
    /// The user's own lessons and scenes (lessons::userDataDir(), under this run's fresh
    /// $HOME) are listed beside the shipped ones, marked as theirs, and open.
    void usersOwnLessonsAndScenesListed()
    {
        const QDir own(lessons::userDataDir());
        QVERIFY2(!own.exists(), qPrintable(own.path())); // a fresh $HOME: none yet
        {
            MainWindow w;
            QCOMPARE(w.lessonPlayer().lessonPaths().size(), shippedLessons().size());
            QVERIFY(!w.findChild<QMenu*>(QStringLiteral("ownScenes")));
        }
        QVERIFY(own.mkpath(QStringLiteral("scenes")));
        QVERIFY(own.mkpath(QStringLiteral("lessons/scenes")));
        QFile shippedScene(
            QDir(MainWindow::scenesFolder()).filePath(QStringLiteral("ball_drop.json")));
        QVERIFY(shippedScene.open(QIODevice::ReadOnly));
        // The shipped scene with its own title (in every language) replaced.
        QJsonObject scene = QJsonDocument::fromJson(shippedScene.readAll()).object();
        QVERIFY(scene.contains(QStringLiteral("title")));
        scene[QStringLiteral("title")] = QStringLiteral("My own drop");
        const QByteArray sceneJson = QJsonDocument(scene).toJson();
        const QString scenePath = own.filePath(QStringLiteral("scenes/my_drop.json"));
        writeTo(scenePath, sceneJson);
        writeTo(own.filePath(QStringLiteral("lessons/scenes/drop.json")), sceneJson);
        const QString lessonPath = own.filePath(QStringLiteral("lessons/mine.json"));
        writeTo(lessonPath, R"({"rigidlab-lesson": 1, "title": "Forces & torques",
                               "steps": [{"title": "Drop", "scene": "scenes/drop.json"}]})");

        MainWindow w;
        // The lesson box and File › Lessons: the shipped lessons, then the user's, marked.
        const QStringList paths = w.lessonPlayer().lessonPaths();
        QCOMPARE(paths.size(), shippedLessons().size() + 1);
        QCOMPARE(QFileInfo(paths.last()).canonicalFilePath(),
                 QFileInfo(lessonPath).canonicalFilePath());
        QString lessonText = w.lessonPlayer().lessonMenuTexts().last();
        QCOMPARE(
            lessonText,
            QStringLiteral("%1. Forces & torques (your own)").arg(shippedLessons().size() + 1));
        QCOMPARE(w.lessonPlayer().firstLessonPath(), paths.first()); // still a shipped one
        QStringList lessonsMenu;
        for (QMenu* menu : w.findChildren<QMenu*>())
            if (menu->title() == MainWindow::tr("&Lessons"))
                for (QAction* a : menu->actions())
                    lessonsMenu << a->text();
        // Its '&' shown, not taken for the entry's key.
        lessonText.replace(u'&', QStringLiteral("&&"));
        QVERIFY2(lessonsMenu.contains(lessonText), qPrintable(lessonsMenu.join(u'\n')));
        QCOMPARE(w.openLesson(paths.last(), true), QString());

        // File › Your own scenes, beside File › Shipped scenes.
        auto* ownScenes = w.findChild<QMenu*>(QStringLiteral("ownScenes"));
        QVERIFY(ownScenes);
        QCOMPARE(ownScenes->actions().size(), 1);
        QAction* open = ownScenes->actions().front();
        QCOMPARE(open->text(), QStringLiteral("My own drop"));
        open->trigger();
        QCOMPARE(w.lastError(), QString());
        const QStringList recent = QSettings().value(QStringLiteral("recentFiles")).toStringList();
        QVERIFY(!recent.isEmpty());
        QCOMPARE(QFileInfo(recent.front()).canonicalFilePath(),
                 QFileInfo(scenePath).canonicalFilePath());
        QVERIFY(QDir(own).removeRecursively()); // the other tests see the shipped ones only
    }
};

RIGIDLAB_TEST_MAIN(TestLessonWindow)
#include "test_lesson_window.moc"
