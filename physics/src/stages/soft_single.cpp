// SPDX-License-Identifier: GPL-3.0-or-later
// The soft step's opt-in single precision (SoftStepSettings::singlePrecision; SoftSolver,
// soft_solver.h): the float copy of the bodies the kernel's float passes work on, and the way
// back. The floats hold what changed since the step began (fast/soft_kernel.h), and only the
// passes' change returns to the double velocities.

#include "soft_solver.h"

#include <array>
#include <cstddef>

namespace rigidlab::physics {

void SoftSolver::toSingle(bool motion)
{
    auto copy = [&](int id) {
        const auto i = static_cast<size_t>(id);
        const soft::BodyState& d = m_state[i];
        soft::SingleBodyState& f = m_singleState[i];
        const std::array<double, 3>& o = m_singleOrigin[i];
        f.vx = static_cast<float>(d.vx - o[0]);
        f.vy = static_cast<float>(d.vy - o[1]);
        f.w = static_cast<float>(d.w - o[2]);
        m_singleBase[i] = {f.vx, f.vy, f.w};
        if (motion) {
            f.dpx = static_cast<float>(d.dpx);
            f.dpy = static_cast<float>(d.dpy);
            f.qc = static_cast<float>(d.qc - 1.0);
            f.qs = static_cast<float>(d.qs);
        }
    };
    for (int id : m_moving)
        copy(id);
    if (motion)
        for (int id : m_kinematic)
            copy(id);
}

void SoftSolver::fromSingle()
{
    // Only the passes' change goes back, not the rounded velocity: a body whose contacts
    // pushed nothing (two balls parting after their exact impact) keeps every bit of its
    // velocity, as in double precision. (The change is taken against the velocities as
    // toSingle() wrote them, kept in m_singleBase: written as f - float(d), GCC 12 at -O2
    // turned the vectorised float(d) into d, and the rounding came back.)
    for (int id : m_moving) {
        const auto i = static_cast<size_t>(id);
        soft::BodyState& d = m_state[i];
        soft::SingleBodyState& f = m_singleState[i];
        std::array<float, 3>& base = m_singleBase[i];
        d.vx += static_cast<double>(f.vx) - static_cast<double>(base[0]);
        d.vy += static_cast<double>(f.vy) - static_cast<double>(base[1]);
        d.w += static_cast<double>(f.w) - static_cast<double>(base[2]);
        const std::array<double, 3>& o = m_singleOrigin[i];
        f.vx = static_cast<float>(d.vx - o[0]);
        f.vy = static_cast<float>(d.vy - o[1]);
        f.w = static_cast<float>(d.w - o[2]);
        base = {f.vx, f.vy, f.w};
    }
}

} // namespace rigidlab::physics
