// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's four integrators over the whole state (q, v), forces evaluated again at every
// stage; the adaptive and implicit ones are in integrators_adaptive.cpp and
// integrator_implicit.cpp.

#include "rigidlab/physics/integrator.h"

#include "integrators_extra.h"
#include "symplectic_euler.h"

#include <array>
#include <memory>

namespace rigidlab::physics {

namespace {

using Eigen::VectorXd;

/// Explicit Euler (the paper's): both q and v advance with the rates at the start.
///   q1 = q0 + h v0,  v1 = v0 + h a(q0, v0)
class ExplicitEuler final : public Integrator {
public:
    void step(OdeSystem& sys, double t, double h, VectorXd& q, VectorXd& v) override
    {
        m_a.resize(v.size());
        sys.acceleration(t, q, v, m_a);
        q += h * v;
        v += h * m_a;
    }
    std::unique_ptr<Integrator> clone() const override
    {
        return std::make_unique<ExplicitEuler>(*this);
    }
    IntegratorKind kind() const override { return IntegratorKind::Euler; }
    int evaluationsPerStep() const override { return 1; }

private:
    VectorXd m_a;
};

/// Semi-implicit (symplectic) Euler: the new velocity moves the position.
///   v1 = v0 + h a(q0, v0),  q1 = q0 + h v1
class SymplecticEuler final : public Integrator {
public:
    void step(OdeSystem& sys, double t, double h, VectorXd& q, VectorXd& v) override
    {
        m_a.resize(v.size());
        sys.acceleration(t, q, v, m_a);
        symplecticEulerUpdate(h, m_a, v, q);
    }
    std::unique_ptr<Integrator> clone() const override
    {
        return std::make_unique<SymplecticEuler>(*this);
    }
    IntegratorKind kind() const override { return IntegratorKind::SymplecticEuler; }
    int evaluationsPerStep() const override { return 1; }

private:
    VectorXd m_a;
};

/// Velocity Verlet (the paper's formula):
///   q1 = q0 + h v0 + h^2/2 a0,  v1 = v0 + h/2 (a0 + a1),  a1 = a(q1, v~1)
/// For velocity-dependent forces (drag, dampers, joints) a1 needs a velocity at t + h:
/// the first-order prediction v~1 = v0 + h a0 keeps the method second order.
class VelocityVerlet final : public Integrator {
public:
    void step(OdeSystem& sys, double t, double h, VectorXd& q, VectorXd& v) override
    {
        m_a0.resize(v.size());
        m_a1.resize(v.size());
        sys.acceleration(t, q, v, m_a0);
        q += h * v + (0.5 * h * h) * m_a0;
        m_vp = v + h * m_a0;
        sys.acceleration(t + h, q, m_vp, m_a1);
        v += (0.5 * h) * (m_a0 + m_a1);
    }
    std::unique_ptr<Integrator> clone() const override
    {
        return std::make_unique<VelocityVerlet>(*this);
    }
    IntegratorKind kind() const override { return IntegratorKind::Verlet; }
    int evaluationsPerStep() const override { return 2; }

private:
    VectorXd m_a0, m_a1, m_vp;
};

/// Classic fourth-order Runge-Kutta on the first-order system (q' = v, v' = a):
///   k_i = (v_i, a(t_i, q_i, v_i)),  y1 = y0 + h/6 (k1 + 2 k2 + 2 k3 + k4)
class RungeKutta4 final : public Integrator {
public:
    void step(OdeSystem& sys, double t, double h, VectorXd& q, VectorXd& v) override
    {
        const auto n = v.size();
        for (auto& a : m_a)
            a.resize(n);
        // Stage 1 at (q, v).
        sys.acceleration(t, q, v, m_a[0]);
        // Stage 2 at the midpoint along k1: q + h/2 v, v + h/2 a1.
        m_q = q + (0.5 * h) * v;
        m_v2 = v + (0.5 * h) * m_a[0];
        sys.acceleration(t + 0.5 * h, m_q, m_v2, m_a[1]);
        // Stage 3 at the midpoint along k2.
        m_q = q + (0.5 * h) * m_v2;
        m_v3 = v + (0.5 * h) * m_a[1];
        sys.acceleration(t + 0.5 * h, m_q, m_v3, m_a[2]);
        // Stage 4 at the end along k3.
        m_q = q + h * m_v3;
        m_v4 = v + h * m_a[2];
        sys.acceleration(t + h, m_q, m_v4, m_a[3]);

        q += (h / 6.0) * (v + 2.0 * m_v2 + 2.0 * m_v3 + m_v4);
        v += (h / 6.0) * (m_a[0] + 2.0 * m_a[1] + 2.0 * m_a[2] + m_a[3]);
    }
    std::unique_ptr<Integrator> clone() const override
    {
        return std::make_unique<RungeKutta4>(*this);
    }
    IntegratorKind kind() const override { return IntegratorKind::RK4; }
    int evaluationsPerStep() const override { return 4; }

private:
    std::array<VectorXd, 4> m_a;
    VectorXd m_q, m_v2, m_v3, m_v4;
};

// Every kind has its row in kIntegrators, at its own index.
constexpr bool everyKindHasItsRow()
{
    for (size_t i = 0; i < kIntegrators.size(); ++i)
        if (static_cast<size_t>(kIntegrators[i].kind) != i)
            return false;
    return true;
}
static_assert(everyKindHasItsRow());

} // namespace

std::unique_ptr<Integrator> makeIntegrator(IntegratorKind kind, const Tolerances& tolerances)
{
    switch (kind) {
    case IntegratorKind::Euler:
        return std::make_unique<ExplicitEuler>();
    case IntegratorKind::SymplecticEuler:
        return std::make_unique<SymplecticEuler>();
    case IntegratorKind::Verlet:
        return std::make_unique<VelocityVerlet>();
    case IntegratorKind::RK4:
        return std::make_unique<RungeKutta4>();
    case IntegratorKind::DormandPrince:
        return makeDormandPrince(tolerances);
    case IntegratorKind::ImplicitMidpoint:
        return makeImplicitMidpoint();
    }
    return nullptr;
}

std::string_view integratorName(IntegratorKind kind)
{
    return integratorInfo(kind).name;
}

std::optional<IntegratorKind> integratorFromName(std::string_view name)
{
    for (const auto& i : kIntegrators)
        if (i.name == name)
            return i.kind;
    return std::nullopt;
}

int integratorOrder(IntegratorKind kind)
{
    return integratorInfo(kind).order;
}

} // namespace rigidlab::physics
