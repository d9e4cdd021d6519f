// SPDX-License-Identifier: GPL-3.0-or-later
// The scene format's rows (scene_schema.h): finding them, and what every row shares. The
// tables are in scene_schema_rows.cpp (scene, world, bodies) and scene_schema_links.cpp
// (springs, pins, a step's settings).

#include "format/scene_schema.h"
#include "format/scene_schema_rows.h"

#include <QCoreApplication>
#include <QHash>

#include <algorithm>

namespace rigidlab::lessons::schema {

using physics::BodyType;
using physics::Vec2;

std::span<const Field> fields(Object object)
{
    switch (object) {
    case Object::Scene:
        return rows::sceneRows();
    case Object::World:
        return rows::worldRows();
    case Object::Body:
        return rows::bodyRows();
    case Object::Spring:
        return rows::springRows();
    case Object::Joint:
        return rows::jointRows();
    }
    return {};
}

const Field* findField(Object object, std::string_view key)
{
    for (const Field& f : fields(object))
        if (f.key == key)
            return &f;
    return nullptr;
}

std::span<const Field> settings()
{
    static const std::vector<Field> table = [] {
        std::vector<Field> out;
        for (const Field& row : rows::worldRows()) {
            if (row.setting == 0)
                continue;
            Field f = row.stepRow ? *row.stepRow : row;
            f.setting = row.setting;
            f.optional = true; // a step that leaves it out keeps the scene's
            out.push_back(f);
        }
        std::stable_sort(out.begin(), out.end(),
                         [](const Field& a, const Field& b) { return a.setting < b.setting; });
        // The window's own after the world's.
        for (const Field& row : rows::windowSettingRows())
            out.push_back(row);
        return out;
    }();
    return table;
}

const Field* findSetting(std::string_view key)
{
    for (const Field& f : settings())
        if (f.key == key)
            return &f;
    return nullptr;
}

const Field* worldRowOf(const Field& setting)
{
    const Field* row = findField(Object::World, setting.key);
    return row && row->setting ? row : nullptr;
}

bool takes(const Field& row, const Value& value)
{
    switch (row.kind) {
    case Kind::Number:
        if (const double* d = std::get_if<double>(&value))
            return row.range.contains(*d);
        return false;
    case Kind::Integer:
        if (const int* i = std::get_if<int>(&value))
            return row.range.contains(*i);
        return false;
    case Kind::Vec2:
        if (const Vec2* v = std::get_if<Vec2>(&value))
            return row.range.contains(v->x()) && row.range.contains(v->y());
        return false;
    case Kind::Bool:
        return std::holds_alternative<bool>(value);
    case Kind::Choice:
        if (const QString* name = std::get_if<QString>(&value))
            return row.accepts(*name);
        return false;
    default:
        return false;
    }
}

QStringList keys(Object object)
{
    QStringList out;
    if (object == Object::Scene)
        out << QStringLiteral("rigidlab");
    for (const Field& f : fields(object))
        if (f.kind != Kind::Size)
            out << rows::fromView(f.key);
    if (object == Object::Scene)
        out << QStringLiteral("world") << QStringLiteral("bodies") << QStringLiteral("springs")
            << QStringLiteral("joints");
    return out;
}

const std::vector<std::string_view>& editorPropertyNames()
{
    static const std::vector<std::string_view> names = [] {
        std::vector<std::string_view> out;
        for (Object o : {Object::Body, Object::Spring, Object::World, Object::Scene})
            for (const Field& f : fields(o))
                if (f.inEditor && std::find(out.begin(), out.end(), f.key) == out.end())
                    out.push_back(f.key);
        return out;
    }();
    return names;
}

const std::vector<std::string_view>& stepControlNames()
{
    static const std::vector<std::string_view> names = [] {
        std::vector<std::string_view> out;
        for (const Field& f : settings())
            out.push_back(f.key);
        return out;
    }();
    return names;
}

std::size_t count(const Scene& scene, Object object)
{
    switch (object) {
    case Object::Scene:
    case Object::World:
        return 1;
    case Object::Body:
        return scene.bodies.size();
    case Object::Spring:
        return scene.springs.size();
    case Object::Joint:
        return scene.joints.size();
    }
    return 0;
}

QString placeOf(Object object, std::size_t index)
{
    switch (object) {
    case Object::Scene:
        return {};
    case Object::World:
        return QStringLiteral("world");
    case Object::Body:
        return detail::indexPlace(QStringLiteral("bodies"), static_cast<qsizetype>(index));
    case Object::Spring:
        return detail::indexPlace(QStringLiteral("springs"), static_cast<qsizetype>(index));
    case Object::Joint:
        return detail::indexPlace(QStringLiteral("joints"), static_cast<qsizetype>(index));
    }
    return {};
}

QString label(const Field& field, int component)
{
    const char* text = component == 1 && field.labelY ? field.labelY : field.label;
    return text ? QCoreApplication::translate(kContext, text) : QString();
}

Value defaultValue(const Field& field)
{
    // One object of each kind as its struct makes it: the defaults are stated there once.
    Scene scene;
    scene.bodies.emplace_back();
    scene.springs.emplace_back();
    scene.joints.emplace_back();
    return field.get ? field.get(scene, 0) : Value();
}

QString text(const Value& value)
{
    return std::visit(
        [](const auto& v) -> QString {
            using T = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<T, std::monostate>)
                return QStringLiteral("unset");
            else if constexpr (std::is_same_v<T, double>)
                return QString::number(v, 'g', 17);
            else if constexpr (std::is_same_v<T, int>)
                return QString::number(v);
            else if constexpr (std::is_same_v<T, bool>)
                return v ? QStringLiteral("true") : QStringLiteral("false");
            else if constexpr (std::is_same_v<T, Vec2>)
                return QStringLiteral("[%1, %2]")
                    .arg(QString::number(v.x(), 'g', 17), QString::number(v.y(), 'g', 17));
            else
                return u'"' + v + u'"';
        },
        value);
}

