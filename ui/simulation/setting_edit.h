// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A setting the user changed by hand during a run (Controls, Inspector), with the step it was
// changed at. The controller keeps the edits of the run it has; made again at the same steps
// of the same start they give the same world, bit for bit (the engine is deterministic), and
// the same change marks on the plots. The language switch rebuilds the run from them.

#include "rigidlab/physics/world.h"

#include <utility>
#include <vector>

namespace rigidlab::ui {

struct SettingEdit {
    enum class Kind {
        Dt,           ///< value: dt [s]
        Integrator,   ///< number: physics::IntegratorKind
        Solver,       ///< number: physics::SolverKind
        Iterations,   ///< number: iterations
        Restitution,  ///< value: e
        Friction,     ///< value: μ
        Gravity,      ///< number: 1 on, 0 off
        BodyMaterial, ///< body; value: e, value2: μ
        BodyMass,     ///< body; value: mass [kg]
        BodyRotation, ///< body; value: the turn about the centre of mass [rad]
        BodyMove,     ///< body; value, value2: how far it is moved, x and y [m]
        BodyPush,     ///< body; value, value2: the velocity added, x and y [m/s]
    };
    long long step = 0; ///< the world's step count when the change was made
    Kind kind = Kind::Dt;
    physics::BodyId body = -1;
    double value = 0.0;
    double value2 = 0.0;
    int number = 0;
};

using SettingEdits = std::vector<SettingEdit>;

/// The edits that give a world started as `start` the settings `now` (dt, integrator, solver,
/// iterations, restitution, friction, gravity), all at step 0: what a reset keeps.
SettingEdits editsAtStart(const physics::WorldDef& start, const physics::WorldDef& now);

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
