// SPDX-License-Identifier: GPL-3.0-or-later
// rigidlab-cli conserve: the conservation experiments (numerics/conservation.h),
// run with every solver that resolves impacts. Argument handling only.

#include "cli_common.h"
#include "cli_numerics.h"

#include "numerics/conservation.h"

#include <cstdio>

namespace rigidlab::cli {

int commandConserve(const QStringList& words)
{
    CommandLine args(QStringLiteral("conserve"));
    for (const char* name : {"balls", "time", "dt"})
        args.addValue(QLatin1StringView(name));
    if (!args.parseOptionsOnly(words))
        return usageError(args.command(), args.error());
    QString error;
    lessons::GasSpec gas;
    if (const auto balls = args.value(QStringLiteral("balls"))) {
        const auto n = wholeNumber(QStringLiteral("--balls"), *balls, 1, 5000, error);
        if (!n)
            return usageError(args.command(), error);
        gas.balls = static_cast<int>(*n);
    }
    if (const auto time = args.value(QStringLiteral("time"))) {
        const auto t = finiteNumber(QStringLiteral("--time"), *time, error);
        if (!t)
            return usageError(args.command(), error);
        if (!(*t > 0 && *t <= 3600))
            return usageError(
                args.command(),
                QStringLiteral("--time: must be > 0 and <= 3600 s, got \"%1\"").arg(*time));
        gas.seconds = *t;
    }
    if (const auto dt = args.value(QStringLiteral("dt"))) {
        const auto h = finiteNumber(QStringLiteral("--dt"), *dt, error);
        if (!h)
            return usageError(args.command(), error);
        if (!(*h >= 1e-5 && *h <= 0.05))
            return usageError(
                args.command(),
                QStringLiteral("--dt: must be from 1e-05 to 0.05 s, got \"%1\"").arg(*dt));
        gas.dt = *h;
    }
    constexpr physics::SolverKind kSolvers[] = {physics::SolverKind::PaperImpulse,
                                                physics::SolverKind::SequentialImpulse,
                                                physics::SolverKind::SoftStep};
    std::vector<lessons::ConservationResult> rows;
    for (const physics::SolverKind solver : kSolvers)
        rows.push_back(lessons::runElasticGas(gas, solver));
    std::printf("Elastic gas: %d balls of radius %g m at up to %g m/s per component, e = 1, "
                "no friction, no gravity, dt = %g s, %g s.\n",
                gas.balls, gas.radius, gas.speed, gas.dt, gas.seconds);
    std::fputs(lessons::conservationTable(rows).c_str(), stdout);

    const lessons::CradleSpec cradle;
    rows.clear();
    for (const physics::SolverKind solver : kSolvers)
        rows.push_back(lessons::runCradleRow(cradle, solver));
    std::printf("\nCradle row: a ball at %g m/s into %d touching balls, e = 1, dt = %g s, %d "
                "steps (worst gain: the largest one-step relative gain).\n",
                cradle.speed, cradle.balls, cradle.dt, cradle.steps);
    std::fputs(lessons::conservationTable(rows).c_str(), stdout);

    rows.clear();
    for (const physics::SolverKind solver : kSolvers)
        rows.push_back(lessons::runNewtonsCradle(solver));
    std::printf("\nNewton's cradle (lessons/scenes/newtons_cradle.json, 2 s): E = kinetic + "
                "gravity; worst gain: the largest one-step gain, relative to the swing's "
                "energy, in steps where two or more contact points pushed.\n");
    std::fputs(lessons::conservationTable(rows).c_str(), stdout);
    std::printf("\ndrift: (E end - E start) / E start; worst: the largest |E(t) - E start| / "
                "E start over the run.\n");
    return kExitOk;
}

} // namespace rigidlab::cli
