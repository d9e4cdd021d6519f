// SPDX-License-Identifier: GPL-3.0-or-later
// The fit's parameters and targets as the command line and the window name them, and how a
// parameter's value gets into a scene definition.
#include "measure/fit.h"

#include <QCoreApplication>
#include <QStringList>

#include <algorithm>

namespace rigidlab::measure {

namespace {

struct KindName {
    ParameterKind kind;
    const char* name;
};
constexpr KindName kKindNames[] = {
    {ParameterKind::Restitution, "restitution"},
    {ParameterKind::Friction, "friction"},
    {ParameterKind::VelocityX, "vx"},
    {ParameterKind::VelocityY, "vy"},
};

/// Search span of an initial velocity about the scene's [m/s].
constexpr double kVelocitySpan = 5.0;
constexpr double kMaxFriction = 2.0;

bool isVelocity(ParameterKind k)
{
    return k == ParameterKind::VelocityX || k == ParameterKind::VelocityY;
}

QString bodyList(const lessons::Scene& scene)
{
    QStringList ids;
    for (const physics::BodyDef& b : scene.bodies)
        ids << QString::fromStdString(b.name);
    return ids.join(QStringLiteral(", "));
}

std::optional<physics::BodyId> findBody(const QString& id, const lessons::Scene& scene,
                                        QString& error)
{
    const auto index = scene.bodyIndex(id);
    if (!index)
        error = QCoreApplication::translate("rigidlab::measure",
                                            "unknown body \"%1\" (the scene has: %2)")
                    .arg(id, bodyList(scene));
    return index;
}

} // namespace

std::optional<Parameter> parseParameter(const QString& text, const lessons::Scene& scene,
                                        QString& error)
{
    const qsizetype colon = text.indexOf(u':');
    const QString kindName = colon < 0 ? text : text.left(colon);
    Parameter p;
    p.name = text;
    const auto kind =
        std::find_if(std::begin(kKindNames), std::end(kKindNames),
                     [&](const KindName& k) { return kindName == QLatin1StringView(k.name); });
    if (kind == std::end(kKindNames)) {
        error = QCoreApplication::translate("rigidlab::measure",
                                            "unknown parameter \"%1\" (expected restitution, "
                                            "friction, vx or vy)")
                    .arg(kindName);
        return std::nullopt;
    }
    p.kind = kind->kind;
    const QStringList ids =
        colon < 0 ? QStringList() : text.mid(colon + 1).split(u',', Qt::KeepEmptyParts);
    for (const QString& id : ids) {
        const auto body = findBody(id.trimmed(), scene, error);
        if (!body)
            return std::nullopt;
        p.bodies.push_back(*body);
    }
    if (isVelocity(p.kind) && p.bodies.size() != 1) {
        error = QCoreApplication::translate("rigidlab::measure", "%1: name one body, as in %2:ball")
                    .arg(text, kindName);
        return std::nullopt;
    }
    return p;
}

std::optional<Target> parseTarget(const QString& text, const lessons::Scene& scene, QString& error)
{
    const qsizetype colon = text.indexOf(u':');
    const auto quantity = quantityFromName(colon < 0 ? text : text.left(colon));
    const bool measurable = quantity && *quantity != Quantity::Time &&
                            *quantity != Quantity::BounceTime && *quantity != Quantity::Ignored;
    if (!measurable || colon < 0) {
        error = QCoreApplication::translate("rigidlab::measure",
                                            "\"%1\": expected QUANTITY:BODY with QUANTITY x, y, "
                                            "vx, vy or v, as in y:ball")
                    .arg(text);
        return std::nullopt;
    }
    const auto body = findBody(text.mid(colon + 1).trimmed(), scene, error);
    if (!body)
        return std::nullopt;
    if (scene.bodies[static_cast<std::size_t>(*body)].type != physics::BodyType::Dynamic) {
        error = QCoreApplication::translate("rigidlab::measure",
                                            "\"%1\": %2 does not move by itself (it is not a "
                                            "dynamic body): measure one that does")
                    .arg(text, text.mid(colon + 1).trimmed());
        return std::nullopt;
    }
    return Target{*quantity, *body, text};
}

double parameterValue(const lessons::Scene& scene, const Parameter& p)
{
    const physics::BodyDef* body =
        p.bodies.empty() ? nullptr : &scene.bodies[static_cast<std::size_t>(p.bodies.front())];
    switch (p.kind) {
    case ParameterKind::Restitution:
        return body ? physics::resolvedMaterial(body->restitution, scene.world.restitution)
                    : scene.world.restitution;
    case ParameterKind::Friction:
        return body ? physics::resolvedMaterial(body->friction, scene.world.friction)
                    : scene.world.friction;
    case ParameterKind::VelocityX:
        return body ? body->velocity.x() : 0.0;
    case ParameterKind::VelocityY:
        return body ? body->velocity.y() : 0.0;
    }
    return 0.0;
}

void setParameter(lessons::Scene& scene, const Parameter& p, double value)
{
    std::vector<physics::BodyId> bodies = p.bodies;
    if (bodies.empty()) {
        for (std::size_t i = 0; i < scene.bodies.size(); ++i)
            bodies.push_back(static_cast<physics::BodyId>(i));
        if (p.kind == ParameterKind::Restitution)
            scene.world.restitution = value;
        if (p.kind == ParameterKind::Friction)
            scene.world.friction = value;
    }
    for (const physics::BodyId id : bodies) {
        physics::BodyDef& b = scene.bodies[static_cast<std::size_t>(id)];
        switch (p.kind) {
        case ParameterKind::Restitution:
            b.restitution = value;
            break;
        case ParameterKind::Friction:
            b.friction = value;
            break;
        case ParameterKind::VelocityX:
            b.velocity.x() = value;
            break;
        case ParameterKind::VelocityY:
            b.velocity.y() = value;
            break;
        }
    }
}

std::pair<double, double> parameterBounds(const lessons::Scene& scene, const Parameter& p)
{
    switch (p.kind) {
    case ParameterKind::Restitution:
        return {0.0, 1.0};
    case ParameterKind::Friction:
        return {0.0, kMaxFriction};
    case ParameterKind::VelocityX:
    case ParameterKind::VelocityY:
        break;
    }
    const double v = parameterValue(scene, p);
    return {v - kVelocitySpan, v + kVelocitySpan};
}

} // namespace rigidlab::measure
