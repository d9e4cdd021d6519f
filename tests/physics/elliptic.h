// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The complete elliptic integral of the first kind, two independent ways: the exact period of
// a pendulum (test_integrators.cpp) is 4 sqrt(L / g) K(sin(theta0 / 2)).

#include <cmath>
#include <numbers>

namespace rigidlab::test {

/// Complete elliptic integral of the first kind K(k) (modulus k) by the arithmetic-geometric
/// mean: K(k) = pi / (2 AGM(1, sqrt(1 - k^2))) (Abramowitz & Stegun 17.6).
inline double ellipticK(double k)
{
    double a = 1.0;
    double b = std::sqrt(1.0 - k * k);
    for (int i = 0; i < 64 && std::abs(a - b) > 1e-16 * a; ++i) {
        const double an = 0.5 * (a + b);
        b = std::sqrt(a * b);
        a = an;
    }
    return std::numbers::pi / (a + b); // pi / (2 * AGM) with AGM = (a + b) / 2 at convergence
}

/// K(k) by composite Simpson on the integral over [0, pi/2] of 1/sqrt(1 - k^2 sin^2 phi),
/// a second, independent way used to check ellipticK (the integrand is smooth for k < 1).
inline double ellipticKSimpson(double k, int intervals)
{
    const double a = 0.0, b = std::numbers::pi / 2;
    const double h = (b - a) / intervals;
    auto f = [k](double phi) {
        return 1.0 / std::sqrt(1.0 - k * k * std::sin(phi) * std::sin(phi));
    };
    double s = f(a) + f(b);
    for (int i = 1; i < intervals; ++i) {
        s += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
    }
    return s * h / 3.0;
}

} // namespace rigidlab::test
