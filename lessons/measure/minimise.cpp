// SPDX-License-Identifier: GPL-3.0-or-later
#include "measure/minimise.h"

#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

namespace rigidlab::measure {

Minimum minimiseBrent(const std::function<double(double)>& f, double lo, double hi)
{
    std::uintmax_t iterations = 200;
    int evaluations = 0;
    const auto counted = [&](double x) {
        ++evaluations;
        return f(x);
    };
    // 24 bits: about 6e-8 relative, well below any uncertainty a measurement gives.
    const auto [x, value] = boost::math::tools::brent_find_minima(counted, lo, hi, 24, iterations);
    return {{x}, value, evaluations};
}

namespace {

void clamp(std::vector<double>& x, const std::vector<double>& lo, const std::vector<double>& hi)
{
    for (std::size_t i = 0; i < x.size(); ++i)
        x[i] = std::clamp(x[i], lo[i], hi[i]);
}

/// p = a + t (b - a), clamped into the bounds.
std::vector<double> along(const std::vector<double>& a, const std::vector<double>& b, double t,
                          const std::vector<double>& lo, const std::vector<double>& hi)
{
    std::vector<double> p(a.size());
    for (std::size_t i = 0; i < a.size(); ++i)
        p[i] = a[i] + t * (b[i] - a[i]);
    clamp(p, lo, hi);
    return p;
}

} // namespace

Minimum minimiseNelderMead(const Objective& f, std::vector<double> start,
                           const std::vector<double>& step, const std::vector<double>& lo,
                           const std::vector<double>& hi, double tolerance, int maxEvaluations)
{
    const std::size_t n = start.size();
    int evaluations = 0;
    const auto eval = [&](const std::vector<double>& x) {
        ++evaluations;
        return f(x);
    };
    clamp(start, lo, hi);
    std::vector<std::vector<double>> simplex(n + 1, start);
    for (std::size_t i = 0; i < n; ++i) {
        // Step inwards where the start lies on the upper bound.
        simplex[i + 1][i] += start[i] + step[i] <= hi[i] ? step[i] : -step[i];
        clamp(simplex[i + 1], lo, hi);
    }
    std::vector<double> values(n + 1);
    for (std::size_t i = 0; i <= n; ++i)
        values[i] = eval(simplex[i]);
    double span = 0;
    for (std::size_t i = 0; i < n; ++i)
        span = std::max(span, hi[i] - lo[i]);
    std::vector<std::size_t> order(n + 1);
    while (evaluations < maxEvaluations) {
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(),
                  [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
        const std::size_t best = order.front(), worst = order.back(), second = order[n - 1];
        double size = 0;
        for (std::size_t i = 0; i <= n; ++i) {
            for (std::size_t k = 0; k < n; ++k)
                size = std::max(size, std::abs(simplex[i][k] - simplex[best][k]));
        }
        if (values[worst] - values[best] <= tolerance * std::abs(values[best]) + 1e-30 &&
            size <= 1e-7 * span)
            break;
        std::vector<double> centroid(n, 0.0);
        for (std::size_t i = 0; i <= n; ++i) {
            for (std::size_t k = 0; k < n && i != worst; ++k)
                centroid[k] += simplex[i][k] / static_cast<double>(n);
        }
        const std::vector<double> reflected = along(centroid, simplex[worst], -1.0, lo, hi);
        const double fr = eval(reflected);
        if (fr < values[best]) {
            const std::vector<double> expanded = along(centroid, simplex[worst], -2.0, lo, hi);
            const double fe = eval(expanded);
            simplex[worst] = fe < fr ? expanded : reflected;
            values[worst] = std::min(fe, fr);
        } else if (fr < values[second]) {
            simplex[worst] = reflected;
            values[worst] = fr;
        } else {
            const bool outside = fr < values[worst];
            const std::vector<double> contracted =
                along(centroid, outside ? reflected : simplex[worst], 0.5, lo, hi);
            const double fc = eval(contracted);
            if (fc < std::min(fr, values[worst])) {
                simplex[worst] = contracted;
                values[worst] = fc;
            } else {
                for (std::size_t i = 0; i <= n; ++i) {
                    if (i == best)
                        continue;
                    simplex[i] = along(simplex[best], simplex[i], 0.5, lo, hi);
                    values[i] = eval(simplex[i]);
                }
            }
        }
    }
    const std::size_t best =
        static_cast<std::size_t>(std::min_element(values.begin(), values.end()) - values.begin());
    return {simplex[best], values[best], evaluations};
}

Minimum minimiseInBounds(const Objective& f, const std::vector<double>& lo,
                         const std::vector<double>& hi, int grid)
{
    const std::size_t n = lo.size();
    grid = std::max(grid, 2);
    std::vector<double> cell(n);
    for (std::size_t i = 0; i < n; ++i)
        cell[i] = (hi[i] - lo[i]) / (grid - 1);
    // Every grid point, by counting in base `grid`.
    std::vector<int> index(n, 0);
    std::vector<double> x(n), bestX;
    double best = std::numeric_limits<double>::infinity();
    int evaluations = 0;
    for (bool more = true; more;) {
        for (std::size_t i = 0; i < n; ++i)
            x[i] = lo[i] + index[i] * cell[i];
        const double value = f(x);
        ++evaluations;
        if (bestX.empty() || value < best) {
            best = value;
            bestX = x;
        }
        more = false;
        for (std::size_t i = 0; i < n && !more; ++i) {
            more = ++index[i] < grid;
            if (!more)
                index[i] = 0;
        }
    }
    std::vector<double> nearLo(n), nearHi(n);
    for (std::size_t i = 0; i < n; ++i) {
        nearLo[i] = std::max(lo[i], bestX[i] - cell[i]);
        nearHi[i] = std::min(hi[i], bestX[i] + cell[i]);
    }
    Minimum m;
    if (n == 1) {
        m = minimiseBrent([&](double v) { return f({v}); }, nearLo[0], nearHi[0]);
    } else {
        // The first simplex: a quarter cell along each axis.
        std::vector<double> step(n);
        for (std::size_t i = 0; i < n; ++i)
            step[i] = 0.25 * cell[i];
        // Within the whole bounds: a valley across the grid can lead out of the cells about
        // the best grid point.
        m = minimiseNelderMead(f, bestX, step, lo, hi);
        // Restarted with a fresh simplex while that helps: in a long narrow valley (μ against
        // the push-off speed) the simplex can shrink across it and stall far from the bottom.
        for (int restart = 0; restart < 8; ++restart) {
            const Minimum again = minimiseNelderMead(f, m.x, step, lo, hi);
            const int total = m.evaluations + again.evaluations;
            const bool better = again.value < m.value * (1 - 1e-9);
            if (again.value <= m.value)
                m = again;
            m.evaluations = total;
            if (!better)
                break;
        }
    }
    m.evaluations += evaluations;
    if (best < m.value) { // the grid's point was better (a flat or rough residual)
        m.x = bestX;
        m.value = best;
    }
    return m;
}

} // namespace rigidlab::measure
