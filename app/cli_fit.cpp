// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli_fit.h"

#include "cli_common.h"
#include "format/scene_loader.h"
#include "measure/fit.h"
#include "measure/measurement.h"

#include <QStringList>

#include <algorithm>
#include <array>
#include <cmath>

namespace rigidlab::cli {

namespace {

struct FitArguments {
    QStringList params;
    QStringList rest;
};

/// Takes every `--param P` (and `--param=P`) out of the words: the command line's parser
/// takes each option once.
std::optional<FitArguments> takeParams(const QStringList& words, QString& error)
{
    FitArguments out;
    bool options = true;
    for (qsizetype i = 0; i < words.size(); ++i) {
        const QString& w = words.at(i);
        options = options && w != u"--";
        const bool bare = w == u"--param" || w == u"-param";
        if (options && bare) {
            if (i + 1 >= words.size() || words.at(i + 1).startsWith(u'-')) {
                error = QStringLiteral("--param: needs a parameter");
                return std::nullopt;
            }
            out.params << words.at(++i);
        } else if (options && (w.startsWith(u"--param=") || w.startsWith(u"-param="))) {
            out.params << w.section(u'=', 1);
        } else {
            out.rest << w;
        }
    }
    return out;
}

std::optional<double> unitScale(const QString& option, const QString& unit,
                                std::initializer_list<std::pair<const char*, double>> units,
                                QString& error)
{
    QStringList names;
    for (const auto& [name, scale] : units) {
        if (unit == QLatin1StringView(name))
            return scale;
        names << QLatin1StringView(name);
    }
    error = QStringLiteral("%1: unknown unit \"%2\" (expected %3)")
                .arg(option, unit, names.join(QStringLiteral(", ")));
    return std::nullopt;
}

/// The measurement options from the command line; false with `error` set.
bool readOptions(const CommandLine& args, measure::MeasurementOptions& options, QString& error)
{
    if (const auto t = args.value(QStringLiteral("time-zero"))) {
        const auto value = finiteNumber(QStringLiteral("--time-zero"), *t, error);
        if (!value)
            return false;
        options.timeZero = *value;
    }
    if (const auto origin = args.value(QStringLiteral("origin"))) {
        const QStringList parts = origin->split(u',');
        if (parts.size() != 2) {
            error = QStringLiteral("--origin: expected X,Y in metres, got \"%1\"").arg(*origin);
            return false;
        }
        const auto x = finiteNumber(QStringLiteral("--origin"), parts[0].trimmed(), error);
        const auto y =
            x ? finiteNumber(QStringLiteral("--origin"), parts[1].trimmed(), error) : std::nullopt;
        if (!x || !y)
            return false;
        options.originX = *x;
        options.originY = *y;
    }
    if (const auto unit = args.value(QStringLiteral("time-unit"))) {
        options.timeScale = unitScale(QStringLiteral("--time-unit"), *unit,
                                      {{"s", 1.0}, {"ms", 1e-3}, {"min", 60.0}}, error);
        if (!options.timeScale)
            return false;
    }
    if (const auto unit = args.value(QStringLiteral("length-unit"))) {
        options.lengthScale = unitScale(QStringLiteral("--length-unit"), *unit,
                                        {{"m", 1.0}, {"cm", 1e-2}, {"mm", 1e-3}}, error);
        if (!options.lengthScale)
            return false;
    }
    return true;
}

QString number(double v)
{
    return QString::number(v, 'g', 6);
}

/// The value and its uncertainties, the 95 % half-width to two significant digits and the
/// value to the same decimal place (0.71993 ± 0.00021).
void printValue(const QString& name, const measure::FittedValue& v)
{
    const double u = v.halfWidth95;
    if (!(u > 0) || !std::isfinite(u)) {
        printOut(QStringLiteral("%1 = %2 ± %3 (95 %), standard uncertainty %4\n")
                     .arg(name, number(v.value), number(u), number(v.standardError)));
        return;
    }
    const int decimals = std::clamp(1 - static_cast<int>(std::floor(std::log10(u))), 0, 15);
    const auto fixed = [&](double x) { return QString::number(x, 'f', decimals); };
    printOut(QStringLiteral("%1 = %2 ± %3 (95 %), standard uncertainty %4\n")
                 .arg(name, fixed(v.value), fixed(u), QString::number(v.standardError, 'g', 2)));
}

int fitBounces(const QStringList& params, const measure::Measurement& m, const QString& file)
{
    const measure::BounceFit fit = measure::fitBounceTimes(m.bounces);
    if (!fit.ok)
        return inputError(file + QStringLiteral(": ") + fit.error);
    QStringList flights;
    for (double T : fit.flightTimes)
        flights << number(T);
    printOut(QStringLiteral("fit: e from %1 bounce times in %2 (each flight lasts e times the "
                            "one before)\nflight times [s]: %3\n")
                 .arg(m.bounces.size())
                 .arg(file, flights.join(u' ')));
    printValue(params.front(), fit.e);
    printOut(QStringLiteral("residual RMS of ln T: %1 (%2 degrees of freedom)\n")
                 .arg(number(fit.rmsLog))
                 .arg(fit.degreesOfFreedom));
    return kExitOk;
}

int fitSeries(const lessons::Scene& scene, const std::vector<measure::Parameter>& params,
              const measure::Target& target, const measure::Measurement& m, const QString& file)
{
    const measure::Series* series = m.find(target.quantity);
    if (!series) {
        return inputError(QStringLiteral("%1: no column holds %2 (columns: t, x, y, vx, vy, v "
                                         "or their phyphox names)")
                              .arg(file, measure::quantityName(target.quantity)));
    }
    const measure::FitResult fit = measure::fitScene(scene, params, target, *series);
    if (!fit.ok)
        return inputError(file + QStringLiteral(": ") + fit.error);
    printOut(
        QStringLiteral("fit: %1 to %2 points of %3\n").arg(target.name).arg(fit.points).arg(file));
    printOut(measure::describeModel(fit, params) + u'\n');
    for (std::size_t i = 0; i < params.size(); ++i)
        printValue(params[i].name, fit.values[i]);
    const bool speed = target.quantity == measure::Quantity::Vx ||
                       target.quantity == measure::Quantity::Vy ||
                       target.quantity == measure::Quantity::Speed;
    printOut(QStringLiteral("residual RMS: %1 %2 (%3 degrees of freedom, %4 runs)\n")
                 .arg(number(fit.rms), speed ? QStringLiteral("m/s") : QStringLiteral("m"))
                 .arg(fit.degreesOfFreedom)
                 .arg(fit.runs));
    return kExitOk;
}

} // namespace

int commandFit(const QStringList& words)
{
    const QString command = QStringLiteral("fit");
    QString error;
    const auto split = takeParams(words, error);
    if (!split)
        return usageError(command, error);
    CommandLine args(command);
    for (const char* name : {"quantity", "time-zero", "origin", "time-unit", "length-unit"})
        args.addValue(QLatin1StringView(name));
    args.addSwitch(QStringLiteral("bounce-times"));
    if (!args.parse(split->rest))
        return usageError(command, args.error());
    const bool bounces = args.isSet(QStringLiteral("bounce-times"));
    const QStringList files = args.positionals();
    if (files.size() != 2)
        return usageError(command, QStringLiteral("expected SCENE.json MEASUREMENT.csv"));
    if (split->params.isEmpty() || split->params.size() > 3)
        return usageError(command, QStringLiteral("name one to three --param"));
    const auto quantity = args.value(QStringLiteral("quantity"));
    if (!bounces && !quantity)
        return usageError(command, QStringLiteral("--quantity: which quantity of which body?"));
    if (bounces && (quantity || split->params.size() != 1))
        return usageError(command, QStringLiteral("--bounce-times: fits one --param "
                                                  "restitution, without --quantity"));
    measure::MeasurementOptions options;
    options.bounceTimesOnly = bounces;
    if (!readOptions(args, options, error))
        return usageError(command, error);

    const lessons::SceneLoadResult loaded = lessons::loadSceneFile(files[0]);
    printWarnings(loaded.warnings);
    if (!loaded.ok)
        return inputError(loaded.error);
    std::vector<measure::Parameter> params;
    for (const QString& text : split->params) {
        const auto p = measure::parseParameter(text, loaded.scene, error);
        if (!p)
            return usageError(command, QStringLiteral("--param: ") + error);
        const bool again = std::any_of(params.begin(), params.end(), [&](const auto& q) {
            return q.kind == p->kind && q.bodies == p->bodies;
        });
        if (again)
            return usageError(command, QStringLiteral("--param: %1 is named twice").arg(text));
        params.push_back(*p);
    }
    if (bounces && params.front().kind != measure::ParameterKind::Restitution)
        return usageError(command, QStringLiteral("--bounce-times: fits restitution only"));
    std::optional<measure::Target> target;
    if (quantity) {
        target = measure::parseTarget(*quantity, loaded.scene, error);
        if (!target)
            return usageError(command, QStringLiteral("--quantity: ") + error);
        options.plainValue = target->quantity;
    }
    const measure::MeasurementResult read = measure::readMeasurementFile(files[1], options);
    if (!read.ok)
        return inputError(read.error);
    if (bounces)
        return fitBounces(split->params, read.measurement, files[1]);
    return fitSeries(loaded.scene, params, *target, read.measurement, files[1]);
}

} // namespace rigidlab::cli
