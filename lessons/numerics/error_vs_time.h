// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Error against run time: the work-precision sweep behind `rigidlab-cli error-vs-time` and the
// window's "Error vs run time" panel.
//
// For every reference problem (reference_problems.h), integrator and step, the equations of
// motion are integrated from 0 to tEnd, and a row records:
//   dt            the step [s] (adaptive methods: the mean accepted substep, tEnd / steps)
//   steps         steps taken (adaptive methods: accepted substeps)
//   evaluations   force evaluations, a(t, q, v) calls (the implicit method's Jacobian included)
//   error         position error at tEnd against the reference [m] (pendulums: arc length)
//   max_error     its largest value over the run, checked at up to 200 evenly spread times
//                 (adaptive methods: at 50 evenly spread times)
//   energy_error  largest |E(t) - E(0)| at the same times, relative to the kinetic plus
//                 absolute potential energies at the start (at least 1 J per kg)
//   seconds       CPU time of the integration alone (no error checks): the smallest of repeated
//                 runs, repeated at least minRepeats times and until minTimingSeconds of CPU
//                 time were spent, on the thread's own CPU clock.
// Integrators: the engine's (euler, symplectic-euler, verlet, rk4, dopri5, implicit-midpoint)
// and Boost.Odeint's runge_kutta4 ("odeint-rk4") and controlled runge_kutta_dopri5
// ("odeint-dopri5") on the same equations. Fixed-step methods sweep dt; the adaptive ones
// sweep their tolerance (absolute = relative) over [tolFrom, tolTo] instead, in as many points.

#include "export/csv_dialect.h"
#include "numerics/reference_problems.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rigidlab::lessons {

/// The sweep's CSV head: the error columns are in the problem's own unit (its state's norm).
inline constexpr const char* kSweepCsvHeader = "problem,integrator,dt [s],steps,evaluations,"
                                               "error,max_error,energy_error,seconds [s]";

struct SweepOptions {
    QStringList problems;               ///< names; empty: all
    QStringList integrators;            ///< names; empty: all of sweepIntegratorNames()
    std::optional<double> dtFrom, dtTo; ///< [s]; unset: each problem's own range
    int points = 6;                     ///< steps (or tolerances) per integrator, >= 2
    std::optional<double> tEnd;         ///< [s]; unset: each problem's own
    double tolFrom = 1e-3;              ///< adaptive methods' loosest tolerance
    double tolTo = 1e-11;               ///< and tightest
    double minTimingSeconds = 0.05;     ///< CPU time to spend timing each row [s]
    int minRepeats = 3;
};

struct SweepRow {
    QString problem;
    QString integrator;
    double dt = 0; ///< [s]
    long long steps = 0;
    long long evaluations = 0;
    double error = 0;       ///< [m]
    double maxError = 0;    ///< [m]
    double energyError = 0; ///< relative
    double seconds = 0;     ///< CPU [s]
    double tolerance = 0;   ///< adaptive methods: the tolerance of the row, else 0
    int repeats = 0;        ///< timed runs behind `seconds`
};

/// Every integrator the sweep knows, in order.
QStringList sweepIntegratorNames();
/// Every problem name, in order.
QStringList sweepProblemNames();

/// Checks the options; an empty string when they are usable, else what is wrong.
QString checkSweepOptions(const SweepOptions& options);

/// Called after each row with the rows done and the total; return false to cancel.
using SweepProgress = std::function<bool(const SweepRow& row, int done, int total)>;

/// Runs the sweep (options checked first; invalid options give no rows).
std::vector<SweepRow> runSweep(const SweepOptions& options, const SweepProgress& progress = {});

/// The observed order of one integrator on one problem: the least-squares slope of
/// log(error) against log(dt) over its rows with 1e-10 < error < 1e-2 (away from round-off and
/// from errors as large as the motion). nullopt with fewer than two such rows.
std::optional<double> observedOrder(const std::vector<SweepRow>& rows, const QString& problem,
                                    const QString& integrator);

/// The errors observedOrder fits, between these bounds [m] (exclusive).
inline constexpr double kOrderErrorMin = 1e-10;
inline constexpr double kOrderErrorMax = 1e-2;

/// Why observedOrder has no value for one integrator on one problem.
enum class OrderGap {
    None,       ///< it has one
    TooFewRuns, ///< fewer than two runs so far
    RoundOff,   ///< the errors are at round-off level (at most kOrderErrorMin)
    TooLarge,   ///< the errors are as large as the motion (at least kOrderErrorMax)
};
OrderGap orderGap(const std::vector<SweepRow>& rows, const QString& problem,
                  const QString& integrator);

/// The rows as CSV in `conventions` (export/csv_writer.h: every number the shortest text
/// that reads back to it), head kSweepCsvHeader.
QByteArray sweepCsv(const std::vector<SweepRow>& rows, const CsvConventions& conventions = {});

} // namespace rigidlab::lessons
