// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The ways a CSV file is written, for the program that opens it:
//   plain        RFC 4180: comma, decimal point, UTF-8 without a BOM. For scripts (Python's
//                csv, pandas, R) and the command line's default.
//   spreadsheet  what a spreadsheet in the language's regional settings reads on a double
//                click: where the language writes a decimal comma (Czech), the list separator
//                is ';' and numbers carry the comma; elsewhere (English) ',' and the point.
//                UTF-8 with a BOM, without which Excel takes the file for the system's 8-bit
//                code page and mangles the diacritics ("kinetickĂˇ").
// The clipboard (Ctrl+C on a plot) takes tab-separated text in the language's number format,
// which every spreadsheet pastes into columns.

#include <QString>

#include <optional>

namespace rigidlab::lessons {

enum class CsvDialect { Plain, Spreadsheet };

/// "plain", "spreadsheet": the names on the command line and in the settings.
QString csvDialectName(CsvDialect dialect);
std::optional<CsvDialect> csvDialectFromName(const QString& name);
/// The names, for a message: "plain, spreadsheet".
QString csvDialectNames();

/// What a dialect comes to in one language.
struct CsvConventions {
    char separator = ',';
    char decimal = '.';
    bool bom = false; ///< the file starts with the UTF-8 byte order mark
};

/// Whether the language (a code of lessons::kLanguages: "cs", "en") writes a decimal comma.
bool usesDecimalComma(const QString& language);

/// The conventions of `dialect` in `language`.
CsvConventions csvConventions(CsvDialect dialect, const QString& language);

/// Tab-separated text in the language's number format, for the clipboard.
CsvConventions clipboardConventions(const QString& language);

} // namespace rigidlab::lessons
