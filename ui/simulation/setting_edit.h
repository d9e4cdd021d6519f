// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A setting the user changed by hand during a run (Controls, Inspector), with the step it was
// changed at. The controller keeps the edits of the run it has; made again at the same steps
// of the same start they give the same world, bit for bit (the engine is deterministic), and
// the same change marks on the plots. The language switch rebuilds the run from them.

#include "rigidlab/physics/forces.h"

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
    };
    long long step = 0; ///< the world's step count when the change was made
    Kind kind = Kind::Dt;
    physics::BodyId body = -1;
    double value = 0.0;
    double value2 = 0.0;
    int number = 0;
};

using SettingEdits = std::vector<SettingEdit>;

} // namespace rigidlab::ui
