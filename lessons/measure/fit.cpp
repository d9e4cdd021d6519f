// SPDX-License-Identifier: GPL-3.0-or-later
#include "measure/fit.h"

#include "format/divergence_message.h"
#include "measure/minimise.h"
#include "rigidlab/physics/world.h"

#include <QCoreApplication>
#include <QStringList>

#include <Eigen/Dense>
#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>

namespace rigidlab::measure {

namespace {

struct KindName {
    ParameterKind kind;
    const char* name;
};
constexpr KindName kKindNames[] = {
    {ParameterKind::Restitution, "restitution"},
    {ParameterKind::Friction, "friction"},
    {ParameterKind::VelocityX, "vx"},
    {ParameterKind::VelocityY, "vy"},
};

/// Search span of an initial velocity about the scene's [m/s].
constexpr double kVelocitySpan = 5.0;
constexpr double kMaxFriction = 2.0;

bool isVelocity(ParameterKind k)
{
    return k == ParameterKind::VelocityX || k == ParameterKind::VelocityY;
}

QString bodyList(const lessons::Scene& scene)
{
    QStringList ids;
    for (const physics::BodyDef& b : scene.bodies)
        ids << QString::fromStdString(b.name);
    return ids.join(QStringLiteral(", "));
}

std::optional<physics::BodyId> findBody(const QString& id, const lessons::Scene& scene,
                                        QString& error)
{
    const auto index = scene.bodyIndex(id);
    if (!index)
        error = QCoreApplication::translate("rigidlab::measure",
                                            "unknown body \"%1\" (the scene has: %2)")
                    .arg(id, bodyList(scene));
    return index;
}

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

double studentsT95(int dof)
{
    const boost::math::students_t dist(std::max(dof, 1));
    return boost::math::quantile(boost::math::complement(dist, 0.025));
}

/// The simulated values with the parameters set to x, or nothing (the error kept).
struct Model {
    const lessons::Scene& scene;
    const std::vector<Parameter>& parameters;
    const Target& target;
    const std::vector<double>& times;
    int runs = 0;
    QString error;

