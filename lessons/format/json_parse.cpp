// SPDX-License-Identifier: GPL-3.0-or-later
// From a file to a parsed JSON document (json_reader.h's readFileBytes and parseJson): the
// bytes read within a size limit, nesting refused past its limit before Qt's parser sees it,
// and a syntax error told by line and column. What the document holds is read and checked by
// JsonReader (json_reader.cpp).

#include "format/json_reader.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonParseError>

#include <algorithm>
#include <utility>

namespace rigidlab::lessons::detail {

FileBytes readFileBytes(const QString& path, qint64 limit)
{
    FileBytes result;
    const QFileInfo info(path);
    if (info.isDir()) {
        result.error = path + FileMessages::tr(": cannot read: is a directory, not a file");
        return result;
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        result.error = path + FileMessages::tr(": cannot read: ") + file.errorString();
        return result;
    }
    // Read one byte past the limit rather than trusting size(): pipes and /proc files have none.
    result.bytes = file.read(limit + 1);
    if (file.error() != QFileDevice::NoError) {
        result.error = path + FileMessages::tr(": cannot read: ") + file.errorString();
        return result;
    }
    if (result.bytes.size() > limit) {
        result.error =
            path + FileMessages::tr(": too large: more than %1 bytes (the limit is %2 MiB)")
                       .arg(limit)
                       .arg(limit / (1024 * 1024));
        result.bytes.clear();
        return result;
    }
    result.ok = true;
    return result;
}

namespace {

/// 1-based line and column (in characters, not bytes) of a byte offset into UTF-8 text.
std::pair<int, int> lineAndColumn(const QByteArray& bytes, qsizetype offset)
{
    offset = std::clamp<qsizetype>(offset, 0, bytes.size());
    int line = 1;
    int column = 1;
    for (qsizetype i = 0; i < offset; ++i) {
        const auto c = static_cast<unsigned char>(bytes[i]);
        if (c == '\n') {
            ++line;
            column = 1;
        } else if ((c & 0xC0) != 0x80) { // not a UTF-8 continuation byte
            ++column;
        }
    }
    return {line, column};
}

/// Qt's parse errors in words that say what to fix. Qt reports where its parser stopped,
/// which is at the problem or just after it.
QString describeParseError(QJsonParseError::ParseError error)
{
    switch (error) {
    case QJsonParseError::NoError:
        break;
    case QJsonParseError::UnterminatedObject:
        return FileMessages::tr("unterminated object: a ',' or the closing '}' is missing");
    case QJsonParseError::MissingNameSeparator:
        return FileMessages::tr("a ':' is missing after a key");
    case QJsonParseError::UnterminatedArray:
        return FileMessages::tr("unterminated array: a ',' or the closing ']' is missing");
    case QJsonParseError::MissingValueSeparator:
        return FileMessages::tr("a ',' is missing between two values");
    case QJsonParseError::IllegalValue:
        return FileMessages::tr("not a JSON value (text needs double quotes; true, false and "
                                "null are lower case)");
    case QJsonParseError::TerminationByNumber:
        return FileMessages::tr("the file ends inside a number");
    case QJsonParseError::IllegalNumber:
        return FileMessages::tr("not a valid number");
    case QJsonParseError::IllegalEscapeSequence:
        return FileMessages::tr("an invalid escape sequence in a string");
    case QJsonParseError::IllegalUTF8String:
        return FileMessages::tr("the text is not valid UTF-8");
    case QJsonParseError::UnterminatedString:
        return FileMessages::tr("unterminated string: the closing '\"' is missing");
    case QJsonParseError::MissingObject:
        return FileMessages::tr("a value is missing here (JSON allows no trailing comma)");
    case QJsonParseError::DeepNesting:
        return FileMessages::tr("nested too deeply");
    case QJsonParseError::DocumentTooLarge:
        return FileMessages::tr("too large for the JSON reader");
    case QJsonParseError::GarbageAtEnd:
        return FileMessages::tr("more text after the end of the JSON document");
    }
    return FileMessages::tr("not valid JSON");
}

bool isNumberChar(char c)
{
    return (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.' || c == 'e' || c == 'E';
}

/// The offset of the first '[' or '{' (outside strings) that opens a level deeper than
/// `limit`, or -1. Syntax is left to the parser; this only counts brackets, so that a hostile
/// file of a million '[' never reaches a recursive parser or a recursive destructor.
qsizetype tooDeep(const QByteArray& bytes, int limit)
{
    int depth = 0;
    bool inString = false;
    for (qsizetype i = 0; i < bytes.size(); ++i) {
        const char c = bytes[i];
        if (inString) {
            if (c == '\\') {
                ++i; // whatever is escaped cannot end the string
            } else if (c == '"') {
                inString = false;
            }
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > limit) {
                return i;
            }
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return -1;
}

} // namespace

ParsedJson parseJson(const QByteArray& bytes, const QString& sourceName, qint64 limit)
{
    ParsedJson result;
    if (bytes.size() > limit) {
        result.error = sourceName + FileMessages::tr(": too large: %1 bytes (the limit is %2 MiB)")
                                        .arg(bytes.size())
                                        .arg(limit / (1024 * 1024));
        return result;
    }
    if (bytes.trimmed().isEmpty()) {
        result.error = sourceName + FileMessages::tr(": line 1, column 1: the file is empty");
        return result;
    }
    if (const qsizetype deep = tooDeep(bytes, limits::kMaxJsonDepth); deep >= 0) {
        const auto [line, column] = lineAndColumn(bytes, deep);
        result.error = FileMessages::tr("%1: line %2, column %3: arrays and objects nested deeper "
                                        "than %4 levels (the limit)")
                           .arg(sourceName, QString::number(line), QString::number(column),
                                QString::number(limits::kMaxJsonDepth));
        return result;
    }
    QJsonParseError parseError;
    result.document = QJsonDocument::fromJson(bytes, &parseError);
    if (parseError.error == QJsonParseError::NoError) {
        result.ok = true;
        return result;
    }
    qsizetype offset = parseError.offset;
    QString what = describeParseError(parseError.error);
    if (parseError.error == QJsonParseError::IllegalNumber) {
        // Qt reports the end of the number; point at its start and quote it. JSON has no
        // infinity, so 1e999 (or 1e-999) lands here: say so rather than "illegal number".
        qsizetype start = std::min<qsizetype>(offset, bytes.size());
        while (start > 0 && isNumberChar(bytes[start - 1])) {
            --start;
        }
        if (start < offset) {
            what = FileMessages::tr("number %1 is not a finite double (out of range or malformed)")
                       .arg(QString::fromLatin1(bytes.mid(start, offset - start)));
            offset = start;
        } else { // a bare word: Qt took it for the start of a number
            what = describeParseError(QJsonParseError::IllegalValue);
        }
    }
    const auto [line, column] = lineAndColumn(bytes, offset);
    result.error = FileMessages::tr("%1: line %2, column %3: %4")
                       .arg(sourceName, QString::number(line), QString::number(column), what);
    return result;
}

} // namespace rigidlab::lessons::detail
