// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private: the integrators beyond the paper's, each in a file of its own.

#include "rigidlab/physics/integrator.h"

#include <memory>

namespace rigidlab::physics {

/// Dormand-Prince 5(4) with error control (integrators_adaptive.cpp).
std::unique_ptr<Integrator> makeDormandPrince(const Tolerances& tolerances);
/// Implicit midpoint rule solved by Newton's method (integrator_implicit.cpp).
std::unique_ptr<Integrator> makeImplicitMidpoint();

} // namespace rigidlab::physics
