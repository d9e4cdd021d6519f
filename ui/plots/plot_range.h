// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The value axis of a live plot: how far it reaches, and how many digits its tick labels need.
//
// Doubles carry about 16 significant digits, so a quantity that physics keeps constant (the
// momentum of a stack at rest, the angular momentum of a free collision) still wanders in its
// last digits: ±5e-16 kg m/s, or -0.00206182 ± 1e-12. Fitted tightly, that rounding noise
// fills the whole axis and reads as physics. The rule here: a variation below a noise floor,
//   floor = kNoiseFloor * max(|min|, |max|, scale),
// is no variation (kMinMagnitude stands in for a magnitude smaller than itself, so that a zero
// with noise and no scale is flat too). Such a series is drawn flat, in the middle of an axis a
// tenth of its magnitude (or of the scene's scale) tall, so that the ticks are few, round and
// distinct; with neither a magnitude nor a scale (an empty scene's 0), on an axis of one unit
// either side. A larger variation is real: it is fitted with a margin, and the tick labels get as
// many digits as it takes for neighbouring ticks to read differently.
//
//   scale: what the quantity is worth in this scene, in its own unit (the total momentum the
//          bodies could have, |E0| for energy...). It keeps a quantity that is zero up to
//          rounding (p = 0 ± 5e-16) from being magnified: without it, the floor of a zero is 0.

#include "export/noise_floor.h"

namespace rigidlab::ui {

struct AxisRange {
    double lower = 0; ///< [unit of the quantity]
    double upper = 1;
    bool flat = false; ///< the data's variation is below the noise floor: drawn as constant
    /// Significant digits the tick labels need to be told apart (at least kMinLabelDigits).
    int labelDigits = 6;
};

/// The noise floor's rule is the files' too (lessons/export/noise_floor.h): what is drawn
/// flat is written as 0.
using lessons::kMinMagnitude;
using lessons::kNoiseFloor;
/// A flat series sits in an axis this fraction of its magnitude above and below it.
inline constexpr double kFlatHalfSpan = 0.05;
/// A flat series with neither a magnitude nor a scale (both below kMinMagnitude) sits in an
/// axis this many of its units above and below it.
inline constexpr double kSizelessHalfSpan = 1.0;
/// Fraction of the data's span added above and below a varying series.
inline constexpr double kValueMargin = 0.08;
inline constexpr int kMinLabelDigits = 6;
/// A double has no more than this many significant digits to show.
inline constexpr int kMaxLabelDigits = 15;

/// The axis for data ranging over [min, max] (finite, min <= max) of a quantity worth `scale`
/// in the scene (>= 0; 0 when unknown). Non-finite input gives the default range [0, 1].
/// `minSpan` > 0 keeps a varying series' axis at least that fraction of the magnitude tall,
/// centred on the data: a conserved quantity (momentum, energy) that the solver changes by
/// 1e-4 of what the scene holds is drawn nearly flat, not as a full-height jump. 0 (the
/// energy drift, which exists to show small changes) fits the data however small it is.
AxisRange niceRange(double min, double max, double scale, double minSpan = 0);

/// A tick step of about span / count, rounded to 1, 2 or 5 times a power of ten.
double niceStep(double span, int count);

} // namespace rigidlab::ui
