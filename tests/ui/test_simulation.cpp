// SPDX-License-Identifier: GPL-3.0-or-later
// The simulation folder: the controller's clock and the helpers it hands its jobs to (the grab
// spring, frame timing, the samples and energy references, the settings-edit log), the one
// clock the status bar and the timeline read, and what the status bar's energy drift is the
// error of. Worlds compared side by side are test_compared_worlds.cpp.

#include "build_paths.h"
#include "common/display_names.h"
#include "simulation/catch_up.h"
#include "simulation/drift_words.h"
#include "simulation/frame_timing.h"
#include "simulation/grab_spring.h"
#include "simulation/sample_recorder.h"
#include "simulation/setting_edit.h"
#include "simulation/simulation_controller.h"
#include "window/main_window.h"

#include <QLabel>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QtTest>

#include <algorithm>
#include <limits>

#include "physics/physics_test_util.h"
#include "simulation_scenes.h"
#include "test_main.h"

using namespace rigidlab;
using namespace rigidlab::ui;
using rigidlab::test::ballScene;
using rigidlab::test::bouncingBall;
using rigidlab::test::kDt;

namespace {

/// The number in the first "t = X s" of a label's text, as shown.
QString shownTime(const QString& text)
{
    static const QRegularExpression t(QStringLiteral("t = ([^ ]+) s"));
    return t.match(text).captured(1);
}

/// What a run of frames did under the catch-up rule.
struct FramesRun {
    int frames = 0;
    long long steps = 0;
    double longestPhysicsMs = 0.0; ///< the most physics one frame did [ms]
    int mostStepsInAFrame = 0;
    double mostOwed = 0.0; ///< the most time owed after a frame [s]
};

/// Runs `frames` frames of a world whose every step costs `stepMs` and whose drawing costs
/// `drawMs`, with the time given (no clock read): the first frame 20 ms after play, each
/// next one 16 ms after the last one started, or when the last one finished if it ran late.
FramesRun runFrames(CatchUp& clock, int frames, double dt, double stepMs, double drawMs)
{
    FramesRun run;
    double wall = 0.020;
    for (int f = 0; f < frames; ++f) {
        clock.beginFrame(wall, 1.0);
        double physicsMs = 0.0;
        int steps = 0;
        while (clock.nextStep(dt, physicsMs)) {
            physicsMs += stepMs;
            clock.stepTaken(dt, stepMs);
            ++steps;
        }
        clock.endFrame(dt);
        ++run.frames;
        run.steps += steps;
        run.longestPhysicsMs = std::max(run.longestPhysicsMs, physicsMs);
        run.mostStepsInAFrame = std::max(run.mostStepsInAFrame, steps);
        run.mostOwed = std::max(run.mostOwed, clock.owed());
        wall = std::max(0.016, (physicsMs + drawMs) * 1e-3);
    }
    return run;
}

} // namespace

class TestSimulation : public QObject {
    Q_OBJECT

private slots:
    void clockTakesTheStepsTheWallTimeOwes()
    {
        SimulationController c;
        c.loadScene(ballScene(false), QStringLiteral("ball.json"));
        QCOMPARE(c.world().def().dt, kDt);
        // Paused, a frame takes no step.
        c.advanceClock(5 * kDt);
        QCOMPARE(c.world().stepCount(), 0LL);
        c.setRunning(true);
        c.advanceClock(5 * kDt);
        QCOMPARE(c.world().stepCount(), 5LL);
        QVERIFY(!c.slowerThanRealTime());
        // At half speed, four steps' worth of wall time owes two.
        c.setTimeScale(0.5);
        c.advanceClock(4 * kDt);
        QCOMPARE(c.world().stepCount(), 7LL);
        c.setTimeScale(1.0);
        // A frame after a long gap counts as 0.1 s at most, and says the run fell behind.
        c.advanceClock(1.0);
        QCOMPARE(c.world().stepCount(), 7LL + static_cast<long long>(0.1 / kDt));
        QVERIFY(c.slowerThanRealTime());
        // Held (the editor), the world never steps.
        c.setStepsHeld(true);
        c.advanceClock(5 * kDt);
        QCOMPARE(c.world().stepCount(), 7LL + static_cast<long long>(0.1 / kDt));
        // The clock's time is the step's time, the samples' time too.
        QCOMPARE(c.time(), stepTime(c.world().stepCount(), kDt));
    }

