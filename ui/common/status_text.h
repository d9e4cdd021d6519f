// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Numbers of the status bar in words a class reads: no rounding noise shown as physics.

#include <QLocale>
#include <QString>

namespace rigidlab::ui {

/// A drift this small [%] is rounding (1.45e-13 % is the last digits of a double): shown as 0.
inline constexpr double kDriftShownAsZeroPercent = 1e-6;

/// The energy drift [%] as the status bar shows it, without the unit: "0" below
/// kDriftShownAsZeroPercent, else three significant digits in fixed notation ("-3.27",
/// "0.0125", "1040"; common/number_format.h), in `locale`;
/// "–" when it is not a number.
QString driftPercentText(double percent, const QLocale& locale = QLocale());

/// Digits of the energy the contacts, friction, drag and dampers took, against the scene's
/// energy scale: a millionth of it (a soft contact's give in an elastic hit) is below the last.
inline constexpr int kDissipatedDigits = 4;

/// What the contacts, friction, drag and dampers took [J], without the unit, as the status bar
/// shows it: kDissipatedDigits digits against `scale` (the scene's energy at the start, [J]),
/// so that round-off and a soft contact's millionth of the energy read "0"; fixed notation
/// in `locale` ("0,0125", never "1,06E-05"; common/number_format.h).
QString dissipatedText(double joules, double scale, const QLocale& locale = QLocale());

/// A small or large number as a power of ten in `locale`, `significant` digits in all
/// ("1,2 × 10⁻⁷"), for a value with no scale to read it against (the integrator's error
/// estimate); a value from 0.001 up to kPlainUpTo in fixed notation; "–" when not a number.
QString estimateText(double value, int significant, const QLocale& locale = QLocale());

} // namespace rigidlab::ui
