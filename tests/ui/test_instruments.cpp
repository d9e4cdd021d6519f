// SPDX-License-Identifier: GPL-3.0-or-later
// The instruments measure what exact mechanics says: a 1 m box's diagonal is √2 m, a 30°
// incline reads 30°, a ball falls 1.25 m under g = 10 m/s² in 0.5 s (± one step); the probe
// says what the inspector says; a graph of chosen bodies keeps the sum of the momenta of an
// elastic collision to round-off, in the plot and in its CSV, and a dropped ball's y(t) is
// −g t²/2 to the step's accuracy.

#include "build_paths.h"
#include "instruments/instrument_readings.h"
#include "instruments/instruments.h"
#include "instruments/instruments_panel.h"
#include "panels/inspector_panel.h"
#include "plots/body_series.h"
#include "plots/plot_export.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"
#include "window/main_window.h"

#include "format/scene_loader.h"

#include <QAction>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QLocale>
#include <QMouseEvent>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QtTest>

#include "csv_reader.h"
#include "near.h"
#include "test_main.h"

#include <cmath>
#include <numbers>

using namespace rigidlab;
using rigidlab::ui::BodyQuantity;
using rigidlab::ui::InstrumentsPanel;

namespace {

/// A static 1 m box at (2, 1) and a static 4 m incline turned by 30°, no gravity.
constexpr const char* kShapes = R"({"rigidlab": 1,
  "world": {"gravity": [0, 0], "dt": 0.001},
  "bodies": [
    {"id": "box", "type": "static", "shape": {"type": "box", "width": 1, "height": 1},
     "position": [2, 1]},
    {"id": "incline", "type": "static", "shape": {"type": "box", "width": 4, "height": 0.2},
     "position": [-3, 0], "angle": 0.52359877559829887}]})";

/// A ball at rest 1.25 m above the line y = 0 and 1.25 m above a floor's top, g = 10 m/s².
constexpr const char* kFall = R"({"rigidlab": 1,
  "world": {"gravity": [0, -10], "dt": 0.001, "integrator": "symplectic-euler"},
  "bodies": [
    {"id": "ball", "shape": {"type": "circle", "radius": 0.1}, "position": [0.5, 1.25],
     "mass": 1},
    {"id": "floor", "type": "static", "shape": {"type": "box", "width": 4, "height": 1},
     "position": [0.5, -0.6]}]})";

/// The same ball with nothing to land on.
constexpr const char* kFreeFall = R"({"rigidlab": 1,
  "world": {"gravity": [0, -10], "dt": 0.001, "integrator": "symplectic-euler"},
  "bodies": [
    {"id": "ball", "shape": {"type": "circle", "radius": 0.1}, "position": [0.5, 1.25],
     "mass": 1}]})";

lessons::Scene sceneFrom(const char* json)
{
    const lessons::SceneLoadResult r = lessons::loadSceneJson(json, QStringLiteral("test.json"));
    if (!r.ok)
        qFatal("%s", qPrintable(r.error));
    return r.scene;
}

/// Runs the clock as the window's frames do, 1/60 s at a time: many steps between two looks.
void runFor(ui::SimulationController& c, double seconds)
{
    c.setRunning(true);
    const double end = c.time() + seconds;
    while (c.time() < end - 1e-12)
        c.advanceClock(1.0 / 60.0);
    c.setRunning(false);
}

/// The reading labelled `name` for a screen reader, or nullptr.
QLabel* readingNamed(const InstrumentsPanel& panel, const QString& name)
{
    for (QLabel* label : panel.findChildren<QLabel*>())
        if (label->accessibleName() == name)
            return label;
    return nullptr;
}

/// The leading number of a text in the default locale ("1,414 m" → 1.414).
double leadingNumber(const QString& text)
{
    static const QRegularExpression number(QStringLiteral("^[^0-9−-]*([−-]?[0-9]+([.,][0-9]+)?)"));
    const auto m = number.match(text);
    QString digits = m.captured(1);
    digits.replace(QChar(0x2212), QLatin1Char('-'));
    bool ok = false;
    const double v = QLocale().toDouble(digits, &ok);
    return ok ? v : std::nan("");
}

} // namespace

class TestInstruments : public QObject {
    Q_OBJECT

private slots:
    void init() { QLocale::setDefault(QLocale(QLocale::Czech)); }
    void cleanup() { QLocale::setDefault(QLocale::c()); }

