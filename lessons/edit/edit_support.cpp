// SPDX-License-Identifier: GPL-3.0-or-later
#include "edit/edit_support.h"

#include "format/json_reader.h"
#include "format/scene_overlaps.h"
#include "format/scene_rules.h"

#include <QStringList>

namespace rigidlab::lessons::edit::support {

using physics::BodyDef;
using physics::BodyId;
using physics::Vec2;

EditResult refused(const QString& error)
{
    EditResult r;
    r.error = error;
    return r;
}

EditResult accepted(Scene scene, BodyId body, const QString& warning)
{
    // Every edit meets the loader's bound on crowding (format/scene_overlaps.h): a body
    // duplicated again and again onto one place is refused before the scene could freeze the
    // window, whichever edit made it so.
    QStringList overlaps; // the editor lists them itself (overlapMessage)
    if (const QString crowded = checkCrowding(scene, EditMessages::tr("the scene"), overlaps);
        !crowded.isEmpty())
        return refused(crowded);
    EditResult r;
    r.ok = true;
    r.scene = std::move(scene);
    r.body = body;
    r.warning = warning;
    return r;
}

/// `source: place: must be from MIN to MAX UNIT, got V`, the loader's words, or empty.
QString rangeError(const QString& source, const QString& place, double value,
                   const limits::Range& range)
{
    detail::JsonReader in(source);
    in.checkRange(value, place, range);
    return in.error();
}

QString placedError(const QString& source, const QString& place, const QString& what)
{
    detail::JsonReader in(source);
    in.fail(place, what);
    return in.error();
}

bool validBody(const Scene& scene, BodyId body)
{
    return body >= 0 && static_cast<size_t>(body) < scene.bodies.size();
}

QString noSuchBody(BodyId body)
{
    return EditMessages::tr("there is no body number %1").arg(body);
}

QString bodyId(const BodyDef& def)
{
    return QString::fromStdString(def.name);
}

/// Empty, or why `def` may not stand in a scene: its placement out of range, or its mass.
QString bodyProblem(const BodyDef& def)
{
    const QString id = bodyId(def);
    for (int i = 0; i < 2; ++i) {
        if (QString e = rangeError(id, QStringLiteral("position[%1]").arg(i), def.position[i],
                                   limits::kCoordinate);
            !e.isEmpty()) {
            return e;
        }
    }
    if (QString e = rangeError(id, QStringLiteral("angle"), def.angle, limits::kAngle);
        !e.isEmpty()) {
        return e;
    }
    if (const auto problem = rules::checkMass(def)) {
        return placedError(id, problem->key, problem->what);
    }
    return {};
}

/// An anchor as the scene format holds it, checked against limits::kCoordinate.
QString anchorError(const QString& source, const QString& key, const Vec2& anchor)
{
    for (int i = 0; i < 2; ++i) {
        if (QString e = rangeError(source, QStringLiteral("%1[%2]").arg(key).arg(i), anchor[i],
                                   limits::kCoordinate);
            !e.isEmpty()) {
            return e;
        }
    }
    return {};
}

QString carryWorldPins(Scene& scene, BodyId body)
{
    const BodyDef& def = scene.bodies[static_cast<size_t>(body)];
    const physics::Transform xf(def.position, def.angle);
    for (size_t i = 0; i < scene.joints.size(); ++i) {
        physics::PinJointDef& joint = scene.joints[i];
        // The joint may name the body as its a or as its b; the other end is the world's.
        const bool bodyIsA = joint.a == body && joint.b == physics::kWorld;
        if (!bodyIsA && !(joint.b == body && joint.a == physics::kWorld)) {
            continue;
        }
        Vec2& worldAnchor = bodyIsA ? joint.anchorB : joint.anchorA;
        worldAnchor = xf.apply(bodyIsA ? joint.anchorA : joint.anchorB);
        if (QString e = anchorError(QStringLiteral("joints[%1]").arg(i),
                                    bodyIsA ? QStringLiteral("anchorB") : QStringLiteral("anchorA"),
                                    worldAnchor);
            !e.isEmpty()) {
            return e;
        }
    }
    return {};
}

} // namespace rigidlab::lessons::edit::support
