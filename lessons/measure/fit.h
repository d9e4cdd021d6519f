// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Fitting a scene's free parameters to a measurement by least squares, with the lab's own
// engine in the loop: each trial value is put into the scene definition, the scene is run
// headless from t = 0, and the simulated quantity is read at the measured times (linear
// interpolation between steps). The sum of squared residuals is minimised within bounds
// (minimise.h). The uncertainty comes from the residuals' curvature (Gauss–Newton):
//     cov = s² (JᵀJ)⁻¹,  s² = Σ r² / (n − k),
// J the Jacobian of the simulated values by central differences, n points, k parameters; the
// 95 % half-width is Student's t(n − k) quantile times the standard error.
//
// From bounce times alone e needs no simulation: between bounces the ball flies up and down
// at the speed it left with, so each flight lasts T = 2v/g and successive flights shrink by
// the factor e exactly. ln T_i = ln T_0 + i ln e is a straight line; its slope, fitted with
// weights T_i² (a timing error δ changes ln T by δ/T), gives e and its uncertainty.

#include "format/scene.h"
#include "measure/measurement.h"
#include "rigidlab/physics/body.h"

#include <QString>

#include <optional>
#include <vector>

namespace rigidlab::measure {

enum class ParameterKind {
    Restitution, ///< coefficient of restitution, searched in [0, 1]
    Friction,    ///< Coulomb friction coefficient, searched in [0, 2]
    VelocityX,   ///< a body's initial velocity, searched within ±5 m/s of the scene's
    VelocityY,
};

/// A free parameter of a scene, as named on the command line:
///   restitution, friction            every body's (and the world's default)
///   restitution:BODY, friction:BODY  one body's
///   restitution:A,B, friction:A,B    a pair's: both bodies get the value, so their contact
///                                    uses it (the larger e, the geometric mean of μ)
///   vx:BODY, vy:BODY                 a body's initial velocity [m/s]
struct Parameter {
    ParameterKind kind = ParameterKind::Restitution;
    std::vector<physics::BodyId> bodies; ///< empty: every body
    QString name;                        ///< as named
};

/// What the measurement is compared with: a quantity of one body (x, y, vx, vy, v), as
/// "y:ball". Positions are the body origin's, as in a trace.
struct Target {
    Quantity quantity = Quantity::Y;
    physics::BodyId body = 0;
    QString name;
};

std::optional<Parameter> parseParameter(const QString& text, const lessons::Scene& scene,
                                        QString& error);
std::optional<Target> parseTarget(const QString& text, const lessons::Scene& scene, QString& error);

/// The parameter's value in the scene (the first body's; its world default where it has none).
double parameterValue(const lessons::Scene& scene, const Parameter& p);
/// Puts the value into the scene definition.
void setParameter(lessons::Scene& scene, const Parameter& p, double value);
/// Where the fit searches.
std::pair<double, double> parameterBounds(const lessons::Scene& scene, const Parameter& p);

/// Longest simulated span a fit runs [steps].
inline constexpr long long kMaxFitSteps = 10'000'000;

struct Simulated {
    bool ok = false;
    QString error;
    std::vector<double> values; ///< at the times asked for
};

/// Runs the scene from t = 0 to the last of `times` (rising, >= 0) and reads the target there.
Simulated simulateAt(const lessons::Scene& scene, const Target& target,
                     const std::vector<double>& times);

struct FittedValue {
    double value = 0;
    double standardError = 0; ///< one standard uncertainty
    double halfWidth95 = 0;   ///< of the 95 % confidence interval
};

struct FitResult {
    bool ok = false;
    QString error;                   ///< one line when !ok
    std::vector<FittedValue> values; ///< per parameter
    double rms = 0;                  ///< of the residuals at the fitted values
    int points = 0;
    int degreesOfFreedom = 0;
    int runs = 0;                  ///< simulations run
    std::vector<double> simulated; ///< at the measured times, with the fitted values
    std::vector<double> residuals; ///< measured − simulated
};

struct FitOptions {
    int grid = 11; ///< grid points per parameter before the minimiser (minimiseInBounds)
};

/// Fits the parameters (one to three) to the series, the target read from the scene.
FitResult fitScene(const lessons::Scene& scene, const std::vector<Parameter>& parameters,
                   const Target& target, const Series& series, const FitOptions& options = {});

struct BounceFit {
    bool ok = false;
    QString error;
    FittedValue e;
    std::vector<double> flightTimes; ///< [s]
    double rmsLog = 0;               ///< weighted RMS of the residuals of ln T
    int degreesOfFreedom = 0;
};

/// Minimum bounces for a fit from bounce times: three flights and one degree of freedom.
inline constexpr int kMinBounces = 4;

/// e from bounce times (rising) [s].
BounceFit fitBounceTimes(const std::vector<double>& bounces);

} // namespace rigidlab::measure
