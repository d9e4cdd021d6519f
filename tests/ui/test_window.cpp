// SPDX-License-Identifier: GPL-3.0-or-later
// The lab window, driven as a user would: keys, mouse, menus, under the offscreen platform.

#include "build_paths.h"
#include "common/dock_names.h"
#include "common/language.h"
#include "common/status_text.h"
#include "lesson_player/lesson_panels.h"
#include "measure/measurement_panel.h"
#include "measure/measurement_session.h"
#include "panels/control_panel.h"
#include "panels/inspector_panel.h"
#include "panels/number_field.h"
#include "panels/sat_panel.h"
#include "plots/plot_export.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "view/body_item.h"
#include "view/world_view.h"
#include "window/dock_tabs.h"
#include "window/main_window.h"
#include "window/window_names.h"

#include <QCheckBox>
#include <QDataStream>
#include <QDockWidget>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QToolBar>
#include <QtTest>

#include "language_rows.h"
#include "test_files.h"
#include "test_main.h"

#include <cstring>
#include <map>
#include <string_view>

using namespace rigidlab;
using rigidlab::test::writeFile;
using rigidlab::ui::MainWindow;

namespace {

QString scene(const char* name)
{
    return rigidlab::test::sourcePath(u"/lessons/scenes/") + QLatin1String(name);
}

/// Every body's state, bit for bit.
QByteArray stateBytes(const physics::World& w)
{
    QByteArray out;
    for (const physics::Body& b : w.bodies()) {
        const double v[6] = {b.position.x(), b.position.y(), b.angle,
                             b.velocity.x(), b.velocity.y(), b.angularVelocity};
        out.append(reinterpret_cast<const char*>(v), sizeof v);
    }
    return out;
}

} // namespace

