// SPDX-License-Identifier: GPL-3.0-or-later
#include "measure/fit.h"

#include "format/divergence_message.h"
#include "measure/exact_flights.h"
#include "measure/minimise.h"
#include "rigidlab/physics/world.h"

#include <QCoreApplication>
#include <QStringList>

#include <Eigen/Dense>
#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rigidlab::measure {

namespace {

/// A halving of the step that moves each value by less than this fraction of its standard
/// uncertainty no longer matters (it adds under 6 % to the interval, in quadrature).
constexpr double kNegligibleStepChange = 1.0 / 3.0;
/// Gauss–Newton iterations at each halved step, from the value at the step before.
constexpr int kRefineIterations = 2;
/// A 95 % interval wider than this share of the search range determines nothing.
constexpr double kWidestInterval = 0.5;

/// The quantity's value of a body in the world.
double read(const physics::World& world, const Target& target)
{
    const physics::Body& b = world.body(target.body);
    switch (target.quantity) {
    case Quantity::X:
        return b.origin().x();
    case Quantity::Y:
        return b.origin().y();
    case Quantity::Vx:
        return world.originVelocity(target.body).x();
    case Quantity::Vy:
        return world.originVelocity(target.body).y();
    case Quantity::Speed:
        return world.originVelocity(target.body).norm();
    default:
        return 0.0;
    }
}

/// The simulated values with the parameters set to x, or nothing (the error kept). Every
/// sum of squares taken is kept with its point: the identifiability check reads them.
struct Model {
    const lessons::Scene& scene;
    const std::vector<Parameter>& parameters;
    const Target& target;
    const Series& series;
    bool exact = false; ///< closed-form flights (exact_flights.h), else the lab's run at dt
    double dt = 0;      ///< [s]
    const FitOptions& options;
    int runs = 0;
    long long work = 0; ///< the lab's steps run so far
    QString error;
    std::vector<std::pair<std::vector<double>, double>> tried;

    const std::vector<double>& times() const { return series.t; }
    long long stepsPerRun() const
    {
        return static_cast<long long>(std::ceil(series.t.back() / dt)) + 1;
    }

    std::optional<std::vector<double>> operator()(const std::vector<double>& x)
    {
        // Cancelled: every run fails at once, and the fit with it (the minimiser's remaining
        // trials cost nothing).
        if (options.cancelled && options.cancelled->load())
            return std::nullopt;
        if (options.runs)
            options.runs->fetch_add(1);
        lessons::Scene trial = scene;
        for (std::size_t i = 0; i < parameters.size(); ++i)
            setParameter(trial, parameters[i], x[i]);
        ++runs;
        if (exact)
            return exactFlightsAt(trial, target, series.t);
        trial.world.dt = dt;
        work += stepsPerRun();
        Simulated s = simulateAt(trial, target, series.t);
        if (!s.ok) {
            if (error.isEmpty())
                error = s.error;
            return std::nullopt;
        }
        return std::move(s.values);
    }

