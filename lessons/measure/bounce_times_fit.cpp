// SPDX-License-Identifier: GPL-3.0-or-later
// e from bounce times alone (fit.h): ln T_i = ln T_0 + i ln e, a weighted straight line.
#include "measure/fit.h"

#include <QCoreApplication>

#include <cmath>

namespace rigidlab::measure {

namespace {

/// Flights whose ratio is this close to 1 are evenly spaced times, not bounces.
constexpr double kEvenlySpaced = 1e-6;

} // namespace

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
    if (static_cast<int>(bounces.size()) > kMaxBounces) {
        fit.error = QCoreApplication::translate("rigidlab::measure",
                                                "%1 bounce times: more than a ball makes (at "
                                                "most %2); is this the time of every frame?")
                        .arg(bounces.size())
                        .arg(kMaxBounces);
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
    // Flights that shrink by e < 1 are a ball's; flights as long as each other (e = 1 within
    // the interval, or within a part in a million when the times have no noise) are not told
    // from evenly spaced times, such as a video's frames.
    if (!(fit.e.value + fit.e.halfWidth95 < 1.0 - kEvenlySpaced)) {
        fit.error = QCoreApplication::translate("rigidlab::measure",
                                                "the flights between the bounces do not get "
                                                "shorter: not the bounces of one ball (evenly "
                                                "spaced times, such as frames?)");
        return fit;
    }
    fit.ok = true;
    return fit;
}

} // namespace rigidlab::measure