    void lateFramesOfACheapWorldCatchUp()
    {
        // Steps of 0.1 ms: a frame 50 ms late pays all it owes, in one frame.
        CatchUp clock;
        runFrames(clock, 5, kDt, 0.1, 2.0);
        QVERIFY(!clock.slower());
        clock.beginFrame(0.050, 1.0);
        int steps = 0;
        double physicsMs = 0.0;
        while (clock.nextStep(kDt, physicsMs)) {
            clock.stepTaken(kDt, 0.1);
            physicsMs += 0.1;
            ++steps;
        }
        clock.endFrame(kDt);
        QCOMPARE(steps, 7); // 50 ms and what the last frames left: 7.2 steps of 1/128 s
        QVERIFY(!clock.slower());
        QCOMPARE(clock.dropped(), 0.0);
        RL_VERIFY_AT_MOST(clock.owed(), kDt);
    }

    void lateFramesOfAHeavyWorldDropTimeAndSaySo()
    {
        // The base-100 pyramid on a loaded machine: 9 ms a step, 9 ms to draw, dt = 1/60 s.
        // Each frame is late (18 ms), and if it took every step it owes it would be later
        // still the next time. It takes one step and drops the rest.
        constexpr double dt = 1.0 / 60.0;
        CatchUp clock;
        const FramesRun run = runFrames(clock, 300, dt, 9.0, 9.0);
        QCOMPARE(run.mostStepsInAFrame, 1);
        RL_VERIFY_AT_MOST(run.longestPhysicsMs, 9.0);
        RL_VERIFY_AT_MOST(run.mostOwed, dt);
        QVERIFY(clock.slower());
        QVERIFY(clock.dropped() > 0.0);
        RL_VERIFY_NEAR(clock.stepEstimateMs(), 9.0, 1e-9, 0.0);

        // 5 ms a step: two fit the budget of 10 ms, a third would not.
        CatchUp medium;
        medium.beginFrame(0.1, 1.0);
        QVERIFY(medium.nextStep(dt, 0.0));
        medium.stepTaken(dt, 5.0);
        QVERIFY(medium.nextStep(dt, 5.0));
        medium.stepTaken(dt, 5.0);
        QVERIFY(!medium.nextStep(dt, 10.0));
        medium.endFrame(dt);
        RL_VERIFY_AT_MOST(medium.owed(), dt);
        RL_VERIFY_NEAR(medium.dropped(), 0.1 - 2 * dt - medium.owed(), 1e-12, 0.0);

        // A step dearer than the whole budget: still one step a frame, so the world moves.
        CatchUp dear;
        const FramesRun slow = runFrames(dear, 10, dt, 40.0, 6.0);
        QCOMPARE(slow.steps, 10LL);
        QCOMPARE(slow.mostStepsInAFrame, 1);
    }

    void slowerThanRealTimeHoldsForASecond()
    {
        constexpr double dt = 1.0 / 60.0;
        CatchUp clock;
        clock.beginFrame(0.5, 1.0); // a gap: counts as 0.1 s, the rest is dropped
        RL_VERIFY_NEAR(clock.dropped(), 0.4, 1e-12, 0.0);
        while (clock.nextStep(dt, 0.0))
            clock.stepTaken(dt, 0.1);
        clock.endFrame(dt);
        QVERIFY(clock.slower());
        // Frames on time: still said for a second, so that the status bar can be read...
        runFrames(clock, 50, dt, 0.1, 2.0); // 0.8 s
        QVERIFY(clock.slower());
        // ...then no more.
        runFrames(clock, 20, dt, 0.1, 2.0);
        QVERIFY(!clock.slower());
        // Nonsense times owe nothing.
        CatchUp odd;
        odd.beginFrame(std::numeric_limits<double>::quiet_NaN(), 1.0);
        odd.beginFrame(-1.0, 1.0);
        QCOMPARE(odd.owed(), 0.0);
    }

