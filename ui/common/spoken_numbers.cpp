// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/spoken_numbers.h"

#include "common/number_format.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace rigidlab::ui {

namespace {

/// The translation context of numbers said aloud.
struct SpokenNumbers {
    Q_DECLARE_TR_FUNCTIONS(SpokenNumbers)
};

/// `text` (a number written in `locale`, maybe with its unit) with a leading negative sign
/// said as a word. A value rounded to 0 was written without a sign: it stays "0".
QString withMinusWord(const QString& text, const QLocale& locale)
{
    const QString sign = locale.negativeSign();
    if (sign.isEmpty() || !text.startsWith(sign))
        return text;
    return SpokenNumbers::tr("minus %1", "a negative number read aloud").arg(text.mid(sign.size()));
}

} // namespace

QString spokenReadable(double v, int significant, double scale, const QLocale& locale)
{
    return withMinusWord(formatReadable(v, significant, scale, locale), locale);
}

QString spokenQuantity(double v, const QString& unit, int significant, double scale,
                       const QLocale& locale)
{
    return withMinusWord(formatQuantity(v, unit, significant, scale, locale), locale);
}

QString coordinateSeparator(const QLocale& locale)
{
    return locale.decimalPoint() == QLatin1String(",") ? QStringLiteral("; ")
                                                       : QStringLiteral(", ");
}

QString spokenPair(double x, double y, const QString& unit, int significant, double scale,
                   const QLocale& locale)
{
    const QString coordinates = QLatin1Char('(') + spokenReadable(x, significant, scale, locale) +
                                coordinateSeparator(locale) +
                                spokenReadable(y, significant, scale, locale) + QLatin1Char(')');
    return unit.isEmpty() ? coordinates : coordinates + QChar(0x00A0) + unit;
}

QString spokenSigns(const QString& text)
{
    // A sign where a number starts: at the start, or after a space, a bracket, "=" or a
    // separator; hyphen-minus or the true minus sign (U+2212).
    static const QRegularExpression sign(QStringLiteral("(^|[\\s(\\[=;:,])[-\\x{2212}](?=\\d)"));
    QString out;
    qsizetype from = 0;
    for (auto m = sign.globalMatch(text); m.hasNext();) {
        const QRegularExpressionMatch match = m.next();
        out += text.mid(from, match.capturedStart() - from) + match.captured(1);
        out += SpokenNumbers::tr("minus %1", "a negative number read aloud").arg(QString());
        from = match.capturedEnd();
    }
    return out + text.mid(from);
}

} // namespace rigidlab::ui
