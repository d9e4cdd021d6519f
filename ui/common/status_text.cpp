// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/status_text.h"

#include "common/number_format.h"

#include <QCoreApplication>

#include <cmath>

namespace rigidlab::ui {

namespace {

/// The translation context of these words.
class StatusWords {
    Q_DECLARE_TR_FUNCTIONS(StatusWords)
};

} // namespace

QString driftPercentText(double percent, const QLocale& locale)
{
    if (!std::isfinite(percent))
        return StatusWords::tr("–", "no drift to show");
    if (std::abs(percent) < kDriftShownAsZeroPercent)
        return locale.toString(0);
    return formatReadable(percent, 3, 0, locale); // "1040", not "1,04E+03"
}

QString dissipatedText(double joules, double scale, const QLocale& locale)
{
    return formatReadable(joules, kDissipatedDigits, scale, locale);
}

QString estimateText(double value, int significant, const QLocale& locale)
{
    if (!std::isfinite(value))
        return QStringLiteral("–");
    const double size = std::abs(value);
    if (size == 0.0 || (size >= 1e-3 && size < kPlainUpTo))
        return formatReadable(value, significant, 0, locale);
    return formatPowerOfTen(value, significant, locale);
}

} // namespace rigidlab::ui
