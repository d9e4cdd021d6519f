// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/json_reader.h"
#include "format/view_text.h"
#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/integrator.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonParseError>
#include <QLocale>

#include <cmath>

namespace rigidlab::lessons::detail {

QString joinPlace(const QString& place, QStringView key)
{
    return place.isEmpty() ? key.toString() : place + u'.' + key.toString();
}

QString indexPlace(const QString& place, qsizetype index)
{
    return place + u'[' + QString::number(index) + u']';
}

QString formatNumber(double value)
{
    return QString::number(value, 'g', QLocale::FloatingPointShortest);
}

QString describeJson(const QJsonValue& value)
{
    switch (value.type()) {
    case QJsonValue::Null:
        return QStringLiteral("null");
    case QJsonValue::Bool:
        return value.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    case QJsonValue::Double:
        return formatNumber(value.toDouble());
    case QJsonValue::String: {
        QString s = value.toString();
        if (s.size() > 40) {
            s = s.left(40) + QStringLiteral("...");
        }
        return u'"' + s + u'"';
    }
    case QJsonValue::Array:
        return FileMessages::tr("an array");
    case QJsonValue::Object:
        return FileMessages::tr("an object");
    case QJsonValue::Undefined:
        break;
    }
    return QStringLiteral("nothing");
}

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

QString describeRange(const limits::Range& range)
{
    QString text =
        FileMessages::tr("from %1 to %2").arg(formatNumber(range.min), formatNumber(range.max));
    if (!range.unit.empty())
        text += u' ' + textFromView(range.unit);
    return text;
}

QString unknownIntegrator(const QString& name)
{
    QStringList names;
    for (const physics::IntegratorInfo& info : physics::kIntegrators)
        names.append(textFromView(info.name));
    return FileMessages::tr("unknown integrator \"%1\" (expected %2)").arg(name, names.join(u", "));
}

QString unknownSolver(const QString& name)
{
    QStringList names;
    for (auto k : {physics::SolverKind::PaperImpulse, physics::SolverKind::SequentialImpulse,
                   physics::SolverKind::SoftStep})
        names.append(textFromView(physics::solverName(k)));
    return FileMessages::tr("unknown solver \"%1\" (expected %2)").arg(name, names.join(u", "));
}

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

namespace {

/// A message as one line: what the file put in it (a key, an id, a name) may hold line breaks
/// and other control characters, which are shown escaped, as JSON writes them.
QString oneLine(const QString& message)
{
    QString out;
    out.reserve(message.size());
    for (const QChar c : message) {
        const char16_t u = c.unicode();
        if (u == u'\n') {
            out += QStringLiteral("\\n");
        } else if (u == u'\r') {
            out += QStringLiteral("\\r");
        } else if (u == u'\t') {
            out += QStringLiteral("\\t");
        } else if (u < 0x20 || u == 0x7f || u == 0x2028 || u == 0x2029) {
            out += QStringLiteral("\\u%1").arg(static_cast<int>(u), 4, 16, QLatin1Char('0'));
        } else {
            out += c;
        }
    }
    return out;
}

} // namespace

bool JsonReader::fail(const QString& place, const QString& what)
{
    if (m_error.isEmpty()) {
        m_error = oneLine(place.isEmpty() ? m_source + QStringLiteral(": ") + what
                                          : m_source + QStringLiteral(": ") + place +
                                                QStringLiteral(": ") + what);
    }
    return false;
}

void JsonReader::warn(const QString& place, const QString& what)
{
    m_warnings.append(
        oneLine(m_source + QStringLiteral(": ") + place + QStringLiteral(": ") + what));
}

bool JsonReader::checkKeys(const QJsonObject& object, const QString& place,
                           std::initializer_list<QStringView> allowed)
{
    QStringList names;
    for (QStringView a : allowed) {
        names.append(a.toString());
    }
    return checkKeys(object, place, names);
}

bool JsonReader::checkKeys(const QJsonObject& object, const QString& place,
                           const QStringList& allowed)
{
    if (failed()) {
        return false;
    }
    // QJsonObject iterates its keys sorted: with several unknown keys, the first in
    // alphabetical order is reported, whatever their order in the file.
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (!allowed.contains(it.key())) {
            return fail(
                joinPlace(place, it.key()),
                FileMessages::tr("unknown key (allowed here: %1)").arg(allowed.join(u", ")));
        }
    }
    return true;
}

