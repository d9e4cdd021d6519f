// SPDX-License-Identifier: GPL-3.0-or-later
// Dormand-Prince 5(4): an embedded Runge-Kutta pair with error control. Within one world
// step h it takes as many substeps as its tolerances need, carrying the last accepted
// substep's size over to the next world step.
//
// The tableau is Dormand and Prince's (J. Comput. Appl. Math. 6, 1980), as tabulated by
// Hairer, Norsett and Wanner, "Solving Ordinary Differential Equations I", table 5.2. The
// step goes on with the fifth-order solution (local extrapolation); the difference to the
// embedded fourth-order one estimates the local error. The last stage is evaluated at the new
// state, so it is the first stage of the next substep ("first same as last"): six force
// evaluations per accepted substep.
//
// Step size control (Hairer I, II.4): with err the root mean square of
// e_i / (atol + rtol max(|y_i|, |y_new,i|)), accept when err <= 1, and go on with
//   h_new = h min(5, max(0.2, 0.9 err^(-1/5)))   (never growing right after a rejection).

#include "integrators_extra.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>

namespace rigidlab::physics {

namespace {

using Eigen::VectorXd;

// c_i, a_ij, b_i (fifth order) and e_i = b_i - b*_i (b* the embedded fourth order).
constexpr std::array<double, 7> kC{0.0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1.0, 1.0};
constexpr double kA[7][6] = {
    {},
    {1.0 / 5},
    {3.0 / 40, 9.0 / 40},
    {44.0 / 45, -56.0 / 15, 32.0 / 9},
    {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
    {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
    {35.0 / 384, 0.0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84},
};
constexpr std::array<double, 7> kE{71.0 / 57600,      0.0,        -71.0 / 16695, 71.0 / 1920,
                                   -17253.0 / 339200, 22.0 / 525, -1.0 / 40};

/// Never more substeps than this in one world step: past it the rest is taken in one go
/// (and a diverging run is then caught by the world's divergence check).
constexpr int kMaxSubsteps = 100000;

class DormandPrince final : public Integrator {
public:
    explicit DormandPrince(const Tolerances& tolerances) : m_tol(tolerances) {}

    void step(OdeSystem& sys, double t, double h, VectorXd& q, VectorXd& v) override
    {
        const Eigen::Index n = q.size();
        m_y.resize(2 * n);
        m_y << q, v;
        for (VectorXd& k : m_k)
            k.resize(2 * n);
        m_stage.resize(2 * n);
        m_error = 0.0;
        m_substeps = 0;

        const double end = t + h;
        double tc = t;
        double hs = m_h > 0 ? std::min(m_h, h) : h;
        bool rejected = false;
        derivative(sys, tc, m_y, m_k[0]);
        while (tc < end) {
            const double remaining = end - tc;
            const bool forced = m_substeps >= kMaxSubsteps || hs <= 1e-12 * h;
            const double nominal = hs;
            if (forced || hs >= remaining * (1 - 1e-12))
                hs = remaining;
            // Stages 2 to 7; stage 7 is at the new state.
            for (int i = 1; i < 7; ++i) {
                m_stage = m_y;
                for (int j = 0; j < i; ++j)
                    if (kA[i][j] != 0.0)
                        m_stage += (hs * kA[i][j]) * m_k[static_cast<size_t>(j)];
                if (i == 6)
                    m_next = m_stage;
                derivative(sys, tc + kC[static_cast<size_t>(i)] * hs, m_stage,
                           m_k[static_cast<size_t>(i)]);
            }
            m_err.setZero(2 * n);
            for (size_t i = 0; i < 7; ++i)
                if (kE[i] != 0.0)
                    m_err += (hs * kE[i]) * m_k[i];
            double sum = 0.0;
            for (Eigen::Index i = 0; i < 2 * n; ++i) {
                const double scale =
                    m_tol.absolute +
                    m_tol.relative * std::max(std::abs(m_y[i]), std::abs(m_next[i]));
                const double r = m_err[i] / scale;
                sum += r * r;
            }
            double err = n > 0 ? std::sqrt(sum / static_cast<double>(2 * n)) : 0.0;
            if (!std::isfinite(err))
                err = std::numeric_limits<double>::infinity();

            double factor = err > 0 ? 0.9 * std::pow(err, -0.2) : 5.0;
            factor = std::clamp(factor, 0.2, 5.0);
            if (err <= 1.0 || forced) {
                tc = hs >= remaining * (1 - 1e-12) ? end : tc + hs;
                m_y.swap(m_next);
                m_k[0].swap(m_k[6]); // first same as last
                ++m_substeps;
                const double rms =
                    n > 0 ? m_err.norm() / std::sqrt(static_cast<double>(2 * n)) : 0.0;
                m_error = std::max(m_error, rms);
                if (rejected)
                    factor = std::min(factor, 1.0);
                rejected = false;
                // A substep cut short to land on the end does not shrink the next one.
                m_h = std::max(hs, std::min(nominal, remaining)) * factor;
                hs = m_h;
            } else {
                rejected = true;
                hs *= factor;
            }
        }
        q = m_y.head(n);
        v = m_y.tail(n);
    }
    std::unique_ptr<Integrator> clone() const override
    {
        return std::make_unique<DormandPrince>(*this);
    }
    IntegratorKind kind() const override { return IntegratorKind::DormandPrince; }
    int evaluationsPerStep() const override { return 6; }
    std::optional<double> errorEstimate() const override { return m_error; }
    int substeps() const override { return m_substeps; }
    void setTolerances(const Tolerances& tolerances) override { m_tol = tolerances; }

private:
    /// dy/dt = (v, a(t, q, v)) for y = (q, v).
    void derivative(OdeSystem& sys, double t, const VectorXd& y, VectorXd& k)
    {
        const Eigen::Index n = y.size() / 2;
        m_q = y.head(n);
        m_v = y.tail(n);
        m_a.resize(n);
        sys.acceleration(t, m_q, m_v, m_a);
        k.head(n) = m_v;
        k.tail(n) = m_a;
    }

    Tolerances m_tol;
    double m_h = 0.0;     ///< proposed substep for the next world step [s], 0 before the first
    double m_error = 0.0; ///< largest local error estimate of the last step
    int m_substeps = 0;
    std::array<VectorXd, 7> m_k;
    VectorXd m_y, m_stage, m_next, m_err;
    VectorXd m_q, m_v, m_a; ///< a stage's state split for the force evaluation
};

} // namespace

std::unique_ptr<Integrator> makeDormandPrince(const Tolerances& tolerances)
{
    return std::make_unique<DormandPrince>(tolerances);
}

} // namespace rigidlab::physics
