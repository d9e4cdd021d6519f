// SPDX-License-Identifier: GPL-3.0-or-later
#include "plots/readable_ticker.h"

#include "common/number_format.h"

#include <algorithm>
#include <cmath>

namespace rigidlab::ui {

void ReadableTicker::generate(const QCPRange& range, const QLocale& locale, QChar formatChar,
                              int precision, QVector<double>& ticks, QVector<double>* subTicks,
                              QVector<QString>* tickLabels)
{
    // A tick's digits count against the whole axis, so that the tick at 0 of a range
    // 0 … 0.0004 reads "0" and its neighbours keep the digits that tell them apart.
    m_scale = std::max(std::abs(range.lower), std::abs(range.upper));
    QCPAxisTicker::generate(range, locale, formatChar, precision, ticks, subTicks, tickLabels);
    // An axis zoomed into digits beyond what a lab quantity carries (kMostDecimals) would
    // label its ticks alike: those keep QCustomPlot's own labels, which tell them apart.
    if (!tickLabels)
        return;
    for (qsizetype i = 1; i < tickLabels->size(); ++i)
        if (tickLabels->at(i) == tickLabels->at(i - 1)) {
            for (qsizetype k = 0; k < tickLabels->size(); ++k)
                (*tickLabels)[k] =
                    QCPAxisTicker::getTickLabel(ticks.at(k), locale, formatChar, precision);
            return;
        }
}

QString ReadableTicker::getTickLabel(double tick, const QLocale& locale, QChar, int precision)
{
    return formatReadable(tick, std::max(precision, 1), m_scale, locale);
}

} // namespace rigidlab::ui
