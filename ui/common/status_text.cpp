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

} // namespace rigidlab::ui
