// SPDX-License-Identifier: GPL-3.0-or-later
// Setting one field of a scene (scene_schema.h): the row says the key, the range and how to
// reach the value, so one function edits every field the format has, with the loader's words
// for what it refuses.

#include "edit/edit_support.h"

#include "format/json_reader.h"
#include "format/scene_loader.h"
#include "format/scene_rules.h"

#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/integrator.h"

#include <cmath>

namespace rigidlab::lessons::edit {

using namespace support;
using physics::BodyId;
using physics::Vec2;
using schema::Kind;
using schema::Object;
using schema::Value;

namespace {

QString keyText(std::string_view key)
{
    return QString::fromLatin1(key.data(), qsizetype(key.size()));
}

/// The name messages start with: the body's id, "world", "springs[2]", "scene".
QString sourceOf(const Scene& scene, Object object, std::size_t index)
{
    if (object == Object::Body)
        return bodyId(scene.bodies[index]);
    if (object == Object::Scene)
        return QStringLiteral("scene");
    return schema::placeOf(object, index);
}

/// A number typed for a number field (an int is a number too).
std::optional<double> numberOf(const Value& value)
{
    if (const double* d = std::get_if<double>(&value))
        return *d;
    if (const int* i = std::get_if<int>(&value))
        return *i;
    return std::nullopt;
}

/// Empty, or why `text` may not be a body's label (the loader's checks; empty removes it).
QString labelProblem(const QString& text)
{
    if (text.size() > kMaxBodyLabelLength)
        return detail::FileMessages::tr("longer than %1 characters").arg(kMaxBodyLabelLength);
    for (QChar c : text)
        if (c.category() == QChar::Other_Control)
            return detail::FileMessages::tr("must not hold control characters");
    return {};
}

/// Empty, or why `value` may not be field `f` of `scene` (object `index`): `value` is the
/// whole value, the pair with one component changed for a pair.
QString valueProblem(const Scene& scene, Object object, std::size_t index, const schema::Field& f,
                     const Value& value, const QString& place)
{
    const QString source = sourceOf(scene, object, index);
    const bool unset = std::holds_alternative<std::monostate>(value);
    if (unset)
        return f.optional ? QString()
                          : placedError(source, place, EditMessages::tr("must be given"));
    switch (f.kind) {
    case Kind::Number:
    case Kind::Size:
        if (const auto v = numberOf(value))
            return rangeError(source, place, *v, f.range);
        break;
    case Kind::Integer:
        if (const auto v = numberOf(value)) {
            if (std::isfinite(*v) && f.range.contains(*v) && *v != std::floor(*v))
                return placedError(source, place, EditMessages::tr("must be a whole number"));
            return rangeError(source, place, *v, f.range);
        }
        break;
    case Kind::Vec2:
        if (const Vec2* v = std::get_if<Vec2>(&value)) {
            for (int i = 0; i < 2; ++i)
                if (QString e =
                        rangeError(source, QStringLiteral("%1[%2]").arg(keyText(f.key)).arg(i),
                                   (*v)[i], f.range);
                    !e.isEmpty())
                    return e;
            return {};
        }
        break;
    case Kind::Bool:
        if (std::holds_alternative<bool>(value))
            return {};
        break;
    case Kind::Choice:
        if (const QString* name = std::get_if<QString>(&value))
            return f.accepts(*name) ? QString() : placedError(source, place, f.unknown(*name));
        break;
    case Kind::Text:
        if (const QString* id = std::get_if<QString>(&value)) {
            if (const QString problem = rules::idProblem(*id); !problem.isEmpty())
                return placedError(source, place, problem);
            for (size_t i = 0; i < scene.bodies.size(); ++i)
                if (i != index && bodyId(scene.bodies[i]) == *id)
                    return placedError(source, place, rules::duplicateId(*id, static_cast<int>(i)));
            return {};
        }
        break;
    case Kind::LocalText:
        if (const QString* text = std::get_if<QString>(&value))
            return object == Object::Body && !labelProblem(*text).isEmpty()
                       ? placedError(source, place, labelProblem(*text))
                       : QString();
        break;
    case Kind::Colour:
        if (const QString* colour = std::get_if<QString>(&value)) {
            const QString problem = rules::colourProblem(*colour);
            return problem.isEmpty() ? QString() : placedError(source, place, problem);
        }
        break;
    case Kind::End:
        if (const QString* id = std::get_if<QString>(&value))
            return scene.bodyIndex(*id) ? QString()
                                        : placedError(source, place,
                                                      detail::FileMessages::tr("no body with id "
                                                                               "\"%1\"")
                                                          .arg(*id));
        break;
    case Kind::Shape:
        return placedError(source, place,
                           EditMessages::tr("a shape is drawn, or changed through its sizes"));
    }
    return placedError(source, place, EditMessages::tr("not a value this field holds"));
}

/// Empty, or why the edited object may not stand: a body's placement and mass, a spring's or
/// pin's ends.
QString objectProblem(Scene& scene, Object object, std::size_t index, std::string_view key)
{
    const QString source = sourceOf(scene, object, index);
    if (object == Object::Body) {
        if (QString e = bodyProblem(scene.bodies[index]); !e.isEmpty())
            return e;
        if (key == "position" || key == "angle")
            return carryWorldPins(scene, static_cast<BodyId>(index));
    }
    if (object == Object::Spring) {
        const physics::SpringDef& s = scene.springs[index];
        if (s.a == physics::kWorld && s.b == physics::kWorld)
            return placedError(source, {}, rules::springBothInWorld());
        if (s.a == s.b)
            return placedError(source, QStringLiteral("b"), rules::springSameBody());
    }
    if (object == Object::Joint) {
        const physics::PinJointDef& j = scene.joints[index];
        if (j.a == physics::kWorld)
            return placedError(source, QStringLiteral("a"),
                               detail::FileMessages::tr("must be a body id, not null"));
        if (j.a == j.b)
            return placedError(source, QStringLiteral("b"), rules::pinSameBody());
    }
    return {};
}

} // namespace

EditResult setField(const Scene& scene, Object object, std::size_t index, std::string_view key,
                    const Value& value, int component)
{
    const schema::Field* f = schema::findField(object, key);
    if (!f || !f->set)
        return refused(EditMessages::tr("there is no property \"%1\"").arg(keyText(key)));
    if (index >= schema::count(scene, object))
        return refused(
            object == Object::Body
                ? noSuchBody(static_cast<BodyId>(index))
                : EditMessages::tr("there is no %1").arg(schema::placeOf(object, index)));
    QString place = keyText(key);
    if (f->kind == Kind::Size)
        place = QStringLiteral("shape.") + place;
    Value whole = value;
    if (f->kind == Kind::Vec2 && component >= 0) {
        Vec2 v = std::get<Vec2>(f->get(scene, index));
        v[component] = numberOf(value).value_or(std::nan(""));
        whole = v;
        place = QStringLiteral("%1[%2]").arg(place).arg(component);
    }
    if (QString e = valueProblem(scene, object, index, *f, whole, place); !e.isEmpty())
        return refused(e);
    if (f->kind == Kind::Integer)
        whole = static_cast<int>(*numberOf(whole));
    Scene out = scene;
    f->set(out, index, whole);
    if (QString e = objectProblem(out, object, index, key); !e.isEmpty())
        return refused(e);
    return accepted(std::move(out),
                    object == Object::Body ? static_cast<BodyId>(index) : physics::kWorld);
}

EditResult setBodyNumber(const Scene& scene, BodyId body, BodyNumber what, double value)
{
    struct Row {
        std::string_view key;
        int component;
    };
    static constexpr Row kRows[] = {
        {"position", 0}, {"position", 1},         {"angle", -1},    {"density", -1},
        {"mass", -1},    {"restitution", -1},     {"friction", -1}, {"velocity", 0},
        {"velocity", 1}, {"angularVelocity", -1},
    };
    if (!validBody(scene, body))
        return refused(noSuchBody(body));
    const Row& row = kRows[static_cast<int>(what)];
    return setField(scene, Object::Body, static_cast<size_t>(body), row.key, value, row.component);
}

EditResult setBodyType(const Scene& scene, BodyId body, physics::BodyType type)
{
    if (!validBody(scene, body))
        return refused(noSuchBody(body));
    return setField(scene, Object::Body, static_cast<size_t>(body), "type",
                    schema::bodyTypeName(type));
}

EditResult setBodyVelocity(const Scene& scene, BodyId body, const Vec2& velocity)
{
    if (!validBody(scene, body))
        return refused(noSuchBody(body));
    return setField(scene, Object::Body, static_cast<size_t>(body), "velocity", velocity);
}

EditResult setBodyColour(const Scene& scene, BodyId body, const QString& colour)
{
    if (!validBody(scene, body))
        return refused(noSuchBody(body));
    return setField(scene, Object::Body, static_cast<size_t>(body), "colour",
                    colour.isEmpty() ? Value() : Value(colour));
}

EditResult setBodyId(const Scene& scene, BodyId body, const QString& id)
{
    if (!validBody(scene, body))
        return refused(noSuchBody(body));
    return setField(scene, Object::Body, static_cast<size_t>(body), "id", id);
}

EditResult setSpringNumber(const Scene& scene, int spring, SpringNumber what, double value)
{
    if (spring < 0 || static_cast<size_t>(spring) >= scene.springs.size())
        return refused(EditMessages::tr("there is no spring number %1").arg(spring));
    static constexpr std::string_view kKeys[] = {"stiffness", "damping", "restLength"};
    return setField(scene, Object::Spring, static_cast<size_t>(spring),
                    kKeys[static_cast<int>(what)], value);
}

EditResult setWorldNumber(const Scene& scene, WorldNumber what, double value)
{
    switch (what) {
    case WorldNumber::GravityX:
    case WorldNumber::GravityY:
        return setField(scene, Object::World, 0, "gravity", value,
                        what == WorldNumber::GravityX ? 0 : 1);
    case WorldNumber::Dt:
        return setField(scene, Object::World, 0, "dt", value);
    case WorldNumber::Iterations:
        break;
    }
    return setField(scene, Object::World, 0, "iterations", value);
}

EditResult setIntegrator(const Scene& scene, physics::IntegratorKind kind)
{
    const std::string_view name = physics::integratorName(kind);
    return setField(scene, Object::World, 0, "integrator",
                    QString::fromLatin1(name.data(), qsizetype(name.size())));
}

EditResult setSolver(const Scene& scene, physics::SolverKind kind)
{
    const std::string_view name = physics::solverName(kind);
    return setField(scene, Object::World, 0, "solver",
                    QString::fromLatin1(name.data(), qsizetype(name.size())));
}

} // namespace rigidlab::lessons::edit
