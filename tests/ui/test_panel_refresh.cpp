// SPDX-License-Identifier: GPL-3.0-or-later
// A frame does only what changed: the view places a body with one sine and one cosine, none
// for a body that stands where it was drawn; the inspector and the SAT panel fill nothing in
// for a frame that changed nothing they show, nor while they are out of sight, and are up to
// date once shown; so is the bounce table opened while the run is paused.

#include "common/number_format.h"
#include "lesson_player/lesson_panels.h"
#include "panels/fitting_table.h"
#include "panels/inspector_panel.h"
#include "panels/sat_panel.h"
#include "simulation/simulation_controller.h"
#include "window/main_window.h"

#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QTemporaryDir>
#include <QtTest>

#include "projector_window.h"
#include "test_files.h"
#include "test_main.h"

#include <cmath>

using namespace rigidlab;
using rigidlab::test::writeFile;
using rigidlab::ui::MainWindow;

namespace {

/// The floor, a box lying on it, and a kinematic box turning and moving (a pose that changes
/// every step), its centre of mass off its origin (a triangle).
constexpr const char* kBoxes = R"({"rigidlab": 1,
  "world": {"gravity": [0, -9.81], "dt": 0.01},
  "bodies": [
    {"id": "floor", "type": "static", "shape": {"type": "box", "width": 6, "height": 0.4},
     "position": [0, -0.2]},
    {"id": "flat", "shape": {"type": "box", "width": 1, "height": 0.5}, "position": [0, 0.25]},
    {"id": "turning", "type": "kinematic",
     "shape": {"type": "polygon", "vertices": [[0, 0], [0.6, 0], [0, 0.3]]},
     "position": [2, 2], "angle": 0.5, "angularVelocity": 1, "velocity": [0.3, 0]}]})";

bool openBoxes(MainWindow& w, QTemporaryDir& dir)
{
    const QString path = dir.filePath(QStringLiteral("boxes.json"));
    return writeFile(path, kBoxes) && w.openScene(path, true).isEmpty();
}

/// "x, y, angle" of a pose, for messages.
QString poseText(const ui::Pose& p)
{
    return QStringLiteral("%1, %2, %3")
        .arg(p.origin.x(), 0, 'g', 17)
        .arg(p.origin.y(), 0, 'g', 17)
        .arg(p.angle, 0, 'g', 17);
}

} // namespace