Value effective(const Scene& scene, const Field& field, std::size_t index)
{
    Value v = field.get(scene, index);
    if (std::holds_alternative<std::monostate>(v) && !field.fallback.empty())
        if (const Field* world = findField(Object::World, field.fallback))
            return world->get(scene, 0);
    return v;
}

QString bodyTypeName(BodyType type)
{
    // The names in files are the labels' English sources.
    for (const auto& [t, name] : rows::kBodyTypes)
        if (t == type)
            return QLatin1String(name);
    return {};
}

std::optional<BodyType> bodyTypeFromName(const QString& name)
{
    for (const auto& [type, label] : rows::kBodyTypes)
        if (name == QLatin1String(label))
            return type;
    return std::nullopt;
}

QString bodyTypeLabel(BodyType type)
{
    for (const auto& [t, label] : rows::kBodyTypes)
        if (t == type)
            return QCoreApplication::translate(kContext, label);
    return {};
}

QString safeFileStem(const QString& title, const QString& fallback)
{
    // Letters that do not decompose into a base letter and marks, as they are written in ASCII.
    static const QHash<QChar, QString> spelled{
        {QChar(0x00DF), QStringLiteral("ss")}, {QChar(0x00E6), QStringLiteral("ae")},
        {QChar(0x00F8), QStringLiteral("o")},  {QChar(0x0153), QStringLiteral("oe")},
        {QChar(0x0142), QStringLiteral("l")},  {QChar(0x0111), QStringLiteral("d")},
        {QChar(0x0131), QStringLiteral("i")},  {QChar(0x00F0), QStringLiteral("d")},
        {QChar(0x00FE), QStringLiteral("th")}};
    QString name;
    const auto append = [&name](QChar c) {
        if ((c >= u'a' && c <= u'z') || (c >= u'0' && c <= u'9'))
            name += c;
        else if (!name.isEmpty() && !name.endsWith(u'_'))
            name += u'_';
    };
    // Decomposed, a letter with a mark is the letter and the mark: the letter stays.
    for (const QChar c : title.toLower().normalized(QString::NormalizationForm_KD)) {
        if (c.category() == QChar::Mark_NonSpacing)
            continue; // the accent of "á", the caron of "č"
        if (const auto it = spelled.find(c); it != spelled.end())
            for (const QChar letter : *it)
                append(letter);
        else
            append(c);
    }
    // Long names are cut where a file system of a school computer still takes them whole.
    constexpr qsizetype kMaxStem = 60;
    name.truncate(kMaxStem);
    while (name.endsWith(u'_'))
        name.chop(1);
    return name.isEmpty() ? fallback : name;
}

QString safeFileName(const QString& title)
{
    return safeFileStem(title, QStringLiteral("scene")) + QStringLiteral(".json");
}

} // namespace rigidlab::lessons::schema
