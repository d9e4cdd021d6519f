#pragma once
// Running a scene headless for a fixed number of steps, writing a trace of the bodies and
// the world's diagnostics as CSV (for `rigidlab-cli run`, and for tests that pin a run).
//
// Trace:       step,t,body,x,y,angle,vx,vy,omega
//              a row per dynamic body per written step; x, y: the body origin [m];
//              angle [rad]; vx, vy: velocity of the origin [m/s]; omega [rad/s].
// Diagnostics: step,t,kinetic,potential,total,px,py,angular_momentum,contacts
//              energies [J], momentum [kg m/s], angular momentum about the origin [kg m^2/s].
// Rows are written every `every` steps; step 0 and the last step always. Numbers carry 17
// significant digits, so that two runs compare bit for bit. The files are written whole or
// not at all: nothing is left behind by a run that fails.

#include "rigidlab/lessons/scene.h"
#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/integrator.h"
#include "rigidlab/physics/profile.h"

#include <QString>

#include <optional>

namespace rigidlab::lessons {

inline constexpr double kDefaultRunTime = 5.0;         ///< when neither time nor steps [s]
inline constexpr long long kMaxRunSteps = 100'000'000; ///< a mistyped --time stops here
inline constexpr const char* kTraceHeader = "step,t,body,x,y,angle,vx,vy,omega";
inline constexpr const char* kDiagnosticsHeader =
    "step,t,kinetic,potential,total,px,py,angular_momentum,contacts";

struct RunOptions {
    std::optional<double> time;     ///< simulated time [s]; not with steps
    std::optional<long long> steps; ///< number of steps; not with time
    std::optional<double> dt;       ///< overrides the scene's step [s]
    std::optional<physics::IntegratorKind> integrator;
    std::optional<physics::SolverKind> solver;
    QString tracePath;       ///< empty: no trace
    QString diagnosticsPath; ///< empty: no diagnostics
    long long every = 1;     ///< write every this many steps (>= 1)
    bool profile = false;    ///< add up each stage's time over the run (RunReport::profile)
};

enum class RunStatus {
    Ok,
    BadOptions,  ///< the options do not fit together or with the scene
    OutputError, ///< an output file could not be written
    NonFinite,   ///< the world diverged (physics::Divergence): the run stopped
};

struct RunReport {
    RunStatus status = RunStatus::BadOptions;
    QString error; ///< one line when status != Ok
    long long steps = 0;
    double dt = 0;            ///< [s]
    double simulatedTime = 0; ///< [s]
    double wallSeconds = 0;   ///< [s]
    double energyStart = 0;   ///< total energy at step 0 [J]
    double energyEnd = 0;     ///< [J]
    double collisionLoss = 0; ///< kinetic energy taken by contacts over the run [J]
    physics::IntegratorKind integrator = physics::IntegratorKind::SymplecticEuler;
    physics::SolverKind solver = physics::SolverKind::SequentialImpulse;
    /// With RunOptions::profile: each stage's time and ran flag summed over the steps [ms]
    /// (ran: the stage ran at least once), the counts of the last step.
    std::optional<physics::StepProfile> profile;

    /// One paragraph for people: steps, times, integrator, solver, energy drift.
    QString summary(const QString& sourceName) const;
    /// The profile as a table: each stage's mean time per step and share of the step, or
    /// "left out" for a stage that never ran. Empty without a profile.
    QString profileTable() const;
};

/// The number of steps of dt that cover `time` (rounded up; a count within 1e-9 of a whole
/// number is taken as that number, so 5 s at 0.001 s is 5000 steps).
long long stepsForTime(double time, double dt);

/// Runs the scene; `sourceName` names it in messages.
RunReport runScene(const Scene& scene, const RunOptions& options, const QString& sourceName);

} // namespace rigidlab::lessons
