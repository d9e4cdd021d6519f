// SPDX-License-Identifier: GPL-3.0-or-later
// The world's equations of motion as an OdeSystem of their own, without the contact stages
// of step(): what a reference solution or another ODE library integrates.

#include "rigidlab/physics/world.h"

#include "dynamics.h"

namespace rigidlab::physics {

namespace {

class WorldEquations final : public OdeSystem {
public:
    WorldEquations(const WorldDef& def, const std::vector<Body>& bodies,
                   const std::vector<int>& slot, const std::vector<SpringDef>& springs,
                   const std::vector<PinJointDef>& joints)
        : m_dynamics(forceField(def), bodies, slot, springs, joints)
    {
    }
    void acceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                      Eigen::VectorXd& a) override
    {
        m_dynamics.acceleration(t, q, v, a);
    }

private:
    Dynamics m_dynamics;
};

} // namespace

void World::getState(Eigen::VectorXd& q, Eigen::VectorXd& v) const
{
    const Eigen::Index n = 3 * static_cast<Eigen::Index>(m_moving.size());
    q.resize(n);
    v.resize(n);
    for (size_t s = 0; s < m_moving.size(); ++s) {
        const Body& b = m_bodies[static_cast<size_t>(m_moving[s])];
        const Eigen::Index i = 3 * static_cast<Eigen::Index>(s);
        q.segment<3>(i) << b.position.x(), b.position.y(), b.angle;
        v.segment<3>(i) << b.velocity.x(), b.velocity.y(), b.angularVelocity;
    }
}

void World::setState(const Eigen::VectorXd& q, const Eigen::VectorXd& v)
{
    for (size_t s = 0; s < m_moving.size(); ++s) {
        Body& b = m_bodies[static_cast<size_t>(m_moving[s])];
        const Eigen::Index i = 3 * static_cast<Eigen::Index>(s);
        b.position = Vec2(q[i], q[i + 1]);
        b.angle = q[i + 2];
        b.velocity = Vec2(v[i], v[i + 1]);
        b.angularVelocity = v[i + 2];
    }
}

std::unique_ptr<OdeSystem> World::equations() const
{
    return std::make_unique<WorldEquations>(m_def, m_bodies, m_slot, m_springs, m_joints);
}

} // namespace rigidlab::physics
