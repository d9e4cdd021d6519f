// SPDX-License-Identifier: GPL-3.0-or-later
#include "export/csv_dialect.h"

#include <QLocale>

namespace rigidlab::lessons {

QString csvDialectName(CsvDialect dialect)
{
    return dialect == CsvDialect::Spreadsheet ? QStringLiteral("spreadsheet")
                                              : QStringLiteral("plain");
}

std::optional<CsvDialect> csvDialectFromName(const QString& name)
{
    for (const CsvDialect d : {CsvDialect::Plain, CsvDialect::Spreadsheet})
        if (name == csvDialectName(d))
            return d;
    return std::nullopt;
}

QString csvDialectNames()
{
    return csvDialectName(CsvDialect::Plain) + QStringLiteral(", ") +
           csvDialectName(CsvDialect::Spreadsheet);
}

bool usesDecimalComma(const QString& language)
{
    // The language's own locale decides, as a spreadsheet's regional settings do.
    return QLocale(language).decimalPoint() == QStringLiteral(",");
}

CsvConventions csvConventions(CsvDialect dialect, const QString& language)
{
    if (dialect == CsvDialect::Plain)
        return {};
    // A spreadsheet's list separator is ';' wherever the comma is the decimal sign.
    const bool comma = usesDecimalComma(language);
    return {comma ? ';' : ',', comma ? ',' : '.', true};
}

CsvConventions clipboardConventions(const QString& language)
{
    return {'\t', usesDecimalComma(language) ? ',' : '.', false};
}

} // namespace rigidlab::lessons
