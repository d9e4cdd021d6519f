// SPDX-License-Identifier: GPL-3.0-or-later
#include "export/csv_writer.h"

#include <charconv>
#include <cmath>
#include <utility>

namespace rigidlab::lessons {

std::string formatCsvNumber(double value, char decimal)
{
    if (std::isnan(value))
        return {};
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value).ptr;
    std::string out(text, end);
    if (decimal != '.')
        for (char& c : out)
            if (c == '.')
                c = decimal;
    return out;
}

CsvWriter::CsvWriter(CsvConventions conventions) : m_conventions(conventions)
{
    if (m_conventions.bom)
        m_buffer = "\xEF\xBB\xBF";
}

void CsvWriter::separate()
{
    if (m_rowStarted)
        m_buffer += m_conventions.separator;
    m_rowStarted = true;
}

void CsvWriter::row(const QStringList& fields)
{
    for (const QString& field : fields)
        text(field);
    endRow();
}

void CsvWriter::number(double value)
{
    separate();
    m_buffer += formatCsvNumber(value, m_conventions.decimal);
}

void CsvWriter::integer(long long value)
{
    separate();
    char text[24];
    const auto end = std::to_chars(text, text + sizeof text, value).ptr;
    m_buffer.append(text, end);
}

void CsvWriter::text(const QString& value)
{
    const QByteArray utf8 = value.toUtf8();
    text(std::string_view(utf8.constData(), static_cast<std::size_t>(utf8.size())));
}

void CsvWriter::text(std::string_view utf8)
{
    separate();
    const char special[] = {m_conventions.separator, '"', '\r', '\n', '\0'};
    if (utf8.find_first_of(special) == std::string_view::npos) {
        m_buffer += utf8;
        return;
    }
    m_buffer += '"';
    for (const char c : utf8) {
        m_buffer += c;
        if (c == '"')
            m_buffer += '"';
    }
    m_buffer += '"';
}

void CsvWriter::endRow()
{
    m_buffer += '\n';
    m_rowStarted = false;
}

std::string CsvWriter::take()
{
    std::string out;
    std::swap(out, m_buffer);
    return out;
}

} // namespace rigidlab::lessons
