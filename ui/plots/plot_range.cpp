// SPDX-License-Identifier: GPL-3.0-or-later
#include "plots/plot_range.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace rigidlab::ui {

double niceStep(double span, int count)
{
    if (!(span > 0) || !std::isfinite(span) || count < 1)
        return 1.0;
    const double raw = span / count;
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    const double mantissa = raw / decade;
    const double nice = mantissa < 1.5 ? 1.0 : mantissa < 3.5 ? 2.0 : mantissa < 7.5 ? 5.0 : 10.0;
    return nice * decade;
}

AxisRange niceRange(double min, double max, double scale, double minSpan)
{
    AxisRange r;
    if (!std::isfinite(min) || !std::isfinite(max))
        return r;
    if (min > max)
        std::swap(min, max);
    if (!(scale >= 0) || !std::isfinite(scale))
        scale = 0;

    const double magnitude = std::max({std::abs(min), std::abs(max), scale, kMinMagnitude});
    const double span = max - min;
    if (span <= kNoiseFloor * magnitude) {
        // Constant up to rounding: drawn flat at the middle of its values, on an axis whose
        // ticks are round at the quantity's own size.
        const double center = 0.5 * (min + max);
        // Nothing to size it by (an empty scene's momentum, 0 with no scale): one unit either
        // side, not a tenth of kMinMagnitude, whose tick labels (0.000025) read as data.
        const bool sizeless = std::max({std::abs(min), std::abs(max), scale}) < kMinMagnitude;
        const double half = sizeless ? kSizelessHalfSpan : kFlatHalfSpan * magnitude;
        r.lower = center - half;
        r.upper = center + half;
        r.flat = true;
    } else {
        const double pad = kValueMargin * span;
        r.lower = min - pad;
        r.upper = max + pad;
        const double tallest = std::isfinite(minSpan) && minSpan > 0 ? minSpan * magnitude : 0;
        if (r.upper - r.lower < tallest) {
            const double center = 0.5 * (min + max);
            r.lower = center - 0.5 * tallest;
            r.upper = center + 0.5 * tallest;
        }
    }

    // Ticks come about every fifth of the axis, at 1, 2, 2.5 or 5 times a power of ten: the
    // labels need the digits from the largest one's leading digit down to the step's, and one
    // more for a step of 2.5.
    const double step = niceStep(r.upper - r.lower, 5);
    const double largest = std::max({std::abs(r.lower), std::abs(r.upper), step});
    const int digits = static_cast<int>(std::floor(std::log10(largest))) -
                       static_cast<int>(std::floor(std::log10(step))) + 2;
    r.labelDigits = std::clamp(digits, kMinLabelDigits, kMaxLabelDigits);
    return r;
}

} // namespace rigidlab::ui
