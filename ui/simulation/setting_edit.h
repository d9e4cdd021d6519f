// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A setting the user changed by hand during a run (Controls, Inspector), with the step it was
// changed at. The controller keeps the edits of the run it has; made again at the same steps
// of the same start they give the same world, bit for bit (the engine is deterministic), and
// the same change marks on the plots. The language switch rebuilds the run from them.

#include "format/scene_schema.h"

#include "rigidlab/physics/world.h"

#include <string_view>
#include <utility>
#include <vector>

namespace rigidlab::ui {

/// What a hand-made change does to a body, besides its rows (a body's edit whose key is none
/// of these is its row's): the inspector's actions.
namespace body_edit {
inline constexpr std::string_view kMaterial = "material"; ///< value: (e, μ)
inline constexpr std::string_view kTurn = "turn";         ///< value: about its centre [rad]
inline constexpr std::string_view kMove = "move";         ///< value: how far, x and y [m]
inline constexpr std::string_view kPush = "push";         ///< value: velocity added [m/s]
} // namespace body_edit

struct SettingEdit {
    long long step = 0; ///< the world's step count when the change was made
    /// The world: a run-time setting (a world row, schema::settings()); a body: one of its rows
    /// ("mass") or one of body_edit's actions.
    lessons::schema::Object object = lessons::schema::Object::World;
    physics::BodyId index = 0;    ///< the body's id; 0 for the world
    std::string_view key;         ///< the row's key, or the action's
    lessons::schema::Value value; ///< as the world row holds it (gravity: its vector)
};

using SettingEdits = std::vector<SettingEdit>;

/// The edits that give a world started as `start` the run-time settings `now`, all at step 0:
/// what a reset keeps.
SettingEdits editsAtStart(const physics::WorldDef& start, const physics::WorldDef& now);

/// Makes a world setting's edit in a compared world (one run beside the main world, for
/// example with another integrator): every world follows the settings, except those the
/// comparison is about (schema::Field::mainWorldOnly: integrator, solver, iterations). A body's
/// edit is the main world's only.
void applyToComparedWorld(const SettingEdit& edit, physics::World& world);

/// The edits of the run the controller has, in order. A change made after going back drops
/// the edits of the future it replaces.
class SettingEditLog {
public:
    const SettingEdits& edits() const { return m_edits; }
    /// Logs `edit` as made at `step`; the edits made after `step` go.
    void log(SettingEdit edit, long long step);
    /// Drops the edits made after `step` (the run branched there).
    void dropAfter(long long step);
    /// The run starts again with these edits (a new scene: none).
    void restart(SettingEdits edits = {}) { m_edits = std::move(edits); }

private:
    SettingEdits m_edits;
};

} // namespace rigidlab::ui
