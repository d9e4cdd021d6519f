// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private: one integration of a reference problem's equations, by the engine's integrators
// (error_vs_time.cpp) or by Boost.Odeint's (odeint_runs.cpp), with an optional observer at
// the checked times.

#include "rigidlab/physics/integrator.h"

#include <Eigen/Core>

#include <functional>

namespace rigidlab::lessons::detail {

/// Counts the force evaluations made through it.
class CountingSystem final : public physics::OdeSystem {
public:
    explicit CountingSystem(physics::OdeSystem& inner) : m_inner(inner) {}
    void acceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                      Eigen::VectorXd& a) override
    {
        ++count;
        m_inner.acceleration(t, q, v, a);
    }
    long long count = 0;

private:
    physics::OdeSystem& m_inner;
};

/// Called at the checked times with the state there.
using Observer = std::function<void(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v)>;

struct RunSpec {
    double tEnd = 0;                    ///< [s]
    double dt = 0;                      ///< fixed-step methods [s]: tEnd / round(tEnd / dt) is used
    double tolerance = 0;               ///< adaptive methods
    const Observer* observer = nullptr; ///< nullptr: no checks (the timed runs)
};

struct RunCount {
    long long steps = 0;
    Eigen::VectorXd q, v; ///< at tEnd
};

/// Fixed-step runs check every ceil(N / kFixedChecks)-th step; adaptive runs integrate
/// kAdaptiveChunks equal chunks and check at the end of each.
inline constexpr int kFixedChecks = 200;
inline constexpr int kAdaptiveChunks = 50;

/// Boost.Odeint's runge_kutta4 ("odeint-rk4") or controlled runge_kutta_dopri5
/// ("odeint-dopri5"), from (q0, v0) at t = 0.
RunCount runOdeint(bool dopri5, physics::OdeSystem& system, const Eigen::VectorXd& q0,
                   const Eigen::VectorXd& v0, const RunSpec& spec);

} // namespace rigidlab::lessons::detail
