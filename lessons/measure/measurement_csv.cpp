// SPDX-License-Identifier: GPL-3.0-or-later
// readTable: the text of a measurement as rows of numbers under an optional header.
#include "measure/measurement.h"

#include <QCoreApplication>
#include <QFile>
#include <QStringDecoder>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>

namespace rigidlab::measure {

namespace {

constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

QString where(int line)
{
    return QCoreApplication::translate("rigidlab::measure", "line %1").arg(line);
}

QString where(int line, int column, const QString& name)
{
    if (name.isEmpty())
        return QCoreApplication::translate("rigidlab::measure", "line %1, column %2")
            .arg(line)
            .arg(column);
    return QCoreApplication::translate("rigidlab::measure", "line %1, column %2 (\"%3\")")
        .arg(line)
        .arg(column)
        .arg(name);
}

/// A cell's text shortened for a message, control characters shown as '?'.
QString quoted(const QString& cell)
{
    QString text = cell.left(24);
    for (QChar& c : text) {
        if (c.unicode() < 0x20)
            c = u'?';
    }
    return text.size() < cell.size() ? text + u'…' : text;
}

/// Splits a line at `separator`, with fields in double quotes as RFC 4180 writes them (a
/// quote doubled inside). ' ' splits at runs of spaces and tabs, and keeps a unit that
/// follows a name ("Time (s)") with it. False: a quote not closed.
bool splitLine(const QString& line, QChar separator, QStringList& fields)
{
    fields.clear();
    const bool spaces = separator == u' ';
    QString field;
    bool inQuotes = false, quoted = false;
    const auto endField = [&] {
        const QString f = field.trimmed();
        if (spaces && !quoted && !fields.isEmpty() && (f.startsWith(u'(') || f.startsWith(u'[')))
            fields.back() += u' ' + f;
        else if (!spaces || quoted || !f.isEmpty())
            fields << f;
        field.clear();
        quoted = false;
    };
    for (qsizetype i = 0; i < line.size(); ++i) {
        const QChar c = line.at(i);
        if (inQuotes) {
            if (c == u'"' && i + 1 < line.size() && line.at(i + 1) == u'"') {
                field += u'"';
                ++i;
            } else if (c == u'"') {
                inQuotes = false;
            } else {
                field += c;
            }
        } else if (c == u'"') {
            inQuotes = quoted = true;
        } else if (c == separator || (spaces && c == u'\t')) {
            endField();
        } else {
            field += c;
        }
    }
    endField();
    return !inQuotes;
}

enum class Cell { Empty, Number, NotFinite, NotNumber };

/// Reads one cell: digits with a decimal point (or a decimal comma when allowed) and an
/// exponent; never the locale's idea of a number.
Cell readNumber(const QString& text, bool allowComma, double& value, bool& usedComma)
{
    if (text.isEmpty())
        return Cell::Empty;
    QString s = text;
    if (allowComma && s.count(u',') == 1 && !s.contains(u'.')) {
        s.replace(u',', u'.');
        usedComma = true;
    }
    if (s.startsWith(u'+'))
        s.remove(0, 1);
    const std::string bytes = s.toStdString();
    const char* first = bytes.data();
    const char* last = first + bytes.size();
    const auto [end, ec] = std::from_chars(first, last, value);
    if (end != last || ec == std::errc::invalid_argument || bytes.empty())
        return Cell::NotNumber;
    if (ec == std::errc::result_out_of_range || !std::isfinite(value))
        return Cell::NotFinite;
    return Cell::Number;
}

/// Whether every non-empty field is a number (and one at least is).
bool isNumberLine(const QStringList& fields, bool allowComma)
{
    bool any = false;
    for (const QString& f : fields) {
        double v = 0;
        bool comma = false;
        const Cell cell = readNumber(f, allowComma, v, comma);
        if (cell == Cell::NotNumber)
            return false;
        any = any || cell != Cell::Empty;
    }
    return any;
}

/// The text, or an error for bytes that are not text: a control character (NUL, ...), or
/// bytes that are neither UTF-8 nor Latin-1 text.
bool decodeText(const QByteArray& bytes, QString& text, QString& error)
{
    int line = 1;
    for (const char c : bytes) {
        const auto u = static_cast<unsigned char>(c);
        if (u == '\n') {
            ++line;
        } else if ((u < 0x20 && u != '\t' && u != '\r') || u == 0x7f) {
            error = QCoreApplication::translate("rigidlab::measure",
                                                "%1: binary data (byte %2), not text")
                        .arg(where(line))
                        .arg(u);
            return false;
        }
    }
    QStringDecoder utf8(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
    text = utf8.decode(bytes);
    if (utf8.hasError())
        text = QString::fromLatin1(bytes); // an old Windows export: Latin-1 names
    if (text.startsWith(QChar(0xfeff)))
        text.remove(0, 1);
    return true;
}

/// Whether the first lines split at `separator` into a header line (if any) and rows of
/// numbers, all with the same number of fields.
bool fitsSeparator(const QStringList& lines, QChar separator)
{
    QStringList fields;
    qsizetype header = -1, columns = -1;
    int rows = 0;
    bool trailing = true; // every row ends in a separator
    for (const QString& line : lines) {
        const QString t = line.trimmed();
        if (t.isEmpty() || t.startsWith(u'#'))
            continue;
        if (!splitLine(line, separator, fields))
            return false;
        if (!isNumberLine(fields, separator != u',')) {
            if (rows > 0)
                break;
            header = fields.size();
            continue;
        }
        if (columns >= 0 && fields.size() != columns)
            return false;
        columns = fields.size();
        trailing = trailing && fields.size() > 1 && fields.back().isEmpty();
        if (++rows == 20)
            break;
    }
    // A single name above two numbers split at a comma is one column of decimal commas
    // ("Time (s)" over 0,4523); other single lines are titles (Tracker's track name).
    const bool title = header == 1 && !(separator == u',' && columns == 2);
    // (A header one short: rows that end in a separator.)
    return rows > 0 &&
           (header < 0 || title || header == columns || (trailing && header + 1 == columns));
}

/// The separator of the file: the first of a tab, a semicolon and a comma at which the first
/// lines split evenly (a header with as many names as the rows have numbers), else spaces if
/// they split evenly at those, else the first of the three the lines hold (the reader then
/// names the uneven line). So a single column of numbers with decimal commas under
/// "Time (s)" is read as one column.
QChar guessSeparator(const QStringList& lines)
{
    const QStringList first = lines.mid(0, kMaxHeaderLines + 20);
    QChar present;
    for (const QChar c : {QChar(u'\t'), QChar(u';'), QChar(u',')}) {
        if (std::none_of(first.cbegin(), first.cend(),
                         [&](const QString& l) { return l.contains(c); }))
            continue;
        if (fitsSeparator(first, c))
            return c;
        if (present.isNull())
            present = c;
    }
    return present.isNull() || fitsSeparator(first, u' ') ? QChar(u' ') : present;
}

/// "Time (s)" -> ("Time", "s"); "y [cm]" -> ("y", "cm").
void splitUnit(const QString& header, QString& name, QString& unit)
{
    name = header.trimmed();
    unit.clear();
    for (const auto& [open, close] : {std::pair{u'(', u')'}, std::pair{u'[', u']'}}) {
        const qsizetype at = name.lastIndexOf(QChar(open));
        if (name.endsWith(QChar(close)) && at > 0) {
            unit = name.mid(at + 1, name.size() - at - 2).trimmed();
            name = name.left(at).trimmed();
            return;
        }
    }
}

Layout guessLayout(const Table& table, bool hasHeader)
{
    if (!hasHeader)
        return Layout::Plain;
    bool allUnits = true;
    for (const Column& c : table.columns)
        allUnits = allUnits && !c.unit.isEmpty();
    if (allUnits && table.columns.front().name.startsWith(u"Time", Qt::CaseInsensitive))
        return Layout::Phyphox;
    if (!table.titleLines.isEmpty() && table.columns.front().name == u"t")
        return Layout::Tracker;
    return Layout::Plain;
}

/// Reads the rows of numbers from line index `first` on into table (whose columns exist).
class RowReader {
public:
    RowReader(Table& table, bool allowComma) : m_table(table), m_allowComma(allowComma) {}

    bool readRow(const QStringList& fields, int line, QString& error)
    {
        const qsizetype n = static_cast<qsizetype>(m_table.columns.size());
        qsizetype count = fields.size();
        if (count == n + 1 && fields.back().isEmpty())
            count = n; // a separator at the end of the row
        if (count != n) {
            error = QCoreApplication::translate("rigidlab::measure",
                                                "%1: %2 values where the header (or the first "
                                                "row) has %3: a ragged row")
                        .arg(where(line))
                        .arg(count)
                        .arg(n);
            return false;
        }
        if (m_table.rows() >= kMaxRows) {
            error = QCoreApplication::translate("rigidlab::measure",
                                                "%1: more than %2 rows of numbers (the limit)")
                        .arg(where(line))
                        .arg(kMaxRows);
            return false;
        }
        for (qsizetype c = 0; c < n; ++c) {
            if (!readCell(fields.at(c), line, static_cast<int>(c), error))
                return false;
        }
        m_table.lines.push_back(line);
        return true;
    }

private:
    bool readCell(const QString& text, int line, int c, QString& error)
    {
        Column& column = m_table.columns[static_cast<std::size_t>(c)];
        double value = kMissing;
        const Cell cell = readNumber(text, m_allowComma, value, m_table.decimalComma);
        if (cell == Cell::NotNumber || cell == Cell::NotFinite) {
            const QString what =
                cell == Cell::NotNumber
                    ? QCoreApplication::translate("rigidlab::measure", "\"%1\" is not a number")
                    : QCoreApplication::translate("rigidlab::measure",
                                                  "\"%1\" is not a finite number");
            error = where(line, c + 1, column.name) + QStringLiteral(": ") + what.arg(quoted(text));
            return false;
        }
        column.values.push_back(cell == Cell::Empty ? kMissing : value);
        return true;
    }

    Table& m_table;
    bool m_allowComma;
};

/// The header lines before the first row of numbers: the last one names the columns when it
/// has as many fields as the rows (or is not a single title); the others are title lines.
bool readHeader(const QStringList& lines, const std::vector<int>& headerLines, QChar separator,
                int columns, Table& table, bool& hasHeader, QString& error)
{
    hasHeader = false;
    QStringList names;
    if (!headerLines.empty()) {
        const int last = headerLines.back();
        splitLine(lines.at(last), separator, names);
        if (names.size() == columns + 1 && names.back().isEmpty())
            names.removeLast();
        if (names.size() == columns) {
            hasHeader = true;
        } else if (names.size() > 1) {
            error = QCoreApplication::translate("rigidlab::measure",
                                                "%1: the header names %2 columns, the rows "
                                                "below it have %3")
                        .arg(where(last + 1))
                        .arg(names.size())
                        .arg(columns);
            return false;
        }
    }
    for (std::size_t i = 0; i + (hasHeader ? 1 : 0) < headerLines.size(); ++i)
        table.titleLines << lines.at(headerLines[i]).trimmed();
    table.columns.resize(static_cast<std::size_t>(columns));
    for (int c = 0; c < columns && hasHeader; ++c) {
        Column& column = table.columns[static_cast<std::size_t>(c)];
        splitUnit(names.at(c), column.name, column.unit);
    }
    return true;
}

TableResult failed(const QString& sourceName, const QString& what)
{
    TableResult r;
    r.error = sourceName + QStringLiteral(": ") + what;
    return r;
}

} // namespace

TableResult readTable(const QByteArray& bytes, const QString& sourceName)
{
    if (bytes.size() > kMaxFileBytes)
        return failed(sourceName, QCoreApplication::translate("rigidlab::measure",
                                                              "larger than %1 MB (the limit)")
                                      .arg(kMaxFileBytes >> 20));
    QString text, error;
    if (!decodeText(bytes, text, error))
        return failed(sourceName, error);
    if (text.trimmed().isEmpty())
        return failed(sourceName,
                      QCoreApplication::translate("rigidlab::measure", "the file is empty"));
    text.replace(QStringLiteral("\r\n"), QStringLiteral("\n")).replace(u'\r', u'\n');
    const QStringList lines = text.split(u'\n');
    const QChar separator = guessSeparator(lines);
    const bool allowComma = separator != u',';

    // The header lines, up to the first row of numbers.
    std::vector<int> headerLines;
    int first = -1;
    QStringList fields;
    for (int i = 0; i < lines.size() && first < 0; ++i) {
        const QString t = lines.at(i).trimmed();
        if (t.isEmpty() || t.startsWith(u'#'))
            continue;
        if (!splitLine(lines.at(i), separator, fields))
            return failed(sourceName, QCoreApplication::translate("rigidlab::measure",
                                                                  "%1: a quote (\") is not closed")
                                          .arg(where(i + 1)));
        if (isNumberLine(fields, allowComma))
            first = i;
        else if (static_cast<int>(headerLines.size()) == kMaxHeaderLines)
            return failed(sourceName,
                          QCoreApplication::translate("rigidlab::measure",
                                                      "no row of numbers in the first %1 lines")
                              .arg(kMaxHeaderLines));
        else
            headerLines.push_back(i);
    }
    if (first < 0)
        return failed(sourceName, QCoreApplication::translate(
                                      "rigidlab::measure",
                                      "no row of numbers (a measurement has a number in every "
                                      "column of its rows)"));
    int columns = static_cast<int>(fields.size());
    if (columns > 1 && fields.back().isEmpty())
        --columns; // a separator at the end of the row
    if (columns > kMaxColumns)
        return failed(sourceName,
                      QCoreApplication::translate("rigidlab::measure",
                                                  "%1: %2 columns, more than %3 (the limit)")
                          .arg(where(first + 1))
                          .arg(columns)
                          .arg(kMaxColumns));

    TableResult result;
    Table& table = result.table;
    table.separator = separator;
    bool hasHeader = false;
    if (!readHeader(lines, headerLines, separator, columns, table, hasHeader, error))
        return failed(sourceName, error);
    RowReader rows(table, allowComma);
    for (int i = first; i < lines.size(); ++i) {
        const QString t = lines.at(i).trimmed();
        if (t.isEmpty() || t.startsWith(u'#'))
            continue;
        if (!splitLine(lines.at(i), separator, fields))
            return failed(sourceName, QCoreApplication::translate("rigidlab::measure",
                                                                  "%1: a quote (\") is not closed")
                                          .arg(where(i + 1)));
        if (!rows.readRow(fields, i + 1, error))
            return failed(sourceName, error);
    }
    table.layout = guessLayout(table, hasHeader);
    result.ok = true;
    return result;
}

TableResult readTableFile(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return failed(path, QCoreApplication::translate("rigidlab::measure", "cannot read: %1")
                                .arg(file.errorString()));
    if (file.size() > kMaxFileBytes)
        return failed(
            path, QCoreApplication::translate("rigidlab::measure", "larger than %1 MB (the limit)")
                      .arg(kMaxFileBytes >> 20));
    return readTable(file.read(kMaxFileBytes + 1), path);
}

} // namespace rigidlab::measure