    void rulerSnapsToTheDiagonal()
    {
        ui::SimulationController c;
        c.loadScene(sceneFrom(kShapes), QString());
        InstrumentsPanel panel(c);
        panel.setSnapRadius(0.05);
        // Dropped near two opposite corners, the ends go exactly there.
        panel.setRuler({1.5 + 0.02, 0.5 - 0.01}, {2.5 - 0.01, 1.5 + 0.03});
        QCOMPARE(panel.rulerStart(), physics::Vec2(1.5, 0.5));
        QCOMPARE(panel.rulerEnd(), physics::Vec2(2.5, 1.5));
        RL_VERIFY_NEAR(panel.rulerLength(), std::numbers::sqrt2, 1e-12, 0);
        QCOMPARE(panel.rulerText(), QStringLiteral("1,414\u00a0m"));
        // Without snapping the hand's imprecision stays.
        panel.setSnapping(false);
        panel.setRuler({1.52, 0.49}, {2.5, 1.5});
        QVERIFY(std::abs(panel.rulerLength() - std::numbers::sqrt2) > 1e-3);
        // Snapping to a centre of mass: the box's centre to a corner is half the diagonal.
        panel.setSnapping(true);
        panel.setRuler({2.01, 1.01}, {2.49, 1.52});
        RL_VERIFY_NEAR(panel.rulerLength(), std::numbers::sqrt2 / 2, 1e-12, 0);
    }

    void rulerTypedByKeyboard()
    {
        ui::SimulationController c;
        c.loadScene(sceneFrom(kShapes), QString());
        InstrumentsPanel panel(c);
        // The fields, as a keyboard user types them: start (1.5, 0.5), end (2.5, 1.5).
        const QList<QDoubleSpinBox*> fields = panel.findChildren<QDoubleSpinBox*>();
        QDoubleSpinBox* f[4] = {};
        for (QDoubleSpinBox* field : fields) {
            const QString name = field->accessibleName();
            const int i = name == panel.tr("Ruler start x")   ? 0
                          : name == panel.tr("Ruler start y") ? 1
                          : name == panel.tr("Ruler end x")   ? 2
                          : name == panel.tr("Ruler end y")   ? 3
                                                              : -1;
            if (i >= 0)
                f[i] = field;
        }
        for (QDoubleSpinBox* field : f)
            QVERIFY(field);
        const double typed[4] = {1.5, 0.5, 2.5, 1.5};
        for (int i = 0; i < 4; ++i) {
            f[i]->selectAll();
            QTest::keyClicks(f[i], QLocale().toString(typed[i]));
            QTest::keyClick(f[i], Qt::Key_Return);
        }
        RL_VERIFY_NEAR(panel.rulerLength(), std::numbers::sqrt2, 1e-12, 0);
        // An arrow key nudges the end by a centimetre.
        QTest::keyClick(f[2], Qt::Key_Up);
        RL_VERIFY_NEAR(panel.rulerEnd().x(), 2.51, 1e-12, 0);
        // The reading is text with a name a screen reader says, read when the panel shows.
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QLabel* reading = readingNamed(panel, panel.tr("Length measured by the ruler"));
        QVERIFY(reading);
        QCOMPARE(reading->text(), panel.rulerText());
    }

    void protractorReadsTheIncline()
    {
        ui::SimulationController c;
        c.loadScene(sceneFrom(kShapes), QString());
        InstrumentsPanel panel(c);
        // The angle of the body.
        panel.setProtractorMode(InstrumentsPanel::ProtractorMode::Body);
        panel.setProtractorBody(1);
        RL_VERIFY_NEAR(panel.protractorDegrees(), 30.0, 1e-9, 0);
        QCOMPARE(panel.protractorText(), QStringLiteral("30°"));
        // Between two lines: the incline's lower edge and the horizontal from its lower corner.
        const std::vector<physics::Vec2> corners = ui::instruments::bodyVertices(c.world().body(1));
        QCOMPARE(corners.size(), std::size_t(4));
        panel.setSnapRadius(0.05);
        panel.setProtractorMode(InstrumentsPanel::ProtractorMode::Lines);
        const physics::Vec2 lowerLeft = corners[0], lowerRight = corners[1];
        panel.setProtractorLines(lowerLeft + physics::Vec2(0.01, 0.02),
                                 lowerRight - physics::Vec2(0.02, 0.01),
                                 lowerLeft + physics::Vec2(2, 0));
        QCOMPARE(panel.protractorVertex(), lowerLeft);
        RL_VERIFY_NEAR(panel.protractorDegrees(), 30.0, 1e-9, 0);
    }

