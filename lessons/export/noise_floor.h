// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Rounding noise, told from physics. Doubles carry about 16 significant digits, so a
// quantity that physics keeps at zero (the energy dissipated before the first bounce, the
// momentum of a stack at rest) still comes out as 2.4e-19 J or ±5e-16 kg m/s. What a quantity
// is worth in the scene (its scale: |E0| for energy, the momentum the bodies could have...)
// says where its noise starts:
//   floor = kNoiseFloor * max(magnitude, kMinMagnitude).
// The plots draw a variation below it flat (ui/plots/plot_range.h), and every exported file
// writes a value below it as 0: one rule for what is seen and what is written.

namespace rigidlab::lessons {

/// Variation below this fraction of the magnitude is rounding noise.
inline constexpr double kNoiseFloor = 1e-9;
/// The smallest magnitude the noise floor is taken of [unit of the quantity]: below 1e-12 in
/// any unit is noise.
inline constexpr double kMinMagnitude = 1e-3;

/// The noise floor of a quantity worth `scale` in the scene (>= 0; 0 when unknown).
double noiseFloor(double scale);

/// `value`, or 0 when its size is below the noise floor of a quantity worth `scale`. NaN and
/// infinities are passed through (a gap stays a gap).
double withoutNoise(double value, double scale);

} // namespace rigidlab::lessons