bool JsonReader::asObject(const QJsonValue& value, const QString& place, QJsonObject& out)
{
    if (failed()) {
        return false;
    }
    if (!value.isObject()) {
        return fail(place, FileMessages::tr("must be an object {...}, got ") + describeJson(value));
    }
    out = value.toObject();
    return true;
}

bool JsonReader::formatVersion(const QJsonObject& root, const QString& key, const QString& document,
                               int version)
{
    const auto it = root.constFind(key);
    if (it == root.constEnd()) {
        return fail(key, FileMessages::tr("missing: %1 starts with \"%2\": %3 (the format version)")
                             .arg(document, key)
                             .arg(version));
    }
    if (!it.value().isDouble() || it.value().toDouble() != version) {
        return fail(key, FileMessages::tr("unsupported format version %1 (this RigidLab reads "
                                          "version %2)")
                             .arg(describeJson(it.value()), QString::number(version)));
    }
    return true;
}

bool JsonReader::asArray(const QJsonValue& value, const QString& place, QJsonArray& out)
{
    if (failed()) {
        return false;
    }
    if (!value.isArray()) {
        return fail(place, FileMessages::tr("must be an array [...], got ") + describeJson(value));
    }
    out = value.toArray();
    return true;
}

bool JsonReader::numberValue(const QJsonValue& value, const QString& place, double& out,
                             NumberRule rule)
{
    if (failed()) {
        return false;
    }
    const auto expected = [rule]() -> QString {
        switch (rule) {
        case NumberRule::Finite:
            return FileMessages::tr("must be a number");
        case NumberRule::Positive:
            return FileMessages::tr("must be a positive number");
        case NumberRule::NonNegative:
            return FileMessages::tr("must be a number >= 0");
        case NumberRule::UnitInterval:
            return FileMessages::tr("must be a number from 0 to 1");
        }
        return {};
    };
    if (!value.isDouble()) {
        return fail(place, expected() + FileMessages::tr(", got ") + describeJson(value));
    }
    const double v = value.toDouble();
    bool good = std::isfinite(v);
    switch (rule) {
    case NumberRule::Finite:
        break;
    case NumberRule::Positive:
        good = good && v > 0;
        break;
    case NumberRule::NonNegative:
        good = good && v >= 0;
        break;
    case NumberRule::UnitInterval:
        good = good && v >= 0 && v <= 1;
        break;
    }
    if (!good) {
        return fail(place, expected() + FileMessages::tr(", got ") + formatNumber(v));
    }
    out = v;
    return true;
}

bool JsonReader::vec2Value(const QJsonValue& value, const QString& place, physics::Vec2& out)
{
    if (failed()) {
        return false;
    }
    if (!value.isArray() || value.toArray().size() != 2) {
        const QString got =
            value.isArray()
                ? FileMessages::tr("an array of %1 elements").arg(value.toArray().size())
                : describeJson(value);
        return fail(place, FileMessages::tr("must be a pair of numbers [x, y], got ") + got);
    }
    const QJsonArray pair = value.toArray();
    double x = 0;
    double y = 0;
    if (!numberValue(pair[0], indexPlace(place, 0), x) ||
        !numberValue(pair[1], indexPlace(place, 1), y)) {
        return false;
    }
    out = physics::Vec2(x, y);
    return true;
}

namespace {

/// The value at `key`, or nullopt when absent.
std::optional<QJsonValue> lookUp(const QJsonObject& object, QStringView key)
{
    const auto it = object.constFind(key);
    if (it == object.constEnd()) {
        return std::nullopt;
    }
    return it.value();
}

} // namespace