    void stopwatchTimesTheFall_data()
    {
        QTest::addColumn<int>("stopOn");
        QTest::newRow("passing the line y = 0") << int(ui::instruments::Trigger::PassesLine);
        QTest::newRow("first contact with the floor")
            << int(ui::instruments::Trigger::FirstContact);
    }
    void stopwatchTimesTheFall()
    {
        QFETCH(int, stopOn);
        const bool line = stopOn == int(ui::instruments::Trigger::PassesLine);
        ui::SimulationController c;
        c.loadScene(sceneFrom(line ? kFreeFall : kFall), QString());
        InstrumentsPanel panel(c);
        ui::instruments::TriggerSpec spec;
        spec.kind = static_cast<ui::instruments::Trigger>(stopOn);
        spec.body = 0;
        spec.lineY = 0.0;
        panel.setStopTrigger(spec);
        // Its centre passes y = 0 (in free fall), or its bottom meets the floor's top at
        // y = -0.1: 1.25 m down either way.
        panel.startStopwatch();
        QCOMPARE(panel.stopwatch().state(), ui::instruments::Stopwatch::State::Running);
        runFor(c, 1.0);
        QCOMPARE(panel.stopwatch().state(), ui::instruments::Stopwatch::State::Stopped);
        const double dt = c.world().def().dt;
        // t = √(2 h / g) = √(2 · 1.25 / 10) = 0.5 s.
        const double exact = std::sqrt(2.0 * 1.25 / 10.0);
        RL_VERIFY_NEAR(panel.stopwatchSeconds(), exact, dt * (1 + 1e-9), 0);
        // Shown to the step, in the locale.
        QCOMPARE(leadingNumber(panel.stopwatchText()), panel.stopwatchSeconds());
        QVERIFY(panel.stopwatchText().endsWith(QStringLiteral("\u00a0s")));
        // Back on the timeline before the stop, the watch runs again from its start.
        c.seek(200);
        QCOMPARE(panel.stopwatch().state(), ui::instruments::Stopwatch::State::Running);
        RL_VERIFY_NEAR(panel.stopwatchSeconds(), 0.2, 1e-12, 0);
    }

    void stopwatchStartsOnAnEvent()
    {
        ui::SimulationController c;
        c.loadScene(sceneFrom(kFall), QString());
        InstrumentsPanel panel(c);
        ui::instruments::TriggerSpec start;
        start.kind = ui::instruments::Trigger::PassesLine;
        start.lineY = 1.25 - 0.45; // reached at t = 0.3 s
        panel.setStartTrigger(start);
        ui::instruments::TriggerSpec stop = start;
        stop.kind = ui::instruments::Trigger::FirstContact; // at t = 0.5 s
        panel.setStopTrigger(stop);
        panel.startStopwatch();
        QCOMPARE(panel.stopwatch().state(), ui::instruments::Stopwatch::State::Armed);
        runFor(c, 1.0);
        QCOMPARE(panel.stopwatch().state(), ui::instruments::Stopwatch::State::Stopped);
        RL_VERIFY_NEAR(panel.stopwatchSeconds(), 0.2, 2 * c.world().def().dt, 0);
        RL_VERIFY_NEAR(double(*panel.stopwatch().startStep()), 300, 1, 0);
    }

    void probeAgreesWithTheInspector()
    {
        ui::SimulationController c;
        c.loadScene(sceneFrom(kFall), QString());
        InstrumentsPanel panel(c);
        ui::InspectorPanel inspector(c);
        panel.setProbeBody(0);
        inspector.setBody(0);
        for (int i = 0; i < 300; ++i)
            c.stepForward();
        const physics::Body& ball = c.world().body(0);
        const ui::instruments::ProbeReading r = panel.probeReading();
        QCOMPARE(r.position, ball.position);
        QCOMPARE(r.speed, ball.velocity.norm());
        RL_VERIFY_NEAR(r.weight.y(), -10.0, 1e-12, 0);
        // The same numbers as the inspector shows, line for line: position, |v|, E_k.
        const QStringList shown = inspector.text().split(QLatin1Char('\n'));
        const QStringList probe = panel.probeLines();
        QCOMPARE(leadingNumber(probe[0]), leadingNumber(shown[3].section(QLatin1Char(';'), 0, 0)));
        QCOMPARE(leadingNumber(probe[3]), leadingNumber(shown[6]));
        QCOMPARE(probe[5].section(QStringLiteral(" = "), 1), shown[8]);
        QVERIFY2(std::isfinite(leadingNumber(probe[3])), qPrintable(probe[3]));
        // At t = 0.3 s the ball falls at g t = 3 m/s.
        RL_VERIFY_NEAR(leadingNumber(probe[3]), 3.0, 1e-3, 0);
        // Lying on the floor, the contact force holds the weight up.
        runFor(c, 1.5);
        RL_VERIFY_NEAR(panel.probeReading().contactForce.y(), 10.0, 0.05, 0);
    }