class TestWindow : public QObject {
    Q_OBJECT
private slots:
    // The status bar's drift: rounding noise (1.45e-13 %) reads 0, numbers follow the locale,
    // and what is not a number is not shown as one.
    void driftInTheStatusBar_data()
    {
        QTest::addColumn<double>("percent");
        QTest::addColumn<QString>("locale");
        QTest::addColumn<QString>("shown");
        QTest::newRow("rounding noise")
            << 1.45e-13 << QStringLiteral("en_US") << QStringLiteral("0");
        QTest::newRow("negative noise")
            << -9.9e-7 << QStringLiteral("de_DE") << QStringLiteral("0");
        // Above the rounding: shown as it is, in three digits.
        QTest::newRow("just above")
            << 2e-6 << QStringLiteral("en_US") << QStringLiteral("0.000002");
        QTest::newRow("small, German")
            << 0.0125 << QStringLiteral("de_DE") << QStringLiteral("0,0125");
        QTest::newRow("large, German")
            << -3.27 << QStringLiteral("de_DE") << QStringLiteral("-3,27");
        QTest::newRow("zero") << 0.0 << QStringLiteral("en_US") << QStringLiteral("0");
    }
    void driftInTheStatusBar()
    {
        QFETCH(double, percent);
        QFETCH(QString, locale);
        QFETCH(QString, shown);
        QCOMPARE(ui::driftPercentText(percent, QLocale(locale)), shown);
    }
    void driftThatIsNotANumber()
    {
        for (double bad :
             {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
            const QString text = ui::driftPercentText(bad, QLocale(QStringLiteral("en_US")));
            QVERIFY(!text.isEmpty());
            QVERIFY2(!text.contains(QLatin1String("nan"), Qt::CaseInsensitive) &&
                         !text.contains(QLatin1String("inf"), Qt::CaseInsensitive),
                     qPrintable(text));
        }
    }
    void sceneLoadsAndRuns()
    {
        MainWindow w;
        QCOMPARE(w.openScene(scene("ball_drop.json"), true), QString());
        const auto& world = w.controller().world();
        const double y0 = world.body(world.bodies().size() - 1).position.y();
        w.controller().setRunning(true);
        // The frame timer drives the clock; wait (with events) until time has passed.
        QTRY_VERIFY_WITH_TIMEOUT(world.time() > 0.05, 10000);
        w.controller().setRunning(false);
        QVERIFY(world.body(world.bodies().size() - 1).position.y() < y0);
    }

    // Each panel a lesson step may show is the dock of its lesson-format name, under that
    // name's titles (short on the tab, full in the tooltip), holding that panel.
    void panelDocksAreTitledByTheirNames()
    {
        MainWindow w;
        const std::map<std::string_view, QWidget*> panels{{"controls", &w.controls()},
                                                          {"inspector", &w.inspector()},
                                                          {"sat", &w.satPanel()},
                                                          {"bounces", &w.bouncePanel()},
                                                          {"collision", &w.collisionPanel()},
                                                          {"measurement", w.measurement().panel()}};
        QCOMPARE(panels.size(), ui::kStepPanelTitles.size());
        for (const ui::StepPartName& part : ui::kStepPanelTitles) {
            const QString name = QLatin1String(part.name);
            QDockWidget* dock = w.dock(name);
            QVERIFY2(dock, part.name);
            QCOMPARE(dock->objectName(), name + QStringLiteral("Dock"));
            QCOMPARE(dock->windowTitle(), ui::dockTitle(dock->objectName()));
            QCOMPARE(ui::fullTitle(*dock), ui::stepPartText(part.title));
            QVERIFY2(dock->isAncestorOf(panels.at(part.name)), part.name);
            QCOMPARE(&ui::stepPanel(part.name), &part);
        }
    }

    // Every dock is named once, from its entry in the docks' table: its title is the entry's
    // text without the mark of its underlined letter, in each language; its object name (which
    // a saved layout finds it by) is its own, "…Dock" once; and each entry has its dock.
    void everyDockIsTitledFromItsEntry_data() { test::addLanguageRows(); }
    void everyDockIsTitledFromItsEntry()
    {
        QFETCH(QString, language);
        QVERIFY(ui::applyLanguage(language));
        MainWindow w;
        QStringList problems;
        QStringList names;
        for (const QDockWidget* dock : w.findChildren<QDockWidget*>()) {
            const QString name = dock->objectName();
            names << name;
            const ui::PanelEntry* entry = ui::panelEntry(name);
            if (!entry) {
                problems << QStringLiteral("no entry: ") + name;
                continue;
            }
            const QString text = ui::panelEntryText(*entry);
            if (QString(text).remove(u'&') != dock->windowTitle() || !text.contains(u'&') ||
                dock->windowTitle().contains(u'&'))
                problems << QStringLiteral("%1: title %2, entry %3")
                                .arg(name, dock->windowTitle(), text);
            if (!name.endsWith(QLatin1String("Dock")) || name.endsWith(QLatin1String("DockDock")))
                problems << QStringLiteral("named %1").arg(name);
        }
        for (const ui::PanelEntry& entry : ui::kPanelEntries)
            if (names.count(QLatin1String(entry.dock)) != 1)
                problems << QStringLiteral("%1 docks named %2")
                                .arg(names.count(QLatin1String(entry.dock)))
                                .arg(QLatin1String(entry.dock));
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(u'\n')));
        QVERIFY(ui::applyLanguage(QStringLiteral("en")));
    }

    // A layout saved while the error dock was named "errorDockDock" still places it: shown
    // there, it is shown again, and the layout saved next names it as it is named now.
    void aLayoutSavedUnderTheErrorDocksOldNameStillPlacesIt()
    {
        {
            MainWindow before;
            before.show();
            QDockWidget* error = before.dock(QStringLiteral("error"));
            QVERIFY(error && error->isHidden());
            error->setObjectName(QStringLiteral("errorDockDock")); // as it was named
            error->show();
            QVERIFY(before.close()); // saves the layout
        }
        MainWindow after;
        QDockWidget* error = after.dock(QStringLiteral("error"));
        QVERIFY(error);
        QCOMPARE(error->objectName(), QStringLiteral("errorDock"));
        QVERIFY(!error->isHidden());
        QByteArray oldName; // as QMainWindow::saveState() writes it
        QDataStream out(&oldName, QIODevice::WriteOnly);
        out << QStringLiteral("errorDockDock");
        QVERIFY(!after.saveState().contains(oldName));
        QSettings().remove(QStringLiteral("layout"));
    }

    void plotsReceiveData()
    {
        MainWindow w;
        QCOMPARE(w.openScene(scene("ball_drop.json"), true), QString());
        for (int i = 0; i < 300; ++i)
            w.controller().stepForward();
        for (auto* plot : w.plots()) {
            plot->drain();
            QVERIFY2(plot->model().pointCount() > 10, qPrintable(plot->objectName()));
        }
    }

    void shortcutsDoWhatTheySay()
    {
        MainWindow w;
        QCOMPARE(w.openScene(scene("ball_drop.json"), true), QString());
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.activateWindow();
        w.view().setFocus();
        auto& c = w.controller();
        QVERIFY(!c.isRunning());
        QTest::keyClick(&w.view(), Qt::Key_Space);
        QVERIFY(c.isRunning());
        QTest::keyClick(&w.view(), Qt::Key_Space);
        QVERIFY(!c.isRunning());
        const long long s0 = c.world().stepCount();
        QTest::keyClick(&w.view(), Qt::Key_S);
        QCOMPARE(c.world().stepCount(), s0 + 1);
        QTest::keyClick(&w.view(), Qt::Key_Right);
        QCOMPARE(c.world().stepCount(), s0 + 2);
        QTest::keyClick(&w.view(), Qt::Key_Left);
        QCOMPARE(c.world().stepCount(), s0 + 1);
        QTest::keyClick(&w.view(), Qt::Key_R);
        QCOMPARE(c.world().stepCount(), 0LL);
        QVERIFY(w.overlayAction(ui::Overlay::Velocities));
        const bool before = w.view().overlays().isEnabled(ui::Overlay::Velocities);
        QTest::keyClick(&w.view(), Qt::Key_V);
        QCOMPARE(w.view().overlays().isEnabled(ui::Overlay::Velocities), !before);
    }

    void stepBackAndForwardIsBitIdentical_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("steps");
        QTest::addColumn<int>("back");
        QTest::newRow("ball-drop") << scene("ball_drop.json") << 900 << 333;
        QTest::newRow("box-stack") << scene("box_stack.json") << 450 << 260;
        QTest::newRow("pendulum") << scene("pendulum.json") << 500 << 250;
        QTest::newRow("cradle") << scene("newtons_cradle.json") << 700 << 401;
    }
    void stepBackAndForwardIsBitIdentical()
    {
        QFETCH(QString, file);
        QFETCH(int, steps);
        QFETCH(int, back);
        MainWindow w;
        QCOMPARE(w.openScene(file, true), QString());
        auto& c = w.controller();
        for (int i = 0; i < steps - back; ++i)
            c.stepForward();
        const QByteArray middle = stateBytes(c.world());
        for (int i = 0; i < back; ++i)
            c.stepForward();
        const QByteArray end = stateBytes(c.world());
        for (int i = 0; i < back; ++i)
            c.stepBack();
        QCOMPARE(c.world().stepCount(), static_cast<long long>(steps - back));
        QVERIFY(stateBytes(c.world()) == middle);
        for (int i = 0; i < back; ++i)
            c.stepForward();
        QVERIFY(stateBytes(c.world()) == end);
        // A jump along the timeline lands on the same state as well.
        c.seek(steps - back);
        QVERIFY(stateBytes(c.world()) == middle);
    }

    void changingASettingBranches()
    {
        MainWindow w;
        QCOMPARE(w.openScene(scene("ball_drop.json"), true), QString());
        auto& c = w.controller();
        for (int i = 0; i < 400; ++i)
            c.stepForward();
        c.seek(200);
        QCOMPARE(c.history().latest(), 400LL);
        ui::NumberField* e = w.controls().restitutionField();
        e->selectAll();
        QTest::keyClicks(e, QStringLiteral("0.2"));
        QTest::keyClick(e, Qt::Key_Return);
        QCOMPARE(c.history().latest(), 200LL);
        QCOMPARE(c.world().def().restitution, 0.2);
    }

    void draggingABodyMovesIt()
    {
        MainWindow w;
        QCOMPARE(w.openScene(scene("ball_drop.json"), true), QString());
        w.controls().gravityBox()->setChecked(false);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto& c = w.controller();
        const physics::BodyId ball = static_cast<physics::BodyId>(c.world().bodies().size() - 1);
        QVERIFY(c.world().body(ball).isDynamic());
        const physics::Vec2 start = c.world().body(ball).position;
        const QPoint at = w.view().mapFromScene(QPointF(start.x(), start.y()));
        QTest::mousePress(w.view().viewport(), Qt::LeftButton, {}, at);
        QVERIFY(c.grabSpring().body().has_value());
        QCOMPARE(w.inspector().body(), static_cast<int>(ball));
        QTest::mouseMove(w.view().viewport(), at + QPoint(0, -60));
        // Upwards, where nothing is in the way.
        const double wanted = w.view().mapToScene(at + QPoint(0, -60)).y() - start.y();
        for (int i = 0; i < 1500; ++i)
            c.stepForward();
        QTest::mouseRelease(w.view().viewport(), Qt::LeftButton, {}, at + QPoint(0, -60));
        QVERIFY(!c.grabSpring().body().has_value());
        const physics::Vec2 end = c.world().body(ball).position;
        // The spring pulls the grabbed point to the cursor.
        QVERIFY(wanted > 0.1);
        QVERIFY2(
            std::abs((end.y() - start.y()) - wanted) < 0.1 * wanted,
            qPrintable(
                QStringLiteral("moved %1 m, cursor %2 m").arg(end.y() - start.y()).arg(wanted)));
    }

    void brokenSceneShowsErrorAndKeepsOldScene()
    {
        QTemporaryDir dir;
        const QString broken = dir.filePath(QStringLiteral("broken.json"));
        QVERIFY(writeFile(
            broken,
            R"({"rigidlab": 1, "bodies": [{"id": "x", "shape": {"type": "circle", "radius": -1}}]})"));
        MainWindow w;
        QCOMPARE(w.openScene(scene("pendulum.json"), true), QString());
        const QString title = w.controller().scene().title;
        const auto bodies = w.controller().world().bodies().size();
        const QString error = w.openScene(broken);
        QVERIFY(error.contains(QStringLiteral("broken.json")));
        QVERIFY(error.contains(QStringLiteral("radius")));
        auto* box = w.findChild<QMessageBox*>(QStringLiteral("sceneErrorBox"));
        QVERIFY(box);
        QCOMPARE(box->text(), error);
        QCOMPARE(w.controller().scene().title, title);
        QCOMPARE(w.controller().world().bodies().size(), bodies);
        box->close();
    }

    void everyShippedSceneOpensAndSteps()
    {
        const QDir dir(MainWindow::scenesFolder());
        const QStringList files = dir.entryList({QStringLiteral("*.json")}, QDir::Files);
        QVERIFY(files.size() >= 9);
        MainWindow w;
        for (const QString& name : files) {
            QCOMPARE(w.openScene(dir.filePath(name), true), QString());
            for (int i = 0; i < 60; ++i)
                w.controller().stepForward();
            for (const physics::Body& b : w.controller().world().bodies())
                QVERIFY2(std::isfinite(b.position.x()) && std::isfinite(b.position.y()),
                         qPrintable(name));
            QVERIFY(std::isfinite(w.controller().recorder().driftPercent(w.controller().world())));
        }
    }

    void exportsFromTheWindow()
    {
        MainWindow w;
        QCOMPARE(w.openScene(scene("spring_oscillator.json"), true), QString());
        for (int i = 0; i < 500; ++i)
            w.controller().stepForward();
        w.plot(u"energy")->drain();
        QTemporaryDir dir;
        for (const char* suffix : {"png", "pdf", "svg", "csv"}) {
            const QString path = dir.filePath(QStringLiteral("energy.") + QLatin1String(suffix));
            const auto r = ui::exportPlot(*w.plot(u"energy"), path,
                                          *ui::formatFromSuffix(QLatin1String(suffix)));
            QVERIFY2(r.ok, qPrintable(r.error));
            QVERIFY(QFileInfo(path).size() > 100);
        }
        QImage png(dir.filePath(QStringLiteral("energy.png")));
        QVERIFY(!png.isNull());
    }

    /// A status-bar message (the editor's hint) stands alone: no label of the status line is
    /// drawn over it, not even one shown again while the message lasts (the details turned
    /// on), and the line comes back when the message ends.
    void statusMessageIsNotDrawnOver()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QStatusBar* bar = w.statusBar();
        const auto drawnLabels = [bar] {
            QStringList drawn;
            for (const QLabel* label : bar->findChildren<QLabel*>())
                if (label->isVisible() && !label->text().isEmpty())
                    drawn << label->text();
            return drawn;
        };
        QVERIFY(!drawnLabels().isEmpty());
        bar->showMessage(QStringLiteral("a hint for the editor"));
        QAction* details = w.findChild<QAction*>(QStringLiteral("statusDetails"));
        QVERIFY(details);
        details->setChecked(!details->isChecked());
        w.controller().stepForward();
        QCoreApplication::processEvents();
        QVERIFY2(drawnLabels().isEmpty(), qPrintable(drawnLabels().join(QStringLiteral(" | "))));
        bar->clearMessage();
        QCoreApplication::processEvents();
        QVERIFY(drawnLabels().join(u' ').contains(QStringLiteral("t =")));
    }

    /// The clock's labels (the status bar's time, the timeline's step and time) change every
    /// frame while the run goes, and ask for no layout then: the status bar and the timeline's
    /// toolbar, and through them the whole window, were laid out again every frame. A frame in
    /// which neither label had to grow posts no layout request to either bar; paused, the
    /// labels take the size of their text again.
    void clockLabelsLayNothingOutWhileRunning()
    {
        MainWindow w;
        QCOMPARE(w.openScene(scene("welcome.json"), true), QString());
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto* timeline = w.findChild<QLabel*>(QStringLiteral("timelineLabel"));
        auto* toolbar = w.findChild<QToolBar*>(QStringLiteral("timelineToolbar"));
        QVERIFY(timeline && toolbar);
        struct CountLayouts : QObject {
            int requests = 0;
            bool eventFilter(QObject*, QEvent* e) override
            {
                requests += e->type() == QEvent::LayoutRequest;
                return false;
            }
        } count;
        w.statusBar()->installEventFilter(&count);
        toolbar->installEventFilter(&count);
        ui::SimulationController& c = w.controller();
        c.setRunning(true);
        QCoreApplication::sendPostedEvents(); // the labels held at the run's start
        const QString before = timeline->text();
        int steadyFrames = 0;
        for (int frame = 0; frame < 30; ++frame) {
            const QSize sizeBefore = timeline->size();
            const QList<QLabel*> labels = w.statusBar()->findChildren<QLabel*>();
            std::vector<QSize> barBefore;
            for (const QLabel* label : labels)
                barBefore.push_back(label->size());
            count.requests = 0;
            c.advanceClock(1.0 / 60.0);
            QCoreApplication::sendPostedEvents();
            bool grew = timeline->size() != sizeBefore;
            for (qsizetype i = 0; i < labels.size(); ++i)
                grew = grew || labels[i]->size() != barBefore[static_cast<std::size_t>(i)];
            if (grew)
                continue;
            ++steadyFrames;
            QVERIFY2(count.requests == 0,
                     qPrintable(QStringLiteral("frame %1: %2 layout requests, \"%3\"")
                                    .arg(frame)
                                    .arg(count.requests)
                                    .arg(timeline->text())));
        }
        QVERIFY2(timeline->text() != before, qPrintable(timeline->text()));
        QVERIFY2(steadyFrames >= 20, qPrintable(QString::number(steadyFrames)));
        c.setRunning(false);
        QCOMPARE(timeline->maximumWidth(), QWIDGETSIZE_MAX);
    }
};

RIGIDLAB_TEST_MAIN(TestWindow)
#include "test_window.moc"
