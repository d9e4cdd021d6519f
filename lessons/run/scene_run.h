// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Running a scene headless for a fixed number of steps, writing a trace of the bodies and
// the world's diagnostics as CSV (for `rigidlab-cli run`, and for tests that pin a run).
//
// Trace:       step,t [s],body,x [m],y [m],angle [rad],v_x [m/s],v_y [m/s],ω [rad/s]
//              a row per dynamic body per written step; x, y: the body origin; v_x, v_y:
//              velocity of the origin.
// Diagnostics: step,t [s],E_k [J],E_p [J],E [J],p_x [kg m/s],p_y [kg m/s],L [kg m²/s],
//              contacts,E_diss [J],drift [1]
//              L: angular momentum about the origin; E_diss: the energy taken since step 0 by
//              contacts (inelastic bounces and friction), drag and the dampers of springs;
//              drift: the numerical error, (E + E_diss - E0) / |E0| with E0 the total at step 0
//              (relative; see energyScale()).
// The heads are those of lessons/export/csv_columns.h, in the language in effect. Rows are
// written every `every` steps; step 0 and the last step always. Written by the lab's one CSV
// writer (lessons/export/csv_writer.h): t as a person writes step k's time (step_time.h),
// every number the shortest text that reads back to the same double, a value below its noise
// floor (noise_floor.h) as 0, in the dialect asked for. The files are written whole or not at
// all: nothing is left behind by a run that fails.

#include "export/csv_dialect.h"
#include "format/scene.h"
#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/integrator.h"
#include "rigidlab/physics/profile.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace rigidlab::lessons {

inline constexpr double kDefaultRunTime = 5.0;         ///< when neither time nor steps [s]
inline constexpr long long kMaxRunSteps = 100'000'000; ///< a mistyped --time stops here
/// The trace's and the diagnostics' column heads, in the language in effect.
QStringList traceHeader();
QStringList diagnosticsHeader();

struct RunOptions {
    std::optional<double> time;     ///< simulated time [s]; not with steps
    std::optional<long long> steps; ///< number of steps; not with time
    std::optional<double> dt;       ///< overrides the scene's step [s]
    std::optional<physics::IntegratorKind> integrator;
    std::optional<physics::SolverKind> solver;
    QString tracePath;       ///< empty: no trace
    QString diagnosticsPath; ///< empty: no diagnostics
    long long every = 1;     ///< write every this many steps (>= 1)
    CsvConventions csv;      ///< the files' dialect (plain unless asked)
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
    double dissipated = 0;    ///< taken by contacts, drag and dampers over the run [J]
    double energyScale = 1;   ///< what the drift is relative to, energyScale() at step 0 [J]
    physics::IntegratorKind integrator = physics::IntegratorKind::SymplecticEuler;
    physics::SolverKind solver = physics::SolverKind::SequentialImpulse;
    /// With RunOptions::profile: each stage's time and ran flag summed over the steps [ms]
    /// (ran: the stage ran at least once), the counts of the last step.
    std::optional<physics::StepProfile> profile;

    /// The numerical error at the end: (energyEnd + dissipated - energyStart) / energyScale.
    double drift() const;
    /// One paragraph for people: steps, times, integrator, solver, energy drift.
    QString summary(const QString& sourceName) const;
    /// The profile as a table: each stage's mean time per step and share of the step, or
    /// "left out" for a stage that never ran. Empty without a profile.
    QString profileTable() const;
};

/// The number of steps of dt that cover `time` (rounded up; a count within 1e-9 of a whole
/// number is taken as that number, so 5 s at 0.001 s is 5000 steps).
long long stepsForTime(double time, double dt);

/// What a drift is relative to [J]: |E0|, the total energy; where E0 is 0 or less than 1e-9
/// of its parts K0 + |P0| (they cancel), K0 + |P0| instead, and 1 J when the world holds no
/// energy at all. (The window's plots use the same rule.)
double energyScale(const physics::Diagnostics& start);

/// Runs the scene; `sourceName` names it in messages.
RunReport runScene(const Scene& scene, const RunOptions& options, const QString& sourceName);

} // namespace rigidlab::lessons
