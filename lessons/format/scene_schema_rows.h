// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The pieces the schema's tables are made of (scene_schema_rows.cpp, scene_schema_links.cpp):
// accessors of a member, the choices' names, and the tables themselves. Internal to
// lessons/format; everything else reads scene_schema.h.

#include "format/scene_schema.h"

#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/integrator.h"

#include <QCoreApplication>

#include <array>
#include <type_traits>

namespace rigidlab::lessons::schema::rows {

using physics::BodyDef;
using physics::BodyType;
using physics::Vec2;
using R = detail::NumberRule;

inline QString fromView(std::string_view s)
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
inline Value endValue(const Scene& s, physics::BodyId end)
{
    if (end < 0 || static_cast<std::size_t>(end) >= s.bodies.size())
        return {};
    return fromView(s.bodies[static_cast<std::size_t>(end)].name);
}
/// The body named by its id, or by its index (the loader's, which knows it already).
inline physics::BodyId endFrom(const Scene& s, const Value& v)
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

inline constexpr std::array<std::pair<BodyType, const char*>, 3> kBodyTypes{{
    {BodyType::Dynamic, QT_TRANSLATE_NOOP("SceneSchema", "dynamic")},
    {BodyType::Static, QT_TRANSLATE_NOOP("SceneSchema", "static")},
    {BodyType::Kinematic, QT_TRANSLATE_NOOP("SceneSchema", "kinematic")},
}};

inline bool isIntegrator(const QString& name)
{
    return physics::integratorFromName(name.toStdString()).has_value();
}
inline bool isSolver(const QString& name)
{
    return physics::solverFromName(name.toStdString()).has_value();
}
inline bool isBodyType(const QString& name)
{
    return bodyTypeFromName(name).has_value();
}
inline bool isPin(const QString& name)
{
    return name == u"pin";
}
inline QString unknownBodyType(const QString& name)
{
    return detail::FileMessages::tr(
               "unknown body type \"%1\" (expected dynamic, static, kinematic)")
        .arg(name);
}
inline QString unknownJointType(const QString& name)
{
    return detail::FileMessages::tr("unknown joint type \"%1\" (expected pin)").arg(name);
}
inline QStringList integratorOptions()
{
    QStringList names;
    for (const physics::IntegratorKind kind : physics::kAllIntegrators)
        names << fromView(physics::integratorName(kind));
    return names;
}
inline QStringList solverOptions()
{
    // The soft step, every scene's default, and the two a lesson compares it with.
    return {fromView(physics::solverName(physics::SolverKind::PaperImpulse)),
            fromView(physics::solverName(physics::SolverKind::SequentialImpulse)),
            fromView(physics::solverName(physics::SolverKind::SoftStep))};
}
inline QStringList bodyTypeOptions()
{
    QStringList names;
    for (const auto& [type, label] : kBodyTypes)
        names << bodyTypeName(type);
    return names;
}
inline QStringList pinOptions()
{
    return {QStringLiteral("pin")};
}

std::span<const Field> sceneRows();
std::span<const Field> worldRows();
std::span<const Field> bodyRows();
std::span<const Field> springRows();
std::span<const Field> jointRows();
/// The run-time settings that are not the world's (the window's time scale).
std::span<const Field> windowSettingRows();

} // namespace rigidlab::lessons::schema::rows
