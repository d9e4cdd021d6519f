// SPDX-License-Identifier: GPL-3.0-or-later
// The rows of springs, pins and the window's run-time settings (scene_schema.h): data, one field a
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

// --- The window's run-time settings --------------------------------------------------------------

// The window's slow motion: a setting of the run, not of the world (no apply); a factor, so its
// messages name no unit.
const Field kWindowSettings[] = {
    {.key = "timeScale",
     .label = QT_TRANSLATE_NOOP("SceneSchema", "Time scale"),
     .range = {limits::kTimeScale.min, limits::kTimeScale.max, ""},
     .rule = R::Positive,
     .optional = true,
     .setting = 1},
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

std::span<const Field> windowSettingRows()
{
    return kWindowSettings;
}

} // namespace rigidlab::lessons::schema::rows
