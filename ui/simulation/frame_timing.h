// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the frames of a run cost and how fast the run goes: the wall time of each frame and
// the physics part of it, steps per second and simulated seconds per wall second over the
// last whole second, and, when asked (rigidlab --measure-frames), a record of the next frames.
// It measures; the controller's clock decides what to do with the time (catch_up.h).

#include <QElapsedTimer>

#include <optional>
#include <vector>

namespace rigidlab::ui {

class FrameTiming {
public:
    FrameTiming();

    /// Play was pressed: the rates measure this run only, not the pause before it, and the
    /// first frame's wall time counts from now.
    void runStarted();
    /// The wall time since the last frame (or runStarted) [s], and starts the next one.
    double wallSinceLastFrame();
    /// The frame's physics starts now.
    void physicsStarted() { m_physicsClock.start(); }
    /// The wall time since the frame's physics started [ms].
    double physicsElapsedMs() const;
    /// One step taken (a frame's, or a single step by hand).
    void stepTaken() { ++m_stepsThisSecond; }
    /// The clock ran `seconds` of simulated time.
    void simulated(double seconds) { m_simulatedThisSecond += seconds; }
    /// The frame is done: `wallSeconds` passed since the last one, of which `countedSeconds`
    /// were run (a longer gap counts as less). True when this frame completes a
    /// measureFrames() record.
    bool frameDone(double wallSeconds, double countedSeconds);

    /// Records the wall time of the next `frames` frames (from one frame to the next, drawing
    /// included) and the physics part of each.
    void measureFrames(int frames);
    const std::vector<double>& measuredFrameMs() const { return m_measuredFrameMs; }
    const std::vector<double>& measuredPhysicsMs() const { return m_measuredPhysicsMs; }

    /// Steps per second of wall time, over the last second.
    double stepsPerSecond() const { return m_stepsPerSecond; }
    /// Simulated seconds per wall second over the last whole second since runStarted.
    std::optional<double> realTimeFactor() const { return m_realTimeFactor; }
    /// The counted wall time of the last frame, and the part of it spent in physics [ms].
    double frameMilliseconds() const { return m_frameMs; }
    double physicsMilliseconds() const { return m_physicsMs; }

private:
    QElapsedTimer m_wall;         ///< since the last frame
    QElapsedTimer m_physicsClock; ///< since the frame's physics started
    QElapsedTimer m_rateClock;    ///< since the rates were last taken
    double m_frameMs = 0.0, m_physicsMs = 0.0, m_stepsPerSecond = 0.0;
    long long m_stepsThisSecond = 0;
    double m_simulatedThisSecond = 0.0; ///< simulated time run since m_rateClock [s]
    std::optional<double> m_realTimeFactor;
    int m_measureFrames = 0; ///< frames still to record
    std::vector<double> m_measuredFrameMs, m_measuredPhysicsMs;
};

} // namespace rigidlab::ui