    /// Σ (measured − simulated)², infinite where the model fails.
    double sumSquares(const std::vector<double>& x)
    {
        const auto sim = (*this)(x);
        double s = 0;
        for (std::size_t i = 0; sim && i < sim->size(); ++i)
            s += std::pow(series.value[i] - (*sim)[i], 2);
        if (!sim)
            s = std::numeric_limits<double>::infinity();
        tried.emplace_back(x, s);
        return s;
    }
};

/// J: d(simulated)/d(parameter) by central differences (one-sided at a bound).
std::optional<Eigen::MatrixXd> jacobian(Model& model, const std::vector<double>& x,
                                        const std::vector<std::pair<double, double>>& bounds)
{
    const std::size_t n = model.times().size(), k = x.size();
    Eigen::MatrixXd J(n, k);
    for (std::size_t j = 0; j < k; ++j) {
        const double h = 1e-3 * std::max(1.0, bounds[j].second - bounds[j].first);
        std::vector<double> up = x, down = x;
        up[j] = std::min(x[j] + h, bounds[j].second);
        down[j] = std::max(x[j] - h, bounds[j].first);
        const auto fu = model(up);
        const auto fd = model(down);
        if (!fu || !fd)
            return std::nullopt;
        for (std::size_t i = 0; i < n; ++i)
            J(i, j) = ((*fu)[i] - (*fd)[i]) / (up[j] - down[j]);
    }
    return J;
}

FitResult fitFailed(const QString& error)
{
    FitResult r;
    r.error = error;
    return r;
}

QString notDetermined(const Parameter& p)
{
    return QCoreApplication::translate("rigidlab::measure",
                                       "%1 cannot be determined from these data: values far "
                                       "apart fit them as well (a ball at rest, too few "
                                       "bounces, or too short a measurement)")
        .arg(p.name);
}

/// The values' standard errors and 95 % half-widths from J and the residuals.
bool uncertainties(const Eigen::MatrixXd& J, double sumSquares, FitResult& result,
                   const std::vector<Parameter>& parameters)
{
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(JtJ);
    for (Eigen::Index j = 0; j < JtJ.rows(); ++j) {
        if (!(JtJ(j, j) > 0)) {
            result.error =
                QCoreApplication::translate("rigidlab::measure",
                                            "the measurement does not depend on %1: it cannot "
                                            "be fitted from it")
                    .arg(parameters[static_cast<std::size_t>(j)].name);
            return false;
        }
    }
    const Eigen::MatrixXd cov = ldlt.solve(Eigen::MatrixXd::Identity(JtJ.rows(), JtJ.cols())) *
                                (sumSquares / result.degreesOfFreedom);
    const double t95 = studentsT95(result.degreesOfFreedom);
    for (std::size_t j = 0; j < result.values.size(); ++j) {
        const double var = cov(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(j));
        if (!(var >= 0) || !std::isfinite(var)) {
            result.error = QCoreApplication::translate("rigidlab::measure",
                                                       "the parameters cannot be told apart "
                                                       "by this measurement");
            return false;
        }
        result.values[j].standardError = std::sqrt(var);
        result.values[j].halfWidth95 = t95 * result.values[j].standardError;
    }
    return true;
}

/// Whether the data determine each value: its interval is not as wide as the search, and no
/// point tried far outside it (the grid spans the whole search) fits the data as well as the
/// interval's own ends. A flat or many-dipped sum of squares has such points; a ball at rest
/// fits every e alike. The first parameter that is not determined, or none.
std::optional<std::size_t> undetermined(const FitResult& result, const Model& model,
                                        const std::vector<double>& best, double bestSum,
                                        const std::vector<std::pair<double, double>>& bounds)
{
    const double t95 = studentsT95(result.degreesOfFreedom);
    const double within = bestSum * (1.0 + t95 * t95 / result.degreesOfFreedom);
    for (std::size_t j = 0; j < best.size(); ++j) {
        const double range = bounds[j].second - bounds[j].first;
        const double halfWidth = result.values[j].halfWidth95;
        if (!(2 * halfWidth < kWidestInterval * range))
            return j;
        for (const auto& [x, sum] : model.tried)
            if (sum <= within && std::abs(x[j] - best[j]) > 2 * halfWidth + 1e-9 * range)
                return j;
    }
    return std::nullopt;
}

/// Residuals, RMS and simulated values at the values in `result`.
bool fillResiduals(Model& model, FitResult& result)
{
    std::vector<double> x;
    for (const FittedValue& v : result.values)
        x.push_back(v.value);
    const auto sim = model(x);
    if (!sim)
        return false;
    result.simulated = *sim;
    result.residuals.clear();
    double sum = 0;
    for (std::size_t i = 0; i < sim->size(); ++i) {
        result.residuals.push_back(model.series.value[i] - (*sim)[i]);
        sum += result.residuals.back() * result.residuals.back();
    }
    result.rms = std::sqrt(sum / static_cast<double>(sim->size()));
    return true;
}

double sumOfSquares(const FitResult& result)
{
    double sum = 0;
    for (const double r : result.residuals)
        sum += r * r;
    return sum;
}

/// Gauss–Newton steps from x with a Jacobian J taken at a nearby step (it hardly changes
/// when the step is halved), kept in the bounds; nothing when the model fails.
std::optional<std::vector<double>> gaussNewton(Model& model, std::vector<double> x,
                                               const Eigen::MatrixXd& J,
                                               const std::vector<std::pair<double, double>>& bounds)
{
    const Eigen::LDLT<Eigen::MatrixXd> normal(J.transpose() * J);
    for (int iteration = 0; iteration < kRefineIterations; ++iteration) {
        const auto sim = model(x);
        if (!sim)
            return std::nullopt;
        Eigen::VectorXd r(static_cast<Eigen::Index>(sim->size()));
        for (std::size_t i = 0; i < sim->size(); ++i)
            r(static_cast<Eigen::Index>(i)) = model.series.value[i] - (*sim)[i];
        const Eigen::VectorXd dx = normal.solve(J.transpose() * r);
        for (std::size_t j = 0; j < x.size(); ++j)
            x[j] = std::clamp(x[j] + dx(static_cast<Eigen::Index>(j)), bounds[j].first,
                              bounds[j].second);
    }
    return x;
}

/// Halves the lab's step until that moves no value by more than kNegligibleStepChange of its
/// standard uncertainty, or the work budget ends (then the last change is added to each
/// interval). `result` holds the values at the scene's step and gets them at the last step.
bool refineStep(Model& model, Eigen::MatrixXd J, FitResult& result,
                const std::vector<Parameter>& parameters,
                const std::vector<std::pair<double, double>>& bounds, long long maxWork)
{
    std::vector<double> x;
    for (const FittedValue& v : result.values)
        x.push_back(v.value);
    result.stepChange.assign(x.size(), 0.0);
    const auto negligible = [&] {
        for (std::size_t j = 0; j < x.size(); ++j)
            if (!(std::abs(result.stepChange[j]) <=
                  kNegligibleStepChange * result.values[j].standardError))
                return false;
        return true;
    };
    // Each level: Gauss–Newton with the Jacobian of the level before (it hardly changes),
    // then the residuals; a Jacobian of its own only at the last level, for the interval.
    const long long levelRuns = kRefineIterations + 1;
    const long long lastRuns = 2 * static_cast<long long>(x.size());
    bool halved = false;
    while (!halved || !negligible()) {
        // At least one halving, else the step's error is unknown; more while the budget lasts.
        const long long next = 2 * model.stepsPerRun() * (levelRuns + lastRuns);
        if (halved && model.work + next > maxWork) {
            result.stepErrorAdded = true;
            break;
        }
        model.dt /= 2;
        const auto refined = gaussNewton(model, x, J, bounds);
        if (!refined)
            return false;
        for (std::size_t j = 0; j < x.size(); ++j) {
            result.stepChange[j] = (*refined)[j] - x[j];
            result.values[j].value = (*refined)[j];
        }
        x = *refined;
        halved = true;
        if (!fillResiduals(model, result) ||
            !uncertainties(J, sumOfSquares(result), result, parameters))
            return false;
    }
    const auto lastJ = jacobian(model, x, bounds);
    if (!lastJ || !uncertainties(*lastJ, sumOfSquares(result), result, parameters))
        return false;
    result.step = model.dt;
    if (result.stepErrorAdded)
        for (std::size_t j = 0; j < x.size(); ++j) {
            FittedValue& v = result.values[j];
            const double change = std::abs(result.stepChange[j]);
            v.halfWidth95 += change;
            v.standardError = std::hypot(v.standardError, change);
        }
    return true;
}

/// The work of a fit at the scene's own step, estimated before it runs: the grid, the
/// minimiser and the Jacobian.
QString tooMuchWork(const Model& model, int grid, std::size_t k, long long maxWork)
{
    const double runs = std::pow(grid, static_cast<double>(k)) + 60.0 * static_cast<double>(k);
    const double steps = static_cast<double>(model.stepsPerRun());
    if (runs * steps <= static_cast<double>(maxWork))
        return {};
    return QCoreApplication::translate("rigidlab::measure",
                                       "the measurement ends %1 s after the scene starts: "
                                       "fitting it would run %2 steps of %3 s about %4 times; "
                                       "give the file's time at which the scene starts "
                                       "(--time-zero) or measure a shorter span")
        .arg(model.series.t.back())
        .arg(model.stepsPerRun())
        .arg(model.dt)
        .arg(runs);
}

} // namespace

