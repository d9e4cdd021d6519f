// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one owner of the world and its clock. Widgets that only read the run take it as a
// RunView (run_view.h) and read its parts there; those that change things ask it to: nothing
// else steps or edits the world. It hands the rest to its helpers:
// the plots' samples and the energy references (sample_recorder.h), a lesson's measurements
// (lesson_watch.h), the grab spring (grab_spring.h), frame timing (frame_timing.h), the
// settings-edit log (setting_edit.h) and time travel (history.h).
//
// Real time: the physics runs on a fixed dt. Each frame adds the wall time that passed
// (times the time scale) to an accumulator and takes as many steps as fit; the view draws
// the bodies interpolated between the last two steps. A frame takes only the steps that fit
// its physics budget and drops the time it could not pay (catch_up.h: no spiral of death);
// then the run is marked "slower than real time".

#include "simulation/catch_up.h"
#include "simulation/frame_timing.h"
#include "simulation/grab_spring.h"
#include "simulation/history.h"
#include "simulation/lesson_watch.h"
#include "simulation/run_view.h"
#include "simulation/sample_recorder.h"
#include "simulation/setting_edit.h"

#include "format/scene.h"
#include "rigidlab/physics/world.h"

#include <QString>
#include <QTimer>

#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace rigidlab::ui {

/// A body pose for drawing: where its origin is [m], its angle [rad] with that angle's cosine
/// and sine (computed once, for the view's transform), and where its centre of mass is [m].
struct Pose {
    physics::Vec2 origin = physics::Vec2::Zero();
    double angle = 0.0;
    physics::Rotation rotation;
    physics::Vec2 centre = physics::Vec2::Zero();
};

class SimulationController : public RunView {
    Q_OBJECT
public:
    explicit SimulationController(QObject* parent = nullptr);

    /// Replaces the scene and its world; the run starts paused at t = 0.
    void loadScene(const lessons::Scene& scene, const QString& path);
    /// Like loadScene, with prepared worlds (a lesson step): worlds[0] is the main one, the
    /// others run beside it as variants (labels: one per world, or empty).
    void loadWorlds(const lessons::Scene& scene, const QString& path,
                    std::vector<physics::World> worlds, const QStringList& labels,
                    const physics::Vec2& offset);
    const lessons::Scene& scene() const override { return m_scene; }
    const QString& scenePath() const override { return m_path; }
    const physics::World& world() const override { return m_world; }

    int variantCount() const override { return static_cast<int>(m_variants.size()); }
    const physics::World& variant(int i) const override
    {
        return m_variants[static_cast<size_t>(i)];
    }
    const QStringList& variantLabels() const override { return m_variantLabels; }
    physics::Vec2 variantOffset() const override { return m_variantOffset; }

    const History& history() const override { return m_history; }
    const SampleRecorder& recorder() const override { return m_sampler; }
    const FrameTiming& timing() const override { return m_timing; }
    const CatchUp& catchUp() const override { return m_catchUp; }
    const LessonWatch& lessonWatch() const override { return m_watch; }
    const SettingEditLog& editLog() const override { return m_edits; }
    const GrabSpring& grabSpring() const override { return m_grab; }

    // What a lesson measures while the world runs (bounces, collisions, timed values).
    void watch(const std::vector<lessons::Measure>& measures);
    /// Whether a table shows the bounces or the collisions (then they are measured in a scene
    /// that is no lesson step too: LessonWatch). A table opened after steps went unmeasured
    /// gets them measured again, from the history's replay of the run: a slice of it per turn
    /// of the event loop (a long run of a large scene takes seconds to walk again, and the
    /// window keeps drawing and answering meanwhile).
    void setEventsShown(bool shown);
    /// Whether the events are measured up to the present step (false while nothing reads them,
    /// and while a table opened late has the run so far measured again).
    bool eventsUpToDate() const { return m_watch.measuring() && !m_watch.behind(); }
    bool eventsCatchingUp() const override { return m_catchingUp; }
    /// The longest a slice of that replay may run before the window's next turn [ms]; 0 gives
    /// one step a slice (a test's).
    void setEventReplaySlice(int ms) { m_eventReplaySliceMs = ms; }

    bool isRunning() const override { return m_running; }
    double timeScale() const override { return m_timeScale; }
    bool slowerThanRealTime() const override { return m_running && m_catchUp.slower(); }
    /// Records the wall time of the next `frames` frames (from one frame to the next, drawing
    /// included) and the physics part of each, then emits framesMeasured (rigidlab
    /// --measure-frames).
    void measureFrames(int frames) { m_timing.measureFrames(frames); }

    /// The body pose to draw: between the last two steps, by how far the clock is into the next
    /// (its centre of mass and its angle, the origin placed from them: one sine and one cosine
    /// a body). A body whose centre and angle are those of `drawn`, the pose drawn last, gets
    /// `drawn` back, without computing them again (a body at rest, the ground).
    Pose drawPose(physics::BodyId id, const Pose* drawn = nullptr) const;

    /// Makes `edit` as its setter would, now (at whatever step the world is).
    void applyEdit(const SettingEdit& edit);
    /// Changes the run-time setting `key` (a world row of schema::settings()) to `value`, as
    /// the world row holds it, in every world that follows it (not the compared worlds' own
    /// integrator or solver). A value the row does not take, or the one in force, changes
    /// nothing; the world's restitution or friction given again gives the bodies back the
    /// world's.
    void setSetting(std::string_view key, const lessons::schema::Value& value);