    void panelReadsOnlyWhatIsInSight()
    {
        ui::SimulationController c;
        c.loadScene(sceneFrom(kFall), QString());
        InstrumentsPanel panel(c);
        panel.setProbeBody(0);
        panel.tabs()->setCurrentIndex(InstrumentsPanel::ProbeTab);
        QLabel* probe = readingNamed(panel, panel.tr("Probe reading"));
        QLabel* watch = readingNamed(panel, panel.tr("Time on the stopwatch"));
        QVERIFY(probe && watch);
        // Hidden: the world falls, and nothing is read, nothing said changed.
        QSignalSpy changed(&panel, &InstrumentsPanel::changed);
        const QString hidden = probe->text();
        runFor(c, 0.25);
        QCOMPARE(changed.count(), 0);
        QCOMPARE(probe->text(), hidden);
        // Shown: the probe reads the world as it is now, at once.
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QCOMPARE(probe->text(), panel.probeText());
        QVERIFY2(probe->text() != hidden, qPrintable(hidden));
        // The open tab follows the world; the stopwatch's tab behind it is not read ...
        panel.startStopwatch();
        const QString behind = watch->text();
        runFor(c, 0.25);
        QCOMPARE(probe->text(), panel.probeText());
        QCOMPARE(watch->text(), behind);
        QVERIFY(panel.stopwatchText() != behind);
        // ... until it is opened.
        panel.tabs()->setCurrentIndex(InstrumentsPanel::StopwatchTab);
        QCOMPARE(watch->text(), panel.stopwatchText());
    }

    void sumOfMomentaIsConservedInPlotAndExport()
    {
        ui::MainWindow w;
        QVERIFY(w.openScene(rigidlab::test::sourcePath(u"/lessons/scenes/two_ball_collision.json"),
                            true)
                    .isEmpty());
        ui::BodyGraphSpec spec;
        spec.quantity = BodyQuantity::Px;
        spec.bodies = {0, 1};
        spec.sum = true;
        ui::PlotWidget* plot = w.instruments().showGraph(spec);
        QVERIFY(w.instruments().graphsShown().contains(plot));
        QCOMPARE(plot->model().seriesCount(), 3);
        runFor(w.controller(), 2.0);
        const auto moving = plot->model().points(0), resting = plot->model().points(1),
                   sum = plot->model().points(2);
        QVERIFY(sum.size() > 100);
        // The collision happened: the moving ball handed its momentum over.
        RL_VERIFY_NEAR(moving.front().y(), 2.0, 1e-12, 0);
        RL_VERIFY_AT_MOST(std::abs(moving.back().y()), 1e-6);
        RL_VERIFY_NEAR(resting.back().y(), 2.0, 1e-6, 0);
        for (const QPointF& p : sum)
            RL_VERIFY_NEAR(p.y(), 2.0, 1e-12, 0);
        // The export writes every digit: the sum column is 2 to round-off too.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("momenta.csv"));
        QVERIFY(ui::exportPlot(*plot, path, ui::ExportFormat::Csv).ok);
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const test::CsvTable table = test::readCsv(file.readAll(), ',');
        QVERIFY(table.rows.size() > 100);
        QCOMPARE(table.rows[0].size(), 4);
        QVERIFY2(table.rows[0][3].startsWith(QStringLiteral("p_x")), qPrintable(table.rows[0][3]));
        for (int i = 1; i < table.rows.size(); ++i)
            RL_VERIFY_NEAR(table.rows[i][3].toDouble(), 2.0, 1e-12, 0);
        // Back on the timeline to before the hit: the curves end there, the rest is the ghost.
        w.controller().seek(500);
        QCOMPARE(plot->model().points(2).back().x(), 0.5);
        QVERIFY(!plot->model().ghostPoints(2).empty());
        RL_VERIFY_NEAR(plot->model().points(0).back().y(), 2.0, 1e-12, 0);
    }