double studentsT95(int dof)
{
    const boost::math::students_t dist(std::max(dof, 1));
    return boost::math::quantile(boost::math::complement(dist, 0.025));
}

Simulated simulateAt(const lessons::Scene& scene, const Target& target,
                     const std::vector<double>& times)
{
    Simulated out;
    const double dt = scene.world.dt;
    if (!times.empty() && times.back() / dt > static_cast<double>(kMaxFitSteps)) {
        out.error = QCoreApplication::translate("rigidlab::measure",
                                                "the measurement lasts %1 s, more than %2 "
                                                "steps of the scene's %3 s")
                        .arg(times.back())
                        .arg(kMaxFitSteps)
                        .arg(dt);
        return out;
    }
    physics::World world = lessons::buildWorld(scene);
    double t0 = world.time(), v0 = read(world, target);
    world.step();
    double t1 = world.time(), v1 = read(world, target);
    out.values.reserve(times.size());
    for (const double t : times) {
        while (t1 < t && !world.divergence()) {
            t0 = t1;
            v0 = v1;
            world.step();
            t1 = world.time();
            v1 = read(world, target);
        }
        if (world.divergence()) {
            out.error = lessons::divergenceMessage(*world.divergence());
            return out;
        }
        const double w = t1 > t0 ? std::clamp((t - t0) / (t1 - t0), 0.0, 1.0) : 1.0;
        out.values.push_back(v0 + w * (v1 - v0));
    }
    out.ok = true;
    return out;
}

