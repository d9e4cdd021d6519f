// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/json_reader.h"
#include "format/view_text.h"
#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/integrator.h"

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
