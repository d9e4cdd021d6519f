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
    gatherState(m_bodies, m_moving, q, v);
}

void World::setState(const Eigen::VectorXd& q, const Eigen::VectorXd& v)
{
    scatterState(q, v, m_moving, Sleepers::Write, m_bodies);
}

std::unique_ptr<OdeSystem> World::equations() const
{
    return std::make_unique<WorldEquations>(m_def, m_bodies, m_slot, m_springs, m_joints);
}

} // namespace rigidlab::physics