    void controllerDropsWhatAFrameCannotPay()
    {
        SimulationController c;
        c.loadScene(ballScene(false), QStringLiteral("ball.json"));
        c.setRunning(true);
        c.advanceClock(1.0);
        QVERIFY(c.slowerThanRealTime());
        RL_VERIFY_NEAR(c.catchUp().dropped(), 0.9, 1e-12, 0.0);
        // What the long frame could not pay is not owed the next one.
        const long long after = c.world().stepCount();
        c.advanceClock(kDt);
        QCOMPARE(c.world().stepCount(), after + 1);
        // Paused, the run is not said to be slow.
        c.setRunning(false);
        QVERIFY(!c.slowerThanRealTime());
    }

    void statusBarAndTimelineShowOneClock()
    {
        MainWindow w;
        QCOMPARE(w.openScene(rigidlab::test::sourcePath(u"/lessons/scenes/welcome.json"), true),
                 QString());
        SimulationController& c = w.controller();
        auto* timeline = w.findChild<QLabel*>(QStringLiteral("timelineLabel"));
        QVERIFY(timeline);
        const auto check = [&](const char* when) {
            const QString status = shownTime(w.statusText());
            const QString bar = shownTime(timeline->text());
            QVERIFY2(!status.isEmpty() && status == bar,
                     qPrintable(QStringLiteral("%1: status bar t = %2 s, timeline t = %3 s")
                                    .arg(QLatin1String(when), status, bar)));
            QCOMPARE(status, QLocale().toString(c.time(), 'f', 3));
        };
        // Running frame by frame (no event loop: the status bar's own timer does not fire).
        c.setRunning(true);
        for (int frame = 0; frame < 12; ++frame) {
            c.advanceClock(1.0 / 60.0);
            check("running");
            if (QTest::currentTestFailed())
                return;
        }
        QVERIFY(c.world().stepCount() > 0);
        // The status bar's own refresh reads the same clock.
        QMetaObject::invokeMethod(&w, "updateStatus");
        check("status refreshed");
        // Paused: a step, a step back, a seek and a reset.
        c.setRunning(false);
        c.stepForward();
        check("step");
        c.stepBack();
        check("back");
        c.seek(c.world().stepCount() / 2);
        check("seek");
        c.reset();
        check("reset");
    }

    void grabSpringPullsTowardTheCursor()
    {
        SimulationController c;
        c.loadScene(ballScene(false), QStringLiteral("ball.json"));
        // Only a dynamic body of the world can be held.
        c.grab(7, physics::Vec2(0, 0));
        QVERIFY(!c.grabSpring().body());
        c.grab(0, physics::Vec2(0, 0));
        QCOMPARE(c.grabSpring().body(), std::optional<physics::BodyId>(0));
        c.dragTo(physics::Vec2(1, 0));
        physics::Vec2 from, to;
        QVERIFY(c.grabSpring().line(c.world(), from, to));
        QCOMPARE(to, physics::Vec2(1, 0));
        const GrabSpring idle;
        QVERIFY(!idle.input(c.world())); // a spring that holds nothing pushes nothing
        for (int i = 0; i < 20; ++i)
            c.stepForward();
        const physics::Body& ball = c.world().body(0);
        QVERIFY2(
            ball.position.x() > 0 && ball.velocity.x() > 0,
            qPrintable(
                QStringLiteral("x %1 m, vx %2 m/s").arg(ball.position.x()).arg(ball.velocity.x())));
        RL_VERIFY_NEAR(ball.position.y(), 0.0, 1e-12, 0.0);
        c.release();
        QVERIFY(!c.grabSpring().body());
        QVERIFY(!c.grabSpring().line(c.world(), from, to));

        // The pushes are logged: going back and forth replays them bit for bit.
        const physics::Vec2 there = ball.position;
        c.seek(0);
        while (c.world().stepCount() < 20)
            c.stepForward();
        QCOMPARE(c.world().body(0).position, there);
    }

    void grabSpringIsCriticallyDamped()
    {
        SimulationController c;
        c.loadScene(ballScene(false), QStringLiteral("ball.json"));
        GrabSpring spring;
        spring.grab(c.world(), 0, physics::Vec2(0, 0));
        spring.dragTo(physics::Vec2(0.5, 0));
        const auto input = spring.input(c.world());
        QVERIFY(input);
        QCOMPARE(input->body, 0);
        // At rest, the pull is k x = m w^2 x, with no torque at the centre.
        const double w = 2.0 * std::numbers::pi * kGrabFrequency;
        RL_VERIFY_NEAR(input->force.x(), 2.0 * w * w * 0.5, 0.0, 1e-12);
        RL_VERIFY_NEAR(input->force.y(), 0.0, 1e-12, 0.0);
        RL_VERIFY_NEAR(input->torque, 0.0, 1e-12, 0.0);
        spring.release();
        QVERIFY(!spring.input(c.world()));
    }

