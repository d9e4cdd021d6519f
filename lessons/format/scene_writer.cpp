// SPDX-License-Identifier: GPL-3.0-or-later
// Scene files, format v1: writing. Keys in the order of SCENE_FORMAT.md, one body, spring or
// joint a line, so that a saved file reads like a shipped one.

#include "format/scene_writer.h"

#include "format/atomic_file.h"
#include "format/languages.h"
#include "format/scene_loader.h"
#include "format/scene_schema.h"

#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/integrator.h"
#include "rigidlab/physics/shape.h"

#include <QJsonArray>
#include <QJsonDocument>

#include <charconv>
#include <string_view>
#include <type_traits>
#include <variant>

namespace rigidlab::lessons {

namespace {

using physics::Vec2;

/// The shortest text that reads back to the same double, always with the decimal point
/// (std::to_chars ignores the locale).
QByteArray number(double x)
{
    char buffer[64];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, x);
    return QByteArray(buffer, static_cast<qsizetype>(r.ptr - buffer));
}

QByteArray vec2(const Vec2& v)
{
    return '[' + number(v.x()) + ", " + number(v.y()) + ']';
}

/// A JSON string literal, escaped as the JSON writer escapes it.
QByteArray string(const QString& text)
{
    const QByteArray array = QJsonDocument(QJsonArray{text}).toJson(QJsonDocument::Compact);
    return array.mid(1, array.size() - 2); // without [ ]
}

/// `"key": value` pairs joined into one object on one line.
class Line {
public:
    Line& add(const char* key, const QByteArray& value)
    {
        m_parts << QByteArray('"' + QByteArray(key) + "\": " + value);
        return *this;
    }
    QByteArray object() const { return '{' + m_parts.join(", ") + '}'; }

private:
    QByteArrayList m_parts;
};

/// A text that is shown as `shown`: a plain string, or the object of languages with `shown` in
/// the language it is shown in (so that an edit of the shown text is kept).
QByteArray localText(const QString& shown, const LocalTextMap& all, const QString& language)
{
    if (all.isEmpty())
        return string(shown);
    LocalTextMap texts = all;
    const QString code = textLanguage(language, texts.keys());
    texts[code] = shown;
    // In the order of the shipped languages (English first), as the shipped files have them.
    QByteArrayList parts;
    for (const Language& l : kLanguages) {
        const QString c = l.code.toString();
        if (texts.contains(c))
            parts << QByteArray(string(c) + ": " + string(texts.value(c)));
    }
    return '{' + parts.join(", ") + '}';
}

QByteArray vertexList(const std::vector<Vec2>& vertices)
{
    QByteArrayList parts;
    for (const Vec2& v : vertices)
        parts << vec2(v);
    return '[' + parts.join(", ") + ']';
}

/// A box if the polygon is exactly the one a box of the format builds, else its vertices (the
/// file's own where the loader replaced them by their hull).
QByteArray shapeObject(const physics::Shape& shape, const std::vector<Vec2>& original)
{
    if (const physics::Circle* c = shape.asCircle())
        return Line().add("type", "\"circle\"").add("radius", number(c->radius)).object();
    const physics::Polygon& p = *shape.asPolygon();
    if (!original.empty())
        return Line().add("type", "\"polygon\"").add("vertices", vertexList(original)).object();
    if (p.vertices.size() == 4) {
        const double width = 2 * p.vertices[2].x();
        const double height = 2 * p.vertices[2].y();
        const physics::Polygon box = physics::makeBox(width, height);
        if (box.vertices == p.vertices && box.normals == p.normals)
            return Line()
                .add("type", "\"box\"")
                .add("width", number(width))
                .add("height", number(height))
                .object();
    }
    return Line().add("type", "\"polygon\"").add("vertices", vertexList(p.vertices)).object();
}

/// A value of a plain kind as JSON.
QByteArray json(const schema::Value& value)
{
    return std::visit(
        [](const auto& v) -> QByteArray {
            using T = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<T, std::monostate>)
                return "null";
            else if constexpr (std::is_same_v<T, double>)
                return number(v);
            else if constexpr (std::is_same_v<T, int>)
                return QByteArray::number(v);
            else if constexpr (std::is_same_v<T, bool>)
                return v ? "true" : "false";
            else if constexpr (std::is_same_v<T, Vec2>)
                return vec2(v);
            else
                return string(v);
        },
        value);
}

/// The JSON of `field` of object `index`.
QByteArray fieldJson(const Scene& scene, const schema::Field& field, std::size_t i)
{
    static const std::vector<Vec2> none;
    switch (field.kind) {
    case schema::Kind::LocalText:
        return localText(std::get<QString>(field.get(scene, i)), field.texts(scene, i),
                         scene.language);
    case schema::Kind::Shape:
        return shapeObject(scene.bodies[i].shape,
                           i < scene.originalVertices.size() ? scene.originalVertices[i] : none);
    default:
        return json(field.get(scene, i));
    }
}

/// The `"key": value` pairs of the fields of `object` the file holds, in file order.
QByteArrayList pairs(const Scene& scene, schema::Object object, std::size_t i)
{
    QByteArrayList out, last;
    for (const schema::Field& f : schema::fields(object)) {
        if (f.kind == schema::Kind::Size || (f.written && !f.written(scene, i)))
            continue;
        (f.writtenLast ? last : out)
            << QByteArray('"' + QByteArray(f.key.data(), qsizetype(f.key.size())) +
                          "\": " + fieldJson(scene, f, i));
    }
    return out + last;
}

QByteArray worldObject(const Scene& scene)
{
    return "{\n    " + pairs(scene, schema::Object::World, 0).join(",\n    ") + "\n  }";
}

QByteArray lineObject(const Scene& scene, schema::Object object, std::size_t i)
{
    return '{' + pairs(scene, object, i).join(", ") + '}';
}

QByteArray list(const QByteArrayList& items)
{
    if (items.isEmpty())
        return "[]";
    return "[\n    " + items.join(",\n    ") + "\n  ]";
}

} // namespace

QByteArray sceneToJson(const Scene& scene)
{
    using schema::Object;
    QByteArrayList bodies, springs, joints;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
        bodies << lineObject(scene, Object::Body, i);
    for (std::size_t i = 0; i < scene.springs.size(); ++i)
        springs << lineObject(scene, Object::Spring, i);
    for (std::size_t i = 0; i < scene.joints.size(); ++i)
        joints << lineObject(scene, Object::Joint, i);

    QByteArrayList top;
    top << "\"rigidlab\": " + QByteArray::number(kSceneFormatVersion);
    top << pairs(scene, Object::Scene, 0);
    top << "\"world\": " + worldObject(scene);
    top << "\"bodies\": " + list(bodies);
    if (!springs.isEmpty())
        top << "\"springs\": " + list(springs);
    if (!joints.isEmpty())
        top << "\"joints\": " + list(joints);
    return "{\n  " + top.join(",\n  ") + "\n}\n";
}

namespace {

void setShown(QString& shown, LocalTextMap& all, const QString& language, const QString& text)
{
    shown = text;
    if (!all.isEmpty())
        all[textLanguage(language, all.keys())] = text;
}

} // namespace

void setSceneTitle(Scene& scene, const QString& text)
{
    setShown(scene.title, scene.titles, scene.language, text);
}

void setSceneDescription(Scene& scene, const QString& text)
{
    setShown(scene.description, scene.descriptions, scene.language, text);
}

QString saveScene(const QString& path, const Scene& scene)
{
    return writeFileAtomically(path, sceneToJson(scene));
}

} // namespace rigidlab::lessons
