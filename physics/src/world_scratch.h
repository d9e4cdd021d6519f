#pragma once
// Private: the world's buffers reused from step to step, shared by the files that implement
// World's stages (world.cpp, world_step.cpp, islands.cpp, continuous.cpp). Nothing here is
// state: a copied world starts with empty buffers and steps exactly as the original.

#include "rigidlab/physics/world.h"

#include "broad_phase.h"
#include "contact_solver.h"

#include <Eigen/Core>

#include <chrono>
#include <utility>
#include <vector>

namespace rigidlab::physics {

struct World::Scratch {
    BroadPhase broadPhase;
    std::vector<std::pair<int, int>> pairs;
    std::vector<Contact> previous;
    Eigen::VectorXd q, v;
    Eigen::VectorXd shake; ///< positions before the joint projection (symplectic Euler)
    /// The state at the start of the step, the mean velocity and the midpoint, for the
    /// energy that drag and dampers take (dissipation.cpp).
    Eigen::VectorXd q0, v0, meanVelocity, midpoint;
    std::vector<Vec2> velocityBefore, velocityAtStart;
    std::vector<double> angularVelocityBefore, angularVelocityAtStart;
    ContactSolver solver;
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

} // namespace rigidlab::physics
