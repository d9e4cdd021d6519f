// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A touching pair of bodies and its manifold, as the contact solver keeps it.

#include "rigidlab/physics/forces.h"
#include "rigidlab/physics/sat.h"

#include <array>
#include <optional>
#include <string_view>

namespace rigidlab::physics {

enum class SolverKind {
    PaperImpulse,      ///< the paper's impulse, contact by contact, once (full denominator)
    SequentialImpulse, ///< accumulated, clamped impulses, iterated and warm started
    /// Soft contacts in substeps with relaxation, after the sequential solver's collision
    /// phase for the bounces (soft_step.cpp, soft_solver.cpp); with springs, pins,
    /// gravitation or another integrator than symplectic Euler, that integrator carries the
    /// smooth motion and the substeps the contacts and the pins they touch.
    SoftStep,
};

/// Every solver, in the order menus and the command line list them.
inline constexpr std::array<SolverKind, 3> kAllSolvers{
    SolverKind::PaperImpulse, SolverKind::SequentialImpulse, SolverKind::SoftStep};

std::string_view solverName(SolverKind kind);
std::optional<SolverKind> solverFromName(std::string_view name);

struct Contact {
    BodyId a = 0, b = 0; ///< a < b
    Manifold manifold;
    double restitution = 0;                     ///< the larger of the two bodies'
    double friction = 0;                        ///< the geometric mean of the two bodies'
    std::array<double, 2> normalImpulse{0, 0};  ///< accumulated this step [N s]
    std::array<double, 2> tangentImpulse{0, 0}; ///< accumulated this step [N s]
    /// The part of normalImpulse that was a bounce (the collision phase of the sequential
    /// solver): the next step does not warm start it [N s].
    std::array<double, 2> bounceImpulse{0, 0};
};

} // namespace rigidlab::physics
