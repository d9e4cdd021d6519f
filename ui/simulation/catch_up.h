// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How many fixed steps a frame takes: the clock's catch-up rule, apart from the wall clock so
// that a test can give it the times.
//
// A frame owes the world the wall time since the last one (times the time scale). A light
// scene pays it all: a late frame catches up with several cheap steps. A heavy scene cannot:
// if each late frame took every step it owes, the frame would take longer still and owe more
// the next time (the spiral of death). So a frame takes a step only while the step is
// expected to fit the physics budget (the frame's first step always, or the world would never
// move), and the owed time the frame could not pay is dropped, not carried over: the run goes
// slower than real time, and says so for a while (slower()), instead of falling behind.

namespace rigidlab::ui {

class CatchUp {
public:
    /// Physics may take this much of a frame [ms]: a frame every 16.7 ms, and drawing the
    /// scene and the plots needs the rest.
    static constexpr double kBudgetMs = 10.0;
    /// A gap longer than this (a paused debugger, a busy window) counts as this much [s].
    static constexpr double kMaxGapSeconds = 0.1;
    /// The run counts as slower than real time for this long after time was dropped [s] (a
    /// word in the status bar that flickered frame by frame could not be read).
    static constexpr double kSlowHoldSeconds = 1.0;

    /// A frame begins `wallSeconds` after the last one; at `timeScale`, it owes the world
    /// that much simulated time (a gap counts as kMaxGapSeconds at most).
    void beginFrame(double wallSeconds, double timeScale);
    /// Whether the frame takes another step of `dt` [s] after `physicsMs` of physics: a whole
    /// step is owed and, unless it is the frame's first, the expected cost of one more step
    /// still fits kBudgetMs.
    bool nextStep(double dt, double physicsMs) const;
    /// A step of `dt` [s] was taken; it cost `ms` of wall time.
    void stepTaken(double dt, double ms);
    /// The frame's steps are done: whole steps still owed are dropped (the part of a step
    /// that is left stays owed, for drawing between steps and for the next frame).
    void endFrame(double dt);

    /// Simulated time owed to the world [s]: less than a step after a frame.
    double owed() const { return m_owed; }
    /// What one step is expected to cost [ms] (an average of the recent steps).
    double stepEstimateMs() const { return m_stepMs; }
    /// Whether time was dropped in the last kSlowHoldSeconds of wall time.
    bool slower() const { return m_sinceDrop < kSlowHoldSeconds; }
    /// Simulated time dropped since reset() [s].
    double dropped() const { return m_dropped; }
    /// Nothing owed, nothing dropped (play pressed, a new scene, a reset).
    void reset();

private:
    double m_owed = 0.0;        ///< simulated time owed [s]
    double m_stepMs = 0.0;      ///< expected wall time of one step [ms]; 0 before the first
    bool m_stepped = false;     ///< whether this frame took a step yet
    double m_sinceDrop = 1e300; ///< wall time since time was last dropped [s]
    double m_dropped = 0.0;     ///< simulated time dropped since reset [s]
};

} // namespace rigidlab::ui
