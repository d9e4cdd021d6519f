// SPDX-License-Identifier: GPL-3.0-or-later
#include "panels/fitting_table.h"

#include "common/language.h"
#include "common/modal_scope.h"
#include "plots/plot_export.h"

#include "export/csv_writer.h"
#include "format/atomic_file.h"
#include "format/scene_schema.h"

#include <QClipboard>
#include <QContextMenuEvent>
#include <QFileInfo>
#include <QGuiApplication>
#include <QHeaderView>
#include <QMenu>
#include <QMessageBox>
#include <QScrollBar>
#include <QShortcut>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace rigidlab::ui {

namespace {

/// Room around a cell's text: the style's margins on both sides and the grid line [px].
constexpr int kCellPadding = 14;
/// Room around a header's text, which has a sort indicator's margin as well [px].
constexpr int kHeaderPadding = 18;
/// What the item delegate takes off a cell's width before wrapping its text (the style's
/// focus frame margins, 3 px on each side), and 2 px to spare [px].
constexpr int kWrapMargin = 8;
/// Slack added to a column's measured text, so that rounding in the text layout never
/// wraps a line that was measured to fit [px].
constexpr int kSlack = 3;
/// A column never gets narrower than this, so that "–" and "?" still have room [px].
constexpr int kMinColumn = 24;

/// The width of the widest line of `text` in `fm` [px].
int textWidth(const QFontMetrics& fm, const QString& text)
{
    int widest = 0;
    for (const QString& line : text.split(QLatin1Char('\n')))
        widest = std::max(widest, fm.horizontalAdvance(line));
    return widest;
}

} // namespace

QString csvNumber(double value)
{
    if (!std::isfinite(value))
        return QString();
    return QString::fromStdString(lessons::formatCsvNumber(value));
}

QByteArray csvBytes(const CsvTable& table, const lessons::CsvConventions& conventions)
{
    // Through the lab's one writer: a cell that is a number (csvNumber's text) takes the
    // dialect's decimal sign, the rest is text.
    lessons::CsvWriter csv(conventions);
    csv.row(table.headers);
    for (const QStringList& row : table.rows) {
        for (const QString& cell : row) {
            bool number = false;
            const double value = cell.toDouble(&number);
            if (number && std::isfinite(value))
                csv.number(value);
            else
                csv.text(cell);
        }
        csv.endRow();
    }
    const std::string& data = csv.data();
    return QByteArray(data.data(), static_cast<qsizetype>(data.size()));
}

CsvTable parseCsv(const QByteArray& bytes)
{
    QList<QStringList> lines;
    QStringList cells;
    QByteArray cell;
    bool quoted = false, any = false;
    for (qsizetype i = 0; i < bytes.size(); ++i) {
        const char ch = bytes[i];
        any = true;
        if (quoted) {
            if (ch == '"' && i + 1 < bytes.size() && bytes[i + 1] == '"') {
                cell += '"';
                ++i;
            } else if (ch == '"') {
                quoted = false;
            } else {
                cell += ch;
            }
        } else if (ch == '"') {
            quoted = true;
        } else if (ch == ',') {
            cells << QString::fromUtf8(cell);
            cell.clear();
        } else if (ch == '\n') {
            cells << QString::fromUtf8(cell);
            cell.clear();
            lines << cells;
            cells.clear();
            any = false;
        } else if (ch != '\r') {
            cell += ch;
        }
    }
    if (any) {
        cells << QString::fromUtf8(cell);
        lines << cells;
    }
    CsvTable table;
    if (!lines.isEmpty())
        table.headers = lines.takeFirst();
    table.rows = lines;
    return table;
}

QString writeCsv(const QString& path, const CsvTable& table,
                 const lessons::CsvConventions& conventions)
{
    return lessons::writeFileAtomically(path, csvBytes(table, conventions));
}

