// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The run as its readers see it: the scene and the world, the worlds compared beside it,
// whether the clock runs, the parts of the run that keep what it did, and the signals that say
// what changed. A widget that shows the run without changing it takes a RunView, not the
// controller: it cannot step or edit anything. SimulationController owns all of it and is the
// one that changes it.
//
// The parts are only named here; a reader includes the header of the part it reads:
// the time-travel snapshots (history.h), the samples and the energy references
// (sample_recorder.h), the frames' cost (frame_timing.h), the time dropped (catch_up.h), what a
// lesson measures (lesson_watch.h), the settings changed by hand (setting_edit.h) and the grab
// spring (grab_spring.h).

#include "format/scene.h"
#include "rigidlab/physics/world.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <vector>

namespace rigidlab::ui {

class CatchUp;
class FrameTiming;
class GrabSpring;
class History;
class LessonWatch;
class SampleRecorder;
class SettingEditLog;

class RunView : public QObject {
    Q_OBJECT
public:
    virtual const lessons::Scene& scene() const = 0;
    virtual const QString& scenePath() const = 0;
    virtual const physics::World& world() const = 0;
    /// The clock's time: the time of the world's current step as the plots, the timeline and
    /// the status bar show it (stepTime: t = 0.35, not 0.35000000000000009) [s].
    double time() const;
    virtual bool isRunning() const = 0;
    virtual double timeScale() const = 0;
    /// Whether the clock dropped time it could not catch up with, in the last second.
    virtual bool slowerThanRealTime() const = 0;

    // Worlds run side by side with the main one (a lesson comparing integrators or solvers).
    // They step in lockstep with it and share its dt, restitution, friction and gravity.
    virtual int variantCount() const = 0;
    virtual const physics::World& variant(int i) const = 0;
    /// Labels of all compared worlds, the main one first; empty when nothing is compared.
    virtual const QStringList& variantLabels() const = 0;
    /// How far each compared world is drawn from the one before it [m].
    virtual physics::Vec2 variantOffset() const = 0;

    // The parts of the run.
    /// The time-travel snapshots: the steps one can go back to.
    virtual const History& history() const = 0;
    /// The plots' samples, the energy references and the drift against them.
    virtual const SampleRecorder& recorder() const = 0;
    /// What the frames cost and how fast the run goes.
    virtual const FrameTiming& timing() const = 0;
    /// The simulated time the clock owes and has dropped.
    virtual const CatchUp& catchUp() const = 0;
    /// What a lesson step measures while the world runs, and whether a body left the stage.
    virtual const LessonWatch& lessonWatch() const = 0;
    /// The settings changed by hand in this run, in order, each at its step (a reset keeps
    /// the ones it keeps, as edits at step 0; a change after going back drops the later ones).
    virtual const SettingEditLog& editLog() const = 0;
    /// The grab spring: which body is held, and where the spring runs.
    virtual const GrabSpring& grabSpring() const = 0;
    /// Whether the run so far is being measured again for a table opened late (the bounces,
    /// the collision): its events are not all in yet. A slice a turn of the event loop;
    /// eventsCatchingUpChanged says when it starts and when it is done.
    virtual bool eventsCatchingUp() const = 0;

signals:
    void sceneLoaded();
    /// The world changed (steps taken, a seek, a reset or an edit).
    void worldChanged();
    void runningChanged(bool running);
    void settingsChanged();
    /// A setting changed mid-run: the plots draw a mark at t.
    void marked(double t, const QString& label);
    /// A frame of the running clock is done: the plots drain after it.
    void frameAdvanced();
    /// The world went back to time t: the plots drop what comes after.
    void rewound(double t);
    /// Samples were cleared (new scene, reset).
    void samplesCleared();
    /// eventsCatchingUp() changed.
    void eventsCatchingUpChanged(bool catchingUp);
    /// A body left the stage at time t [s] and the run paused.
    void leftStage(physics::BodyId body, double t);
    /// The run reached the end time it was given (a lesson step's) at time t [s] and paused.
    void endTimeReached(double t);
    /// Frames asked for were measured: each frame's wall time and physics time [ms].
    void framesMeasured(const std::vector<double>& frameMs, const std::vector<double>& physicsMs);

protected:
    explicit RunView(QObject* parent) : QObject(parent) {}
};

} // namespace rigidlab::ui
