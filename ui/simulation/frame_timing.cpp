// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulation/frame_timing.h"

namespace rigidlab::ui {

FrameTiming::FrameTiming()
{
    m_rateClock.start();
}

void FrameTiming::runStarted()
{
    m_wall.start();
    m_rateClock.restart();
    m_stepsThisSecond = 0;
    m_simulatedThisSecond = 0.0;
    m_stepsPerSecond = 0.0;
    m_realTimeFactor.reset();
}

double FrameTiming::wallSinceLastFrame()
{
    // Nanoseconds: restart() would round to whole milliseconds and lose ~3% of the time.
    const double seconds = m_wall.isValid() ? m_wall.nsecsElapsed() * 1e-9 : 0.0;
    m_wall.start();
    return seconds;
}

double FrameTiming::physicsElapsedMs() const
{
    return static_cast<double>(m_physicsClock.nsecsElapsed()) * 1e-6;
}

bool FrameTiming::frameDone(double wallSeconds, double countedSeconds)
{
    m_physicsMs = m_physicsClock.nsecsElapsed() * 1e-6;
    m_frameMs = countedSeconds * 1e3;
    bool measured = false;
    if (m_measureFrames > 0) {
        m_measuredFrameMs.push_back(wallSeconds * 1e3);
        m_measuredPhysicsMs.push_back(m_physicsMs);
        measured = --m_measureFrames == 0;
    }
    if (m_rateClock.elapsed() >= 1000) {
        const double seconds = static_cast<double>(m_rateClock.nsecsElapsed()) * 1e-9;
        m_rateClock.restart();
        m_stepsPerSecond = static_cast<double>(m_stepsThisSecond) / seconds;
        m_realTimeFactor = m_simulatedThisSecond / seconds;
        m_stepsThisSecond = 0;
        m_simulatedThisSecond = 0.0;
    }
    return measured;
}

void FrameTiming::measureFrames(int frames)
{
    m_measureFrames = frames;
    m_measuredFrameMs.clear();
    m_measuredPhysicsMs.clear();
}

} // namespace rigidlab::ui
