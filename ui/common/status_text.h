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

} // namespace rigidlab::ui
