// SPDX-License-Identifier: GPL-3.0-or-later
// The work-precision sweep (see error_vs_time.h).

#include "numerics/error_vs_time.h"

#include "export/csv_writer.h"
#include "format/view_text.h"

#include "numerics/sweep_run.h"

#include "rigidlab/physics/integrator.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <ctime>
#include <limits>
#include <memory>

namespace rigidlab::lessons {

using detail::Observer;
using detail::RunCount;
using detail::RunSpec;

namespace {

constexpr const char* kOdeintRk4 = "odeint-rk4";
constexpr const char* kOdeintDopri5 = "odeint-dopri5";
/// Timed runs stop here even when the CPU budget is not spent (very fast runs).
constexpr int kMaxRepeats = 1000;

/// CPU time of this thread [s]: other threads and processes on the machine do not count.
double threadCpuSeconds()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

bool isAdaptive(const QString& integrator)
{
    return integrator == u"dopri5" || integrator == QLatin1String(kOdeintDopri5);
}

/// The engine's integrator from (q0, v0) at t = 0.
RunCount runEngine(physics::IntegratorKind kind, physics::OdeSystem& system,
                   const Eigen::VectorXd& q0, const Eigen::VectorXd& v0, const RunSpec& spec)
{
    auto integrator = physics::makeIntegrator(kind, {spec.tolerance, spec.tolerance});
    RunCount out;
    out.q = q0;
    out.v = v0;
    if (spec.observer)
        (*spec.observer)(0.0, out.q, out.v);
    if (kind == physics::IntegratorKind::DormandPrince) {
        const double chunk = spec.tEnd / detail::kAdaptiveChunks;
        for (int c = 0; c < detail::kAdaptiveChunks; ++c) {
            const double t = c * chunk;
            const double end = c + 1 == detail::kAdaptiveChunks ? spec.tEnd : (c + 1) * chunk;
            integrator->step(system, t, end - t, out.q, out.v);
            out.steps += integrator->substeps();
            if (spec.observer)
                (*spec.observer)(end, out.q, out.v);
        }
        return out;
    }
    const long long steps = std::max(1LL, std::llround(spec.tEnd / spec.dt));
    const double h = spec.tEnd / static_cast<double>(steps);
    const long long stride = (steps + detail::kFixedChecks - 1) / detail::kFixedChecks;
    for (long long i = 0; i < steps; ++i) {
        integrator->step(system, static_cast<double>(i) * h, h, out.q, out.v);
        if (spec.observer && ((i + 1) % stride == 0 || i + 1 == steps))
            (*spec.observer)(static_cast<double>(i + 1) * h, out.q, out.v);
    }
    out.steps = steps;
    return out;
}

/// Total, kinetic and absolute potential energies of the world at its state [J].
struct Energy {
    double total = 0;
    double scale = 0;
};
Energy energyOf(physics::World& world)
{
    world.updateDiagnostics();
    const physics::Diagnostics& d = world.diagnostics();
    return {d.total, physics::energyParts(d)};
}

std::vector<double> logSpaced(double from, double to, int points)
{
    std::vector<double> out;
    for (int i = 0; i < points; ++i) {
        const double f = points > 1 ? static_cast<double>(i) / (points - 1) : 0.0;
        out.push_back(from * std::pow(to / from, f));
    }
    return out;
}

/// One row: the error pass (with checks), then the timed runs (without).
SweepRow measure(const ReferenceProblem& problem, const QString& integrator, double tEnd, double dt,
                 double tolerance, const SweepOptions& options)
{
    SweepRow row;
    row.problem = QString::fromStdString(problem.name);
    row.integrator = integrator;
    row.tolerance = isAdaptive(integrator) ? tolerance : 0.0;

    physics::World world = problem.build();
    physics::World probe = problem.build(); // for energies at the checked states
    const std::unique_ptr<physics::OdeSystem> equations = world.equations();
    Eigen::VectorXd q0, v0;
    world.getState(q0, v0);
    Energy start = energyOf(probe);
    double mass = 0;
    for (const physics::Body& b : probe.bodies())
        mass += b.mass;
    start.scale = std::max(start.scale, mass * 1.0); // 1 J/kg: a world at rest has a scale

    RunSpec spec;
    spec.tEnd = tEnd;
    spec.dt = dt;
    spec.tolerance = tolerance;
    auto run = [&](physics::OdeSystem& system) {
        if (integrator == QLatin1String(kOdeintRk4))
            return detail::runOdeint(false, system, q0, v0, spec);
        if (integrator == QLatin1String(kOdeintDopri5))
            return detail::runOdeint(true, system, q0, v0, spec);
        const auto kind = physics::integratorFromName(integrator.toStdString());
        return runEngine(*kind, system, q0, v0, spec);
    };

    // Error pass.
    double maxError = 0, maxEnergy = 0, lastError = 0;
    const Observer observer = [&](double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
        const double e = problemError(problem, world, q, problem.reference(t));
        lastError = e;
        maxError = std::isnan(e) || std::isnan(maxError) ? std::nan("") : std::max(maxError, e);
        probe.setState(q, v);
        const double de = std::abs(energyOf(probe).total - start.total) / start.scale;
        maxEnergy =
            std::isnan(de) || std::isnan(maxEnergy) ? std::nan("") : std::max(maxEnergy, de);
    };
    detail::CountingSystem counted(*equations);
    spec.observer = &observer;
    const RunCount counts = run(counted);
    row.steps = counts.steps;
    row.evaluations = counted.count;
    row.error = lastError;
    row.maxError = maxError;
    row.energyError = maxEnergy;
    row.dt = counts.steps > 0 ? tEnd / static_cast<double>(counts.steps) : 0.0;

    // Timed runs: the same integration, without checks.
    spec.observer = nullptr;
    double best = std::numeric_limits<double>::infinity(), spent = 0;
    int repeats = 0;
    while ((repeats < options.minRepeats || spent < options.minTimingSeconds) &&
           repeats < kMaxRepeats) {
        const double begin = threadCpuSeconds();
        const RunCount timed = run(*equations);
        const double seconds = threadCpuSeconds() - begin;
        // Keep the result alive, so that the run cannot be optimised away.
        if (timed.steps < 0)
            break;
        best = std::min(best, seconds);
        spent += seconds;
        ++repeats;
    }
    row.seconds = best;
    row.repeats = repeats;
    return row;
}

} // namespace

QStringList sweepIntegratorNames()
{
    QStringList names;
    for (physics::IntegratorKind k : physics::kAllIntegrators)
        names.append(textFromView(physics::integratorName(k)));
    names.append(QLatin1String(kOdeintRk4));
    names.append(QLatin1String(kOdeintDopri5));
    return names;
}

QStringList sweepProblemNames()
{
    QStringList names;
    for (const ReferenceProblem& p : referenceProblems())
        names.append(QString::fromStdString(p.name));
    return names;
}

QString checkSweepOptions(const SweepOptions& o)
{
    const QStringList problems = sweepProblemNames();
    for (const QString& p : o.problems)
        if (!problems.contains(p))
            return QStringLiteral("unknown problem \"%1\" (expected %2 or all)")
                .arg(p, problems.join(u", "));
    const QStringList integrators = sweepIntegratorNames();
    for (const QString& i : o.integrators)
        if (!integrators.contains(i))
            return QStringLiteral("unknown integrator \"%1\" (expected %2)")
                .arg(i, integrators.join(u", "));
    auto positive = [](const std::optional<double>& x) {
        return !x || (std::isfinite(*x) && *x > 0);
    };
    if (!positive(o.dtFrom) || !positive(o.dtTo))
        return QStringLiteral("the steps must be positive numbers of seconds");
    if (!positive(o.tEnd))
        return QStringLiteral("the end time must be a positive number of seconds");
    if (o.points < 2 || o.points > 100)
        return QStringLiteral("the number of points must be from 2 to 100");
    if (!(o.tolFrom > 0 && o.tolTo > 0 && std::isfinite(o.tolFrom) && std::isfinite(o.tolTo)))
        return QStringLiteral("the tolerances must be positive numbers");
    for (const ReferenceProblem& p : referenceProblems()) {
        const double tEnd = o.tEnd.value_or(p.tEnd);
        const double smallest = std::min(o.dtFrom.value_or(p.dtFrom), o.dtTo.value_or(p.dtTo));
        if (tEnd / smallest > 1e8)
            return QStringLiteral("%1 s at a step of %2 s is more than 1e8 steps")
                .arg(tEnd)
                .arg(smallest);
    }
    return {};
}

std::vector<SweepRow> runSweep(const SweepOptions& options, const SweepProgress& progress)
{
    std::vector<SweepRow> rows;
    if (!checkSweepOptions(options).isEmpty())
        return rows;
    const QStringList integrators =
        options.integrators.isEmpty() ? sweepIntegratorNames() : options.integrators;
    std::vector<ReferenceProblem> problems;
    for (ReferenceProblem& p : referenceProblems())
        if (options.problems.isEmpty() || options.problems.contains(QString::fromStdString(p.name)))
            problems.push_back(std::move(p));
    const int total =
        static_cast<int>(problems.size()) * static_cast<int>(integrators.size()) * options.points;
    for (const ReferenceProblem& problem : problems) {
        const double tEnd = options.tEnd.value_or(problem.tEnd);
        const std::vector<double> steps =
            logSpaced(options.dtFrom.value_or(problem.dtFrom), options.dtTo.value_or(problem.dtTo),
                      options.points);
        const std::vector<double> tolerances =
            logSpaced(options.tolFrom, options.tolTo, options.points);
        for (const QString& integrator : integrators) {
            for (int i = 0; i < options.points; ++i) {
                const size_t k = static_cast<size_t>(i);
                rows.push_back(
                    measure(problem, integrator, tEnd, steps[k], tolerances[k], options));
                if (progress && !progress(rows.back(), static_cast<int>(rows.size()), total))
                    return rows;
            }
        }
    }
    return rows;
}

std::optional<double> observedOrder(const std::vector<SweepRow>& rows, const QString& problem,
                                    const QString& integrator)
{
    std::vector<double> x, y;
    for (const SweepRow& r : rows)
        if (r.problem == problem && r.integrator == integrator && r.error > kOrderErrorMin &&
            r.error < kOrderErrorMax && r.dt > 0) {
            x.push_back(std::log(r.dt));
            y.push_back(std::log(r.error));
        }
    if (x.size() < 2)
        return std::nullopt;
    const double n = static_cast<double>(x.size());
    double mx = 0, my = 0;
    for (size_t i = 0; i < x.size(); ++i) {
        mx += x[i] / n;
        my += y[i] / n;
    }
    double sxy = 0, sxx = 0;
    for (size_t i = 0; i < x.size(); ++i) {
        sxy += (x[i] - mx) * (y[i] - my);
        sxx += (x[i] - mx) * (x[i] - mx);
    }
    if (sxx <= 0)
        return std::nullopt;
    return sxy / sxx;
}

OrderGap orderGap(const std::vector<SweepRow>& rows, const QString& problem,
                  const QString& integrator)
{
    if (observedOrder(rows, problem, integrator))
        return OrderGap::None;
    int runs = 0, small = 0, large = 0;
    for (const SweepRow& r : rows) {
        if (r.problem != problem || r.integrator != integrator || r.dt <= 0)
            continue;
        ++runs;
        if (r.error <= kOrderErrorMin)
            ++small;
        else if (!(r.error < kOrderErrorMax)) // NaN too: a run that blew up is large
            ++large;
    }
    if (runs < 2)
        return OrderGap::TooFewRuns;
    return small >= large ? OrderGap::RoundOff : OrderGap::TooLarge;
}

QByteArray sweepCsv(const std::vector<SweepRow>& rows, const CsvConventions& conventions)
{
    CsvWriter csv(conventions);
    csv.row(QString::fromLatin1(kSweepCsvHeader).split(u','));
    for (const SweepRow& r : rows) {
        csv.text(r.problem);
        csv.text(r.integrator);
        csv.number(r.dt);
        csv.integer(r.steps);
        csv.integer(r.evaluations);
        for (double v : {r.error, r.maxError, r.energyError, r.seconds})
            csv.number(v);
        csv.endRow();
    }
    const std::string& data = csv.data();
    return QByteArray(data.data(), static_cast<qsizetype>(data.size()));
}

} // namespace rigidlab::lessons