    void frameTimingRecordsTheFramesAskedFor()
    {
        FrameTiming timing;
        timing.measureFrames(3);
        QVERIFY(!timing.frameDone(0.020, 0.020));
        QVERIFY(!timing.frameDone(0.250, 0.100));
        QVERIFY(timing.frameDone(0.016, 0.016));
        QCOMPARE(timing.measuredFrameMs().size(), 3u);
        QCOMPARE(timing.measuredPhysicsMs().size(), 3u);
        // The record keeps the whole gap; the last frame counts what was run.
        RL_VERIFY_NEAR(timing.measuredFrameMs()[1], 250.0, 1e-9, 0.0);
        RL_VERIFY_NEAR(timing.frameMilliseconds(), 16.0, 1e-9, 0.0);
        QVERIFY(!timing.frameDone(0.016, 0.016)); // nothing more was asked for

        // Through the controller: one signal with every frame asked for.
        SimulationController c;
        c.loadScene(ballScene(false), QStringLiteral("ball.json"));
        QSignalSpy measured(&c, &SimulationController::framesMeasured);
        c.measureFrames(2);
        c.setRunning(true);
        c.advanceClock(2 * kDt);
        QCOMPARE(measured.count(), 0);
        c.advanceClock(3 * kDt);
        QCOMPARE(measured.count(), 1);
        const auto frames = measured.first().first().value<std::vector<double>>();
        QCOMPARE(frames.size(), 2u);
        RL_VERIFY_NEAR(frames[1], 3e3 * kDt, 1e-9, 0.0);
    }

    void samplesAreTakenWhenDue()
    {
        SimulationController c;
        c.loadScene(ballScene(true), QStringLiteral("ball.json"));
        // A sample at the start, then one every kSampleInterval (1/240 s) of simulated time:
        // with dt = 1/128 s, one per step.
        QCOMPARE(c.recorder().samples().written(), 1u);
        for (int i = 0; i < 4; ++i)
            c.stepForward();
        std::uint64_t cursor = 0;
        const std::vector<Sample> samples = c.recorder().samples().readSince(cursor);
        QCOMPARE(samples.size(), 5u);
        QCOMPARE(samples.back().t, c.time());
        RL_VERIFY_NEAR(samples.back().driftPercent, c.recorder().driftPercent(c.world()), 0.0, 0.0);
        // A reset forgets them and samples the start again.
        c.reset();
        QCOMPARE(c.recorder().samples().readSince(cursor).size(), 1u);

        // The recorder alone: the references are the worlds at restart.
        physics::World world = lessons::buildWorld(ballScene(true));
        world.updateDiagnostics();
        SampleRecorder recorder;
        recorder.restart(world, {});
        RL_VERIFY_NEAR(recorder.driftPercent(world), 0.0, 0.0, 0.0);
        RL_VERIFY_NEAR(recorder.dissipated(world), 0.0, 0.0, 0.0);
        QVERIFY(recorder.energyScale() > 0);
        recorder.record(world, {}, false);
        recorder.record(world, {}, false); // same time: not due again
        QCOMPARE(recorder.samples().written(), 1u);
        recorder.rewound(stepTime(world));
        recorder.record(world, {}, false);
        QCOMPARE(recorder.samples().written(), 2u);
    }