void exportCsvInteractively(QWidget* parent, const CsvTable& table, const QString& baseName)
{
    const ModalScope modal;
    // Where the plots' exports go (the last folder, else Documents), in the same dialect.
    const QString stem = lessons::schema::safeFileStem(
        QStringList{baseName, currentLanguage()}.join(u' '), QStringLiteral("table"));
    const auto chosen =
        askCsvFile(parent, FittingTable::tr("Export table as CSV"), stem + QStringLiteral(".csv"));
    if (!chosen)
        return;
    const QString why =
        writeCsv(chosen->path, table, lessons::csvConventions(chosen->dialect, currentLanguage()));
    if (!why.isEmpty())
        QMessageBox::warning(parent, FittingTable::tr("Export failed"), why);
}

void FittingTable::copyData() const
{
    const QByteArray text = csvBytes(m_csv, lessons::clipboardConventions(currentLanguage()));
    QGuiApplication::clipboard()->setText(QString::fromUtf8(text));
}

FittingTable::FittingTable(QWidget* parent) : QTableWidget(parent)
{
    verticalHeader()->setVisible(false);
    horizontalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    horizontalHeader()->setMinimumSectionSize(kMinColumn);
    verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setVerticalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setSelectionMode(QAbstractItemView::NoSelection);
    setWordWrap(true);
    setTextElideMode(Qt::ElideNone);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Maximum);
    // Ctrl+C copies the table's numbers, tab-separated, for a spreadsheet.
    auto* copy = new QShortcut(QKeySequence::Copy, this, this, &FittingTable::copyData);
    copy->setContext(Qt::WidgetShortcut);
}

void FittingTable::setContent(const TableText& wide, const TableText& narrow)
{
    if (wide == m_wideText && narrow == m_narrowText && rowCount() > 0)
        return; // refreshed every frame while the world runs: nothing to lay out
    m_wideText = wide;
    m_narrowText = narrow;
    relayout();
}

void FittingTable::setCsv(const CsvTable& csv, const QString& baseName)
{
    m_csv = csv;
    m_csvName = baseName;
}

QString FittingTable::exportCsv(const QString& path) const
{
    return writeCsv(path, m_csv);
}

void FittingTable::exportCsvInteractively()
{
    ui::exportCsvInteractively(this, m_csv, m_csvName);
}

QList<int> FittingTable::columnWidths(const TableText& text) const
{
    const QFontMetrics cellMetrics(font());
    const QFontMetrics headerMetrics(horizontalHeader()->font());
    QList<int> widths;
    for (const QString& h : text.headers)
        widths << std::max(kMinColumn, textWidth(headerMetrics, h) + kHeaderPadding);
    for (int r = 0; r < text.rows.size(); ++r) {
        if (text.isTitle(r))
            continue; // spans the table: wraps in whatever width the columns add up to
        const QStringList& row = text.rows[r];
        for (int c = 0; c < row.size() && c < widths.size(); ++c)
            widths[c] = std::max(widths[c], textWidth(cellMetrics, row[c]) + kCellPadding + kSlack);
    }
    return widths;
}

int FittingTable::wideWidth() const
{
    const QList<int> widths = columnWidths(m_wideText);
    return std::accumulate(widths.begin(), widths.end(), 0) + 2 * frameWidth();
}

void FittingTable::relayout()
{
    if (m_relayingOut)
        return;
    m_relayingOut = true;
    const bool narrow = wideWidth() > width() && !m_narrowText.headers.isEmpty();
    const TableText& text = narrow ? m_narrowText : m_wideText;
    m_narrow = narrow;
    fill(text);
    sizeColumnsAndRows(text);
    m_relayingOut = false;
}