    std::optional<std::vector<double>> operator()(const std::vector<double>& x)
    {
        lessons::Scene trial = scene;
        for (std::size_t i = 0; i < parameters.size(); ++i)
            setParameter(trial, parameters[i], x[i]);
        ++runs;
        Simulated s = simulateAt(trial, target, times);
        if (!s.ok) {
            if (error.isEmpty())
                error = s.error;
            return std::nullopt;
        }
        return std::move(s.values);
    }
};

/// J: d(simulated)/d(parameter) by central differences (one-sided at a bound).
std::optional<Eigen::MatrixXd> jacobian(Model& model, const std::vector<double>& x,
                                        const std::vector<std::pair<double, double>>& bounds)
{
    const std::size_t n = model.times.size(), k = x.size();
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

/// The values' standard errors and 95 % half-widths from J and the residuals.
bool uncertainties(const Eigen::MatrixXd& J, double sumSquares, FitResult& result,
                   const std::vector<Parameter>& parameters)
{
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(JtJ);
    const double scale = JtJ.diagonal().maxCoeff();
    for (Eigen::Index j = 0; j < JtJ.rows(); ++j) {
        if (!(JtJ(j, j) > 1e-12 * scale) || !(JtJ(j, j) > 0)) {
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

} // namespace

std::optional<Parameter> parseParameter(const QString& text, const lessons::Scene& scene,
                                        QString& error)
{
    const qsizetype colon = text.indexOf(u':');
    const QString kindName = colon < 0 ? text : text.left(colon);
    Parameter p;
    p.name = text;
    const auto kind =
        std::find_if(std::begin(kKindNames), std::end(kKindNames),
                     [&](const KindName& k) { return kindName == QLatin1StringView(k.name); });
    if (kind == std::end(kKindNames)) {
        error = QCoreApplication::translate("rigidlab::measure",
                                            "unknown parameter \"%1\" (expected restitution, "
                                            "friction, vx or vy)")
                    .arg(kindName);
        return std::nullopt;
    }
    p.kind = kind->kind;
    const QStringList ids =
        colon < 0 ? QStringList() : text.mid(colon + 1).split(u',', Qt::KeepEmptyParts);
    for (const QString& id : ids) {
        const auto body = findBody(id.trimmed(), scene, error);
        if (!body)
            return std::nullopt;
        p.bodies.push_back(*body);
    }
    if (isVelocity(p.kind) && p.bodies.size() != 1) {
        error = QCoreApplication::translate("rigidlab::measure", "%1: name one body, as in %2:ball")
                    .arg(text, kindName);
        return std::nullopt;
    }
    return p;
}

std::optional<Target> parseTarget(const QString& text, const lessons::Scene& scene, QString& error)
{
    const qsizetype colon = text.indexOf(u':');
    const auto quantity = quantityFromName(colon < 0 ? text : text.left(colon));
    const bool measurable = quantity && *quantity != Quantity::Time &&
                            *quantity != Quantity::BounceTime && *quantity != Quantity::Ignored;
    if (!measurable || colon < 0) {
        error = QCoreApplication::translate("rigidlab::measure",
                                            "\"%1\": expected QUANTITY:BODY with QUANTITY x, y, "
                                            "vx, vy or v, as in y:ball")
                    .arg(text);
        return std::nullopt;
    }
    const auto body = findBody(text.mid(colon + 1).trimmed(), scene, error);
    if (!body)
        return std::nullopt;
    return Target{*quantity, *body, text};
}

double parameterValue(const lessons::Scene& scene, const Parameter& p)
{
    const physics::BodyDef* body =
        p.bodies.empty() ? nullptr : &scene.bodies[static_cast<std::size_t>(p.bodies.front())];
    switch (p.kind) {
    case ParameterKind::Restitution:
        return body && body->restitution >= 0 ? body->restitution : scene.world.restitution;
    case ParameterKind::Friction:
        return body && body->friction >= 0 ? body->friction : scene.world.friction;
    case ParameterKind::VelocityX:
        return body ? body->velocity.x() : 0.0;
    case ParameterKind::VelocityY:
        return body ? body->velocity.y() : 0.0;
    }
    return 0.0;
}

void setParameter(lessons::Scene& scene, const Parameter& p, double value)
{
    std::vector<physics::BodyId> bodies = p.bodies;
    if (bodies.empty()) {
        for (std::size_t i = 0; i < scene.bodies.size(); ++i)
            bodies.push_back(static_cast<physics::BodyId>(i));
        if (p.kind == ParameterKind::Restitution)
            scene.world.restitution = value;
        if (p.kind == ParameterKind::Friction)
            scene.world.friction = value;
    }
    for (const physics::BodyId id : bodies) {
        physics::BodyDef& b = scene.bodies[static_cast<std::size_t>(id)];
        switch (p.kind) {
        case ParameterKind::Restitution:
            b.restitution = value;
            break;
        case ParameterKind::Friction:
            b.friction = value;
            break;
        case ParameterKind::VelocityX:
            b.velocity.x() = value;
            break;
        case ParameterKind::VelocityY:
            b.velocity.y() = value;
            break;
        }
    }
}

std::pair<double, double> parameterBounds(const lessons::Scene& scene, const Parameter& p)
{
    switch (p.kind) {
    case ParameterKind::Restitution:
        return {0.0, 1.0};
    case ParameterKind::Friction:
        return {0.0, kMaxFriction};
    case ParameterKind::VelocityX:
    case ParameterKind::VelocityY:
        break;
    }
    const double v = parameterValue(scene, p);
    return {v - kVelocitySpan, v + kVelocitySpan};
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

FitResult fitScene(const lessons::Scene& scene, const std::vector<Parameter>& parameters,
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
    Model model{scene, parameters, target, series.t, 0, QString()};
    std::vector<std::pair<double, double>> bounds;
    std::vector<double> lo, hi;
    for (const Parameter& p : parameters) {
        bounds.push_back(parameterBounds(scene, p));
        lo.push_back(bounds.back().first);
        hi.push_back(bounds.back().second);
    }
    const auto sumSquares = [&](const std::vector<double>& x) {
        const auto sim = model(x);
        if (!sim)
            return std::numeric_limits<double>::infinity();
        double s = 0;
        for (int i = 0; i < n; ++i)
            s += std::pow(
                series.value[static_cast<std::size_t>(i)] - (*sim)[static_cast<std::size_t>(i)], 2);
        return s;
    };
    const Minimum best = minimiseInBounds(sumSquares, lo, hi, options.grid);
    if (!std::isfinite(best.value))
        return fitFailed(model.error);
    FitResult result;
    result.points = n;
    result.degreesOfFreedom = n - static_cast<int>(k);
    for (double x : best.x)
        result.values.push_back({x, 0, 0});
    const auto J = jacobian(model, best.x, bounds);
    const auto sim = model(best.x);
    if (!J || !sim)
        return fitFailed(model.error);
    result.simulated = *sim;
    for (int i = 0; i < n; ++i)
        result.residuals.push_back(series.value[static_cast<std::size_t>(i)] -
                                   result.simulated[static_cast<std::size_t>(i)]);
    result.rms = std::sqrt(best.value / n);
    result.runs = model.runs;
    if (!uncertainties(*J, best.value, result, parameters))
        return fitFailed(result.error);
    result.ok = true;
    return result;
}

BounceFit fitBounceTimes(const std::vector<double>& bounces)
{
    BounceFit fit;
    if (static_cast<int>(bounces.size()) < kMinBounces) {
        fit.error = QCoreApplication::translate("rigidlab::measure",
                                                "%1 bounce times: e needs at least %2 (three "
                                                "flights between them)")
                        .arg(bounces.size())
                        .arg(kMinBounces);
        return fit;
    }
    for (std::size_t i = 1; i < bounces.size(); ++i) {
        fit.flightTimes.push_back(bounces[i] - bounces[i - 1]);
        if (!(fit.flightTimes.back() > 0) || !std::isfinite(fit.flightTimes.back())) {
            fit.error =
                QCoreApplication::translate("rigidlab::measure", "bounce %1 is not after bounce %2")
                    .arg(i + 1)
                    .arg(i);
            return fit;
        }
    }
    // Weighted straight line ln T = a + b i, weights T² (a timing error δ moves ln T by δ/T).
    double sw = 0, si = 0, sy = 0, sii = 0, siy = 0;
    const std::size_t m = fit.flightTimes.size();
    for (std::size_t i = 0; i < m; ++i) {
        const double T = fit.flightTimes[i], w = T * T, y = std::log(T), x = static_cast<double>(i);
        sw += w;
        si += w * x;
        sy += w * y;
        sii += w * x * x;
        siy += w * x * y;
    }
    const double det = sw * sii - si * si;
    const double b = (sw * siy - si * sy) / det, a = (sy - b * si) / sw;
    double chi2 = 0;
    for (std::size_t i = 0; i < m; ++i) {
        const double T = fit.flightTimes[i];
        chi2 += T * T * std::pow(std::log(T) - a - b * static_cast<double>(i), 2);
    }
    fit.degreesOfFreedom = static_cast<int>(m) - 2;
    const double s2 = chi2 / fit.degreesOfFreedom;
    fit.rmsLog = std::sqrt(chi2 / sw);
    fit.e.value = std::exp(b);
    fit.e.standardError = fit.e.value * std::sqrt(s2 * sw / det);
    fit.e.halfWidth95 = studentsT95(fit.degreesOfFreedom) * fit.e.standardError;
    if (!(fit.e.value < 1)) {
        fit.error = QCoreApplication::translate("rigidlab::measure",
                                                "the flights between the bounces do not get "
                                                "shorter (e = %1): not the bounces of one ball")
                        .arg(fit.e.value);
        return fit;
    }
    fit.ok = true;
    return fit;
}

} // namespace rigidlab::measure
