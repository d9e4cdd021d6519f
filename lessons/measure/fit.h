// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Fitting a scene's free parameters to a measurement by least squares. The model is exact
// where it can be: one ball bouncing straight up and down on a flat floor has closed-form
// flights (exact_flights.h), with no time step and so no discretisation error. Any other scene
// runs in the lab's own engine: each trial value is put into the scene definition, the scene
// is run headless from t = 0, and the simulated quantity is read at the measured times (linear
// interpolation between steps). The sum of squared residuals is minimised within bounds
// (minimise.h). The uncertainty comes from the residuals' curvature (Gauss–Newton):
//     cov = s² (JᵀJ)⁻¹,  s² = Σ r² / (n − k),
// J the Jacobian of the simulated values by central differences, n points, k parameters; the
// 95 % half-width is Student's t(n − k) quantile times the standard error.
//
// That interval counts the measurement's noise only, so the fit makes sure it is the only
// error left:
//   - the lab's step: the fit halves the scene's step, refitting each time (Gauss–Newton from
//     the value before), until halving it moves every value by less than a third of its
//     standard uncertainty, and says which step it used; when the work budget ends first, the
//     last change (the step's error, for a method of order one) is added to the interval;
//   - identifiability: when the data cannot determine a parameter (a flat sum of squares, a
//     ball at rest, a measurement with no bounce, an interval as wide as the search) the fit
//     says so in one line and gives no number;
//   - the work is bounded before it starts (in constant time): a measurement that ends long
//     after the scene starts, at the scene's step, is refused with the reason.
//
// From bounce times alone e needs no simulation: between bounces the ball flies up and down
// at the speed it left with, so each flight lasts T = 2v/g and successive flights shrink by
// the factor e exactly. ln T_i = ln T_0 + i ln e is a straight line; its slope, fitted with
// weights T_i² (a timing error δ changes ln T by δ/T), gives e and its uncertainty. The times
// must look like bounces: rising, far fewer than a video's frames, and not evenly spaced.

#include "format/scene.h"
#include "measure/measurement.h"
#include "rigidlab/physics/body.h"

#include <QString>

#include <atomic>
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
/// The most steps of the lab's engine one fit runs, all runs and step halvings together
/// (a few seconds for a ball on a floor).
inline constexpr long long kMaxFitWork = 40'000'000;

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
    /// The model: the exact flights of a ball on a floor (no step), else the lab's run at
    /// `step`.
    bool exact = false;
    double step = 0; ///< the lab's step the values are from [s]; 0 for the exact model
    /// Per parameter: how much the last halving of the step moved the value (0 for the exact
    /// model, and when the scene's own step was never halved).
    std::vector<double> stepChange;
    /// The work budget ended before halving the step stopped mattering: stepChange is added
    /// to each halfWidth95 (and, in quadrature, to each standardError).
    bool stepErrorAdded = false;
    double rms = 0; ///< of the residuals at the fitted values
    int points = 0;
    int degreesOfFreedom = 0;
    int runs = 0;                  ///< simulations run
    bool cancelled = false;        ///< stopped by FitOptions::cancelled (error says so)
    std::vector<double> simulated; ///< at the measured times, with the fitted values
    std::vector<double> residuals; ///< measured − simulated
};

struct FitOptions {
    int grid = 11; ///< grid points per parameter before the minimiser (minimiseInBounds)
    /// Off: the lab's run even where the flights are exact (to compare the two).
    bool exactWherePossible = true;
    long long maxWork = kMaxFitWork; ///< steps of the lab's engine, at most
    /// For a fit in a thread of its own (the window's): set from another thread, the fit stops
    /// at its next run and fails with FitResult::cancelled; null, it runs to the end.
    const std::atomic_bool* cancelled = nullptr;
    /// Counts the model's runs as they end (read from another thread, for a progress
    /// indication); may be null.
    std::atomic_int* runs = nullptr;
};

/// Fits the parameters (one to three) to the series, the target read from the scene.
FitResult fitScene(const lessons::Scene& scene, const std::vector<Parameter>& parameters,
                   const Target& target, const Series& series, const FitOptions& options = {});

/// One line: which model the values come from, and what its step does to them ("the lab's
/// run at dt = 0.000125 s: halving the step moved e by 2e-05, less than a third of its
/// standard uncertainty").
QString describeModel(const FitResult& fit, const std::vector<Parameter>& parameters);

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

/// Most bounce times a fit takes: a ball heard or seen bounces a few dozen times; more are a
/// column of frames.
inline constexpr int kMaxBounces = 200;

/// The 95 % two-sided quantile of Student's t with `dof` degrees of freedom (at least 1).
double studentsT95(int dof);

/// e from bounce times (rising) [s].
BounceFit fitBounceTimes(const std::vector<double>& bounces);

} // namespace rigidlab::measure
