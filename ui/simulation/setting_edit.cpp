// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulation/setting_edit.h"

namespace rigidlab::ui {

SettingEdits editsAtStart(const physics::WorldDef& start, const physics::WorldDef& now)
{
    namespace schema = lessons::schema;
    lessons::Scene before;
    before.world = start;
    lessons::Scene after;
    after.world = now;
    SettingEdits edits;
    for (const schema::Field& setting : schema::settings()) {
        const schema::Field* row = schema::worldRowOf(setting);
        if (row == nullptr)
            continue; // the window's, not the world's
        const schema::Value v = row->get(after, 0);
        if (v != row->get(before, 0))
            edits.push_back({0, schema::Object::World, 0, row->key, v});
    }
    return edits;
}

void applyToComparedWorld(const SettingEdit& edit, physics::World& world)
{
    namespace schema = lessons::schema;
    if (edit.object != schema::Object::World)
        return;
    const schema::Field* row = schema::findField(schema::Object::World, edit.key);
    if (row != nullptr && row->apply != nullptr && !row->mainWorldOnly)
        row->apply(world, edit.value);
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
