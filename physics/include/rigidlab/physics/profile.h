#pragma once
// What the last step cost, stage by stage, and which stages it left out.

namespace rigidlab::physics {

/// The stages of a step, in the order World::step() runs them.
enum class Stage {
    BroadPhase,   ///< pairs of bodies whose boxes overlap (broad_phase.cpp)
    NarrowPhase,  ///< SAT and manifolds for those pairs (sat.cpp)
    Islands,      ///< touching bodies grouped; a woken body wakes its island (islands.cpp)
    Forces,       ///< applied forces and joint forces (forces.cpp, joints.cpp)
    Integration,  ///< the integrator, without the force evaluations (integrators.cpp)
    ContactSolve, ///< impulses and position correction (contact_solver.cpp)
    Sleep,        ///< resting islands put to sleep (islands.cpp)
    Diagnostics,  ///< energies and momenta (diagnostics.cpp)
};
inline constexpr int kStageCount = 8;

/// Wall time of each stage of the last step [ms] (std::chrono::steady_clock), and what ran.
/// A stage the step left out has ran == false and exactly 0 ms.
struct StepProfile {
    double ms[kStageCount] = {}; ///< per Stage [ms]
    bool ran[kStageCount] = {};  ///< per Stage
    double total = 0;            ///< the whole step [ms]
    /// Integrated directly on the bodies (symplectic Euler without springs, joints or
    /// gravitation), not through the ODE system's state vectors.
    bool directIntegration = false;
    int pairs = 0;          ///< from the broad phase
    int contacts = 0;       ///< pairs with a manifold
    int solved = 0;         ///< contacts with an awake dynamic body, given to the solver
    int positionPasses = 0; ///< position correction passes made
    int awake = 0;          ///< dynamic bodies awake
    int asleep = 0;         ///< dynamic bodies asleep
    int islands = 0;        ///< islands of awake bodies (when sleeping is on)

    double stage(Stage s) const { return ms[static_cast<int>(s)]; }
    bool stageRan(Stage s) const { return ran[static_cast<int>(s)]; }
};

/// The stage's name as the CLI and the window print it ("broad phase").
const char* stageName(Stage s);

} // namespace rigidlab::physics