    void resetKeepsTheSettingsAsEditsAtTheStart()
    {
        physics::WorldDef start;
        physics::WorldDef now = start;
        QVERIFY(editsAtStart(start, now).empty());
        now.dt = start.dt / 2;
        now.friction = start.friction + 0.25;
        const SettingEdits edits = editsAtStart(start, now);
        QCOMPARE(edits.size(), 2u);
        QCOMPARE(edits[0].key, std::string_view("dt"));
        QCOMPARE(std::get<double>(edits[0].value), now.dt);
        QCOMPARE(edits[1].key, std::string_view("friction"));
        QCOMPARE(std::get<double>(edits[1].value), now.friction);
        for (const SettingEdit& e : edits)
            QCOMPARE(e.step, 0LL);

        SettingEditLog log;
        log.log({0, lessons::schema::Object::World, 0, "iterations", 4}, 5);
        log.log({0, lessons::schema::Object::World, 0, "iterations", 6}, 10);
        QCOMPARE(log.edits().size(), 2u);
        // A change after going back to step 7 drops the future it replaces.
        log.log({0, lessons::schema::Object::World, 0, "iterations", 8}, 7);
        QCOMPARE(log.edits().size(), 2u);
        QCOMPARE(log.edits()[1].step, 7LL);
        QCOMPARE(std::get<int>(log.edits()[1].value), 8);

        SimulationController c;
        c.loadScene(ballScene(true), QStringLiteral("ball.json"));
        for (int i = 0; i < 3; ++i)
            c.stepForward();
        c.setFriction(0.9);
        QCOMPARE(c.editLog().edits().size(), 1u);
        QCOMPARE(c.editLog().edits()[0].step, 3LL);
        c.reset();
        QCOMPARE(c.world().stepCount(), 0LL);
        QCOMPARE(c.world().def().friction, 0.9);
        QCOMPARE(c.editLog().edits().size(), 1u);
        QCOMPARE(c.editLog().edits()[0].step, 0LL);
        QCOMPARE(c.editLog().edits()[0].key, std::string_view("friction"));
    }

    void driftIsTheErrorOfContactsTooNotOnlyTheIntegrator()
    {
        // What the status bar says: velocity Verlet follows a free fall exactly, so the drift
        // of a falling ball is rounding; where the ball meets the floor, it is not.
        SimulationController c;
        c.loadScene(ballScene(true, "verlet"), QStringLiteral("ball.json"));
        for (int i = 0; i < 128; ++i)
            c.stepForward();
        RL_VERIFY_AT_MOST(std::abs(c.recorder().driftPercent(c.world())), 1e-9);

        c.loadScene(bouncingBall(), QStringLiteral("bounce.json"));
        double largest = 0.0;
        for (int i = 0; i < 3 * 128; ++i) {
            c.stepForward();
            largest = std::max(largest, std::abs(c.recorder().driftPercent(c.world())));
        }
        QVERIFY2(largest > 1e-6, qPrintable(QStringLiteral("largest drift %1 %").arg(largest)));

        // The words say so.
        QVERIFY(driftLabel(false).contains(QStringLiteral("%1")));
        QVERIFY(driftLabel(true).contains(QStringLiteral("%1")));
        QVERIFY(driftLabel(false).contains(QStringLiteral("contacts")));
        QVERIFY(driftExplanation().contains(QStringLiteral("Verlet")));
        MainWindow w;
        QCOMPARE(w.openScene(rigidlab::test::sourcePath(u"/lessons/scenes/welcome.json"), true),
                 QString());
        QMetaObject::invokeMethod(&w, "updateStatus");
        bool found = false;
        for (const QLabel* label : w.findChildren<QLabel*>())
            found = found || label->toolTip().contains(driftExplanation());
        QVERIFY(found);
    }

    void statusSaysWhichSolverRuns()
    {
        // The welcome scene asks for the soft step and has springs and pins: the soft step runs
        // them too, and the status bar names it, with no other solver standing in.
        MainWindow w;
        QCOMPARE(w.openScene(rigidlab::test::sourcePath(u"/lessons/scenes/welcome.json"), true),
                 QString());
        QCOMPARE(w.controller().world().def().solver, physics::SolverKind::SoftStep);
        QMetaObject::invokeMethod(&w, "updateStatus");
        auto* solver = w.findChild<QLabel*>(QStringLiteral("statusSolver"));
        QVERIFY(solver);
        const QString soft = solverDisplayName(physics::SolverKind::SoftStep);
        QCOMPARE(solver->text(), soft);
        QVERIFY2(solver->toolTip().contains(soft), qPrintable(solver->toolTip()));
        QVERIFY(w.statusText().contains(solver->text()));
        // A stack of boxes alone: the soft step runs, and says so.
        QCOMPARE(w.openScene(rigidlab::test::sourcePath(u"/lessons/scenes/box_stack.json"), true),
                 QString());
        QMetaObject::invokeMethod(&w, "updateStatus");
        QCOMPARE(solver->text(), soft);
    }
};

RIGIDLAB_TEST_MAIN(TestSimulation)
#include "test_simulation.moc"
