// SPDX-License-Identifier: GPL-3.0-or-later
#include "export/noise_floor.h"

#include <algorithm>
#include <cmath>

namespace rigidlab::lessons {

double noiseFloor(double scale)
{
    const double magnitude = std::isfinite(scale) && scale > 0 ? scale : 0.0;
    return kNoiseFloor * std::max(magnitude, kMinMagnitude);
}

double withoutNoise(double value, double scale)
{
    if (!std::isfinite(value))
        return value;
    return std::abs(value) < noiseFloor(scale) ? 0.0 : value;
}

} // namespace rigidlab::lessons
