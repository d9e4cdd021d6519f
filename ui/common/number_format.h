// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Numbers for people: what the inspector, the panels and the plots' readouts show.
//
//   - Fixed notation, never "1,04E+03" or "−1,18E−18": a value gets `significant` digits
//     measured against the larger of itself and the quantity's scale, so that its last digit
//     is a step a student can see.
//   - Rounding noise reads 0: whatever is below that last digit of the scale is noise
//     (a box lying flat at 4.146e-7 rad, with the angle's scale of π rad, shows "0"), and
//     "−0" never shows.
//   - Large values in a unit with SI prefixes are scaled (12 345 J → "12,35 kJ"); other
//     large values keep their digits up to kPlainUpTo, then a power of ten ("1,2 × 10⁹").
//   - The locale's decimal separator, no group separators (a value is copied into fields).

#include <QLocale>
#include <QString>

namespace rigidlab::ui {

/// Values up to this magnitude are written out in fixed notation without a power of ten.
inline constexpr double kPlainUpTo = 1e6;
/// Decimals are never more than this (below it everything is noise for any lab quantity).
inline constexpr int kMostDecimals = 9;

/// `v` in fixed notation with `significant` digits relative to max(|v|, scale) (scale >= 0,
/// what the quantity is worth here; 0 when unknown: digits relative to v alone, down to
/// kMostDecimals), trailing zeros dropped, noise below the last digit shown as "0"; "–" when
/// not a number.
QString formatReadable(double v, int significant = 4, double scale = 0,
                       const QLocale& locale = QLocale());

/// `v` as a mantissa of `significant` digits (trailing zeros dropped) times a power of ten,
/// in `locale` ("1,2 × 10⁻⁷", "−3 × 10⁹"; no power for one of 1 to 10); "0"; "–" when not a
/// number. Never "1,2E-07": for a value with no scale to read it against.
QString formatPowerOfTen(double v, int significant = 3, const QLocale& locale = QLocale());

/// `v` with its unit, a no-break space between ("1,5 m/s", "12,35 kJ"): as formatReadable,
/// and a value of 10 000 or more in a unit that takes SI prefixes (m, J, N, W, Pa) is
/// written with k, M or G.
QString formatQuantity(double v, const QString& unit, int significant = 4, double scale = 0,
                       const QLocale& locale = QLocale());

} // namespace rigidlab::ui
