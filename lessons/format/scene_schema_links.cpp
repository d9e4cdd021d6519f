// SPDX-License-Identifier: GPL-3.0-or-later
// The rows of springs, pins and a lesson step's settings (scene_schema.h): data, one field a
// row.

#include "format/scene_schema_rows.h"

namespace rigidlab::lessons::schema::rows {

namespace {

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

std::span<const Field> springRows()
{
    return kSpringFields;
}

std::span<const Field> jointRows()
{
    return kJointFields;
}

std::span<const SettingsField> settingsRows()
{
    return kSettingsFields;
}

} // namespace rigidlab::lessons::schema::rows
