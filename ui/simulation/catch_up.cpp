// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulation/catch_up.h"

#include <algorithm>
#include <cmath>

namespace rigidlab::ui {

namespace {

/// The weight of the newest step in the expected cost: a few steps follow a scene that got
/// heavier (a pyramid settling), one slow step (another process) does not halve the rate.
constexpr double kNewStepWeight = 0.25;

} // namespace

void CatchUp::beginFrame(double wallSeconds, double timeScale)
{
    const double wall = std::isfinite(wallSeconds) ? std::max(0.0, wallSeconds) : 0.0;
    if (wall > kMaxGapSeconds) {
        m_dropped += (wall - kMaxGapSeconds) * timeScale;
        m_sinceDrop = 0.0;
    } else {
        m_sinceDrop += wall;
    }
    m_owed += std::min(wall, kMaxGapSeconds) * timeScale;
    m_stepped = false;
}

bool CatchUp::nextStep(double dt, double physicsMs) const
{
    if (m_owed < dt)
        return false;
    return !m_stepped || physicsMs + m_stepMs <= kBudgetMs;
}

void CatchUp::stepTaken(double dt, double ms)
{
    m_owed -= dt;
    m_stepped = true;
    m_stepMs = m_stepMs > 0.0 ? m_stepMs + kNewStepWeight * (ms - m_stepMs) : ms;
}

void CatchUp::endFrame(double dt)
{
    if (m_owed < dt)
        return;
    const double kept = std::fmod(m_owed, dt);
    m_dropped += m_owed - kept;
    m_owed = kept;
    m_sinceDrop = 0.0;
}

void CatchUp::reset()
{
    *this = CatchUp();
}

} // namespace rigidlab::ui
