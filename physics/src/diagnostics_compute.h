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

/// Kinetic energy of the dynamic bodies [J].
double kineticEnergy(const std::vector<Body>& bodies);

} // namespace rigidlab::physics
