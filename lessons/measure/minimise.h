// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Minimisers for fitting a few parameters within bounds: Brent's method in one dimension
// (Boost.Math's brent_find_minima), Nelder–Mead's simplex in more, each started from the best
// point of a coarse grid so that a residual with several dips (a bouncing ball whose later
// bounces fall out of step) ends in the deepest one.

#include <functional>
#include <vector>

namespace rigidlab::measure {

using Objective = std::function<double(const std::vector<double>&)>;

struct Minimum {
    std::vector<double> x;
    double value = 0;
    int evaluations = 0;
};

/// Brent's method on [lo, hi] to a relative precision of about 1e-7.
Minimum minimiseBrent(const std::function<double(double)>& f, double lo, double hi);

/// Nelder–Mead from `start` with a first simplex of `step` along each axis, every point kept
/// inside [lo, hi] (clamped). Stops when the simplex's values differ by less than `tolerance`
/// (relative to the best, plus 1e-30) and its size is below 1e-7 of the bounds, or after
/// maxEvaluations.
Minimum minimiseNelderMead(const Objective& f, std::vector<double> start,
                           const std::vector<double>& step, const std::vector<double>& lo,
                           const std::vector<double>& hi, double tolerance = 1e-10,
                           int maxEvaluations = 400);

/// A grid of `grid` points per axis over the bounds, then from the best grid point Brent (one
/// parameter, within the grid cells around it) or Nelder–Mead (more, within the bounds,
/// restarted while that helps).
Minimum minimiseInBounds(const Objective& f, const std::vector<double>& lo,
                         const std::vector<double>& hi, int grid);

} // namespace rigidlab::measure
