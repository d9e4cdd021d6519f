// SPDX-License-Identifier: GPL-3.0-or-later
// What joins the bodies of a scene file: springs and pin joints, their ends read as body ids
// (or the world), and their anchors checked and completed where the bodies stand at load.

#include "format/scene_reader.h"

#include "format/limits.h"
#include "format/scene_rules.h"

#include <QJsonArray>

#include <cmath>

namespace rigidlab::lessons::detail {

using physics::BodyId;
using physics::Vec2;

namespace {

/// Anchors closer than this count as one point when a pin joint is loaded [m].
constexpr double kJointAnchorTolerance = 1e-6;

} // namespace

bool SceneReader::readEnd(const QJsonObject& object, QStringView key, const QString& place,
                          BodyId& out, bool worldAllowed)
{
    const QString at = joinPlace(place, key);
    const auto it = object.constFind(key);
    if (it == object.constEnd() || it.value().isNull()) {
        if (!worldAllowed) {
            return m_in.fail(at, it == object.constEnd()
                                     ? FileMessages::tr("required, but missing (a body id)")
                                     : FileMessages::tr("must be a body id, not null"));
        }
        out = physics::kWorld;
        return true;
    }
    if (!it.value().isString()) {
        return m_in.fail(at, FileMessages::tr("must be a body id (a string)%1, got %2")
                                 .arg(worldAllowed ? FileMessages::tr(" or null") : QString(),
                                      describeJson(it.value())));
    }
    const QString id = it.value().toString();
    const auto found = m_ids.constFind(id);
    if (found == m_ids.constEnd()) {
        return m_in.fail(at, FileMessages::tr("no body with id \"%1\"").arg(id));
    }
    out = found.value();
    return true;
}

Vec2 SceneReader::worldPoint(BodyId body, const Vec2& anchor) const
{
    if (body == physics::kWorld) {
        return anchor;
    }
    const physics::BodyDef& def = m_scene.bodies[static_cast<size_t>(body)];
    return physics::Transform(def.position, def.angle).apply(anchor);
}

bool SceneReader::readSprings(const QJsonObject& root)
{
    const QString place = QStringLiteral("springs");
    if (!root.contains(u"springs")) {
        return true;
    }
    QJsonArray springs;
    if (!m_in.asArray(root.value(u"springs"), place, springs)) {
        return false;
    }
    if (springs.size() > kMaxSprings) {
        return m_in.fail(place, FileMessages::tr("%1 springs, more than the limit of %2")
                                    .arg(springs.size())
                                    .arg(kMaxSprings));
    }
    for (qsizetype i = 0; i < springs.size(); ++i) {
        if (!readSpring(springs[i], indexPlace(place, i))) {
            return false;
        }
    }
    return true;
}

bool SceneReader::readSpring(const QJsonValue& value, const QString& place)
{
    QJsonObject object;
    if (!m_in.asObject(value, place, object) ||
        !m_in.checkKeys(object, place, schema::keys(schema::Object::Spring))) {
        return false;
    }
    const std::size_t index = m_scene.springs.size();
    m_scene.springs.emplace_back();
    if (!readFields(schema::Object::Spring, object, place, index)) {
        return false;
    }
    physics::SpringDef& spring = m_scene.springs.back();
    if (spring.a == physics::kWorld && spring.b == physics::kWorld) {
        return m_in.fail(place, rules::springBothInWorld());
    }
    if (spring.a == spring.b) {
        return m_in.fail(joinPlace(place, u"b"), rules::springSameBody());
    }
    if (!object.contains(u"restLength")) {
        // Without one, the spring rests as it is drawn.
        spring.restLength =
            (worldPoint(spring.b, spring.anchorB) - worldPoint(spring.a, spring.anchorA)).norm();
        if (!std::isfinite(spring.restLength)) {
            return m_in.fail(place, FileMessages::tr("the anchors are too far apart to measure"));
        }
    }
    return true;
}

bool SceneReader::readJoints(const QJsonObject& root)
{
    const QString place = QStringLiteral("joints");
    if (!root.contains(u"joints")) {
        return true;
    }
    QJsonArray joints;
    if (!m_in.asArray(root.value(u"joints"), place, joints)) {
        return false;
    }
    if (joints.size() > kMaxJoints) {
        return m_in.fail(place, FileMessages::tr("%1 joints, more than the limit of %2")
                                    .arg(joints.size())
                                    .arg(kMaxJoints));
    }
    for (qsizetype i = 0; i < joints.size(); ++i) {
        if (!readJoint(joints[i], indexPlace(place, i))) {
            return false;
        }
    }
    return true;
}

bool SceneReader::readJoint(const QJsonValue& value, const QString& place)
{
    QJsonObject object;
    if (!m_in.asObject(value, place, object) ||
        !m_in.checkKeys(object, place, schema::keys(schema::Object::Joint))) {
        return false;
    }
    const std::size_t index = m_scene.joints.size();
    m_scene.joints.emplace_back();
    if (!readFields(schema::Object::Joint, object, place, index)) {
        return false;
    }
    physics::PinJointDef& joint = m_scene.joints.back();
    if (joint.a == joint.b) {
        return m_in.fail(joinPlace(place, u"b"), rules::pinSameBody());
    }
    // Without anchorB, the pin holds the bodies as they are placed: anchorB is the point of b
    // (or of the world) that coincides with anchorA at load.
    const Vec2 pinPoint = worldPoint(joint.a, joint.anchorA);
    if (object.contains(u"anchorB")) {
        const double gap = (worldPoint(joint.b, joint.anchorB) - pinPoint).norm();
        if (!(gap <= kJointAnchorTolerance)) {
            m_in.warn(place, FileMessages::tr("the anchors are %1 m apart at the start; the joint "
                                              "pulls them together at once")
                                 .arg(formatNumber(gap)));
        }
    } else if (joint.b == physics::kWorld) {
        joint.anchorB = pinPoint;
    } else {
        const physics::BodyDef& b = m_scene.bodies[static_cast<size_t>(joint.b)];
        joint.anchorB = physics::Transform(b.position, b.angle).applyInverse(pinPoint);
    }
    return true;
}

} // namespace rigidlab::lessons::detail
