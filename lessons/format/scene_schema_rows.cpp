// SPDX-License-Identifier: GPL-3.0-or-later
// The rows of the scene itself, its world and its bodies (scene_schema.h): data, one field a
// row.

#include "format/scene_schema_rows.h"

#include "format/languages.h"

#include "format/scene_writer.h"

#include "rigidlab/physics/shape.h"

#include <algorithm>

namespace rigidlab::lessons::schema::rows {

namespace {

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

using physics::World;
using physics::WorldDef;

/// Gravity for `gravity: true` on a scene that has none [m/s^2].
const Vec2 kStandardGravity(0.0, -9.81);

// A lesson step turns gravity on or off: off is none at all, on the scene's own gravity, or
// the Earth's when the scene has none.
const Field kGravitySwitch{
    .key = "gravity",
    .label = QT_TRANSLATE_NOOP("SceneSchema", "Gravity"),
    .kind = Kind::Bool,
    .get = [](const Scene& s, std::size_t) { return Value(!s.world.gravity.isZero()); },
    .set = [](Scene& s, std::size_t,
              const Value& v) { s.world.gravity = as<bool>(v) ? kStandardGravity : Vec2::Zero(); },
    .apply =
        [](World& w, const Value& v) {
            if (!as<bool>(v))
                w.setGravity(Vec2::Zero());
            else if (w.def().gravity == Vec2::Zero())
                w.setGravity(kStandardGravity);
        },
};

const Field kWorldFields[] = {
    {.key = "gravity",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Gravity gx"),
     .labelY = QT_TRANSLATE_NOOP("SceneSchema", "Gravity gy"),
     .kind = Kind::Vec2,
     .range = limits::kGravity,
     .get = worldGet<&WorldDef::gravity>,
     .set = worldSet<&WorldDef::gravity>,
     .inEditor = true,
     .setting = 7,
     .apply = [](World& w, const Value& v) { w.setGravity(as<Vec2>(v)); },
     .stepRow = &kGravitySwitch},
    {.key = "dt",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Time step dt"),
     .range = limits::kDt,
     .rule = R::Positive,
     .get = worldGet<&WorldDef::dt>,
     .set = worldSet<&WorldDef::dt>,
     .inEditor = true,
     .shownScale = 1e3,
     .shownUnit = QT_TRANSLATE_NOOP("SceneSchema", "ms"),
     .setting = 2,
     .apply = [](World& w, const Value& v) { w.setDt(as<double>(v)); }},
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
     .options = integratorOptions,
     .setting = 1,
     .apply =
         [](World& w, const Value& v) {
             // A name the row accepts (the loader and the controls check it).
             if (const auto kind = physics::integratorFromName(as<QString>(v).toStdString()))
                 w.setIntegrator(*kind);
         },
     .mainWorldOnly = true},
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
     .options = solverOptions,
     .setting = 3,
     .apply =
         [](World& w, const Value& v) {
             if (const auto kind = physics::solverFromName(as<QString>(v).toStdString()))
                 w.setSolver(*kind);
         },
     .mainWorldOnly = true},
    {.key = "iterations",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Iterations"),
     .kind = Kind::Integer,
     .range = limits::kIterations,
     .get = worldGet<&WorldDef::iterations>,
     .set = worldSet<&WorldDef::iterations>,
     .inEditor = true,
     .setting = 4,
     .apply = [](World& w, const Value& v) { w.setIterations(as<int>(v)); },
     .mainWorldOnly = true},
    {.key = "restitution",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Restitution e"),
     .range = limits::kRestitution,
     .rule = R::UnitInterval,
     .get = worldGet<&WorldDef::restitution>,
     .set = worldSet<&WorldDef::restitution>,
     .setting = 5,
     .apply = [](World& w, const Value& v) { w.setRestitution(as<double>(v)); }},
    {.key = "friction",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Friction μ"),
     .range = limits::kFriction,
     .rule = R::NonNegative,
     .get = worldGet<&WorldDef::friction>,
     .set = worldSet<&WorldDef::friction>,
     .setting = 6,
     .apply = [](World& w, const Value& v) { w.setFriction(as<double>(v)); }},
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
                 all[textLanguage(s.language, all.keys())] = *text;
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

} // namespace

std::span<const Field> sceneRows()
{
    return kSceneFields;
}

std::span<const Field> worldRows()
{
    return kWorldFields;
}

std::span<const Field> bodyRows()
{
    return kBodyFields;
}

} // namespace rigidlab::lessons::schema::rows
