// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private: computing the diagnostics of a world's state.

#include "rigidlab/physics/body.h"
#include "rigidlab/physics/diagnostics.h"
#include "rigidlab/physics/forces.h"
#include "rigidlab/physics/world.h"

#include <vector>

namespace rigidlab::physics {

/// Energies and momenta of the state; collisionLoss and contacts are left for the world.
Diagnostics computeDiagnostics(const WorldDef& def, const std::vector<Body>& bodies,
                               const std::vector<SpringDef>& springs);

/// The energy the contact solver took in this step [J] (dissipation.cpp), from each body's
/// velocities at the start of the step, after integration (before the solver) and now, and
/// the fraction of the step before its bounce (ContactSolver::impactFractions()).
double contactLoss(const std::vector<Body>& bodies, const std::vector<Vec2>& velocityAtStart,
                   const std::vector<double>& angularVelocityAtStart,
                   const std::vector<Vec2>& velocityBefore,
                   const std::vector<double>& angularVelocityBefore,
                   const std::vector<double>& impact);

} // namespace rigidlab::physics
