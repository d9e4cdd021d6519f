// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/frame_measurement.h"

#include "simulation/simulation_controller.h"

#include "format/divergence_message.h"

#include <QApplication>
#include <QTextStream>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <numeric>
#include <vector>

namespace rigidlab::ui {

namespace {

/// Median and 95th percentile of the frame times, the share of physics in them, and the
/// process's CPU time per frame (what the frames cost on a machine that is not shared).
void printFrameTimes(std::vector<double> frames, const std::vector<double>& physics,
                     double cpuMsPerFrame)
{
    const double total = std::accumulate(frames.begin(), frames.end(), 0.0);
    const double inPhysics = std::accumulate(physics.begin(), physics.end(), 0.0);
    std::sort(frames.begin(), frames.end());
    const auto at = [&](double q) {
        return frames[std::min(frames.size() - 1,
                               static_cast<size_t>(q * static_cast<double>(frames.size())))];
    };
    std::printf("%zu frames: median %.2f ms, 95th percentile %.2f ms, longest %.2f ms; "
                "physics %.1f %% of the frame time (%.2f ms per frame); CPU %.2f ms per frame\n",
                frames.size(), at(0.5), at(0.95), frames.back(), 100.0 * inPhysics / total,
                inPhysics / static_cast<double>(frames.size()), cpuMsPerFrame);
}

} // namespace

void measureFrames(SimulationController& controller, int frames)
{
    const std::clock_t cpuStart = std::clock();
    QObject::connect(
        &controller, &SimulationController::framesMeasured, qApp,
        [cpuStart](const std::vector<double>& frameMs, const std::vector<double>& physicsMs) {
            const double cpuMs = 1e3 * static_cast<double>(std::clock() - cpuStart) /
                                 CLOCKS_PER_SEC / static_cast<double>(frameMs.size());
            printFrameTimes({frameMs.begin() + kWarmUpFrames, frameMs.end()},
                            {physicsMs.begin() + kWarmUpFrames, physicsMs.end()}, cpuMs);
            QApplication::exit(0);
        });
    // A scene that diverges stops the run (the window's banner), and no more frames come:
    // said, and the exit status is the command line's for a divergence.
    QObject::connect(&controller, &SimulationController::runningChanged, qApp,
                     [&controller](bool running) {
                         const auto& diverged = controller.world().divergence();
                         if (running || !diverged)
                             return;
                         QTextStream(stderr)
                             << "rigidlab: --measure-frames: the scene "
                             << lessons::divergenceMessage(*diverged) << "; no frames to measure\n";
                         QApplication::exit(kExitDiverged);
                     });
    controller.measureFrames(frames + kWarmUpFrames);
}

} // namespace rigidlab::ui
