// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private: the world's buffers reused from step to step, shared by the files that implement
// World's stages (profile.h names them), the timer of a stage, and World::withState. Nothing
// in Scratch is state: a copied world starts with empty buffers (FreshOnCopy) and steps
// exactly as the original (the golden test checks it).

#include "rigidlab/physics/world.h"

#include "broad_phase.h"
#include "contact_solver.h"
#include "dynamics.h"
#include "narrow_phase.h"
#include "soft_solver.h"

#include <Eigen/Core>

#include <chrono>
#include <utility>
#include <vector>

namespace rigidlab::physics {

struct World::Scratch {
    BroadPhase broadPhase;
    std::vector<std::pair<int, int>> pairs;
    std::vector<Contact> previous;
    NarrowPhaseCache narrow; ///< saves the narrow phase work, changes no result (narrow_phase.h)
    Eigen::VectorXd q, v;
    Eigen::VectorXd shake; ///< positions before the joint projection (symplectic Euler)
    /// The state at the start of the step, the mean velocity and the midpoint, for the
    /// energy that drag and dampers take (dissipation.cpp).
    Eigen::VectorXd q0, v0, meanVelocity, midpoint;
    std::vector<Vec2> velocityBefore, velocityAtStart;
    std::vector<double> angularVelocityBefore, angularVelocityAtStart;
    ContactSolver solver;
    SoftSolver softSolver;
    /// The soft step's collision phase: each body's velocities at the start of the step, and
    /// how far its bounce moves it back, -f dt dv and -f dt dw (empty: nothing bounced).
    std::vector<Vec2> softVelocity, impactShift;
    std::vector<double> softAngularVelocity, impactTurn;
    /// Some body has restitution this step (else no contact has, and none can bounce).
    bool anyRestitution = true;
    /// The direct integration's accelerations [m/s^2] and [rad/s^2].
    std::vector<Vec2> acceleration;
    std::vector<double> angularAcceleration;
    /// Each body's placement at the start of the step, and the pose it was computed for.
    std::vector<Transform> xf;
    std::vector<Vec2> xfPosition;
    std::vector<double> xfAngle;
    /// Islands (islands.cpp): union-find parents and the bodies of each island.
    std::vector<int> islandParent;
    std::vector<int> islandOrder, islandStart;
    std::vector<double> islandRest;
};

/// Times a stage into the world's profile: the wall time from construction to stop().
class StageTimer {
public:
    using Clock = std::chrono::steady_clock;
    StageTimer(StepProfile& profile, Stage stage)
        : m_profile(profile), m_stage(static_cast<int>(stage)), m_start(Clock::now())
    {
    }
    ~StageTimer() { stop(); }
    StageTimer(const StageTimer&) = delete;
    StageTimer& operator=(const StageTimer&) = delete;
    void stop()
    {
        if (m_stopped)
            return;
        m_stopped = true;
        m_profile.ran[m_stage] = true;
        m_profile.ms[m_stage] +=
            std::chrono::duration<double, std::milli>(Clock::now() - m_start).count();
    }

private:
    StepProfile& m_profile;
    int m_stage;
    Clock::time_point m_start;
    bool m_stopped = false;
};

template <typename Fn> inline void World::withState(Fn&& fn)
{
    Eigen::VectorXd& q = m_scratch->q;
    Eigen::VectorXd& v = m_scratch->v;
    const Eigen::Index n = 3 * static_cast<Eigen::Index>(m_moving.size());
    q.resize(n);
    v.resize(n);
    for (size_t s = 0; s < m_moving.size(); ++s) {
        const Body& b = m_bodies[static_cast<size_t>(m_moving[s])];
        const Eigen::Index i = 3 * static_cast<Eigen::Index>(s);
        q.segment<3>(i) << b.position.x(), b.position.y(), b.angle;
        v.segment<3>(i) << b.velocity.x(), b.velocity.y(), b.angularVelocity;
    }
    Dynamics dynamics(m_def, m_bodies, m_slot, m_springs, m_joints);
    fn(dynamics, q, v);
    m_evaluations += dynamics.evaluations;
    for (size_t s = 0; s < m_moving.size(); ++s) {
        Body& b = m_bodies[static_cast<size_t>(m_moving[s])];
        if (b.isDynamic() && !b.awake)
            continue; // asleep: it does not move, whatever the integrator made of it
        const Eigen::Index i = 3 * static_cast<Eigen::Index>(s);
        b.position = Vec2(q[i], q[i + 1]);
        b.angle = q[i + 2];
        b.velocity = Vec2(v[i], v[i + 1]);
        b.angularVelocity = v[i + 2];
    }
}

} // namespace rigidlab::physics
