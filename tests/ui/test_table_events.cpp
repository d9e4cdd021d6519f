// SPDX-License-Identifier: GPL-3.0-or-later
// The bounce and collision tables in a scene that is no lesson: measured only while a table
// shows them; one opened later has the run so far measured again, a slice a turn of the event
// loop, and says so over the table and in its description until it is up to date.

#include "lesson_player/lesson_panels.h"
#include "panels/fitting_table.h"
#include "simulation/simulation_controller.h"
#include "window/main_window.h"

#include "format/scene.h"
#include "format/scene_schema.h"
#include "run/measurements.h"

#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QLabel>
#include <QtTest>

#include "test_main.h"

using namespace rigidlab;
using rigidlab::ui::FittingTable;
using rigidlab::ui::MainWindow;

namespace {

/// Where two measurements of the same run differ ("" when they agree bit for bit): each
/// body's bounce times and apexes, and the collisions.
QString eventsDiffer(const lessons::Measurements& a, const lessons::Measurements& b,
                     std::size_t bodies)
{
    for (std::size_t i = 0; i < bodies; ++i) {
        const auto id = static_cast<physics::BodyId>(i);
        if (a.bounces(id) != b.bounces(id))
            return QStringLiteral("body %1: %2 bounces, %3 expected")
                .arg(i)
                .arg(a.bounces(id).size())
                .arg(b.bounces(id).size());
        const auto& pa = a.apexes(id);
        const auto& pb = b.apexes(id);
        if (pa.size() != pb.size())
            return QStringLiteral("body %1: %2 apexes, %3 expected")
                .arg(i)
                .arg(pa.size())
                .arg(pb.size());
        for (std::size_t k = 0; k < pa.size(); ++k)
            if (pa[k].t != pb[k].t || pa[k].y != pb[k].y || pa[k].bounceY != pb[k].bounceY)
                return QStringLiteral("body %1, apex %2: y %3, %4 expected")
                    .arg(i)
                    .arg(k)
                    .arg(pa[k].y, 0, 'g', 17)
                    .arg(pb[k].y, 0, 'g', 17);
    }
    if (a.collisions().size() != b.collisions().size())
        return QStringLiteral("%1 collisions, %2 expected")
            .arg(a.collisions().size())
            .arg(b.collisions().size());
    for (std::size_t k = 0; k < a.collisions().size(); ++k) {
        const lessons::CollisionEvent& ca = a.collisions()[k];
        const lessons::CollisionEvent& cb = b.collisions()[k];
        if (ca.t != cb.t || ca.a != cb.a || ca.b != cb.b ||
            ca.velocityAfter[0] != cb.velocityAfter[0] || ca.impulse != cb.impulse)
            return QStringLiteral("collision %1 at t = %2 s, %3 s expected")
                .arg(k)
                .arg(ca.t)
                .arg(cb.t);
    }
    return {};
}

} // namespace

class TestTableEvents : public QObject {
    Q_OBJECT
private slots:
    void eventsMeasuredWhileATableReads();
};

/// The line over each event table that says the run so far is still being measured, with
/// the table's description, as "line|description", for the tables that show it now.
QStringList measuringNotes(MainWindow& w)
{
    QStringList out;
    for (QWidget* panel :
         {static_cast<QWidget*>(&w.bouncePanel()), static_cast<QWidget*>(&w.collisionPanel())}) {
        auto* note = panel->findChild<QLabel*>(QStringLiteral("measuringNote"));
        const auto* table = panel->findChild<FittingTable*>();
        if (!note || !table)
            return QStringList{QStringLiteral("no note")};
        if (note->isVisibleTo(panel))
            out << note->text() + u'|' + table->accessibleDescription();
    }
    return out;
}

