// SPDX-License-Identifier: GPL-3.0-or-later
// The implicit midpoint rule, for stiff springs:
//   y1 = y0 + h f(t + h/2, (y0 + y1) / 2),   y = (q, v),  f = (v, a(t, q, v)).
// It is A-stable (a linear oscillator keeps its amplitude exactly, whatever k h^2), of order
// 2 and symplectic (Hairer, Lubich and Wanner, "Geometric Numerical Integration", II.1).
//
// Unknown: the midpoint velocity w = (v0 + v1) / 2. The midpoint position is then
// q0 + h/2 w, and the rule reads
//   G(w) = w - v0 - h/2 a(t + h/2, q0 + h/2 w, w) = 0,
// solved by Newton's method with the Jacobian
//   dG/dw = I - h^2/4 da/dq - h/2 da/dv,
// da/dq and da/dv by forward differences of OdeSystem::acceleration (2n evaluations), factored
// once per step with partial-pivoting LU and formed again only when Newton stalls. Linear
// forces (springs along a fixed line, gravity) make G linear: one iteration solves it.
// Then q1 = q0 + h w, v1 = 2 w - v0.

#include "integrators_extra.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace rigidlab::physics {

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

constexpr int kMaxNewtonIterations = 30;
/// Newton stops when the update is this small against the velocities [relative].
constexpr double kNewtonTolerance = 1e-13;

class ImplicitMidpoint final : public Integrator {
public:
    void step(OdeSystem& sys, double t, double h, VectorXd& q, VectorXd& v) override
    {
        const Eigen::Index n = q.size();
        const double tm = t + 0.5 * h;
        m_a.resize(n);
        // Start from the explicit midpoint guess w = v0 + h/2 a(q0, v0).
        sys.acceleration(t, q, v, m_a);
        m_w = v + (0.5 * h) * m_a;

        bool factored = false;
        double previous = std::numeric_limits<double>::infinity();
        for (int it = 0; it < kMaxNewtonIterations; ++it) {
            residual(sys, tm, h, q, v);
            const double size = m_g.lpNorm<Eigen::Infinity>();
            if (!std::isfinite(size))
                break; // let the world's divergence check report it
            // Slow convergence: the Jacobian went stale (non-linear forces); form it again.
            if (!factored || size > 0.5 * previous) {
                jacobian(sys, tm, h, q);
                factored = true;
            }
            previous = size;
            m_dw = m_lu.solve(m_g);
            m_w -= m_dw;
            const double scale = 1.0 + m_w.lpNorm<Eigen::Infinity>();
            if (m_dw.lpNorm<Eigen::Infinity>() <= kNewtonTolerance * scale)
                break;
        }
        q += h * m_w;
        v = 2.0 * m_w - v;
    }
    std::unique_ptr<Integrator> clone() const override
    {
        return std::make_unique<ImplicitMidpoint>(*this);
    }
    IntegratorKind kind() const override { return IntegratorKind::ImplicitMidpoint; }
    /// Without the Jacobian: the first guess and one residual. Forming the Jacobian costs 2n
    /// more, each further Newton iteration one more.
    int evaluationsPerStep() const override { return 2; }

private:
    /// m_g = G(m_w).
    void residual(OdeSystem& sys, double tm, double h, const VectorXd& q0, const VectorXd& v0)
    {
        m_qm = q0 + (0.5 * h) * m_w;
        sys.acceleration(tm, m_qm, m_w, m_a);
        m_g = m_w - v0 - (0.5 * h) * m_a;
    }

    /// Factors dG/dw at the current m_w; m_a must hold a(tm, q0 + h/2 w, w).
    void jacobian(OdeSystem& sys, double tm, double h, const VectorXd& q0)
    {
        const Eigen::Index n = q0.size();
        m_jac.setIdentity(n, n);
        m_qm = q0 + (0.5 * h) * m_w;
        m_a0 = m_a;
        m_ap.resize(n);
        constexpr double kSqrtEpsilon = 1.4901161193847656e-08;
        for (Eigen::Index j = 0; j < n; ++j) {
            // da/dq_j
            const double dq = kSqrtEpsilon * std::max(1.0, std::abs(m_qm[j]));
            const double keepQ = m_qm[j];
            m_qm[j] = keepQ + dq;
            sys.acceleration(tm, m_qm, m_w, m_ap);
            m_qm[j] = keepQ;
            m_jac.col(j) -= (0.25 * h * h / dq) * (m_ap - m_a0);
            // da/dv_j
            const double dv = kSqrtEpsilon * std::max(1.0, std::abs(m_w[j]));
            const double keepV = m_w[j];
            m_w[j] = keepV + dv;
            sys.acceleration(tm, m_qm, m_w, m_ap);
            m_w[j] = keepV;
            m_jac.col(j) -= (0.5 * h / dv) * (m_ap - m_a0);
        }
        m_lu.compute(m_jac);
    }

    VectorXd m_a, m_a0, m_ap, m_w, m_dw, m_g, m_qm;
    MatrixXd m_jac;
    Eigen::PartialPivLU<MatrixXd> m_lu;
};

} // namespace

std::unique_ptr<Integrator> makeImplicitMidpoint()
{
    return std::make_unique<ImplicitMidpoint>();
}

} // namespace rigidlab::physics
