// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the last step cost, stage by stage, and which stages it left out.

namespace rigidlab::physics {

/// The stages of a step, in the order World::step() runs them: the one description of that
/// order (world.h and the stages' files refer to it). Each stage is a free function of the
/// step's context in physics/src/stages/ (stages.h), written as a textbook writes it; where it
/// has an acceleration, that is in physics/src/fast/ (EngineSettings::plainPaths runs the
/// plain ones, with the same bits). Before the stages, the step's plan (step_plan.cpp) leaves
/// out what the scene does not need; after them, a non-finite state or runaway energy stops
/// the world (divergence.cpp).
enum class Stage {
    /// Pairs of bodies whose boxes overlap (broad_phase.cpp), and fast bodies' pairs over
    /// their motion (continuous.cpp). Each body's placement: step_plan.cpp, or only the
    /// bodies that moved in fast/body_placement.cpp.
    BroadPhase,
    /// The contacts of those pairs: SAT (sat.cpp; fast/sat_fast.cpp), manifolds
    /// (manifold.cpp), warm start and mixed materials (narrow_phase.cpp; the kept faces in
    /// fast/kept_faces.cpp).
    NarrowPhase,
    /// Touching bodies grouped; a woken body wakes its island (islands.cpp).
    Islands,
    /// Applied forces and the pin joints' exact forces (forces.cpp, joints.cpp), evaluated at
    /// every stage of the integrator, so timed from inside Integration.
    Forces,
    /// The integrator (integrators/, integration.cpp; symplectic Euler straight on the
    /// bodies in fast/integrate_direct.cpp), then the joints projected back (joints.cpp).
    Integration,
    /// Impulses, the joints projected again, position correction (contact_response.cpp,
    /// contact_solver.cpp, paper_impulse.cpp, sequential_impulses.cpp). The soft step
    /// (soft_step.cpp) runs Forces, Integration and
    /// ContactSolve together in substeps, its contacts in soft_solver.cpp, coloured in
    /// fast/soft_colouring.cpp and solved by fast/soft_kernel.cpp.
    ContactSolve,
    /// Resting islands put to sleep (islands.cpp).
    Sleep,
    /// Energies and momenta (diagnostics.cpp).
    Diagnostics,
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
    int reusedFaces = 0;    ///< of them, clipped from the faces the SAT chose before
    int solved = 0;         ///< contacts with an awake dynamic body, given to the solver
    int positionPasses = 0; ///< position correction passes made
    int awake = 0;          ///< dynamic bodies awake
    int asleep = 0;         ///< dynamic bodies asleep
    int islands = 0;        ///< islands of awake bodies (when sleeping is on)
    int fast = 0;           ///< bodies with a swept margin (continuous collision)
    int refitted = 0;       ///< bodies put back in the broad phase's tree, one query each

    double stage(Stage s) const { return ms[static_cast<int>(s)]; }
    bool stageRan(Stage s) const { return ran[static_cast<int>(s)]; }
};

/// The stage's name as the CLI and the window print it ("broad phase").
const char* stageName(Stage s);

} // namespace rigidlab::physics