    /// The most the time-travel snapshots may take [bytes] (96 MiB unless set).
    void setHistoryBudget(std::size_t bytes) { m_history.setBudget(bytes); }

    // Dragging a body with the grab spring (grab_spring.h).
    void grab(physics::BodyId id, const physics::Vec2& worldPoint)
    {
        m_grab.grab(m_world, id, worldPoint);
    }
    void dragTo(const physics::Vec2& worldPoint) { m_grab.dragTo(worldPoint); }
    void release() { m_grab.release(); }

    /// Held, the world never steps: Step, Back and seek do nothing (the scene editor holds it
    /// while editing; running it again leaves Edit mode first, which lets go).
    void setStepsHeld(bool held) { m_stepsHeld = held; }
    /// The running clock pauses when the world's time reaches `time` [s] (a lesson step's
    /// "endTime"); nullopt: it runs on. Play after it runs on from there.
    void setEndTime(std::optional<double> time) { m_endTime = time; }
    /// Whether the running clock pauses when a body leaves the stage (lessons/run/off_stage.h:
    /// a cart run off the end of its ground), once per run, saying so (leftStage); a lesson
    /// step turns it on. The stage is the world's as it is now.
    void setStageWatched(bool on) { m_watch.watchStage(on, m_world); }

public slots:
    void setRunning(bool running);
    void toggleRunning() { setRunning(!m_running); }
    void stepForward();
    void stepBack();
    /// Goes to any step in [history().earliest(), history().latest()]; running stops.
    void seek(long long step);
    void reset();
    void setTimeScale(double scale);
    void setDt(double dt);
    void setIntegrator(physics::IntegratorKind kind);
    void setSolver(physics::SolverKind kind);
    void setIterations(int iterations);
    void setRestitution(double e);
    void setFriction(double mu);
    void setGravityEnabled(bool on);
    void setBodyMaterial(physics::BodyId id, double restitution, double friction);
    /// Gives a dynamic body a new mass [kg] within limits::kMass (World::setBodyMass: the
    /// inertia scales with it). Anything else changes nothing.
    void setBodyMass(physics::BodyId id, double mass);
    /// Turns a body about its centre of mass by `radians` (a teaching aid: it is moved, not
    /// pushed, so the future branches from here).
    void rotateBody(physics::BodyId id, double radians);
    /// Moves a moving body by (dx, dy) [m] without turning it, and gives it a velocity
    /// changed by (dvx, dvy) [m/s] (the scene's keyboard: arrows and Shift+arrows). Like
    /// rotateBody, a teaching aid the run's future branches from. Non-finite values or a
    /// static body change nothing.
    void moveBody(physics::BodyId id, double dx, double dy);
    void pushBody(physics::BodyId id, double dvx, double dvy);
    /// Advances the clock by the wall time since the last frame (the frame timer calls it).
    void advanceFrame();
    /// Advances the clock as a frame would after `wallSeconds` of wall time (advanceFrame
    /// with the time measured; a test gives it).
    void advanceClock(double wallSeconds);

private:
    void doStep();
    void pushSample();
    void afterEdit(const QString& mark);
    /// The words of a setting's change mark on the plots: "dt = 0.002 s", "gravity off".
    QString settingMark(const lessons::schema::Field& row,
                        const lessons::schema::Value& value) const;
    /// Logs an edit made now; edits of the future the change drops go.
    void logEdit(const SettingEdit& edit) { m_edits.log(edit, m_world.stepCount()); }
    void resetClock();
    /// Starts measuring the run's events again from the history's earliest state when they are
    /// read and went unmeasured (setEventsShown), or stops a replay that is no longer wanted.
    void catchUpEvents();
    /// One slice of that replay; the timer brings the next while the present is not reached.
    void replayEventSlice();
    /// Sets eventsCatchingUp(), saying so when it changes.
    void setCatchingUp(bool on);
    template <typename Fn> void forEachWorld(Fn&& fn);

    lessons::Scene m_scene;
    QString m_path;
    physics::World m_world;
    physics::World m_worldStart; ///< as loaded, for reset
    /// Each body's centre of mass [m] and angle [rad] before the last step, for drawPose.
    std::vector<std::pair<physics::Vec2, double>> m_previousPoses;
    History m_history;
    SampleRecorder m_sampler;
    physics::Vec2 m_sceneGravity = physics::Vec2::Zero();
    std::vector<physics::World> m_variants;
    std::vector<physics::World> m_variantStarts; ///< to rebuild them on reset and seek
    QStringList m_variantLabels;
    physics::Vec2 m_variantOffset = physics::Vec2::Zero();
    LessonWatch m_watch;
    SettingEditLog m_edits;
    GrabSpring m_grab;
    FrameTiming m_timing;

    QTimer m_frameTimer;
    std::optional<physics::World> m_eventReplay; ///< the run walked again for its events
    QTimer m_eventReplayTimer;
    int m_eventReplaySliceMs = 5;
    bool m_catchingUp = false; ///< see eventsCatchingUp()
    CatchUp m_catchUp;         ///< the simulated time owed, and how much of it a frame pays
    double m_timeScale = 1.0;
    bool m_running = false;
    bool m_stepsHeld = false;        ///< see setStepsHeld
    std::optional<double> m_endTime; ///< see setEndTime [s]
};

} // namespace rigidlab::ui
