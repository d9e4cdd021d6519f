// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/verdict.h"

#include <QChar>
#include <QLocale>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>

namespace rigidlab::lessons {

QString keepUnitsTogether(QString text)
{
    // A line may break after a slash between letters ("m/" | "s"); a word joiner after each
    // slash that follows a number's unit ("3 m/s", "2 rad/s", "4 kg m/s") forbids it. The
    // no-break spaces between the number and its unit and inside the unit are the text's own.
    static const QRegularExpression unitSlash(
        QStringLiteral("(\\d\\x{00A0}[^\\s/]+(?:\\x{00A0}[^\\s/]+)*)/(?=\\S)"));
    text.replace(unitSlash, QStringLiteral("\\1/") + QChar(0x2060));
    return text;
}

QString formatAnswer(double value, double relativeTolerance, const QString& unit)
{
    int digits = 3;
    if (relativeTolerance > 0) {
        digits = std::clamp(static_cast<int>(std::ceil(-std::log10(relativeTolerance))) + 1, 3, 8);
    }
    if (std::abs(value) < 1e-12) {
        value = 0;
    }
    // On screen, so in the window's locale: "0,41" in Czech (the answer box reads both).
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    QString text = locale.toString(value, 'g', digits);
    if (text.contains(locale.exponential(), Qt::CaseInsensitive)) {
        // 1e-05 reads badly; fixed notation with the same digits
        const int decimals = std::clamp(
            digits - 1 - static_cast<int>(std::floor(std::log10(std::abs(value)))), 0, 12);
        text = locale.toString(value, 'f', std::abs(value) < 1 ? decimals : 0);
    }
    // No-break spaces: the unit stays on the number's line, and a unit of two words ("kg m/s",
    // as a teacher may type it) stays whole.
    if (unit.isEmpty())
        return text;
    QString whole = unit.simplified();
    whole.replace(u' ', QChar(0x00A0));
    return text + QChar(0x00A0) + whole;
}

} // namespace rigidlab::lessons