class TestPanelRefresh : public QObject {
    Q_OBJECT
private slots:
    void init() { QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates)); }

    // The pose drawn is the body's (Body::transform(): its origin, its angle, that angle's
    // cosine and sine), computed once; given the pose drawn last of a body that has not moved
    // since, drawPose hands that back and computes nothing.
    void poseComputedOnce()
    {
        QTemporaryDir dir;
        MainWindow w;
        QVERIFY(openBoxes(w, dir));
        ui::SimulationController& c = w.controller();
        const auto turning = static_cast<physics::BodyId>(2);
        const ui::Pose pose = c.drawPose(turning);
        const physics::Transform t = c.world().body(turning).transform();
        QVERIFY2(pose.origin == t.p && pose.rotation.c == t.q.c && pose.rotation.s == t.q.s &&
                     pose.angle == c.world().body(turning).angle,
                 qPrintable(poseText(pose)));
        QVERIFY(t.p != c.world().body(turning).position); // the origin is not the centre

        ui::Pose marked = pose;
        marked.rotation = physics::Rotation(2.0); // what no sine of 0.5 gives
        const ui::Pose again = c.drawPose(turning, &marked);
        QCOMPARE(again.rotation.c, marked.rotation.c);
        QCOMPARE(again.rotation.s, marked.rotation.s);

        c.stepForward(); // it turned: computed anew
        const ui::Pose moved = c.drawPose(turning, &marked);
        const physics::Transform now = c.world().body(turning).transform();
        QVERIFY2(moved.angle != pose.angle && moved.rotation.c == now.q.c &&
                     moved.rotation.s == now.q.s && moved.origin == now.p,
                 qPrintable(poseText(moved)));

        // Between two steps, a running clock draws the rigid motion between them: the centre
        // on its line, the origin placed from it with the angle drawn.
        c.setRunning(true);
        c.advanceClock(1.5 * c.world().def().dt);
        const ui::Pose between = c.drawPose(turning);
        const physics::Rotation q(between.angle);
        QCOMPARE(between.rotation.c, q.c);
        QCOMPARE(between.rotation.s, q.s);
        const physics::Vec2 origin = between.centre - q.apply(c.world().body(turning).localCenter);
        QVERIFY2(between.origin == origin, qPrintable(poseText(between)));
        c.setRunning(false);
    }

    // Behind the controls' tab the inspector fills in nothing, whatever the world does; shown,
    // it is up to date at once, and a frame that takes no step fills nothing in again.
    void inspectorFillsInWhatChanged()
    {
        QTemporaryDir dir;
        MainWindow w;
        test::showOnProjector(w);
        QVERIFY(openBoxes(w, dir));
        ui::SimulationController& c = w.controller();
        ui::InspectorPanel& inspector = w.inspector();
        QDockWidget* dock = w.dock(QStringLiteral("inspector"));
        QVERIFY(dock);
        w.dock(QStringLiteral("controls"))->raise();
        QCoreApplication::processEvents();
        QVERIFY(!inspector.isVisible());
        inspector.setBody(2);
        const int hidden = inspector.fillCount();
        for (int i = 0; i < 5; ++i)
            c.stepForward();
        QCOMPARE(inspector.fillCount(), hidden);

        dock->raise();
        QCoreApplication::processEvents();
        QVERIFY(inspector.isVisible());
        QCOMPARE(inspector.fillCount(), hidden + 1);
        // What it shows is the world's now (5 steps moved and turned it), as the panel writes
        // a position: four digits against a metre.
        const physics::Vec2 o = c.world().body(2).origin();
        const QString position =
            QStringLiteral("(%1, %2) m")
                .arg(ui::formatReadable(o.x(), 4, 1.0), ui::formatReadable(o.y(), 4, 1.0));
        QVERIFY2(inspector.text().contains(position),
                 qPrintable(inspector.text() + QStringLiteral(" | ") + position));

        c.setRunning(true); // a change of the clock: filled in
        const int running = inspector.fillCount();
        QCOMPARE(running, hidden + 2);
        c.advanceClock(0.0); // a frame that takes no step
        c.advanceClock(0.0);
        QCOMPARE(inspector.fillCount(), running);
        c.advanceClock(1.5 * c.world().def().dt); // one that does
        QCOMPARE(inspector.fillCount(), running + 1);
        c.setRunning(false);
    }

    // The SAT panel's table likewise; the overlay in the view reads the model, which follows
    // the pair even while the table is out of sight.
    void satTableFillsInWhatChanged()
    {
        QTemporaryDir dir;
        MainWindow w;
        test::showOnProjector(w);
        QVERIFY(openBoxes(w, dir));
        ui::SimulationController& c = w.controller();
        ui::SatPanel& sat = w.satPanel();
        QDockWidget* dock = w.dock(QStringLiteral("sat"));
        QVERIFY(dock && dock->isHidden());
        sat.setBodies(1, 2);
        QVERIFY(sat.active());
        const int hidden = sat.tableFillCount();
        const double before = sat.result().axes.front().minB;
        c.stepForward();
        QCOMPARE(sat.tableFillCount(), hidden);
        QVERIFY2(sat.result().axes.front().minB != before,
                 qPrintable(QString::number(before))); // the model followed the pair

        dock->show();
        dock->raise();
        QCoreApplication::processEvents();
        QVERIFY(sat.isVisible());
        QCOMPARE(sat.tableFillCount(), hidden + 1);

        c.setRunning(true); // nothing moved
        c.advanceClock(0.0);
        QCOMPARE(sat.tableFillCount(), hidden + 1);
        c.advanceClock(1.5 * c.world().def().dt); // the turning box moved
        QCOMPARE(sat.tableFillCount(), hidden + 2);
        c.setRunning(false);
    }

    // The bounce table skips the run's frames while out of sight; opened while the run is
    // paused (nothing more changes to refresh it), it shows the bounces measured so far.
    void bounceTableCatchesUpWhenShown()
    {
        MainWindow w;
        test::showOnProjector(w);
        const QString path =
            QDir(MainWindow::scenesFolder()).filePath(QStringLiteral("four_balls.json"));
        QCOMPARE(w.openScene(path, true), QString());
        ui::SimulationController& c = w.controller();
        QDockWidget* bounces = w.dock(QStringLiteral("bounces"));
        QDockWidget* collision = w.dock(QStringLiteral("collision"));
        QVERIFY(bounces->isHidden() && collision->isHidden());
        collision->toggleViewAction()->trigger(); // the run's events measured from here
        for (int k = 0; k < 1000; ++k)
            c.stepForward();
        QTRY_VERIFY_WITH_TIMEOUT(c.eventsUpToDate(), 120000);
        const auto ball = static_cast<physics::BodyId>(4); // e = 1: it rises again
        const auto& apexes = c.lessonWatch().measurements().apexes(ball);
        QVERIFY(!apexes.empty());
        const QString h1 = ui::csvNumber(apexes.front().y - apexes.front().bounceY);

        bounces->toggleViewAction()->trigger(); // View › Panels › Bounces, the run paused
        bounces->raise();
        QCoreApplication::processEvents();
        QVERIFY(w.bouncePanel().isVisible());
        const ui::CsvTable& csv = w.bouncePanel().table()->csv();
        QStringList cells; // the ball's row: ball, e, drop, h1, h1/h0, …
        for (const QStringList& row : csv.rows)
            if (row.value(0) == c.scene().bodyLabel(ball))
                cells = row;
        QVERIFY2(cells.value(3) == h1,
                 qPrintable(cells.join(u'|') + QStringLiteral(" | h1 ") + h1));
    }
};

RIGIDLAB_TEST_MAIN(TestPanelRefresh)
#include "test_panel_refresh.moc"
