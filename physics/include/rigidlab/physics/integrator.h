// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Time integrators over the whole state: positions q = (x, y, angle) and velocities
// v = (vx, vy, omega) of every moving body, stacked. They only see accelerations a(t, q, v).

#include <Eigen/Core>

#include <array>
#include <memory>
#include <optional>
#include <string_view>

namespace rigidlab::physics {

enum class IntegratorKind {
    Euler,            ///< explicit Euler, the seed's own: order 1, energy grows
    SymplecticEuler,  ///< semi-implicit Euler: velocity first, then position: order 1, bounded
    Verlet,           ///< velocity Verlet, the seed's formula: order 2, bounded
    RK4,              ///< classic Runge-Kutta, the seed's: order 4, slow drift
    DormandPrince,    ///< embedded Runge-Kutta 5(4), adaptive substeps within each step
    ImplicitMidpoint, ///< implicit midpoint by Newton's method: order 2, A-stable, symplectic
};

/// Every integrator, in the order menus list them.
inline constexpr std::array<IntegratorKind, 6> kAllIntegrators{
    IntegratorKind::Euler, IntegratorKind::SymplecticEuler, IntegratorKind::Verlet,
    IntegratorKind::RK4,   IntegratorKind::DormandPrince,   IntegratorKind::ImplicitMidpoint,
};

/// Error control of the adaptive integrator: a substep is accepted when its estimated local
/// error e_i satisfies sqrt(mean((e_i / (absolute + relative |y_i|))^2)) <= 1 over the state
/// (positions [m, rad] and velocities [m/s, rad/s] alike).
struct Tolerances {
    double absolute = 1e-8;
    double relative = 1e-8;
};

/// The system being integrated: gives accelerations for a state.
class OdeSystem {
public:
    virtual ~OdeSystem() = default;
    /// a = d v / dt at time t for positions q and velocities v (all of size 3 * bodies).
    virtual void acceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                              Eigen::VectorXd& a) = 0;
};

class Integrator {
public:
    virtual ~Integrator() = default;
    /// Advances (q, v) from t to t + h.
    virtual void step(OdeSystem& system, double t, double h, Eigen::VectorXd& q,
                      Eigen::VectorXd& v) = 0;
    virtual IntegratorKind kind() const = 0;
    /// A copy that goes on exactly as this one would (dopri5's proposed substep included).
    virtual std::unique_ptr<Integrator> clone() const = 0;
    /// Force evaluations per step (for the adaptive and implicit methods, per substep or
    /// Newton-free step: the world counts the real number).
    virtual int evaluationsPerStep() const = 0;
    /// The adaptive method's estimate of the local error of its last step: the largest over
    /// that step's substeps, root mean square over the state; nullopt for fixed-step methods.
    virtual std::optional<double> errorEstimate() const { return std::nullopt; }
    /// Substeps taken by the last step (1 for fixed-step methods).
    virtual int substeps() const { return 1; }
    virtual void setTolerances(const Tolerances& /*tolerances*/) {}
};

std::unique_ptr<Integrator> makeIntegrator(IntegratorKind kind, const Tolerances& tolerances = {});

/// The scene-file name ("euler", "symplectic-euler", "verlet", "rk4", "dopri5",
/// "implicit-midpoint").
std::string_view integratorName(IntegratorKind kind);
std::optional<IntegratorKind> integratorFromName(std::string_view name);
/// The order of accuracy in theory (1, 1, 2, 4, 5, 2).
int integratorOrder(IntegratorKind kind);

} // namespace rigidlab::physics
