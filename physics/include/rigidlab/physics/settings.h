// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The world's settings: what a scene sets (WorldDef), the tuning of contacts and of the soft
// step that a scene does not set, and how the engine computes (EngineSettings). Each carries
// its defaults; World takes them in its constructor and its setters (world.h).

#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/integrator.h"
#include "rigidlab/physics/math.h"

#include <optional>

namespace rigidlab::physics {

/// World settings, with the defaults a scene file gets when it names none.
struct WorldDef {
    Vec2 gravity{0.0, -9.81}; ///< uniform acceleration [m/s^2]
    double dt = 0.001;        ///< fixed time step [s]
    IntegratorKind integrator = IntegratorKind::SymplecticEuler;
    /// The soft step by default: it keeps stacks and pyramids standing, and is exact where the
    /// lab promises (isolated impacts, soft_impacts.cpp), with springs, joints, gravitation
    /// and every integrator.
    SolverKind solver = SolverKind::SoftStep;
    /// Velocity iterations of the sequential-impulse solver, and the sweeps of the soft step's
    /// bounce pass (its resting contacts take SoftStepSettings::substeps instead).
    int iterations = 10;
    double restitution = 0.5; ///< default coefficient of restitution of bodies
    double friction = 0.3;    ///< default friction coefficient of bodies
    double gravitation = 0.0; ///< Newton's constant G between bodies [m^3/(kg s^2)], 0 = off
    double drag = 0.0;        ///< linear drag rate: F = -drag m v, M = -drag I w [1/s]
    Tolerances tolerances;    ///< error control of the adaptive integrator (dopri5)
    /// Continuous collision: a body that moves more than its own size in a step gets
    /// speculative contacts over the whole of its motion (continuous.cpp).
    bool continuous = true;
    /// Resting bodies go to sleep (islands.cpp): not integrated, not solved, until a contact
    /// or the user wakes them. Unset: on in large scenes (kLargeSceneBodies or more dynamic
    /// bodies), where nobody follows one body's energy, and off in the others.
    std::optional<bool> sleep;
};

/// Whether every number of def is inside its range of limits.h (the tolerances aside: see
/// World::setTolerances). World's constructor asserts it.
bool withinLimits(const WorldDef& def);

/// A scene with this many dynamic bodies or more is large: it sleeps unless told otherwise.
inline constexpr int kLargeSceneBodies = 200;

/// Tuning of the soft step (SolverKind::SoftStep, soft_solver.cpp).
struct SoftStepSettings {
    /// Substeps per step, each integrates and solves once. 5: the 12-box stack within 8 mm
    /// and the base-40 pyramid's top within 2.5 cm (6: 5 mm and 1.5 cm, for a fifth more time).
    int substeps = 5;
    /// Frequency of the contact spring between moving bodies, as a fraction of the substep
    /// rate (0.25: a quarter, 75 Hz at dt = 1/60 s; stiffer was unstable in stacks); twice
    /// that against a body that does not move. A load sinks a contact by about its weight /
    /// (effective mass (2 pi f)^2).
    double contactFrequency = 0.25;
    /// Damping ratio of the contact's spring. 2, over-damped: at 10 (Box2D v3's) the base-40
    /// pyramid's middle boxes crept up to 0.14 m sideways in 10 s, at 2 up to 1.4 cm.
    double dampingRatio = 2.0;
    double maxPushSpeed = 3.0; ///< fastest push that separates overlapping bodies [m/s]
    /// Friction in the soft solve as well as in the relax pass. Off: friction only in the relax
    /// pass, where the normal impulses hold the weight without the push (the base-100 pyramid
    /// slides apart with it on).
    bool frictionWithBias = false;
    /// The four-lane AVX2 kernel where the processor has it; false: the two-lane one. Both
    /// give the same bits (soft_kernel.h).
    bool wideKernel = true;
    /// The soft solve and relax passes in single precision: eight lanes with AVX2, four
    /// without (Box2D v3's choice); the warm start and the step's last relax in double. The
    /// velocities and impulses stay double and take only the passes' change, so a body no
    /// contact pushed keeps every bit; the floats hold what changed since the step began
    /// (soft_kernel.h), so a disc slides into rolling, a box rests on a slope and a body at
    /// rest sinks as in double, to 1e-6. Off by default: its bits are not double precision's
    /// (docs/performance-log.md). The collision phase, the positions and the energy books stay
    /// in double either way; a world whose contacts touch a pin joint solves in double.
    bool singlePrecision = false;
    /// Two polygons that moved less than this against each other since the full test made
    /// their manifold keep it (Box2D v3.2's contact recycling, narrow_phase.cpp): each point
    /// stays on both bodies and its separation follows them, as the substeps already move
    /// it. Bodies faster than the contact margin always get the full test. 0: every pair every
    /// step [m].
    double recycleDistance = 0.005;
};

/// Tuning of contacts that a scene does not set (Box2D's choices, in metres).
struct ContactSettings {
    double linearSlop = 0.005;  ///< allowed penetration, keeps contacts alive [m]
    double margin = 0.01;       ///< contacts are made closer than this [m]
    double baumgarte = 0.2;     ///< fraction of penetration removed per position pass
    double maxCorrection = 0.2; ///< largest position correction per pass [m]
    int positionIterations = 3;
    /// Touching polygons that barely moved are clipped from the faces the SAT chose before,
    /// without the SAT: the same contacts, bit for bit (narrow_phase.cpp). Off only to show
    /// that.
    bool reuseFaces = true;
    /// Approaches slower than this never bounce [m/s] (sequential impulses; see below).
    double restitutionThreshold = 0.5;
    SoftStepSettings soft; ///< the soft step's (its position correction is its own)
};

/// The approach speed below which a new contact rests instead of bouncing [m/s]: what gravity
/// adds in two steps, 2 |g| dt, but at least 0.01 m/s and at most the settings' threshold;
/// and never less than what gravity adds in one step, |g| dt. A contact that already pushed in
/// the step before (resting) keeps the settings' threshold. So without gravity a slow elastic
/// collision is elastic (a fixed 0.5 m/s, as in games, made a slow gas lose its energy), and
/// at a long step a resting ball does not bounce: at dt = 0.1 s, where a hop of one step lands
/// at about |g| dt = 0.98 m/s, a ball with e = 0.5 bounced on every landing and hopped 75 mm
/// for ever.
double restitutionThreshold(const WorldDef& def, const ContactSettings& settings);

/// How the engine computes, not what it computes: every choice here gives the same bits.
struct EngineSettings {
    /// Runs each stage's plain algorithm, as a textbook writes it (physics/src/stages/),
    /// instead of its accelerated form (physics/src/fast/): every body's placement computed
    /// anew, the SAT over every axis without hints, kept faces or unrolled boxes, the contacts
    /// coloured anew each step and solved one lane at a time, symplectic Euler through the
    /// integrator over the state vectors. The golden runs give the same hashes either way
    /// (tests/physics/test_golden.cpp).
    bool plainPaths = false;
};

} // namespace rigidlab::physics
