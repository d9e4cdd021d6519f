// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A CSV reader for the tests, written apart from the lab's writer: it reads a file as a
// spreadsheet set to some conventions would (the separator, the decimal sign, quoted fields
// with doubled quotes, a UTF-8 byte order mark), and the time a person writes for step k.

#include <QByteArray>
#include <QList>
#include <QString>
#include <QStringList>

#include <cmath>
#include <limits>
#include <optional>

namespace rigidlab::test {

struct CsvTable {
    bool bom = false;
    QList<QStringList> rows; ///< the header first
};

/// Splits `bytes` into rows and fields at `separator`, as RFC 4180 reads them.
inline CsvTable readCsv(QByteArray bytes, char separator)
{
    CsvTable table;
    if (bytes.startsWith("\xEF\xBB\xBF")) {
        table.bom = true;
        bytes.remove(0, 3);
    }
    const QString text = QString::fromUtf8(bytes);
    QStringList row;
    QString field;
    bool quoted = false;
    for (qsizetype i = 0; i < text.size(); ++i) {
        const QChar c = text[i];
        if (quoted) {
            if (c == u'"' && i + 1 < text.size() && text[i + 1] == u'"') {
                field += u'"';
                ++i;
            } else if (c == u'"') {
                quoted = false;
            } else {
                field += c;
            }
        } else if (c == u'"') {
            quoted = true;
        } else if (c == QLatin1Char(separator)) {
            row.append(field);
            field.clear();
        } else if (c == u'\n') {
            row.append(field);
            table.rows.append(row);
            row.clear();
            field.clear();
        } else {
            field += c;
        }
    }
    if (!field.isEmpty() || !row.isEmpty()) {
        row.append(field);
        table.rows.append(row);
    }
    return table;
}

/// A number as a spreadsheet with this decimal sign reads it; nothing when it is not one (a
/// decimal point where a comma is expected, a thousands separator, text).
inline std::optional<double> readNumber(const QString& field, char decimal)
{
    if (field.isEmpty())
        return std::numeric_limits<double>::quiet_NaN(); // an empty cell: a gap
    const QChar other = decimal == ',' ? u'.' : u',';
    if (field.contains(other))
        return std::nullopt;
    QString text = field;
    text.replace(QLatin1Char(decimal), u'.');
    bool ok = false;
    const double value = text.toDouble(&ok);
    return ok ? std::optional<double>(value) : std::nullopt;
}

/// The time of step k as a person writes it, worked out in whole numbers: dt = m / 10^places
/// (0.001 s: m = 1, places = 3), k m with the decimal point put `places` from the right,
/// trailing zeros dropped: step 9 of 0.003 s is "0.027", step 1000 of 1 ms is "1".
inline QString decimalStepTime(long long k, long long m, int places)
{
    QString digits = QString::number(k * m).rightJustified(places + 1, u'0');
    QString text = digits.left(digits.size() - places) + u'.' + digits.right(places);
    while (text.endsWith(u'0'))
        text.chop(1);
    if (text.endsWith(u'.'))
        text.chop(1);
    return text;
}

/// The time of step k at `rate` steps a second as a person writes it where it is a decimal of
/// up to 9 places (step 9 at 60 per second: "0.15"); nothing where it is not (step 7: 7/60).
inline std::optional<QString> rateStepTime(long long k, long long rate)
{
    long long scale = 1;
    for (int places = 0; places <= 9; ++places, scale *= 10)
        if ((k * scale) % rate == 0)
            return decimalStepTime(k * scale / rate, 1, places);
    return std::nullopt;
}

} // namespace rigidlab::test
