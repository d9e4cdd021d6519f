// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The class's table written out, its heads and cells from the one column list
// (class_table.h): as text for a terminal (columns aligned) and as CSV in any dialect
// (export/csv_writer.h: numbers as numbers, the Czech spreadsheet's decimal comma). The PDF
// is the window's (ui/worksheet/class_results_pdf.h).

#include "export/csv_dialect.h"
#include "results/class_table.h"

#include <QString>

#include <string>
#include <vector>

namespace rigidlab::lessons {

/// The lesson's title, then the table with its columns aligned, the summary row last.
QString classTableText(const ClassTable& table);

/// The table as CSV: a row of heads, a row per student, the summary row. Several tables
/// (several lessons) follow one another, each after an empty row and a row with its lesson's
/// title and file.
std::string classTablesCsv(const std::vector<ClassTable>& tables, CsvConventions conventions);

} // namespace rigidlab::lessons
