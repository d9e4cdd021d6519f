// SPDX-License-Identifier: GPL-3.0-or-later
// The scene format's rows (scene_schema.h). Each table is data: a key, a label, a kind, a range,
// and the accessors that reach the value in a Scene or a lesson step's settings.

#include "format/scene_schema.h"

#include "format/scene_writer.h"

#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/integrator.h"
#include "rigidlab/physics/shape.h"

#include <QCoreApplication>

#include <algorithm>
#include <array>
#include <type_traits>

namespace rigidlab::lessons::schema {

namespace {

using physics::BodyDef;
using physics::BodyType;
using physics::Vec2;
using R = detail::NumberRule;

QString fromView(std::string_view s)
{
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

// --- Accessors of a member of the world, a body, a spring or a joint ---------------------------

template <class T> T as(const Value& v)
{
    if constexpr (std::is_same_v<T, double>) {
        // An integer typed for a number is the number.
        if (const int* i = std::get_if<int>(&v))
            return *i;
    }
    return std::get<T>(v);
}

template <auto Member> Value worldGet(const Scene& s, std::size_t)
{
    return Value(s.world.*Member);
}
template <auto Member> void worldSet(Scene& s, std::size_t, const Value& v)
{
    using T = std::remove_cvref_t<decltype(s.world.*Member)>;
    s.world.*Member = as<T>(v);
}
template <auto Member> Value bodyGet(const Scene& s, std::size_t i)
{
    return Value(s.bodies[i].*Member);
}
template <auto Member> void bodySet(Scene& s, std::size_t i, const Value& v)
{
    using T = std::remove_cvref_t<decltype(s.bodies[i].*Member)>;
    s.bodies[i].*Member = as<T>(v);
}
template <auto Member> Value springGet(const Scene& s, std::size_t i)
{
    return Value(s.springs[i].*Member);
}
template <auto Member> void springSet(Scene& s, std::size_t i, const Value& v)
{
    using T = std::remove_cvref_t<decltype(s.springs[i].*Member)>;
    s.springs[i].*Member = as<T>(v);
}
template <auto Member> Value jointGet(const Scene& s, std::size_t i)
{
    return Value(s.joints[i].*Member);
}
template <auto Member> void jointSet(Scene& s, std::size_t i, const Value& v)
{
    using T = std::remove_cvref_t<decltype(s.joints[i].*Member)>;
    s.joints[i].*Member = as<T>(v);
}

/// physics::BodyDef's "< 0: the world's" as an unset value.
template <double BodyDef::*Member> Value bodyOptionalGet(const Scene& s, std::size_t i)
{
    const double x = s.bodies[i].*Member;
    return x >= 0 ? Value(x) : Value();
}
template <double BodyDef::*Member> void bodyOptionalSet(Scene& s, std::size_t i, const Value& v)
{
    s.bodies[i].*Member = std::holds_alternative<std::monostate>(v) ? -1.0 : as<double>(v);
}
template <double BodyDef::*Member> bool bodyOptionalWritten(const Scene& s, std::size_t i)
{
    return s.bodies[i].*Member >= 0;
}

/// An end: the body's id, unset for the world.
Value endValue(const Scene& s, physics::BodyId end)
{
    if (end < 0 || static_cast<std::size_t>(end) >= s.bodies.size())
        return {};
    return fromView(s.bodies[static_cast<std::size_t>(end)].name);
}
/// The body named by its id, or by its index (the loader's, which knows it already).
physics::BodyId endFrom(const Scene& s, const Value& v)
{
    if (const int* index = std::get_if<int>(&v))
        return *index;
    const QString* id = std::get_if<QString>(&v);
    if (!id)
        return physics::kWorld;
    return s.bodyIndex(*id).value_or(physics::kWorld);
}
template <auto Member> Value springEndGet(const Scene& s, std::size_t i)
{
    return endValue(s, s.springs[i].*Member);
}
template <auto Member> void springEndSet(Scene& s, std::size_t i, const Value& v)
{
    s.springs[i].*Member = endFrom(s, v);
}
template <auto Member> Value jointEndGet(const Scene& s, std::size_t i)
{
    return endValue(s, s.joints[i].*Member);
}
template <auto Member> void jointEndSet(Scene& s, std::size_t i, const Value& v)
{
    s.joints[i].*Member = endFrom(s, v);
}

template <class List> auto entry(const List& list, std::size_t i)
{
    return i < list.size() ? list[i] : typename List::value_type{};
}

// --- Choices -------------------------------------------------------------------------------------

constexpr std::array<std::pair<BodyType, const char*>, 3> kBodyTypes{{
    {BodyType::Dynamic, QT_TRANSLATE_NOOP("SceneSchema", "dynamic")},
    {BodyType::Static, QT_TRANSLATE_NOOP("SceneSchema", "static")},
    {BodyType::Kinematic, QT_TRANSLATE_NOOP("SceneSchema", "kinematic")},
}};

bool isIntegrator(const QString& name)
{
    return physics::integratorFromName(name.toStdString()).has_value();
}
bool isSolver(const QString& name)
{
    return physics::solverFromName(name.toStdString()).has_value();
}
bool isBodyType(const QString& name)
{
    return bodyTypeFromName(name).has_value();
}
bool isPin(const QString& name)
{
    return name == u"pin";
}
QString unknownBodyType(const QString& name)
{
    return detail::FileMessages::tr(
               "unknown body type \"%1\" (expected dynamic, static, kinematic)")
        .arg(name);
}
QString unknownJointType(const QString& name)
{
    return detail::FileMessages::tr("unknown joint type \"%1\" (expected pin)").arg(name);
}
QStringList integratorOptions()
{
    QStringList names;
    for (const physics::IntegratorKind kind : physics::kAllIntegrators)
        names << fromView(physics::integratorName(kind));
    return names;
}
QStringList solverOptions()
{
    // The soft step is for large scenes, chosen in a file; the editor offers the two a lesson
    // compares.
    return {fromView(physics::solverName(physics::SolverKind::SeedImpulse)),
            fromView(physics::solverName(physics::SolverKind::SequentialImpulse))};
}
QStringList bodyTypeOptions()
{
    QStringList names;
    for (const auto& [type, label] : kBodyTypes)
        names << bodyTypeName(type);
    return names;
}
QStringList pinOptions()
{
    return {QStringLiteral("pin")};
}

// --- Shapes --------------------------------------------------------------------------------------

/// The width and height of a box of the format, or nullopt for any other shape.
std::optional<Vec2> boxSize(const Scene& s, std::size_t i)
{
    const physics::Polygon* p = s.bodies[i].shape.asPolygon();
    if (!p || p->vertices.size() != 4 || !entry(s.originalVertices, i).empty())
        return std::nullopt;
    const Vec2 size(2 * p->vertices[2].x(), 2 * p->vertices[2].y());
    const physics::Polygon box = physics::makeBox(size.x(), size.y());
    if (box.vertices != p->vertices || box.normals != p->normals)
        return std::nullopt;
    return size;
}
template <int Component> Value boxGet(const Scene& s, std::size_t i)
{
    const auto size = boxSize(s, i);
    return size ? Value((*size)[Component]) : Value();
}
template <int Component> void boxSet(Scene& s, std::size_t i, const Value& v)
{
    Vec2 size = boxSize(s, i).value_or(Vec2(1.0, 1.0));
    size[Component] = as<double>(v);
    s.bodies[i].shape = physics::makePolygonShape(physics::makeBox(size.x(), size.y()));
}
template <int Component> bool isBox(const Scene& s, std::size_t i)
{
    return boxSize(s, i).has_value();
}
Value radiusGet(const Scene& s, std::size_t i)
{
    const physics::Circle* c = s.bodies[i].shape.asCircle();
    return c ? Value(c->radius) : Value();
}
void radiusSet(Scene& s, std::size_t i, const Value& v)
{
    s.bodies[i].shape = physics::makeCircleShape(as<double>(v));
}
bool isCircle(const Scene& s, std::size_t i)
{
    return s.bodies[i].shape.asCircle() != nullptr;
}

// --- The tables ----------------------------------------------------------------------------------

const Field kSceneFields[] = {
    {.key = "title",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Title"),
     .kind = Kind::LocalText,
     .get = [](const Scene& s, std::size_t) { return Value(s.title); },
     .set = [](Scene& s, std::size_t, const Value& v) { setSceneTitle(s, as<QString>(v)); },
     .inEditor = true,
     .texts = [](const Scene& s, std::size_t) { return s.titles; }},
    {.key = "description",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Description"),
     .kind = Kind::LocalText,
     .get = [](const Scene& s, std::size_t) { return Value(s.description); },
     .set = [](Scene& s, std::size_t, const Value& v) { setSceneDescription(s, as<QString>(v)); },
     .written = [](const Scene& s,
                   std::size_t) { return !s.description.isEmpty() || !s.descriptions.isEmpty(); },
     .inEditor = true,
     .texts = [](const Scene& s, std::size_t) { return s.descriptions; }},
};

using physics::WorldDef;

const Field kWorldFields[] = {
    {.key = "gravity",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Gravity gx"),
     .labelY = QT_TRANSLATE_NOOP("SceneSchema", "Gravity gy"),
     .kind = Kind::Vec2,
     .range = limits::kGravity,
     .get = worldGet<&WorldDef::gravity>,
     .set = worldSet<&WorldDef::gravity>,
     .inEditor = true},
    {.key = "dt",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Time step dt"),
     .range = limits::kDt,
     .rule = R::Positive,
     .get = worldGet<&WorldDef::dt>,
     .set = worldSet<&WorldDef::dt>,
     .inEditor = true,
     .shownScale = 1e3,
     .shownUnit = QT_TRANSLATE_NOOP("SceneSchema", "ms")},
    {.key = "integrator",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Integrator"),
     .kind = Kind::Choice,
     .get =
         [](const Scene& s, std::size_t) {
             return Value(fromView(physics::integratorName(s.world.integrator)));
         },
     .set =
         [](Scene& s, std::size_t, const Value& v) {
             s.world.integrator = *physics::integratorFromName(as<QString>(v).toStdString());
         },
     .inEditor = true,
     .accepts = isIntegrator,
     .unknown = detail::unknownIntegrator,
     .options = integratorOptions},
    {.key = "solver",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Solver"),
     .kind = Kind::Choice,
     .get = [](const Scene& s,
               std::size_t) { return Value(fromView(physics::solverName(s.world.solver))); },
     .set =
         [](Scene& s, std::size_t, const Value& v) {
             s.world.solver = *physics::solverFromName(as<QString>(v).toStdString());
         },
     .inEditor = true,
     .accepts = isSolver,
     .unknown = detail::unknownSolver,
     .options = solverOptions},
    {.key = "iterations",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Iterations"),
     .kind = Kind::Integer,
     .range = limits::kIterations,
     .get = worldGet<&WorldDef::iterations>,
     .set = worldSet<&WorldDef::iterations>,
     .inEditor = true},
    {.key = "restitution",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Restitution e"),
     .range = limits::kRestitution,
     .rule = R::UnitInterval,
     .get = worldGet<&WorldDef::restitution>,
     .set = worldSet<&WorldDef::restitution>},
    {.key = "friction",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Friction μ"),
     .range = limits::kFriction,
     .rule = R::NonNegative,
     .get = worldGet<&WorldDef::friction>,
     .set = worldSet<&WorldDef::friction>},
    {.key = "gravitation",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Gravitation G"),
     .range = limits::kGravitation,
     .rule = R::NonNegative,
     .get = worldGet<&WorldDef::gravitation>,
     .set = worldSet<&WorldDef::gravitation>},
    {.key = "drag",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Drag"),
     .range = limits::kDrag,
     .rule = R::NonNegative,
     .get = worldGet<&WorldDef::drag>,
     .set = worldSet<&WorldDef::drag>},
    {.key = "sleep",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Sleep"),
     .kind = Kind::Bool,
     .get = [](const Scene& s,
               std::size_t) { return s.world.sleep ? Value(*s.world.sleep) : Value(); },
     .set =
         [](Scene& s, std::size_t, const Value& v) {
             s.world.sleep =
                 std::holds_alternative<bool>(v) ? std::optional(std::get<bool>(v)) : std::nullopt;
         },
     .written = [](const Scene& s, std::size_t) { return s.world.sleep.has_value(); },
     .optional = true,
     .writtenLast = true},
    {.key = "continuous",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Continuous collision"),
     .kind = Kind::Bool,
     .get = worldGet<&WorldDef::continuous>,
     .set = worldSet<&WorldDef::continuous>},
    // The format has one tolerance for both of dopri5's.
    {.key = "tolerance",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Tolerance"),
     .range = limits::kTolerance,
     .rule = R::Positive,
     .get = [](const Scene& s, std::size_t) { return Value(s.world.tolerances.absolute); },
     .set =
         [](Scene& s, std::size_t, const Value& v) {
             s.world.tolerances.absolute = s.world.tolerances.relative = as<double>(v);
         }},
};

bool moves(const Scene& s, std::size_t i)
{
    return s.bodies[i].type != BodyType::Static;
}
bool dynamic(const Scene& s, std::size_t i)
{
    return s.bodies[i].type == BodyType::Dynamic;
}

const Field kBodyFields[] = {
    {.key = "id",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Id"),
     .kind = Kind::Text,
     .get = [](const Scene& s, std::size_t i) { return Value(fromView(s.bodies[i].name)); },
     .set = [](Scene& s, std::size_t i,
               const Value& v) { s.bodies[i].name = as<QString>(v).toStdString(); },
     .required = true,
     .inEditor = true},
    {.key = "label",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Label"),
     .kind = Kind::LocalText,
     .get =
         [](const Scene& s, std::size_t i) {
             const auto id = static_cast<physics::BodyId>(i);
             return s.hasLabel(id) ? Value(s.bodyLabel(id)) : Value();
         },
     .set =
         [](Scene& s, std::size_t i, const Value& v) {
             s.labels.resize(std::max(s.labels.size(), i + 1));
             s.labelTexts.resize(std::max(s.labelTexts.size(), i + 1));
             const QString* text = std::get_if<QString>(&v);
             if (!text || text->isEmpty()) {
                 s.labels[i].clear();
                 s.labelTexts[i].clear();
                 return;
             }
             s.labels[i] = *text;
             LocalTextMap& all = s.labelTexts[i];
             if (!all.isEmpty())
                 all[all.contains(s.language) ? s.language : kFallbackLanguage.toString()] = *text;
         },
     .written = [](const Scene& s,
                   std::size_t i) { return s.hasLabel(static_cast<physics::BodyId>(i)); },
     .optional = true,
     .inEditor = true,
     .texts = [](const Scene& s, std::size_t i) { return entry(s.labelTexts, i); }},
    {.key = "type",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Type"),
     .kind = Kind::Choice,
     .get = [](const Scene& s, std::size_t i) { return Value(bodyTypeName(s.bodies[i].type)); },
     .set = [](Scene& s, std::size_t i,
               const Value& v) { s.bodies[i].type = *bodyTypeFromName(as<QString>(v)); },
     .inEditor = true,
     .accepts = isBodyType,
     .unknown = unknownBodyType,
     .options = bodyTypeOptions},
    {.key = "shape",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Shape"),
     .kind = Kind::Shape,
     .required = true},
    {.key = "width",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Width"),
     .kind = Kind::Size,
     .range = limits::kSize,
     .rule = R::Positive,
     .get = boxGet<0>,
     .set = boxSet<0>,
     .applies = isBox<0>,
     .inEditor = true},
    {.key = "height",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Height"),
     .kind = Kind::Size,
     .range = limits::kSize,
     .rule = R::Positive,
     .get = boxGet<1>,
     .set = boxSet<1>,
     .applies = isBox<1>,
     .inEditor = true},
    {.key = "radius",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Radius"),
     .kind = Kind::Size,
     .range = limits::kSize,
     .rule = R::Positive,
     .get = radiusGet,
     .set = radiusSet,
     .applies = isCircle,
     .inEditor = true},
    {.key = "position",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Position x"),
     .labelY = QT_TRANSLATE_NOOP("SceneSchema", "Position y"),
     .kind = Kind::Vec2,
     .range = limits::kCoordinate,
     .get = bodyGet<&BodyDef::position>,
     .set = bodySet<&BodyDef::position>,
     .inEditor = true},
    {.key = "angle",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Angle θ"),
     .range = limits::kAngle,
     .get = bodyGet<&BodyDef::angle>,
     .set = bodySet<&BodyDef::angle>,
     .inEditor = true},
    {.key = "velocity",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Velocity vx"),
     .labelY = QT_TRANSLATE_NOOP("SceneSchema", "Velocity vy"),
     .kind = Kind::Vec2,
     .range = limits::kVelocity,
     .get = bodyGet<&BodyDef::velocity>,
     .set = bodySet<&BodyDef::velocity>,
     .written = [](const Scene& s, std::size_t i) { return s.bodies[i].velocity != Vec2::Zero(); },
     .applies = moves,
     .inEditor = true},
    {.key = "angularVelocity",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Angular vel. ω"),
     .range = limits::kAngularVelocity,
     .get = bodyGet<&BodyDef::angularVelocity>,
     .set = bodySet<&BodyDef::angularVelocity>,
     .written = [](const Scene& s, std::size_t i) { return s.bodies[i].angularVelocity != 0; },
     .applies = moves,
     .inEditor = true},
    // A body gives its density or its mass: setting the density lets the mass follow from it.
    {.key = "density",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Density"),
     .range = limits::kDensity,
     .rule = R::Positive,
     .get = bodyGet<&BodyDef::density>,
     .set =
         [](Scene& s, std::size_t i, const Value& v) {
             s.bodies[i].density = as<double>(v);
             s.bodies[i].mass = 0.0;
         },
     .written = [](const Scene& s, std::size_t i) { return !(s.bodies[i].mass > 0); },
     .applies = dynamic,
     .inEditor = true},
    {.key = "mass",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Mass"),
     .range = limits::kMass,
     .rule = R::Positive,
     .get = [](const Scene& s,
               std::size_t i) { return s.bodies[i].mass > 0 ? Value(s.bodies[i].mass) : Value(); },
     .set =
         [](Scene& s, std::size_t i, const Value& v) {
             s.bodies[i].mass = std::holds_alternative<std::monostate>(v) ? 0.0 : as<double>(v);
         },
     .written = [](const Scene& s, std::size_t i) { return s.bodies[i].mass > 0; },
     .applies = dynamic,
     .optional = true,
     .inEditor = true},
    {.key = "restitution",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Restitution e"),
     .range = limits::kRestitution,
     .rule = R::UnitInterval,
     .get = bodyOptionalGet<&BodyDef::restitution>,
     .set = bodyOptionalSet<&BodyDef::restitution>,
     .written = bodyOptionalWritten<&BodyDef::restitution>,
     .optional = true,
     .inEditor = true,
     .fallback = "restitution"},
    {.key = "friction",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Friction μ"),
     .range = limits::kFriction,
     .rule = R::NonNegative,
     .get = bodyOptionalGet<&BodyDef::friction>,
     .set = bodyOptionalSet<&BodyDef::friction>,
     .written = bodyOptionalWritten<&BodyDef::friction>,
     .optional = true,
     .inEditor = true,
     .fallback = "friction"},
    {.key = "collide",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Collides"),
     .kind = Kind::Bool,
     .get = bodyGet<&BodyDef::collide>,
     .set = bodySet<&BodyDef::collide>,
     .written = [](const Scene& s, std::size_t i) { return !s.bodies[i].collide; }},
    {.key = "colour",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Colour"),
     .kind = Kind::Colour,
     .get =
         [](const Scene& s, std::size_t i) {
             const QString c = s.colourOf(i);
             return c.isEmpty() ? Value() : Value(c);
         },
     .set =
         [](Scene& s, std::size_t i, const Value& v) {
             s.colours.resize(std::max(s.colours.size(), i + 1));
             const QString* c = std::get_if<QString>(&v);
             s.colours[i] = c ? c->toLower() : QString();
         },
     .written = [](const Scene& s, std::size_t i) { return !s.colourOf(i).isEmpty(); },
     .optional = true,
     .inEditor = true},
};

using physics::PinJointDef;
using physics::SpringDef;

const Field kSpringFields[] = {
    {.key = "a",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Body A"),
     .kind = Kind::End,
     .get = springEndGet<&SpringDef::a>,
     .set = springEndSet<&SpringDef::a>,
     .optional = true},
    {.key = "anchorA",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Anchor A x"),
     .labelY = QT_TRANSLATE_NOOP("SceneSchema", "Anchor A y"),
     .kind = Kind::Vec2,
     .range = limits::kCoordinate,
     .get = springGet<&SpringDef::anchorA>,
     .set = springSet<&SpringDef::anchorA>},
    {.key = "b",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Body B"),
     .kind = Kind::End,
     .get = springEndGet<&SpringDef::b>,
     .set = springEndSet<&SpringDef::b>,
     .optional = true},
    {.key = "anchorB",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Anchor B x"),
     .labelY = QT_TRANSLATE_NOOP("SceneSchema", "Anchor B y"),
     .kind = Kind::Vec2,
     .range = limits::kCoordinate,
     .get = springGet<&SpringDef::anchorB>,
     .set = springSet<&SpringDef::anchorB>},
    {.key = "stiffness",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Stiffness k"),
     .range = limits::kStiffness,
     .rule = R::NonNegative,
     .get = springGet<&SpringDef::stiffness>,
     .set = springSet<&SpringDef::stiffness>,
     .inEditor = true},
    {.key = "damping",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Damping c"),
     .range = limits::kDamping,
     .rule = R::NonNegative,
     .get = springGet<&SpringDef::damping>,
     .set = springSet<&SpringDef::damping>,
     .inEditor = true},
    {.key = "restLength",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Rest length"),
     .range = limits::kRestLength,
     .rule = R::NonNegative,
     .get = springGet<&SpringDef::restLength>,
     .set = springSet<&SpringDef::restLength>,
     .inEditor = true},
};

const Field kJointFields[] = {
    {.key = "type",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Type"),
     .kind = Kind::Choice,
     .get = [](const Scene&, std::size_t) { return Value(QStringLiteral("pin")); },
     .set = [](Scene&, std::size_t, const Value&) {},
     .required = true,
     .accepts = isPin,
     .unknown = unknownJointType,
     .options = pinOptions},
    {.key = "a",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Body A"),
     .kind = Kind::End,
     .get = jointEndGet<&PinJointDef::a>,
     .set = jointEndSet<&PinJointDef::a>,
     .required = true},
    {.key = "anchorA",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Anchor A x"),
     .labelY = QT_TRANSLATE_NOOP("SceneSchema", "Anchor A y"),
     .kind = Kind::Vec2,
     .range = limits::kCoordinate,
     .get = jointGet<&PinJointDef::anchorA>,
     .set = jointSet<&PinJointDef::anchorA>},
    {.key = "b",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Body B"),
     .kind = Kind::End,
     .get = jointEndGet<&PinJointDef::b>,
     .set = jointEndSet<&PinJointDef::b>,
     .optional = true},
    {.key = "anchorB",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Anchor B x"),
     .labelY = QT_TRANSLATE_NOOP("SceneSchema", "Anchor B y"),
     .kind = Kind::Vec2,
     .range = limits::kCoordinate,
     .get = jointGet<&PinJointDef::anchorB>,
     .set = jointSet<&PinJointDef::anchorB>},
};

// --- A lesson step's settings --------------------------------------------------------------------

template <auto Member> Value settingGet(const StepSettings& s, std::size_t)
{
    const auto& v = s.*Member;
    return v ? Value(*v) : Value();
}
template <auto Member> void settingSet(StepSettings& s, std::size_t, const Value& v)
{
    using T = typename std::remove_cvref_t<decltype(s.*Member)>::value_type;
    if (std::holds_alternative<std::monostate>(v))
        s.*Member = std::nullopt;
    else
        s.*Member = as<T>(v);
}

const SettingsField kSettingsFields[] = {
    {.key = "integrator",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Integrator"),
     .kind = Kind::Choice,
     .get =
         [](const StepSettings& s, std::size_t) {
             return s.integrator ? Value(fromView(physics::integratorName(*s.integrator)))
                                 : Value();
         },
     .set =
         [](StepSettings& s, std::size_t, const Value& v) {
             s.integrator = physics::integratorFromName(as<QString>(v).toStdString());
         },
     .optional = true,
     .accepts = isIntegrator,
     .unknown = detail::unknownIntegrator,
     .options = integratorOptions},
    {.key = "dt",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Time step dt"),
     .range = limits::kDt,
     .rule = R::Positive,
     .get = settingGet<&StepSettings::dt>,
     .set = settingSet<&StepSettings::dt>,
     .optional = true},
    {.key = "solver",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Solver"),
     .kind = Kind::Choice,
     .get =
         [](const StepSettings& s, std::size_t) {
             return s.solver ? Value(fromView(physics::solverName(*s.solver))) : Value();
         },
     .set =
         [](StepSettings& s, std::size_t, const Value& v) {
             s.solver = physics::solverFromName(as<QString>(v).toStdString());
         },
     .optional = true,
     .accepts = isSolver,
     .unknown = detail::unknownSolver,
     .options = solverOptions},
    {.key = "iterations",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Iterations"),
     .kind = Kind::Integer,
     .range = limits::kIterations,
     .get = settingGet<&StepSettings::iterations>,
     .set = settingSet<&StepSettings::iterations>,
     .optional = true},
    {.key = "restitution",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Restitution e"),
     .range = limits::kRestitution,
     .rule = R::UnitInterval,
     .get = settingGet<&StepSettings::restitution>,
     .set = settingSet<&StepSettings::restitution>,
     .optional = true},
    {.key = "friction",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Friction μ"),
     .range = limits::kFriction,
     .rule = R::NonNegative,
     .get = settingGet<&StepSettings::friction>,
     .set = settingSet<&StepSettings::friction>,
     .optional = true},
    {.key = "gravity",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Gravity"),
     .kind = Kind::Bool,
     .get = settingGet<&StepSettings::gravity>,
     .set = settingSet<&StepSettings::gravity>,
     .optional = true},
    // The window's slow motion; a factor, so its messages name no unit.
    {.key = "timeScale",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Time scale"),
     .range = {limits::kTimeScale.min, limits::kTimeScale.max, ""},
     .rule = R::Positive,
     .get = settingGet<&StepSettings::timeScale>,
     .set = settingSet<&StepSettings::timeScale>,
     .optional = true},
};

} // namespace

std::span<const Field> fields(Object object)
{
    switch (object) {
    case Object::Scene:
        return kSceneFields;
    case Object::World:
        return kWorldFields;
    case Object::Body:
        return kBodyFields;
    case Object::Spring:
        return kSpringFields;
    case Object::Joint:
        return kJointFields;
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

std::span<const SettingsField> settingsFields()
{
    return kSettingsFields;
}

const SettingsField* findSettingsField(std::string_view key)
{
    for (const SettingsField& f : kSettingsFields)
        if (f.key == key)
            return &f;
    return nullptr;
}

QStringList keys(Object object)
{
    QStringList out;
    if (object == Object::Scene)
        out << QStringLiteral("rigidlab");
    for (const Field& f : fields(object))
        if (f.kind != Kind::Size)
            out << fromView(f.key);
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
        for (const SettingsField& f : kSettingsFields)
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
    for (const auto& [t, name] : kBodyTypes)
        if (t == type)
            return QLatin1String(name);
    return {};
}

std::optional<BodyType> bodyTypeFromName(const QString& name)
{
    for (const auto& [type, label] : kBodyTypes)
        if (name == QLatin1String(label))
            return type;
    return std::nullopt;
}

QString bodyTypeLabel(BodyType type)
{
    for (const auto& [t, label] : kBodyTypes)
        if (t == type)
            return QCoreApplication::translate(kContext, label);
    return {};
}

QString safeFileName(const QString& title)
{
    // Decomposed, a letter with a mark is the letter and the mark: the letter stays.
    const QString plain = title.normalized(QString::NormalizationForm_KD).toLower();
    QString name;
    for (const QChar c : plain) {
        if ((c >= u'a' && c <= u'z') || (c >= u'0' && c <= u'9'))
            name += c;
        else if (c.category() == QChar::Mark_NonSpacing)
            continue;
        else if (!name.isEmpty() && !name.endsWith(u'_'))
            name += u'_';
    }
    while (name.endsWith(u'_'))
        name.chop(1);
    // Long names are cut where a file system of a school computer still takes them whole.
    constexpr qsizetype kMaxStem = 60;
    if (name.size() > kMaxStem) {
        name.truncate(kMaxStem);
        while (name.endsWith(u'_'))
            name.chop(1);
    }
    if (name.isEmpty())
        name = QStringLiteral("scene");
    return name + QStringLiteral(".json");
}

} // namespace rigidlab::lessons::schema