// In a scene that is no lesson the bounces and collisions are measured only while a table
// shows them; one opened later shows the run so far, as measured by a run without a window
// from the start (the same scene, the same steps, the same setting changed at the same step).
void TestTableEvents::eventsMeasuredWhileATableReads()
{
    MainWindow w;
    const QString path =
        QDir(MainWindow::scenesFolder()).filePath(QStringLiteral("four_balls.json"));
    QCOMPARE(w.openScene(path, true), QString());
    ui::SimulationController& c = w.controller();
    const ui::LessonWatch& watch = c.lessonWatch();
    QDockWidget* bounces = w.dock(QStringLiteral("bounces"));
    QDockWidget* collision = w.dock(QStringLiteral("collision"));
    QVERIFY(bounces->isHidden() && collision->isHidden());

    // The same run without a window, measured from its start.
    physics::World world = lessons::buildWorld(c.scene());
    world.updateDiagnostics();
    lessons::Measurements all;
    all.reset(world, {});
    const lessons::schema::Field* restitution =
        lessons::schema::findField(lessons::schema::Object::World, "restitution");
    QVERIFY(restitution);
    const auto stepBoth = [&](int steps) {
        for (int k = 0; k < steps; ++k) {
            c.stepForward();
            world.step();
            all.observe(world);
            if (world.stepCount() == 700) { // a setting changed mid-run, in both
                c.setRestitution(0.9);
                restitution->apply(world, 0.9);
            }
        }
    };
    const std::size_t n = world.bodies().size();

    stepBoth(1000);
    QVERIFY(!all.collisions().empty() && !all.apexes(4).empty()); // e = 1 rose again
    // Read by nobody: measured not (a window measured every step of every scene).
    QVERIFY(!watch.measuring());
    QVERIFY(watch.measurements().collisions().empty());
    for (std::size_t i = 0; i < n; ++i)
        QVERIFY(watch.measurements().bounces(static_cast<physics::BodyId>(i)).empty());

    // The run so far measured again a slice per turn of the event loop, here one step a slice,
    // while the present steps on, unmeasured until the replay reaches it.
    c.setEventReplaySlice(0);
    // Meanwhile each table says so in a line over it, and in its description for a screen
    // reader; the line goes once the table is up to date.
    const auto notes = [&w] { return measuringNotes(w); };
    const QString measuring = QStringLiteral("Measuring the run so far…");
    QCOMPARE(notes(), QStringList());
    QSignalSpy catchingUp(&c, &ui::RunView::eventsCatchingUpChanged);
    bounces->toggleViewAction()->trigger(); // View › Panels › Bounces
    QVERIFY(watch.measuring());
    QVERIFY(!c.eventsUpToDate()); // 1,000 steps to walk again, one walked in this turn
    QVERIFY(c.eventsCatchingUp());
    QCOMPARE(notes(), QStringList(2, measuring + u'|' + measuring));
    stepBoth(20);
    QVERIFY(!c.eventsUpToDate());
    QTRY_VERIFY_WITH_TIMEOUT(c.eventsUpToDate(), 120000);
    QCOMPARE(eventsDiffer(watch.measurements(), all, n), QString());
    QVERIFY(!c.eventsCatchingUp());
    QCOMPARE(notes(), QStringList());
    QCOMPARE(catchingUp.size(), 2); // said when it started and when it was done, no more
    c.setEventReplaySlice(5);
    stepBoth(300); // measured as the run goes
    QCOMPARE(eventsDiffer(watch.measurements(), all, n), QString());

    bounces->toggleViewAction()->trigger(); // closed: not measured
    QVERIFY(!watch.measuring());
    stepBoth(400);
    collision->toggleViewAction()->trigger(); // the other table reads them too
    QVERIFY(watch.measuring());
    QTRY_VERIFY_WITH_TIMEOUT(c.eventsUpToDate(), 120000);
    QCOMPARE(eventsDiffer(watch.measurements(), all, n), QString());
}

RIGIDLAB_TEST_MAIN(TestTableEvents)
#include "test_table_events.moc"