    void graphsOfBodiesStayWithTheirBodies()
    {
        ui::MainWindow w;
        QVERIFY(w.openScene(rigidlab::test::sourcePath(u"/lessons/scenes/two_ball_collision.json"),
                            true)
                    .isEmpty());
        ui::Instruments& instruments = w.instruments();
        ui::BodyGraphSpec resting;
        resting.quantity = BodyQuantity::Vx;
        resting.bodies = {1}; // "resting"
        ui::PlotWidget* kept = instruments.showGraph(resting);
        ui::BodyGraphSpec both;
        both.quantity = BodyQuantity::Px;
        both.bodies = {0, 1};
        both.sum = true;
        instruments.showGraph(both);
        QCOMPARE(instruments.graphsShown().size(), 2);
        // The same scene again (as an edit or Reset would load it): both graphs stay.
        QVERIFY(w.openScene(rigidlab::test::sourcePath(u"/lessons/scenes/two_ball_collision.json"),
                            true)
                    .isEmpty());
        QCOMPARE(instruments.graphsShown().size(), 2);
        // A scene with the resting ball alone, first now, and pushed at 1 m/s: its graph stays
        // and plots it there; the graph of both balls closes.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("resting_alone.json"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"rigidlab": 1, "title": "resting alone",
            "world": {"gravity": [0, 0], "dt": 0.001},
            "bodies": [
              {"id": "resting", "label": "ball at rest", "shape": {"type": "circle", "radius": 0.2},
               "mass": 1, "velocity": [1, 0]},
              {"id": "other", "shape": {"type": "circle", "radius": 0.2}, "mass": 1,
               "position": [0, 2]}]})");
        file.close();
        QCOMPARE(w.openScene(path, true), QString());
        QCoreApplication::processEvents(); // the closed dock goes
        const QList<ui::PlotWidget*> shown = instruments.graphsShown();
        QCOMPARE(shown.size(), 1);
        ui::PlotWidget* graph = shown.front();
        QVERIFY(graph != kept); // a plot of the new scene's world
        QCOMPARE(graph->model().seriesCount(), 1);
        QCOMPARE(graph->model().seriesLegend(0), QStringLiteral("ball at rest"));
        runFor(w.controller(), 0.5);
        const auto points = graph->model().points(0);
        QVERIFY(points.size() > 10);
        for (const QPointF& p : points)
            RL_VERIFY_NEAR(p.y(), 1.0, 1e-12, 0);
    }

    void centreOfMassFrameShowsOppositeMomenta()
    {
        ui::SimulationController c;
        c.loadScene(lessons::loadSceneFile(
                        rigidlab::test::sourcePath(u"/lessons/scenes/two_ball_collision.json"))
                        .scene,
                    QString());
        ui::PlotWidget plot(QStringLiteral("p"));
        ui::BodyGraph graph(plot, BodyQuantity::Px, ui::ReferenceFrame{{0, 1}});
        graph.addBody(0, QStringLiteral("a"));
        graph.addBody(1, QStringLiteral("b"));
        graph.addSum({0, 1}, QStringLiteral("a + b"));
        graph.record(c.world(), c.time());
        runFor(c, 2.0);
        graph.record(c.world(), c.time());
        // Before: +1 and −1 kg m/s about the centre of mass; after, exchanged; always 0 in sum.
        RL_VERIFY_NEAR(plot.model().points(0).front().y(), 1.0, 1e-12, 0);
        RL_VERIFY_NEAR(plot.model().points(1).front().y(), -1.0, 1e-12, 0);
        RL_VERIFY_NEAR(plot.model().points(0).back().y(), -1.0, 1e-6, 0);
        for (const QPointF& p : plot.model().points(2))
            RL_VERIFY_AT_MOST(std::abs(p.y()), 1e-12);
    }

    void droppedBallFollowsTheParabola()
    {
        ui::SimulationController c;
        c.loadScene(sceneFrom(kFall), QString());
        ui::PlotWidget plot(QStringLiteral("y"));
        ui::BodyGraph y(plot, BodyQuantity::Y, {});
        y.addBody(0, QStringLiteral("ball"));
        ui::PlotWidget plotX(QStringLiteral("x"));
        ui::BodyGraph x(plotX, BodyQuantity::X, {});
        x.addBody(0, QStringLiteral("ball"));
        QObject::connect(&c, &ui::SimulationController::worldChanged, &plot, [&] {
            y.record(c.world(), c.time());
            x.record(c.world(), c.time());
        });
        y.record(c.world(), c.time());
        runFor(c, 0.45); // before it reaches the floor
        const double g = 10.0, dt = c.world().def().dt, y0 = 1.25;
        const auto points = plot.model().points(0);
        QVERIFY(points.size() > 20);
        for (const QPointF& p : points) {
            const double t = p.x();
            // Symplectic Euler is first order: it falls g t dt / 2 further than −g t²/2.
            RL_VERIFY_AT_MOST(std::abs(p.y() - (y0 - g * t * t / 2)), g * t * dt);
        }
        for (const QPointF& p : plotX.model().points(0))
            QCOMPARE(p.y(), 0.5);
    }

    void viewFollowsTheCentreOfMassFrame()
    {
        ui::MainWindow w;
        w.resize(1024, 768);
        w.show();
        QVERIFY(w.openScene(rigidlab::test::sourcePath(u"/lessons/scenes/two_ball_collision.json"),
                            true)
                    .isEmpty());
        w.instruments().panel()->setFrameBodies({0, 1});
        runFor(w.controller(), 1.5);
        // The view's centre is the two balls' centre of mass, wherever it went.
        const physics::World& world = w.controller().world();
        const physics::Vec2 com = (world.body(0).position + world.body(1).position) / 2;
        const QPointF centre = w.view().mapToScene(w.view().viewport()->rect().center());
        const double pixel = 1.0 / w.view().zoom();
        RL_VERIFY_NEAR(centre.x(), com.x(), 2 * pixel, 0);
        RL_VERIFY_NEAR(centre.y(), com.y(), 2 * pixel, 0);
        // It moved on from x = -0.5 at 1 m/s: the view went with it.
        RL_VERIFY_NEAR(com.x(), -0.5 + w.controller().time(), 1e-9, 0);
    }

    void rulerLaidWithTheMouse()
    {
        ui::MainWindow w;
        w.resize(1024, 768);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.openScene(rigidlab::test::sourcePath(u"/lessons/scenes/two_ball_collision.json"),
                            true)
                    .isEmpty());
        w.instruments().dock()->show();
        InstrumentsPanel& panel = *w.instruments().panel();
        panel.tabs()->setCurrentIndex(InstrumentsPanel::RulerTab);
        QCoreApplication::processEvents();
        // Shift and a drag from near one ball's centre to near the other's: snapped, 2 m.
        ui::WorldView& view = w.view();
        const auto at = [&](double x, double y) {
            return view.mapFromScene(QPointF(x, y)) + QPoint(2, -1); // a hand is not exact
        };
        QWidget* viewport = view.viewport();
        QTest::mousePress(viewport, Qt::LeftButton, Qt::ShiftModifier, at(-1.5, 0));
        QMouseEvent move(QEvent::MouseMove, at(0.5, 0), viewport->mapToGlobal(at(0.5, 0)),
                         Qt::NoButton, Qt::LeftButton, Qt::ShiftModifier);
        QCoreApplication::sendEvent(viewport, &move);
        QTest::mouseRelease(viewport, Qt::LeftButton, Qt::ShiftModifier, at(0.5, 0));
        QCOMPARE(panel.rulerStart(), physics::Vec2(-1.5, 0));
        QCOMPARE(panel.rulerEnd(), physics::Vec2(0.5, 0));
        RL_VERIFY_NEAR(panel.rulerLength(), 2.0, 1e-12, 0);
        // The ruler is not a grab: the balls stayed where they were.
        QCOMPARE(w.controller().world().body(0).position, physics::Vec2(-1.5, 0));
        QVERIFY(!w.controller().grabSpring().body());
    }

    void lessonCanHideThem()
    {
        ui::MainWindow w;
        ui::Instruments& instruments = w.instruments();
        instruments.dock()->show();
        instruments.setAvailable(false);
        QVERIFY(instruments.dock()->isHidden());
        QVERIFY(!instruments.graphAction()->isEnabled());
        instruments.setAvailable(true);
        QVERIFY(instruments.graphAction()->isEnabled());
    }
};

RIGIDLAB_TEST_MAIN(TestInstruments)
#include "test_instruments.moc"