void FittingTable::fill(const TableText& text)
{
    clearSpans();
    const int columns = static_cast<int>(text.headers.size());
    setColumnCount(columns);
    setHorizontalHeaderLabels(text.headers);
    for (int c = 0; c < columns; ++c)
        if (QTableWidgetItem* h = horizontalHeaderItem(c))
            h->setToolTip(c < text.headerTips.size() ? text.headerTips[c] : QString());
    setRowCount(static_cast<int>(text.rows.size()));
    for (int r = 0; r < rowCount(); ++r) {
        const QStringList& row = text.rows[r];
        const bool title = text.isTitle(r);
        if (title && columns > 1)
            setSpan(r, 0, 1, columns);
        for (int c = 0; c < columns; ++c) {
            const QString cell = c < row.size() && (!title || c == 0) ? row[c] : QString();
            QTableWidgetItem* item = this->item(r, c);
            if (!item) {
                item = new QTableWidgetItem;
                setItem(r, c, item);
            }
            if (item->text() != cell)
                item->setText(cell);
            // A screen reader says "empty" rather than nothing for a cell with no value.
            item->setData(Qt::AccessibleTextRole, cell.isEmpty() ? tr("empty") : QVariant());
            QFont f = font();
            f.setBold(title);
            item->setFont(f);
            item->setTextAlignment(title || c == 0 ? Qt::AlignLeft | Qt::AlignVCenter
                                                   : Qt::AlignRight | Qt::AlignVCenter);
        }
    }
}

void FittingTable::sizeColumnsAndRows(const TableText& text)
{
    QList<int> widths = columnWidths(text);
    const int columns = static_cast<int>(widths.size());
    if (columns == 0) {
        m_contentHeight = horizontalHeader()->sizeHint().height();
        updateGeometry();
        return;
    }
    // The columns share the width: what is left over goes to the last column; where they do
    // not fit (narrower than the narrow form), the last one gives up its width and wraps.
    const int available = std::max(
        0, width() - 2 * frameWidth() -
               (verticalScrollBar()->isVisible() ? verticalScrollBar()->sizeHint().width() : 0));
    const int others = std::accumulate(widths.begin(), widths.end() - 1, 0);
    widths.last() = std::max(kMinColumn, available - others);
    for (int c = 0; c < columns; ++c)
        setColumnWidth(c, widths[c]);
    // Rows as tall as their wrapped text.
    const QFontMetrics fm(font());
    QFont bold = font();
    bold.setBold(true);
    const QFontMetrics boldMetrics(bold);
    const int total = std::accumulate(widths.begin(), widths.end(), 0);
    int height = horizontalHeader()->sizeHint().height();
    for (int r = 0; r < rowCount(); ++r) {
        int rowHeight = fm.height() + 8;
        const QStringList& row = text.rows[r];
        for (int c = 0; c < row.size() && c < columns; ++c) {
            const bool title = text.isTitle(r);
            if (title && c > 0)
                break;
            // The delegate wraps text at the cell's width less its focus frame margins.
            const int w = (title ? total : widths[c]) - kWrapMargin;
            const QRect bounds =
                (title ? boldMetrics : fm)
                    .boundingRect(QRect(0, 0, std::max(1, w), 10000), Qt::TextWordWrap, row[c]);
            rowHeight = std::max(rowHeight, bounds.height() + 8);
        }
        setRowHeight(r, rowHeight);
        height += rowHeight;
    }
    m_contentHeight = height + 2 * frameWidth();
    updateGeometry();
}

QSize FittingTable::sizeHint() const
{
    // As wide as the narrow form needs, so that the table never pushes its column wider.
    const QList<int> widths =
        columnWidths(m_narrowText.headers.isEmpty() ? m_wideText : m_narrowText);
    const int width = std::accumulate(widths.begin(), widths.end(), 0) + 2 * frameWidth();
    return {width, m_contentHeight};
}

QSize FittingTable::minimumSizeHint() const
{
    return {kMinColumn * 2, std::min(m_contentHeight, 4 * fontMetrics().height())};
}

void FittingTable::resizeEvent(QResizeEvent* event)
{
    QTableWidget::resizeEvent(event);
    relayout();
}

void FittingTable::contextMenuEvent(QContextMenuEvent* event)
{
    QMenu menu(this);
    QAction* exportAction = menu.addAction(tr("Export as CSV…"));
    exportAction->setEnabled(!m_csv.headers.isEmpty());
    connect(exportAction, &QAction::triggered, this, &FittingTable::exportCsvInteractively);
    QAction* copyAction = menu.addAction(tr("Copy"), this, &FittingTable::copyData);
    copyAction->setShortcut(QKeySequence::Copy);
    copyAction->setEnabled(!m_csv.headers.isEmpty());
    menu.exec(event->globalPos());
}

} // namespace rigidlab::ui
