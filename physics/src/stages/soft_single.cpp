// SPDX-License-Identifier: GPL-3.0-or-later
// The soft step's opt-in single precision (SoftStepSettings::singlePrecision; SoftSolver,
// soft_solver.h): the float copy of the bodies the kernel's float passes work on, and the way
// back. The floats hold what changed since the step began (fast/soft_kernel.h), and only the
// passes' change returns to the double velocities.
//
// The warm start is double, body by body (SoftSolver::warmStart): a resting contact's impulse,
// about m g h a substep, is applied by each warm start and taken back by the passes, and with
// the impulse applied in floats a float's grain of it (6e-8 of g h) came back each substep,
// which the soft push made into a sink 1.4e-6 off (docs/performance-log-precision.md). What a warm
// start gives a body is the sum of its contacts' impulses at the start of the step (fillLaneOf, in
// double) and of every velocity change the passes made since, which fromSingle() adds as it
// hands them to the double velocities: no pass over the contacts, and each change rounded to
// its own size. The step's last relax pass is double too (fast/soft_kernel.cpp, relaxDouble),
// so that the step ends with double precision's velocities: a ball an e = 0 bounce put to rest
// ends at 0 m/s, not at a float's grain of the step's change of velocity, up or down.

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
        const double dvx = static_cast<double>(f.vx) - static_cast<double>(base[0]);
        const double dvy = static_cast<double>(f.vy) - static_cast<double>(base[1]);
        const double dw = static_cast<double>(f.w) - static_cast<double>(base[2]);
        d.vx += dvx;
        d.vy += dvy;
        d.w += dw;
        // The next warm start gives the impulses as changed (soft_solver.h, m_singleWarm).
        std::array<double, 3>& warm = m_singleWarm[i];
        warm[0] += dvx;
        warm[1] += dvy;
        warm[2] += dw;
        const std::array<double, 3>& o = m_singleOrigin[i];
        f.vx = static_cast<float>(d.vx - o[0]);
        f.vy = static_cast<float>(d.vy - o[1]);
        f.w = static_cast<float>(d.w - o[2]);
        base = {f.vx, f.vy, f.w};
    }
}

} // namespace rigidlab::physics
