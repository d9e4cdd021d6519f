// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/number_format.h"

#include <QChar>
#include <QStringList>

#include <algorithm>
#include <array>
#include <cmath>

namespace rigidlab::ui {

namespace {

/// Drops the zeros after the decimal separator, and the separator when nothing follows.
QString withoutTrailingZeros(QString text, const QLocale& locale)
{
    const QString point = locale.decimalPoint();
    if (!text.contains(point))
        return text;
    while (text.endsWith(locale.zeroDigit()))
        text.chop(1);
    if (text.endsWith(point))
        text.chop(point.size());
    return text;
}

/// "−0" (a negative value rounded to nothing) is 0.
bool isZeroText(const QString& text, const QLocale& locale)
{
    for (const QChar c : text) {
        const QString s(c);
        if (s != locale.zeroDigit() && s != locale.negativeSign() && s != locale.decimalPoint())
            return false;
    }
    return true;
}

QString superscript(int n)
{
    static const std::array<QChar, 10> kDigits{u'⁰', u'¹', u'²', u'³', u'⁴',
                                               u'⁵', u'⁶', u'⁷', u'⁸', u'⁹'};
    QString text;
    for (const QChar c : QString::number(std::abs(n)))
        text += kDigits[static_cast<std::size_t>(c.digitValue())];
    return n < 0 ? QStringLiteral("⁻") + text : text;
}

bool takesPrefix(const QString& unit)
{
    static const QStringList kUnits{QStringLiteral("m"), QStringLiteral("J"), QStringLiteral("N"),
                                    QStringLiteral("W"), QStringLiteral("Pa")};
    return kUnits.contains(unit);
}

} // namespace

QString formatReadable(double v, int significant, double scale, const QLocale& base)
{
    if (!std::isfinite(v))
        return QStringLiteral("–");
    QLocale locale = base;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    significant = std::max(1, significant);
    scale = std::isfinite(scale) ? std::abs(scale) : 0.0;
    const double reference = std::max(std::abs(v), scale);
    if (reference == 0.0)
        return locale.toString(0);
    if (std::abs(v) >= kPlainUpTo)
        return formatPowerOfTen(v, significant, locale);
    const int magnitude = static_cast<int>(std::floor(std::log10(reference)));
    const int decimals = std::clamp(significant - 1 - magnitude, 0, kMostDecimals);
    const QString text = withoutTrailingZeros(locale.toString(v, 'f', decimals), locale);
    return isZeroText(text, locale) ? locale.toString(0) : text;
}

QString formatPowerOfTen(double v, int significant, const QLocale& base)
{
    if (!std::isfinite(v))
        return QStringLiteral("–");
    QLocale locale = base;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    significant = std::max(1, significant);
    if (v == 0.0)
        return locale.toString(0);
    // The mantissa with the digits asked for.
    int power = static_cast<int>(std::floor(std::log10(std::abs(v))));
    double mantissa = v / std::pow(10.0, power);
    QString digits = locale.toString(mantissa, 'f', significant - 1);
    if (std::abs(locale.toDouble(digits)) >= 10) { // 9,9996 rounded up to 10,000
        ++power;
        mantissa /= 10;
        digits = locale.toString(mantissa, 'f', significant - 1);
    }
    digits = withoutTrailingZeros(digits, locale);
    return power == 0 ? digits : digits + QStringLiteral(" × 10") + superscript(power);
}

QString formatQuantity(double v, const QString& unit, int significant, double scale,
                       const QLocale& locale)
{
    static constexpr std::array<std::pair<double, char16_t>, 3> kPrefixes{
        {{1e9, u'G'}, {1e6, u'M'}, {1e3, u'k'}}};
    if (std::isfinite(v) && std::abs(v) >= 1e4 && takesPrefix(unit)) {
        for (const auto& [factor, prefix] : kPrefixes)
            if (std::abs(v) >= factor && std::abs(v) < 1e4 * factor)
                return formatReadable(v / factor, significant, scale / factor, locale) +
                       QChar(0x00A0) + QChar(prefix) + unit;
    }
    const QString number = formatReadable(v, significant, scale, locale);
    return unit.isEmpty() ? number : number + QChar(0x00A0) + unit;
}

} // namespace rigidlab::ui
