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
    Euler,            ///< explicit Euler, the paper's own: order 1, energy grows
    SymplecticEuler,  ///< semi-implicit Euler: velocity first, then position: order 1, bounded
    Verlet,           ///< velocity Verlet, the paper's formula: order 2, bounded
    RK4,              ///< classic Runge-Kutta, the paper's: order 4, slow drift
    DormandPrince,    ///< embedded Runge-Kutta 5(4), adaptive substeps within each step
    ImplicitMidpoint, ///< implicit midpoint by Newton's method: order 2, A-stable, symplectic
};

/// How a method behaves on the undamped oscillator x'' = -w^2 x at a fixed step dt.
enum class Stability {
    Bounded,  ///< stable for w dt below IntegratorInfo::stabilityBound
    Unstable, ///< no bound: the energy grows every step (by (1 + (w dt)^2) for explicit Euler)
    Adaptive, ///< substeps as the error control needs them, whatever dt
    AStable,  ///< stable for every dt
};

/// How the energy drag and dampers take over a step is measured (dissipation.cpp): the
/// power of the dissipative forces, P(q, v, u) with u the mean of the step's velocities.
enum class DissipationRule {
    StartOfStep, ///< h P(q0, v0, u): the force the method used, the one at the start
    Midpoint,    ///< h P(qm, u, u) at the midpoint, where the method evaluates it
    Trapezoid,   ///< h/2 (P(q0, v0, u) + P(q1, v1, u)): both ends, as the method's average
};

/// An integrator's facts, held on the integrator: every reader (the scene format, the
/// stress suite, the menus, the dissipation's measure) takes them from kIntegrators.
struct IntegratorInfo {
    IntegratorKind kind;
    std::string_view name; ///< the scene-file (JSON) key, "symplectic-euler"
    int order;             ///< order of accuracy in theory
    Stability stability;
    /// With Stability::Bounded, the largest w dt that stays stable on the undamped
    /// oscillator; 0 for the others.
    double stabilityBound;
    DissipationRule dissipation;
    /// How far one step moves the position under a constant acceleration a, from rest:
    /// q1 - q0 = steadyPush h^2 a. 0 for explicit Euler (q1 = q0 + h v0), 1 for symplectic
    /// Euler (q1 = q0 + h v1), 1/2 for the methods exact on a constant force (the true
    /// motion's h^2 a / 2). A resting contact's impulse is such a force held through the step,
    /// and the contact stage moves the position by what the integrator would have made of it
    /// (contact_response.cpp).
    double steadyPush;
};

/// Every integrator, in the order menus list them. A new integrator is a row here, an enum
/// value above, and its class in makeIntegrator (integrators.cpp).
inline constexpr std::array<IntegratorInfo, 6> kIntegrators{{
    {IntegratorKind::Euler, "euler", 1, Stability::Unstable, 0.0, DissipationRule::StartOfStep,
     0.0},
    {IntegratorKind::SymplecticEuler, "symplectic-euler", 1, Stability::Bounded, 2.0,
     DissipationRule::StartOfStep, 1.0},
    {IntegratorKind::Verlet, "verlet", 2, Stability::Bounded, 2.0, DissipationRule::Trapezoid, 0.5},
    // |1 - x^2/2 + x^4/24| <= 1 for x = w dt <= 2 sqrt(2)
    {IntegratorKind::RK4, "rk4", 4, Stability::Bounded, 2.8284271247461903,
     DissipationRule::Trapezoid, 0.5},
    {IntegratorKind::DormandPrince, "dopri5", 5, Stability::Adaptive, 0.0,
     DissipationRule::Trapezoid, 0.5},
    {IntegratorKind::ImplicitMidpoint, "implicit-midpoint", 2, Stability::AStable, 0.0,
     DissipationRule::Midpoint, 0.5},
}};

/// Every integrator's kind, in the order of kIntegrators.
inline constexpr std::array<IntegratorKind, kIntegrators.size()> kAllIntegrators = [] {
    std::array<IntegratorKind, kIntegrators.size()> kinds{};
    for (size_t i = 0; i < kIntegrators.size(); ++i)
        kinds[i] = kIntegrators[i].kind;
    return kinds;
}();

/// The row of kIntegrators of `kind`.
constexpr const IntegratorInfo& integratorInfo(IntegratorKind kind)
{
    for (const IntegratorInfo& info : kIntegrators)
        if (info.kind == kind)
            return info;
    return kIntegrators[0]; // unreachable: every kind has its row (integrators.cpp checks it)
}

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

/// The scene-file name (IntegratorInfo::name).
std::string_view integratorName(IntegratorKind kind);
std::optional<IntegratorKind> integratorFromName(std::string_view name);
/// The order of accuracy in theory (IntegratorInfo::order).
int integratorOrder(IntegratorKind kind);

} // namespace rigidlab::physics
