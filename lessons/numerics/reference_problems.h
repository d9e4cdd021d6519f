// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reference problems for measuring the integrators: worlds without contacts whose motion is
// known, exactly where mathematics gives it, from a much finer run where it does not.
//
//   oscillator       a mass on a spring, x(t) = x0 cos(w t)                          exact
//   pendulum         a large-amplitude (2.5 rad) physical pendulum, by the Jacobi
//                    elliptic function sn (computed by the AGM / descending Landen)  exact
//   kepler           two bodies under Newtonian gravitation on an orbit of
//                    eccentricity 0.5, by Kepler's equation                          exact
//   spinning-body    a box thrown spinning under gravity and linear drag              exact
//   double-pendulum  two bobs on pins, from horizontal: the reference is a
//                    Dormand-Prince run at tolerances of 1e-13                       NOT exact
//
// (Pendulums are measured by the arc length L |dangle| instead, see armLength.)
// Errors are of positions only: per body sqrt(|dx|^2 + (rho dangle)^2), rho the body's radius
// of gyration sqrt(I / m), so that an angle error counts as the distance a typical point of
// the body is off; summed over the bodies as a root of the sum of squares [m].

#include "rigidlab/physics/world.h"

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

namespace rigidlab::lessons {

struct ReferenceProblem {
    std::string name;        ///< "oscillator", ...
    std::string description; ///< one line
    bool exact = true;       ///< false: the reference is a finer run
    double tEnd = 10.0;      ///< default end time [s]
    double dtFrom = 0.1;     ///< default sweep of steps [s]
    double dtTo = 0.001;
    /// The world at t = 0 (no contacts take part: only its equations are integrated).
    std::function<physics::World()> build;
    /// The reference positions q(t) of the moving bodies (as World::getState orders them).
    /// Calls come in increasing t within a run; an earlier t starts the reference again.
    std::function<Eigen::VectorXd(double t)> reference;
    /// > 0 for bodies on pins that turn with their rods (pendulums): the error is then the arc
    /// length armLength |dangle| per body [m]. The equations integrated here have no drift
    /// projection (World::step has one), so positions creep off the pins (3e-7 m over the
    /// pendulum's 10 s whatever the step): the angles are what the method gets right or wrong.
    double armLength = 0;
};

/// The problems, in the order above; new objects at every call (a sweep may run in a thread).
std::vector<ReferenceProblem> referenceProblems();

/// The position error of q against the reference qr for the moving bodies of `world` [m].
double positionError(const physics::World& world, const Eigen::VectorXd& q,
                     const Eigen::VectorXd& qr);
/// The problem's error measure: positionError, or the arc-length error for pendulums [m].
double problemError(const ReferenceProblem& problem, const physics::World& world,
                    const Eigen::VectorXd& q, const Eigen::VectorXd& qr);

/// Jacobi elliptic functions sn, cn, dn of u for the parameter m = k^2 in [0, 1), by the
/// arithmetic-geometric mean and descending Landen transformation (Abramowitz and Stegun
/// 16.4); accurate to a few units of 1e-16 for moderate |u|.
struct JacobiElliptic {
    double sn = 0, cn = 1, dn = 1;
};
JacobiElliptic jacobiElliptic(double u, double m);
/// The complete elliptic integral of the first kind K(m), by the AGM (A&S 17.6).
double ellipticK(double m);
/// The eccentric anomaly E with E - e sin E = M (Kepler's equation), by Newton's method.
double solveKepler(double meanAnomaly, double eccentricity);

} // namespace rigidlab::lessons
