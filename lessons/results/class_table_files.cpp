// SPDX-License-Identifier: GPL-3.0-or-later
#include "results/class_table_files.h"

#include "export/csv_writer.h"

#include <algorithm>

namespace rigidlab::lessons {

namespace {

/// The cells of every row, heads first and the summary last: what both files write.
std::vector<std::vector<ClassCell>> tableCells(const ClassTable& table)
{
    const std::vector<ClassColumn> columns = classColumns(table);
    std::vector<std::vector<ClassCell>> rows(1);
    for (const ClassColumn& c : columns)
        rows.front().push_back({classColumnHead(table, c), std::nullopt});
    for (std::size_t r = 0; r < table.rows.size(); ++r) {
        rows.emplace_back();
        for (const ClassColumn& c : columns)
            rows.back().push_back(classCell(table, r, c));
    }
    rows.emplace_back();
    for (const ClassColumn& c : columns)
        rows.back().push_back(classSummaryCell(table, c));
    return rows;
}

} // namespace

QString classTableText(const ClassTable& table)
{
    const std::vector<std::vector<ClassCell>> rows = tableCells(table);
    std::vector<qsizetype> widths(rows.front().size(), 0);
    for (const auto& row : rows)
        for (std::size_t c = 0; c < row.size(); ++c)
            widths[c] = std::max(widths[c], row[c].text.size());
    QString out = QStringLiteral("%1 (%2)\n").arg(table.lessonTitle, table.lessonFile);
    for (const auto& row : rows) {
        QString line;
        for (std::size_t c = 0; c < row.size(); ++c) {
            const qsizetype width = widths[c];
            // Numbers to the right, text to the left, two spaces between columns.
            line += row[c].number ? row[c].text.rightJustified(width)
                                  : row[c].text.leftJustified(width);
            if (c + 1 < row.size())
                line += QStringLiteral("  ");
        }
        while (!line.isEmpty() && line.back().isSpace())
            line.chop(1);
        out += line + u'\n';
    }
    return out;
}

std::string classTablesCsv(const std::vector<ClassTable>& tables, CsvConventions conventions)
{
    CsvWriter csv(conventions);
    for (std::size_t t = 0; t < tables.size(); ++t) {
        if (tables.size() > 1) {
            if (t > 0)
                csv.endRow();
            csv.row({tables[t].lessonTitle, tables[t].lessonFile});
        }
        for (const auto& row : tableCells(tables[t])) {
            for (const ClassCell& cell : row) {
                if (cell.number)
                    csv.number(*cell.number);
                else
                    csv.text(cell.text);
            }
            csv.endRow();
        }
    }
    return csv.data();
}

} // namespace rigidlab::lessons
