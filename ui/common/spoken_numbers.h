// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Numbers for a screen reader: what the scene's and the plots' accessible texts say. They are
// number_format.h's numbers in the locale (its decimal separator), with two changes for
// speech:
//   - A negative value says the word "minus" ("minus 0.15", "minus 0,15"): Orca and NVDA
//     read a hyphen-minus and U+2212 differently by their punctuation level, and at the
//     lowest level drop both, which turns -0.15 into 0.15. The word reads the same everywhere.
//   - A pair of coordinates is separated by ", " where the decimal separator is a point and by
//     "; " where it is a comma ("(0.5, minus 1.2) m", "(0,5; minus 1,2) m"), so that the
//     separator never reads as a decimal comma.

#include <QLocale>
#include <QString>

namespace rigidlab::ui {

/// formatReadable(v, ...) for speech: a negative value as "minus" and its magnitude.
QString spokenReadable(double v, int significant = 4, double scale = 0,
                       const QLocale& locale = QLocale());

/// formatQuantity(v, unit, ...) for speech: a negative value as "minus" and its magnitude.
QString spokenQuantity(double v, const QString& unit, int significant = 4, double scale = 0,
                       const QLocale& locale = QLocale());

/// What separates the two coordinates of a pair in `locale`: ", " after a decimal point,
/// "; " after a decimal comma.
QString coordinateSeparator(const QLocale& locale = QLocale());

/// "(x, y) unit" for speech, with the locale's separator; `significant` and `scale` as in
/// formatReadable, for both coordinates.
QString spokenPair(double x, double y, const QString& unit, int significant = 3, double scale = 0,
                   const QLocale& locale = QLocale());

/// `text` as written for the eye (a status line, a label), with every negative number's sign
/// said as the word "minus" ("drift -0.15 %" reads "drift minus 0.15 %"). A hyphen between
/// words or numbers ("1-2", "Runge-Kutta") is left as it is.
QString spokenSigns(const QString& text);

} // namespace rigidlab::ui
