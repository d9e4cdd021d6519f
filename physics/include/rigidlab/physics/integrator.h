#pragma once
// Time integrators over the whole state: positions q = (x, y, angle) and velocities
// v = (vx, vy, omega) of every moving body, stacked. They only see accelerations a(t, q, v).

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <string_view>

namespace rigidlab::physics {

enum class IntegratorKind {
    Euler,           ///< explicit Euler, the seed's own: order 1, energy grows
    SymplecticEuler, ///< semi-implicit Euler: velocity first, then position: order 1, bounded
    Verlet,          ///< velocity Verlet, the seed's formula: order 2, bounded
    RK4,             ///< classic Runge-Kutta, the seed's: order 4, slow drift
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
    /// Force evaluations per step.
    virtual int evaluationsPerStep() const = 0;
};

std::unique_ptr<Integrator> makeIntegrator(IntegratorKind kind);

/// The scene-file name ("euler", "symplectic-euler", "verlet", "rk4").
std::string_view integratorName(IntegratorKind kind);
std::optional<IntegratorKind> integratorFromName(std::string_view name);
/// The order of accuracy in theory (1, 1, 2, 4).
int integratorOrder(IntegratorKind kind);

} // namespace rigidlab::physics
