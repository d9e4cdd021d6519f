// SPDX-License-Identifier: GPL-3.0-or-later
#include "export/step_time.h"

#include <algorithm>
#include <cmath>

namespace rigidlab::lessons {

double stepTime(long long k, double dt)
{
    // Integers below 2^53 are exact doubles, and a division is correctly rounded: (k m) / 10^d
    // is the double nearest the decimal k dt.
    constexpr double kExactInteger = 9007199254740992.0; // 2^53
    double scale = 1.0;
    for (int places = 0; places <= 9; ++places, scale *= 10.0) {
        const double m = std::round(dt * scale);
        if (m > 0 && m / scale == dt && std::abs(static_cast<double>(k)) * m < kExactInteger)
            return static_cast<double>(k) * m / scale;
    }
    const double rate = std::round(1.0 / dt);
    if (rate > 0 && 1.0 / rate == dt)
        return static_cast<double>(k) / rate;
    return static_cast<double>(k) * dt;
}

double stepTime(long long k, double dt, double summed)
{
    const double exact = stepTime(k, dt);
    // The sum of k dts is within k rounding errors of k dt; a dt changed mid-run, or a world
    // that did not start at 0, is far from it.
    const double tolerance = 1e-9 * std::max(std::abs(exact), dt);
    return std::abs(summed - exact) <= tolerance ? exact : summed;
}

} // namespace rigidlab::lessons
