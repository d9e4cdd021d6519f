// SPDX-License-Identifier: GPL-3.0-or-later
// The same equations integrated by Boost.Odeint, the library a user might pick instead:
// runge_kutta4 at a fixed step, and runge_kutta_dopri5 in a controlled stepper (its error
// checker with absolute = relative tolerance), with the state as a std::vector<double>
// y = (q, v).

#include "numerics/sweep_run.h"

#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace rigidlab::lessons::detail {

namespace {

using State = std::vector<double>;

/// dy/dt = (v, a(t, q, v)) through the counting system.
struct Rhs {
    physics::OdeSystem& system;
    Eigen::VectorXd q, v, a;
    void operator()(const State& y, State& dydt, double t)
    {
        const Eigen::Index n = q.size();
        for (Eigen::Index i = 0; i < n; ++i) {
            q[i] = y[static_cast<size_t>(i)];
            v[i] = y[static_cast<size_t>(n + i)];
        }
        system.acceleration(t, q, v, a);
        for (Eigen::Index i = 0; i < n; ++i) {
            dydt[static_cast<size_t>(i)] = v[i];
            dydt[static_cast<size_t>(n + i)] = a[i];
        }
    }
};

void split(const State& y, Eigen::Index n, Eigen::VectorXd& q, Eigen::VectorXd& v)
{
    q.resize(n);
    v.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        q[i] = y[static_cast<size_t>(i)];
        v[i] = y[static_cast<size_t>(n + i)];
    }
}

} // namespace

RunCount runOdeint(bool dopri5, physics::OdeSystem& system, const Eigen::VectorXd& q0,
                   const Eigen::VectorXd& v0, const RunSpec& spec)
{
    namespace odeint = boost::numeric::odeint;
    const Eigen::Index n = q0.size();
    State y(static_cast<size_t>(2 * n));
    for (Eigen::Index i = 0; i < n; ++i) {
        y[static_cast<size_t>(i)] = q0[i];
        y[static_cast<size_t>(n + i)] = v0[i];
    }
    Rhs rhs{system, q0, v0, Eigen::VectorXd(n)};
    // odeint copies the system it is given: hand it a reference wrapper.
    auto f = [&rhs](const State& s, State& d, double t) { rhs(s, d, t); };
    RunCount out;
    Eigen::VectorXd q, v;
    auto observe = [&](double t) {
        if (spec.observer) {
            split(y, n, q, v);
            (*spec.observer)(t, q, v);
        }
    };
    observe(0.0);
    if (!dopri5) {
        odeint::runge_kutta4<State> stepper;
        const long long steps = std::max(1LL, std::llround(spec.tEnd / spec.dt));
        const double h = spec.tEnd / static_cast<double>(steps);
        const long long stride = (steps + kFixedChecks - 1) / kFixedChecks;
        for (long long i = 0; i < steps; ++i) {
            stepper.do_step(f, y, static_cast<double>(i) * h, h);
            if ((i + 1) % stride == 0 || i + 1 == steps)
                observe(static_cast<double>(i + 1) * h);
        }
        out.steps = steps;
    } else {
        auto stepper = odeint::make_controlled<odeint::runge_kutta_dopri5<State>>(spec.tolerance,
                                                                                  spec.tolerance);
        const double chunk = spec.tEnd / kAdaptiveChunks;
        double t = 0.0, h = chunk;
        for (int c = 1; c <= kAdaptiveChunks; ++c) {
            const double end = c == kAdaptiveChunks ? spec.tEnd : c * chunk;
            int failures = 0;
            while (t < end) {
                double trial = std::min(h, end - t);
                const bool last = trial >= end - t;
                const double before = t;
                if (stepper.try_step(f, y, t, trial) == odeint::success) {
                    ++out.steps;
                    if (last)
                        t = end;
                    // try_step proposes the next step in `trial`; keep it unless this one was
                    // cut short to land on the chunk's end.
                    h = last ? std::max(h, trial) : trial;
                    failures = 0;
                } else {
                    h = trial;
                    t = before;
                    if (++failures > 500) {
                        // No step size works (a non-finite state): end the run as garbage.
                        std::fill(y.begin(), y.end(), std::nan(""));
                        t = end;
                    }
                }
            }
            observe(t);
        }
    }
    split(y, n, out.q, out.v);
    return out;
}

} // namespace rigidlab::lessons::detail