bool JsonReader::number(const QJsonObject& object, QStringView key, const QString& place,
                        double& out, NumberRule rule, bool required)
{
    if (failed()) {
        return false;
    }
    const auto value = lookUp(object, key);
    if (!value) {
        return !required || fail(joinPlace(place, key), FileMessages::tr("required, but missing"));
    }
    return numberValue(*value, joinPlace(place, key), out, rule);
}

bool JsonReader::integer(const QJsonObject& object, QStringView key, const QString& place, int& out,
                         int min, int max, bool required)
{
    if (failed()) {
        return false;
    }
    const auto value = lookUp(object, key);
    const QString at = joinPlace(place, key);
    if (!value) {
        return !required || fail(at, FileMessages::tr("required, but missing"));
    }
    const QString expected =
        FileMessages::tr("must be a whole number from %1 to %2").arg(min).arg(max);
    if (!value->isDouble()) {
        return fail(at, expected + FileMessages::tr(", got ") + describeJson(*value));
    }
    const double v = value->toDouble();
    if (!std::isfinite(v) || v != std::floor(v) || v < min || v > max) {
        return fail(at, expected + FileMessages::tr(", got ") + formatNumber(v));
    }
    out = static_cast<int>(v);
    return true;
}

bool JsonReader::string(const QJsonObject& object, QStringView key, const QString& place,
                        QString& out, bool required)
{
    if (failed()) {
        return false;
    }
    const auto value = lookUp(object, key);
    const QString at = joinPlace(place, key);
    if (!value) {
        return !required || fail(at, FileMessages::tr("required, but missing"));
    }
    if (!value->isString()) {
        return fail(at, FileMessages::tr("must be a string \"...\", got ") + describeJson(*value));
    }
    out = value->toString();
    return true;
}

bool JsonReader::boolean(const QJsonObject& object, QStringView key, const QString& place,
                         bool& out, bool required)
{
    if (failed()) {
        return false;
    }
    const auto value = lookUp(object, key);
    const QString at = joinPlace(place, key);
    if (!value) {
        return !required || fail(at, FileMessages::tr("required, but missing"));
    }
    if (!value->isBool()) {
        return fail(at, FileMessages::tr("must be true or false, got ") + describeJson(*value));
    }
    out = value->toBool();
    return true;
}

bool JsonReader::vec2(const QJsonObject& object, QStringView key, const QString& place,
                      physics::Vec2& out, bool required)
{
    if (failed()) {
        return false;
    }
    const auto value = lookUp(object, key);
    if (!value) {
        return !required || fail(joinPlace(place, key), FileMessages::tr("required, but missing"));
    }
    return vec2Value(*value, joinPlace(place, key), out);
}

bool JsonReader::checkRange(double value, const QString& place, const limits::Range& range)
{
    if (failed()) {
        return false;
    }
    if (!range.contains(value)) {
        return fail(
            place,
            FileMessages::tr("must be %1, got %2").arg(describeRange(range), formatNumber(value)));
    }
    return true;
}

bool JsonReader::number(const QJsonObject& object, QStringView key, const QString& place,
                        double& out, NumberRule rule, const limits::Range& range, bool required)
{
    const bool present = object.contains(key);
    return number(object, key, place, out, rule, required) &&
           (!present || checkRange(out, joinPlace(place, key), range));
}

bool JsonReader::vec2Value(const QJsonValue& value, const QString& place, physics::Vec2& out,
                           const limits::Range& range)
{
    physics::Vec2 v = out;
    if (!vec2Value(value, place, v) || !checkRange(v.x(), indexPlace(place, 0), range) ||
        !checkRange(v.y(), indexPlace(place, 1), range)) {
        return false;
    }
    out = v;
    return true;
}

bool JsonReader::vec2(const QJsonObject& object, QStringView key, const QString& place,
                      physics::Vec2& out, const limits::Range& range, bool required)
{
    if (failed()) {
        return false;
    }
    const auto value = lookUp(object, key);
    if (!value) {
        return !required || fail(joinPlace(place, key), FileMessages::tr("required, but missing"));
    }
    return vec2Value(*value, joinPlace(place, key), out, range);
}

} // namespace rigidlab::lessons::detail
