// SPDX-License-Identifier: GPL-3.0-or-later
// Stage::Forces (profile.h): the applied forces (the paper's force and torque accumulators,
// gravity, springs, mutual gravitation, linear drag), turned into accelerations. A body's own
// load is appliedLoad (dynamics.h).

#include "dynamics.h"

#include <chrono>
#include <cmath>

namespace rigidlab::physics {

BodyState Dynamics::state(BodyId id, const Eigen::VectorXd& q, const Eigen::VectorXd& v) const
{
    const Body& body = m_bodies[static_cast<size_t>(id)];
    const int s = m_slot[static_cast<size_t>(id)];
    BodyState st;
    if (s < 0) {
        st.x = body.position;
        st.q = Rotation(body.angle);
        return st;
    }
    const Eigen::Index i = 3 * static_cast<Eigen::Index>(s);
    st.x = Vec2(q[i], q[i + 1]);
    st.q = Rotation(q[i + 2]);
    st.v = Vec2(v[i], v[i + 1]);
    st.w = v[i + 2];
    return st;
}

Dynamics::SpringEnds Dynamics::springEnds(const SpringDef& s, const Eigen::VectorXd& q,
                                          const Eigen::VectorXd& v) const
{
    SpringEnds e;
    e.pA = s.anchorA;
    e.pB = s.anchorB;
    if (s.a != kWorld) {
        const BodyState sa = state(s.a, q, v);
        e.rA = lever(s.a, sa.q, s.anchorA);
        e.pA = sa.x + e.rA;
        e.vA = sa.v + cross(sa.w, e.rA);
    }
    if (s.b != kWorld) {
        const BodyState sb = state(s.b, q, v);
        e.rB = lever(s.b, sb.q, s.anchorB);
        e.pB = sb.x + e.rB;
        e.vB = sb.v + cross(sb.w, e.rB);
    }
    return e;
}

Vec2 Dynamics::lever(BodyId id, const Rotation& rot, const Vec2& localAnchor) const
{
    return rot.apply(localAnchor - m_bodies[static_cast<size_t>(id)].localCenter);
}

void Dynamics::acceleration(double /*t*/, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                            Eigen::VectorXd& a)
{
    const auto start = std::chrono::steady_clock::now();
    ++evaluations;
    appliedAccelerations(q, v, a);
    if (!m_joints.empty())
        addJointAccelerations(q, v, a);
    forceMilliseconds +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void Dynamics::appliedAccelerations(const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                    Eigen::VectorXd& a) const
{
    // Accumulate forces and torques per state slot in `a`, then divide by mass and inertia.
    a.setZero();
    auto addForce = [&](BodyId id, const Vec2& f, double torque) {
        const int s = m_slot[static_cast<size_t>(id)];
        if (s < 0 || !m_bodies[static_cast<size_t>(id)].isDynamic())
            return;
        const Eigen::Index i = 3 * static_cast<Eigen::Index>(s);
        a[i] += f.x();
        a[i + 1] += f.y();
        a[i + 2] += torque;
    };

    // Gravity, drag and the user's accumulators.
    for (size_t id = 0; id < m_bodies.size(); ++id) {
        const Body& b = m_bodies[id];
        if (!b.isDynamic())
            continue;
        const Eigen::Index i = 3 * static_cast<Eigen::Index>(m_slot[id]);
        const AppliedLoad load = appliedLoad(m_field, b, Vec2(v[i], v[i + 1]), v[i + 2]);
        a[i] += load.force.x();
        a[i + 1] += load.force.y();
        a[i + 2] += load.torque;
    }

    // Springs: F = k (L - L0) + c dL/dt along the line between the anchors, pulling A to B.
    for (const SpringDef& s : m_springs) {
        const SpringEnds e = springEnds(s, q, v);
        const Vec2 d = e.pB - e.pA;
        const double length = d.norm();
        if (length <= 1e-12)
            continue; // direction undefined; a zero-length spring pulls nowhere
        const Vec2 n = d / length;
        const double tension =
            s.stiffness * (length - s.restLength) + s.damping * (e.vB - e.vA).dot(n);
        const Vec2 f = tension * n; // on A, towards B when stretched
        if (s.a != kWorld)
            addForce(s.a, f, cross(e.rA, f));
        if (s.b != kWorld)
            addForce(s.b, -f, cross(e.rB, Vec2(-f)));
    }

    // Mutual gravitation between dynamic bodies, as point masses at their centres.
    if (m_field.gravitation != 0.0) {
        for (size_t i = 0; i < m_bodies.size(); ++i) {
            if (!m_bodies[i].isDynamic())
                continue;
            const Vec2 xi = state(static_cast<BodyId>(i), q, v).x;
            for (size_t j = i + 1; j < m_bodies.size(); ++j) {
                if (!m_bodies[j].isDynamic())
                    continue;
                const Vec2 d = state(static_cast<BodyId>(j), q, v).x - xi;
                const double r2 = d.squaredNorm();
                if (r2 <= 1e-24)
                    continue;
                const double r = std::sqrt(r2);
                const Vec2 f =
                    (m_field.gravitation * m_bodies[i].mass * m_bodies[j].mass / (r2 * r)) * d;
                addForce(static_cast<BodyId>(i), f, 0.0);
                addForce(static_cast<BodyId>(j), -f, 0.0);
            }
        }
    }

    // Newton for translation and rotation: a = F / m, alpha = M / I.
    for (size_t id = 0; id < m_bodies.size(); ++id) {
        const int s = m_slot[id];
        if (s < 0)
            continue;
        const Body& b = m_bodies[id];
        const Eigen::Index i = 3 * static_cast<Eigen::Index>(s);
        a[i] *= b.invMass;
        a[i + 1] *= b.invMass;
        a[i + 2] *= b.invInertia;
    }
}

} // namespace rigidlab::physics
