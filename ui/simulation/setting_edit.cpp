// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulation/setting_edit.h"

namespace rigidlab::ui {

SettingEdits editsAtStart(const physics::WorldDef& start, const physics::WorldDef& now)
{
    using Kind = SettingEdit::Kind;
    SettingEdits edits;
    if (now.dt != start.dt)
        edits.push_back({0, Kind::Dt, -1, now.dt, 0.0, 0});
    if (now.integrator != start.integrator)
        edits.push_back({0, Kind::Integrator, -1, 0.0, 0.0, static_cast<int>(now.integrator)});
    if (now.solver != start.solver)
        edits.push_back({0, Kind::Solver, -1, 0.0, 0.0, static_cast<int>(now.solver)});
    if (now.iterations != start.iterations)
        edits.push_back({0, Kind::Iterations, -1, 0.0, 0.0, now.iterations});
    if (now.restitution != start.restitution)
        edits.push_back({0, Kind::Restitution, -1, now.restitution, 0.0, 0});
    if (now.friction != start.friction)
        edits.push_back({0, Kind::Friction, -1, now.friction, 0.0, 0});
    if (now.gravity != start.gravity)
        edits.push_back({0, Kind::Gravity, -1, 0.0, 0.0, now.gravity.isZero() ? 0 : 1});
    return edits;
}

void SettingEditLog::log(SettingEdit edit, long long step)
{
    dropAfter(step);
    edit.step = step;
    m_edits.push_back(edit);
}

void SettingEditLog::dropAfter(long long step)
{
    std::erase_if(m_edits, [step](const SettingEdit& e) { return e.step > step; });
}

} // namespace rigidlab::ui
