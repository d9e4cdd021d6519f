// SPDX-License-Identifier: GPL-3.0-or-later
// The window survives what a class throws at it: garbage typed into every field, a scene that
// diverges, closing it in the middle of an export or a sweep, opening a file while another
// runs, and settings that cannot be saved. Offscreen, driven as a user would.

#include "build_paths.h"
#include "lesson_player/lesson_player.h"
#include "panels/control_panel.h"
#include "panels/divergence_banner.h"
#include "panels/error_panel.h"
#include "panels/inspector_panel.h"
#include "panels/number_field.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "window/main_window.h"

#include "format/limits.h"
#include "format/scene_loader.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QImage>
#include <QLineEdit>
#include <QMenuBar>
#include <QPointer>
#include <QProcess>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSpinBox>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>

#include "run_gui.h"
#include "test_main.h"

#include <sys/resource.h>

#include <cmath>
#include <csignal>
#include <functional>

using namespace rigidlab;
using rigidlab::ui::MainWindow;

namespace {

QString scene(const char* name)
{
    return rigidlab::test::sourcePath(u"/lessons/scenes/") + QLatin1String(name);
}

QString lesson(const char* name)
{
    return rigidlab::test::sourcePath(u"/lessons/lessons/") + QLatin1String(name);
}

/// What students type when asked for a number.
const QStringList kGarbage = {
    QStringLiteral("abc"),          QStringLiteral("-1e309"), QStringLiteral("1e999"),
    QStringLiteral("nan"),          QStringLiteral("inf"),    QStringLiteral("--"),
    QStringLiteral("1,2,3"),        QStringLiteral("1e-400"), QStringLiteral("99999999999999"),
    QStringLiteral("-0"),           QStringLiteral("0x10"),   QStringLiteral("1.2.3"),
    QStringLiteral("☃ 🙂"),     QStringLiteral("  7  "),  QStringLiteral("-5"),
    QString(300, QLatin1Char('9')), QStringLiteral("1e-7"),   QStringLiteral("\t\n"),
};

/// Types `text` into `w` key by key; what is not printable ASCII (QTest's key table) goes as a key
/// event carrying the character, as an input method would send it.
void typeText(QWidget* w, const QString& text)
{
    for (const QChar c : text) {
        if (c == u'\t') {
            QTest::keyClick(w, Qt::Key_Tab);
        } else if (c == u'\n') {
            QTest::keyClick(w, Qt::Key_Return);
        } else if (c.unicode() >= 0x20 && c.unicode() < 0x7f) {
            QTest::keyClick(w, static_cast<char>(c.unicode()));
        } else {
            QTest::sendKeyEvent(QTest::Press, w, Qt::Key_unknown, QString(c), Qt::NoModifier);
            QTest::sendKeyEvent(QTest::Release, w, Qt::Key_unknown, QString(c), Qt::NoModifier);
        }
    }
}

/// The controller's settings are within a scene file's limits, whatever was typed.
void checkSettingsInRange(const ui::SimulationController& c, const QString& after)
{
    const physics::WorldDef& d = c.world().def();
    const QByteArray where = after.toUtf8();
    QVERIFY2(d.dt >= lessons::kMinDt && d.dt <= lessons::kMaxDt, where.constData());
    QVERIFY2(d.iterations >= 1 && d.iterations <= lessons::kMaxIterations, where.constData());
    QVERIFY2(d.restitution >= 0 && d.restitution <= 1, where.constData());
    QVERIFY2(lessons::limits::kFriction.contains(d.friction), where.constData());
    QVERIFY2(lessons::limits::kTimeScale.contains(c.timeScale()), where.constData());
    for (const physics::Body& b : c.world().bodies()) {
        QVERIFY2(b.restitution >= 0 && b.restitution <= 1, where.constData());
        QVERIFY2(lessons::limits::kFriction.contains(b.friction), where.constData());
        if (b.isDynamic())
            QVERIFY2(lessons::limits::kMass.contains(b.mass), where.constData());
    }
}

/// Runs `action` on the modal dialog as soon as one is open (a file dialog, a message box).
void onModal(std::function<void(QWidget*)> action)
{
    auto* timer = new QTimer;
    timer->setInterval(10);
    QObject::connect(timer, &QTimer::timeout, [timer, action] {
        if (QWidget* modal = QApplication::activeModalWidget()) {
            timer->stop();
            timer->deleteLater();
            action(modal);
        }
    });
    timer->start();
}

/// Closes `window` from inside a modal dialog's event loop, then runs the deferred deletions that
/// loop may run before the dialog returns. Whether a busy loop runs them first depends on what
/// else is pending (file-system watchers, other threads' events): on a loaded machine it did,
/// the window and its dialog were deleted and the export was dropped. Doing it here
/// makes that order certain instead of rare.
void closeAndRunDeferredDeletes(QWidget* window)
{
    window->close();
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
}

/// Chooses `path` in a (Qt, not native) file dialog as a user does: types it, whole, into the
/// file name field. QFileDialog::selectFile() does not write the field while it has the focus,
/// so whether it took depended on when the dialog's window became active (on a
/// loaded machine the export went to the dialog's default name instead).
void typeIntoFileDialog(QFileDialog* dialog, const QString& path)
{
    auto* name = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"));
    QVERIFY(name);
    dialog->setDirectory(QFileInfo(path).absolutePath());
    name->setText(path);
    QCOMPARE(dialog->selectedFiles().value(0), path);
}

QAction* findAction(QWidget* root, const QString& menuPath)
{
    // "File/Export plot/Energy/As PNG…", matched without '&'.
    const QStringList parts = menuPath.split(u'/');
    QList<QAction*> actions = root->findChild<QMenuBar*>()->actions();
    QAction* found = nullptr;
    for (const QString& part : parts) {
        found = nullptr;
        for (QAction* a : actions)
            if (QString(a->text()).remove(u'&') == part)
                found = a;
        if (!found)
            return nullptr;
        if (found->menu()) {
            emit found->menu()->aboutToShow(); // a menu may be filled as it opens
            actions = found->menu()->actions();
        }
    }
    return found;
}

} // namespace

