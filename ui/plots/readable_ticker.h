// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Tick labels for people: "0,00004", not QCustomPlot's "4E-05"; rounding noise at a tick
// next to zero reads "0"; large values keep their digits (number_format.h says how).

#include <qcustomplot.h>

namespace rigidlab::ui {

class ReadableTicker : public QCPAxisTicker {
public:
    void generate(const QCPRange& range, const QLocale& locale, QChar formatChar, int precision,
                  QVector<double>& ticks, QVector<double>* subTicks,
                  QVector<QString>* tickLabels) override;

protected:
    QString getTickLabel(double tick, const QLocale& locale, QChar formatChar,
                         int precision) override;

private:
    double m_scale = 0; ///< the axis range's largest magnitude: what a tick's digits are of
};

} // namespace rigidlab::ui
