// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A lesson's table that fits the window's right column. At 1024 × 768 that column is about
// 200 px wide, too narrow for a table of five or eleven columns: the table then switches to
// its narrow form, which the panel writes as well (a title row spanning the table, then a
// few short columns under it). Either form shows every cell's text whole: columns are as
// wide as their widest text, text wraps in the last one, and rows are as tall as their text.
// The table is as tall as its rows (no inner scroll bar while the column has the height).
//
// The table also exports itself as CSV (its context menu, or a panel's button): the numbers
// as they are, in their shortest form that reads back exactly, through the lab's CSV writer
// (lessons/export/csv_writer.h) in the window's dialect, written atomically. Ctrl+C copies
// them as tab-separated text in the language's number format.

#include "export/csv_dialect.h"

#include <QList>
#include <QStringList>
#include <QTableWidget>

namespace rigidlab::ui {

/// A table as text: one header per column, rows of cells. A title row has one cell, shown
/// across the whole table.
struct TableText {
    QStringList headers;
    QList<QStringList> rows;
    QList<bool> titleRows;  ///< per row: true for a title row (may be shorter than rows)
    QStringList headerTips; ///< per column, may be empty or shorter than headers

    bool isTitle(int row) const { return row < titleRows.size() && titleRows[row]; }
    bool operator==(const TableText&) const = default;
};

/// Cells of a CSV file: numbers already in their file form (csvNumber).
struct CsvTable {
    QStringList headers;
    QList<QStringList> rows;
};

/// The shortest text that reads back as the same double, with a decimal point; empty for a
/// value that is not finite (a gap).
QString csvNumber(double value);
/// The table as CSV in a dialect (plain, RFC 4180, unless told), through the lab's writer:
/// a number cell takes the dialect's decimal sign, a cell is quoted where it needs it.
QByteArray csvBytes(const CsvTable& table, const lessons::CsvConventions& conventions = {});
/// Reads back what csvBytes wrote (used by the tests and by nothing else).
CsvTable parseCsv(const QByteArray& bytes);
/// Writes the table to `path` atomically: empty on success, else the reason.
QString writeCsv(const QString& path, const CsvTable& table,
                 const lessons::CsvConventions& conventions = {});
/// Asks for a file name (from `baseName` and the language, in the folder last exported into)
/// and a dialect (the window's, remembered when changed), and writes the table there; a
/// failure is shown in a message box.
void exportCsvInteractively(QWidget* parent, const CsvTable& table, const QString& baseName);

class FittingTable : public QTableWidget {
    Q_OBJECT
public:
    explicit FittingTable(QWidget* parent = nullptr);

    /// The table in both forms; the wide one is shown where all its columns fit.
    void setContent(const TableText& wide, const TableText& narrow);
    /// What "Export as CSV…" writes; `baseName` is the file name offered.
    void setCsv(const CsvTable& csv, const QString& baseName);
    const CsvTable& csv() const { return m_csv; }
    /// Writes the CSV to `path` atomically: empty on success, else the reason.
    QString exportCsv(const QString& path) const;
    /// Asks for a file name and writes the CSV there; a failure is shown in a message box.
    void exportCsvInteractively();
    /// Puts the table's numbers on the clipboard, tab-separated, in the language's number
    /// format (Ctrl+C).
    void copyData() const;

    bool isNarrow() const { return m_narrow; }
    const TableText& shownText() const { return m_narrow ? m_narrowText : m_wideText; }
    /// The table in its wide form, whichever form is shown: one row per quantity.
    const TableText& wideText() const { return m_wideText; }
    /// The width the wide form needs to show every column whole [px].
    int wideWidth() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void resizeEvent(QResizeEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;

private:
    /// The width each column needs for its widest text (header included) [px].
    QList<int> columnWidths(const TableText& text) const;
    void relayout();
    void fill(const TableText& text);
    void sizeColumnsAndRows(const TableText& text);

    TableText m_wideText;
    TableText m_narrowText;
    CsvTable m_csv;
    QString m_csvName;
    bool m_narrow = false;
    bool m_relayingOut = false;
    int m_contentHeight = 0; ///< header and rows [px]
};

} // namespace rigidlab::ui