class TestRobustness : public QObject {
    Q_OBJECT

private slots:
    void garbageInEveryField()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QCOMPARE(w.openScene(scene("box_stack.json"), true), QString());
        w.inspector().setBody(static_cast<int>(w.controller().world().bodies().size()) - 1);
        // Open a lesson step with a question too, for its answer box; then the plain lab
        // again for the controls (a lesson step may lock some).
        QCOMPARE(w.openLesson(lesson("restitution.json"), true), QString());
        // (The questions sit below the lesson's scrolling text, in the dock.)
        const auto* questions = w.findChild<QWidget*>(QStringLiteral("lessonQuestions"));
        QVERIFY(questions);
        const QList<QLineEdit*> answers = questions->findChildren<QLineEdit*>();
        QVERIFY(!answers.isEmpty());
        for (QLineEdit* edit : answers) {
            for (const QString& text : kGarbage) {
                edit->clear();
                edit->setFocus();
                typeText(edit, text);
                QTest::keyClick(edit, Qt::Key_Return);
                for (QPushButton* check : questions->findChildren<QPushButton*>())
                    if (check->text() == QLatin1String("Check") && check->isVisible())
                        check->click();
            }
        }
        QCOMPARE(w.openScene(scene("box_stack.json"), true), QString());
        w.inspector().setBody(static_cast<int>(w.controller().world().bodies().size()) - 1);
        // The iterations field is enabled for the sequential solver (the scene's is the soft step).
        w.controller().setSolver(physics::SolverKind::SequentialImpulse);

