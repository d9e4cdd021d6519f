// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one CSV writer of the lab: the command line's trace and diagnostics, a plot's data from
// the window, a lesson's handouts and the clipboard all write their rows here, so that every
// file says its numbers the same way:
//   - a number is the shortest text that reads back to the same double (0.009, not
//     0.0090000000000000001), with the dialect's decimal sign, never the C library's locale;
//     a NaN (a gap in a plot) is an empty cell;
//   - a text field is quoted as RFC 4180 asks when it holds the separator, a quote or a line
//     break, quotes doubled;
//   - rows end with "\n"; a spreadsheet dialect's file starts with the UTF-8 BOM.
// The rows are gathered in memory; the caller writes them (atomically, lessons/format/
// atomic_file.h or a QSaveFile) and may take them in parts (take()) for a long run.

#include "export/csv_dialect.h"

#include <QString>
#include <QStringList>

#include <string>
#include <string_view>

namespace rigidlab::lessons {

/// The shortest text that reads back as `value`, with `decimal` as the decimal sign; "" for
/// NaN.
std::string formatCsvNumber(double value, char decimal = '.');

class CsvWriter {
public:
    explicit CsvWriter(CsvConventions conventions = {});

    const CsvConventions& conventions() const { return m_conventions; }

    /// A row of text fields (a header), ended.
    void row(const QStringList& fields);
    void number(double value);
    void integer(long long value);
    void text(const QString& value);
    void text(std::string_view utf8);
    /// Ends the row; the next field starts a new one.
    void endRow();

    /// What was written so far (the BOM first in a spreadsheet dialect).
    const std::string& data() const { return m_buffer; }
    std::size_t size() const { return m_buffer.size(); }
    /// Hands over what was written so far and starts an empty buffer (no second BOM).
    std::string take();

private:
    void separate();

    CsvConventions m_conventions;
    std::string m_buffer;
    bool m_rowStarted = false;
};

} // namespace rigidlab::lessons