QString describeModel(const FitResult& fit, const std::vector<Parameter>& parameters)
{
    if (fit.exact)
        return QCoreApplication::translate("rigidlab::measure",
                                           "model: the exact flights of a ball bouncing on a "
                                           "flat floor (closed form, no time step)");
    QStringList changes;
    for (std::size_t i = 0; i < parameters.size() && i < fit.stepChange.size(); ++i)
        changes << QCoreApplication::translate("rigidlab::measure", "%1 by %2")
                       .arg(parameters[i].name, QString::number(fit.stepChange[i], 'g', 2));
    const QString changed = changes.join(QStringLiteral(", "));
    const QString step = QString::number(fit.step, 'g', 6);
    if (fit.stepErrorAdded)
        return QCoreApplication::translate("rigidlab::measure",
                                           "model: the lab's run at dt = %1 s; halving the "
                                           "step still moved %2: that is added to the interval")
            .arg(step, changed);
    return QCoreApplication::translate("rigidlab::measure",
                                       "model: the lab's run at dt = %1 s (halving the step "
                                       "moved %2, less than a third of the standard "
                                       "uncertainty)")
        .arg(step, changed);
}

namespace {

/// fitScene's work, a cancelled fit aside.
FitResult fitAll(const lessons::Scene& scene, const std::vector<Parameter>& parameters,
                 const Target& target, const Series& series, const FitOptions& options)
{
    const std::size_t k = parameters.size();
    const int n = static_cast<int>(series.t.size());
    if (k == 0 || k > 3)
        return fitFailed(
            QCoreApplication::translate("rigidlab::measure", "fit one to three parameters"));
    if (n <= static_cast<int>(k))
        return fitFailed(QCoreApplication::translate("rigidlab::measure",
                                                     "%1 points cannot fit %2 parameters: "
                                                     "measure more")
                             .arg(n)
                             .arg(k));
    Model model{scene, parameters, target, series, false, scene.world.dt, options, 0, 0, {}, {}};
    model.exact =
        options.exactWherePossible &&
        std::none_of(parameters.begin(), parameters.end(),
                     [](const Parameter& p) { return p.kind == ParameterKind::VelocityX; }) &&
        exactFlightsAt(scene, target, series.t).has_value();
    if (!model.exact)
        if (const QString error = tooMuchWork(model, options.grid, k, options.maxWork);
            !error.isEmpty())
            return fitFailed(error);
    std::vector<std::pair<double, double>> bounds;
    std::vector<double> lo, hi;
    for (const Parameter& p : parameters) {
        bounds.push_back(parameterBounds(scene, p));
        lo.push_back(bounds.back().first);
        hi.push_back(bounds.back().second);
    }
    const Minimum best = minimiseInBounds(
        [&](const std::vector<double>& x) { return model.sumSquares(x); }, lo, hi, options.grid);
    if (!std::isfinite(best.value))
        return fitFailed(model.error);
    FitResult result;
    result.exact = model.exact;
    result.points = n;
    result.degreesOfFreedom = n - static_cast<int>(k);
    for (double x : best.x)
        result.values.push_back({x, 0, 0});
    const auto J = jacobian(model, best.x, bounds);
    if (!J || !fillResiduals(model, result))
        return fitFailed(model.error);
    if (!uncertainties(*J, best.value, result, parameters))
        return fitFailed(result.error);
    if (const auto j = undetermined(result, model, best.x, best.value, bounds))
        return fitFailed(notDetermined(parameters[*j]));
    if (model.exact)
        result.stepChange.assign(k, 0.0);
    else if (!refineStep(model, *J, result, parameters, bounds, options.maxWork))
        return fitFailed(result.error.isEmpty() ? model.error : result.error);
    result.runs = model.runs;
    result.ok = true;
    return result;
}

} // namespace

FitResult fitScene(const lessons::Scene& scene, const std::vector<Parameter>& parameters,
                   const Target& target, const Series& series, const FitOptions& options)
{
    FitResult result = fitAll(scene, parameters, target, series, options);
    // Cancelled while it ran: whatever the runs left, no value (a result finished just as
    // the flag was set is dropped too: the user asked for none).
    if (options.cancelled && options.cancelled->load()) {
        result =
            fitFailed(QCoreApplication::translate("rigidlab::measure", "the fit was cancelled"));
        result.cancelled = true;
    }
    return result;
}

} // namespace rigidlab::measure