        // Number fields (ui/number_field.h) and any spin box left.
        QList<QWidget*> boxes;
        for (QWidget* panel :
             {static_cast<QWidget*>(&w.controls()), static_cast<QWidget*>(&w.inspector())}) {
            for (auto* f : panel->findChildren<ui::NumberField*>())
                boxes << f;
            for (auto* b : panel->findChildren<QAbstractSpinBox*>())
                boxes << b;
        }
        QVERIFY(boxes.size() >= 8); // dt, iterations, time scale, e, μ; the body's m, e, μ
        for (QWidget* box : boxes) {
            QVERIFY2(box->isEnabled(), qPrintable(box->objectName()));
            for (const QString& text : kGarbage) {
                box->setFocus();
                if (auto* line = qobject_cast<QLineEdit*>(box))
                    line->selectAll();
                else
                    static_cast<QAbstractSpinBox*>(box)->selectAll();
                typeText(box, text);
                QTest::keyClick(box, Qt::Key_Return);
                box->clearFocus(); // focus out: the field takes, refuses or reverts what it holds
                checkSettingsInRange(w.controller(), text);
                // A number field shows a number again: the value in force.
                if (auto* f = qobject_cast<ui::NumberField*>(box))
                    QVERIFY2(ui::parseNumber(f->text()).has_value(),
                             qPrintable(box->objectName() + QStringLiteral(": ") + f->text()));
                w.controller().stepForward();
            }
        }
        // Typing may have given a dt of a second, at which the stack may blow up (the banner's
        // case, below). Back to a sane dt from the start: the world runs, finite.
        w.controller().setDt(0.001);
        w.controller().reset();
        for (int i = 0; i < 100; ++i)
            w.controller().stepForward();
        w.controller().setRunning(true);
        QTest::qWait(100);
        w.controller().setRunning(false);
        QVERIFY(!w.controller().world().divergence());
        for (const physics::Body& b : w.controller().world().bodies())
            QVERIFY(std::isfinite(b.position.x()) && std::isfinite(b.position.y()));
    }

    // Out-of-range values sent to the controller directly change nothing.
    void outOfRangeCallsChangeNothing()
    {
        MainWindow w;
        QCOMPARE(w.openScene(scene("box_stack.json"), true), QString());
        const physics::WorldDef before = w.controller().world().def();
        const double scale = w.controller().timeScale();
        w.controller().setDt(0.0);
        w.controller().setDt(-1.0);
        w.controller().setDt(1e300);
        w.controller().setDt(std::nan(""));
        w.controller().setIterations(0);
        w.controller().setIterations(1 << 30);
        w.controller().setRestitution(2.0);
        w.controller().setFriction(1e300);
        w.controller().setFriction(-1.0);
        w.controller().setTimeScale(std::nan(""));
        w.controller().setTimeScale(1e9);
        w.controller().setBodyMaterial(0, std::nan(""), 0.5);
        QCOMPARE(w.controller().world().def().dt, before.dt);
        QCOMPARE(w.controller().world().def().iterations, before.iterations);
        QCOMPARE(w.controller().world().def().restitution, before.restitution);
        QCOMPARE(w.controller().world().def().friction, before.friction);
        QCOMPARE(w.controller().timeScale(), scale);
    }

    void answerBoxesTakeOnlyNumbers()
    {
        MainWindow w;
        QCOMPARE(w.openLesson(lesson("restitution.json"), true), QString());
        ui::LessonPlayer& player = w.lessonPlayer();
        // Find a step with a question.
        int step = -1;
        for (int i = 0; i < static_cast<int>(player.lesson()->steps.size()) && step < 0; ++i)
            if (!player.lesson()->steps[static_cast<std::size_t>(i)].questions.empty())
                step = i;
        QVERIFY(step >= 0);
        player.goToStep(step);
        for (const QString& text :
             {QStringLiteral("abc"), QStringLiteral("1e999"), QStringLiteral("nan"), QString()}) {
            player.answer(0, text);
            QCOMPARE(player.result(0), QStringLiteral("Type a number first."));
        }
        player.answer(0, QStringLiteral("1e300"));
        QCOMPARE(player.result(0), QStringLiteral("Type a number from -1e+15 to 1e+15."));
    }

    void divergingSceneStopsWithABanner()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        // The stiff spring past its stability limit: Verlet at dt = 10 ms diverges at once.
        QCOMPARE(w.openScene(scene("stiff_spring.json"), true), QString());
        w.controller().setDt(0.01);
        w.controller().setRunning(true);
        QTRY_VERIFY_WITH_TIMEOUT(w.controller().world().divergence().has_value(), 20000);
        auto* banner = w.findChild<ui::DivergenceBanner*>();
        QVERIFY(banner);
        QTRY_VERIFY_WITH_TIMEOUT(banner->isVisible(), 5000);
        QVERIFY(!w.controller().isRunning());
        QVERIFY2(banner->text().contains(QStringLiteral("diverged")), qPrintable(banner->text()));
        // Stepping on, stepping back, drawing and the plots all carry on without garbage.
        const long long at = w.controller().world().stepCount();
        for (int i = 0; i < 10; ++i)
            w.controller().stepForward();
        w.controller().stepBack();
        QTest::qWait(100);
        for (auto* plot : w.plots())
            plot->drain();
        QVERIFY(w.controller().world().stepCount() <= at + 10);
        // Halve dt: back to the start with dt = 5 ms, where Verlet is stable.
        auto* halve = banner->findChild<QPushButton*>(QStringLiteral("halveDt"));
        QVERIFY(halve && halve->isEnabled());
        halve->click();
        QCOMPARE(w.controller().world().def().dt, 0.005);
        QCOMPARE(w.controller().world().stepCount(), 0LL);
        QVERIFY(!w.controller().world().divergence());
        w.controller().setRunning(true);
        QTest::qWait(300);
        w.controller().setRunning(false);
        QVERIFY(!w.controller().world().divergence());
        QTRY_VERIFY(!banner->isVisible());
        // At the smallest dt there is nothing left to halve.
        w.controller().setDt(lessons::kMinDt);
        banner->refresh();
        QVERIFY(!halve->isEnabled());
    }

    void closingDuringTheSweep()
    {
        // The error-vs-time sweep runs in a thread of its own: closing and destroying the
        // window mid-sweep stops it after the row in progress, without a crash or a leak.
        auto* w = new MainWindow;
        w->show();
        auto* panel = w->findChild<ui::ErrorPanel*>();
        QVERIFY(panel);
        panel->start();
        QVERIFY(panel->isRunning());
        QTest::qWait(50);
        w->close();
        QElapsedTimer clock;
        clock.start();
        delete w;
        QVERIFY(clock.elapsed() < 60000);
    }

    void closingDuringAPlotExport()
    {
        // File › Export plot: the window is closed while the file dialog is up (it runs an
        // event loop of its own), then the file is chosen. The export completes, whole.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("energy.png"));
        QPointer<MainWindow> w = new MainWindow;
        w->setAttribute(Qt::WA_DeleteOnClose);
        w->show();
        QCOMPARE(w->openScene(scene("ball_drop.json"), true), QString());
        for (int i = 0; i < 200; ++i)
            w->controller().stepForward();
        QAction* exportPng = findAction(w, QStringLiteral("File/Export plot/Energy/As PNG…"));
        QVERIFY(exportPng);
        bool dialogSeen = false;
        onModal([&](QWidget* modal) {
            dialogSeen = true;
            QPointer<QFileDialog> dialog = qobject_cast<QFileDialog*>(modal);
            QVERIFY(dialog);
            closeAndRunDeferredDeletes(w);
            QVERIFY2(w && dialog, "the window was deleted under its open export dialog");
            typeIntoFileDialog(dialog, path);
            static_cast<QDialog*>(dialog)->accept(); // QFileDialog hides it
        });
        exportPng->trigger();
        QVERIFY(dialogSeen);
        QTRY_VERIFY(w.isNull()); // deleted on close, once back in the main event loop
        QImage image(path);
        QVERIFY2(!image.isNull(), "the exported picture is not whole");
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden),
                 QStringList{QStringLiteral("energy.png")});
    }

    void closingDuringALessonExport()
    {
        // The lesson's "Export plots…": the window closes while the folder dialog is up.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QPointer<MainWindow> w = new MainWindow;
        w->setAttribute(Qt::WA_DeleteOnClose);
        w->show();
        QCOMPARE(w->openLesson(lesson("energy_drift.json"), true), QString());
        for (int i = 0; i < 100; ++i)
            w->controller().stepForward();
        onModal([&](QWidget* modal) {
            QPointer<QFileDialog> dialog = qobject_cast<QFileDialog*>(modal);
            QVERIFY(dialog);
            closeAndRunDeferredDeletes(w);
            QVERIFY2(w && dialog, "the window was deleted under its open folder dialog");
            typeIntoFileDialog(dialog, dir.path());
            static_cast<QDialog*>(dialog)->accept(); // QFileDialog hides it
        });
        emit w->lessonPlayer().exportRequested();
        QTRY_VERIFY(w.isNull());
        const QStringList files = QDir(dir.path()).entryList(QDir::Files | QDir::Hidden);
        QVERIFY2(files.size() >= 4, qPrintable(files.join(u' ')));
        for (const QString& f : files)
            QVERIFY2(!f.startsWith(u'.') && QFileInfo(dir.filePath(f)).size() > 0, qPrintable(f));
    }

    void openingFilesWhileOneRuns()
    {
        MainWindow w;
        w.show();
        QCOMPARE(w.openScene(scene("billiards_break.json"), true), QString());
        w.controller().setRunning(true);
        QTRY_VERIFY_WITH_TIMEOUT(w.controller().world().time() > 0.05, 10000);
        // Dragging a body, mid-run, when the next file opens.
        w.controller().grab(static_cast<int>(w.controller().world().bodies().size()) - 1,
                            physics::Vec2(0, 0));
        QCOMPARE(w.openScene(scene("newtons_cradle.json"), true), QString());
        QVERIFY(!w.controller().grabSpring().body());
        QCOMPARE(w.controller().world().time(), 0.0);
        const lessons::SceneLoadResult cradle =
            lessons::loadSceneFile(scene("newtons_cradle.json"));
        QCOMPARE(w.controller().world().bodies().size(), cradle.scene.bodies.size());
        // A broken file while running: the running scene stays.
        w.controller().setRunning(true);
        QTRY_VERIFY_WITH_TIMEOUT(w.controller().world().time() > 0.05, 10000);
        QVERIFY(!w.openScene(QStringLiteral("/nonexistent/scene.json"), true).isEmpty());
        QCOMPARE(w.controller().world().bodies().size(), cradle.scene.bodies.size());
        // A lesson while a scene runs, then a scene while the lesson's step runs.
        QCOMPARE(w.openLesson(lesson("billiards_momentum.json"), true), QString());
        w.controller().setRunning(true);
        QTRY_VERIFY_WITH_TIMEOUT(w.controller().world().time() > 0.05, 10000);
        QCOMPARE(w.openScene(scene("pendulum.json"), true), QString());
        QVERIFY(!w.lessonPlayer().lesson());
        // Plots start again from the new scene's t = 0.
        for (int i = 0; i < 50; ++i)
            w.controller().stepForward();
        for (auto* plot : w.plots()) {
            plot->drain();
            QVERIFY(plot->model().pointCount() > 0);
        }
        // A second lesson over the first, mid-run, and the sweep running through it all.
        QCOMPARE(w.openLesson(lesson("stacks.json"), true), QString());
        w.findChild<ui::ErrorPanel*>()->start();
        w.controller().setRunning(true);
        QTest::qWait(100);
        QCOMPARE(w.openLesson(lesson("energy_drift.json"), true), QString());
        w.controller().setRunning(true);
        QTest::qWait(100);
        QCOMPARE(w.openScene(scene("welcome.json"), true), QString());
        QTest::qWait(100);
        w.findChild<ui::ErrorPanel*>()->cancel();
    }

    void settingsThatCannotBeSavedAreReported()
    {
        // A full disk, as far as QSettings can tell: a file size limit (it stops root too).
        MainWindow w;
        w.show();
        QSettings().clear();
        QSettings().sync();
        rlimit old{};
        getrlimit(RLIMIT_FSIZE, &old);
        auto* oldHandler = std::signal(SIGXFSZ, SIG_IGN);
        rlimit limited = old;
        limited.rlim_cur = 16;
        QVERIFY(setrlimit(RLIMIT_FSIZE, &limited) == 0);
        QCOMPARE(w.openScene(scene("ball_drop.json"), true), QString()); // a recent file
        const QString message = w.statusBar()->currentMessage();
        setrlimit(RLIMIT_FSIZE, &old);
        std::signal(SIGXFSZ, oldHandler);
        QVERIFY2(message.startsWith(QStringLiteral("Settings not saved: cannot write ")),
                 qPrintable(message));
    }

    /// The window's own flags, run as a process (offscreen): a bad one is refused in one line
    /// with exit status 2 and no window; --measure-frames prints its figures and quits.
    void commandLineFlags()
    {
        const auto run = [](const QStringList& args, QString& out, QString& err) {
            return test::runGui(args, test::offscreenEnvironment(), out, err);
        };
        QString out, err;
        for (const QStringList& bad :
             {QStringList{QStringLiteral("--measure-frames")},
              QStringList{QStringLiteral("--measure-frames"), QStringLiteral("ten")},
              QStringList{QStringLiteral("--measure-frames"), QStringLiteral("0")},
              QStringList{QStringLiteral("--measure-frames"), QStringLiteral("-5")}}) {
            QCOMPARE(run(bad, out, err), 2);
            QVERIFY2(err.contains(QStringLiteral("--measure-frames needs a whole number")),
                     qPrintable(err));
        }
        QCOMPARE(run({QStringLiteral("--measure-frames"), QStringLiteral("5")}, out, err), 2);
        QVERIFY2(err.contains(QStringLiteral("needs a scene")), qPrintable(err));
        QTemporaryDir dir;
        QFile broken(dir.filePath(QStringLiteral("broken.json")));
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write("{\"rigidlab\": 1,");
        broken.close();
        QCOMPARE(run({QStringLiteral("--measure-frames"), QStringLiteral("5"), broken.fileName()},
                     out, err),
                 2);
        QVERIFY2(err.contains(QStringLiteral("broken.json: line")), qPrintable(err));
        QVERIFY2(err.contains(QStringLiteral("needs a scene that opens")), qPrintable(err));

        QCOMPARE(
            run({QStringLiteral("--measure-frames"), QStringLiteral("20"), scene("box_stack.json")},
                out, err),
            0);
        const QRegularExpression figures(
            QStringLiteral(R"(^20 frames: median ([0-9.]+) ms, 95th percentile ([0-9.]+) ms)"));
        const QRegularExpressionMatch m = figures.match(out);
        QVERIFY2(m.hasMatch(), qPrintable(out));
        QVERIFY(m.captured(1).toDouble() > 0);
        QVERIFY(m.captured(2).toDouble() >= m.captured(1).toDouble());

        // A scene that diverges at once stops its run: the measurement says so and returns,
        // with the command line's status for a divergence, instead of waiting for frames.
        QFile diverging(dir.filePath(QStringLiteral("diverging.json")));
        QVERIFY(diverging.open(QIODevice::WriteOnly));
        diverging.write(R"({"rigidlab": 1,
            "world": {"gravity": [0, 0], "dt": 0.02, "integrator": "verlet"},
            "bodies": [{"id": "mass", "shape": {"type": "circle", "radius": 0.1}, "mass": 1,
                        "position": [0.1, 0]}],
            "springs": [{"a": "mass", "b": null, "anchorB": [-1, 0], "stiffness": 1e6,
                         "restLength": 1}]})");
        diverging.close();
        QCOMPARE(
            run({QStringLiteral("--measure-frames"), QStringLiteral("20"), diverging.fileName()},
                out, err),
            3);
        QVERIFY2(err.contains(QStringLiteral("--measure-frames: the scene diverged at t = ")),
                 qPrintable(err));
    }
};

RIGIDLAB_TEST_MAIN(TestRobustness)
#include "test_robustness.moc"
