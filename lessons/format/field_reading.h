// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reading one schema row (scene_schema.h) of the plain kinds, numbers, pairs, flags and
// choices, from a JSON object: the same words for a scene's world, a body, a spring and a
// lesson step's settings. The other kinds (ids, texts, shapes, ends) are the scene reader's.

#include "format/json_reader.h"
#include "format/scene_schema.h"

namespace rigidlab::lessons::detail {

/// Reads `field` from `object` at `place` into `out`: unset when the key is absent (fine unless
/// the row is required) or the kind is not plain (left to the caller).
template <class Target>
bool readPlainValue(JsonReader& in, const schema::FieldOf<Target>& field, const QJsonObject& object,
                    const QString& place, schema::Value& out)
{
    using schema::Kind;
    const QString key = QString::fromLatin1(field.key.data(), qsizetype(field.key.size()));
    if (!object.contains(key) && !field.required)
        return true;
    switch (field.kind) {
    case Kind::Number: {
        double v = 0;
        if (!in.number(object, key, place, v, field.rule, field.range, field.required))
            return false;
        out = v;
        return true;
    }
    case Kind::Integer: {
        int v = 0;
        if (!in.integer(object, key, place, v, static_cast<int>(field.range.min),
                        static_cast<int>(field.range.max), field.required))
            return false;
        out = v;
        return true;
    }
    case Kind::Vec2: {
        physics::Vec2 v = physics::Vec2::Zero();
        if (!in.vec2(object, key, place, v, field.range, field.required))
            return false;
        out = v;
        return true;
    }
    case Kind::Bool: {
        bool v = false;
        if (!in.boolean(object, key, place, v, field.required))
            return false;
        out = v;
        return true;
    }
    case Kind::Choice: {
        QString name;
        if (!in.string(object, key, place, name, field.required))
            return false;
        if (!field.accepts(name))
            return in.fail(joinPlace(place, key), field.unknown(name));
        out = name;
        return true;
    }
    default:
        return true;
    }
}

/// Reads `field` from `object` at `place` into `target` (object `index`). An absent key is
/// fine unless the row is required; a kind that is not plain is left to the caller (true).
template <class Target>
bool readPlainField(JsonReader& in, const schema::FieldOf<Target>& field, const QJsonObject& object,
                    const QString& place, Target& target, std::size_t index)
{
    schema::Value v;
    if (!readPlainValue(in, field, object, place, v))
        return false;
    if (!std::holds_alternative<std::monostate>(v))
        field.set(target, index, v);
    return true;
}

} // namespace rigidlab::lessons::detail
