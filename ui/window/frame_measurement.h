// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// rigidlab --measure-frames N: the window runs its scene for N frames (after a warm-up that
// does not count: the first layouts and paints), then prints the median, 95th-percentile and
// longest frame time, the physics' share of it and the process's CPU time per frame on one
// line, and quits. A scene that diverges has no frames to measure: said, and the exit status
// is rigidlab-cli run's for a divergence.

namespace rigidlab::ui {

class SimulationController;

/// Frames run before measuring, so that the first layout and paint do not count.
inline constexpr int kWarmUpFrames = 30;
/// The exit status of a run that diverged, as rigidlab-cli run gives it.
inline constexpr int kExitDiverged = 3;

/// Measures `frames` frames of `controller`'s run (it must be running or about to run), then
/// prints their times on stdout and quits the application with 0 (kExitDiverged, the reason
/// on stderr, if the scene diverges first).
void measureFrames(SimulationController& controller, int frames);

} // namespace rigidlab::ui
