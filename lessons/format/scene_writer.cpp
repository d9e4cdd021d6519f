// SPDX-License-Identifier: GPL-3.0-or-later
// Scene files, format v1: writing. Keys in the order of SCENE_FORMAT.md, one body, spring or
// joint a line, so that a saved file reads like a shipped one.

#include "format/scene_writer.h"

#include "format/atomic_file.h"
#include "format/languages.h"
#include "format/scene_loader.h"

#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/integrator.h"
#include "rigidlab/physics/shape.h"

#include <QJsonArray>
#include <QJsonDocument>

#include <charconv>
#include <string_view>

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

QByteArray string(std::string_view text)
{
    return string(QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size())));
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
    const QString code = texts.contains(language) ? language : kFallbackLanguage.toString();
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

QByteArray worldObject(const physics::WorldDef& w)
{
    QByteArray out = "{\n";
    QByteArrayList lines;
    const auto add = [&lines](const char* key, const QByteArray& value) {
        lines << QByteArray("    \"" + QByteArray(key) + "\": " + value);
    };
    add("gravity", vec2(w.gravity));
    add("dt", number(w.dt));
    add("integrator", string(physics::integratorName(w.integrator)));
    add("solver", string(physics::solverName(w.solver)));
    add("iterations", QByteArray::number(w.iterations));
    add("restitution", number(w.restitution));
    add("friction", number(w.friction));
    add("gravitation", number(w.gravitation));
    add("drag", number(w.drag));
    add("continuous", w.continuous ? "true" : "false");
    // The format has one tolerance for both; a scene read from a file has them equal.
    add("tolerance", number(w.tolerances.absolute));
    if (w.sleep)
        add("sleep", *w.sleep ? "true" : "false");
    return out + lines.join(",\n") + "\n  }";
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

QByteArray bodyType(physics::BodyType type)
{
    switch (type) {
    case physics::BodyType::Static:
        return "\"static\"";
    case physics::BodyType::Kinematic:
        return "\"kinematic\"";
    case physics::BodyType::Dynamic:
        break;
    }
    return "\"dynamic\"";
}

QByteArray bodyObject(const Scene& scene, std::size_t i)
{
    const physics::BodyDef& b = scene.bodies[i];
    static const std::vector<Vec2> none;
    Line line;
    line.add("id", string(b.name)).add("type", bodyType(b.type));
    line.add(
        "shape",
        shapeObject(b.shape, i < scene.originalVertices.size() ? scene.originalVertices[i] : none));
    line.add("position", vec2(b.position)).add("angle", number(b.angle));
    if (b.velocity != Vec2::Zero())
        line.add("velocity", vec2(b.velocity));
    if (b.angularVelocity != 0)
        line.add("angularVelocity", number(b.angularVelocity));
    if (b.mass > 0)
        line.add("mass", number(b.mass));
    else
        line.add("density", number(b.density));
    if (b.restitution >= 0)
        line.add("restitution", number(b.restitution));
    if (b.friction >= 0)
        line.add("friction", number(b.friction));
    if (!b.collide)
        line.add("collide", "false");
    if (const QString colour = scene.colourOf(i); !colour.isEmpty())
        line.add("colour", string(colour));
    return line.object();
}

/// A spring's or joint's end: the body's id, or null for the world.
QByteArray end(const Scene& scene, physics::BodyId body)
{
    if (body == physics::kWorld || body < 0 ||
        static_cast<std::size_t>(body) >= scene.bodies.size())
        return "null";
    return string(scene.bodies[static_cast<std::size_t>(body)].name);
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
    QByteArrayList bodies, springs, joints;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
        bodies << bodyObject(scene, i);
    for (const physics::SpringDef& s : scene.springs)
        springs << Line()
                       .add("a", end(scene, s.a))
                       .add("anchorA", vec2(s.anchorA))
                       .add("b", end(scene, s.b))
                       .add("anchorB", vec2(s.anchorB))
                       .add("stiffness", number(s.stiffness))
                       .add("damping", number(s.damping))
                       .add("restLength", number(s.restLength))
                       .object();
    for (const physics::PinJointDef& j : scene.joints)
        joints << Line()
                      .add("type", "\"pin\"")
                      .add("a", end(scene, j.a))
                      .add("anchorA", vec2(j.anchorA))
                      .add("b", end(scene, j.b))
                      .add("anchorB", vec2(j.anchorB))
                      .object();

    QByteArrayList top;
    top << "\"rigidlab\": " + QByteArray::number(kSceneFormatVersion);
    top << "\"title\": " + localText(scene.title, scene.titles, scene.language);
    if (!scene.description.isEmpty() || !scene.descriptions.isEmpty())
        top << "\"description\": " +
                   localText(scene.description, scene.descriptions, scene.language);
    top << "\"world\": " + worldObject(scene.world);
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
        all[all.contains(language) ? language : kFallbackLanguage.toString()] = text;
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
