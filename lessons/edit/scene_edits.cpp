// SPDX-License-Identifier: GPL-3.0-or-later
// Scene edits: copy, change, check with the loader's rules. A refusal reads like the loader's
// (`ID: PLACE: what is wrong`, PLACE a key of the scene format), so that what the editor refuses
// and what a file may not hold are one list.

#include "edit/scene_edits.h"
#include "edit/edit_support.h"

#include "format/json_reader.h"
#include "format/limits.h"
#include "format/scene_loader.h"
#include "format/scene_rules.h"

#include "rigidlab/physics/sat.h"
#include "rigidlab/physics/shape.h"
#include "rigidlab/physics/world.h"

#include <QRegularExpression>
#include <QSet>

#include <algorithm>
#include <cmath>

namespace rigidlab::lessons::edit {

using namespace support;
using physics::BodyDef;
using physics::BodyId;
using physics::Vec2;

namespace {

/// Adds `def` (named already) as the last body.
EditResult addBody(const Scene& scene, BodyDef def, std::vector<Vec2> original = {},
                   const QString& warning = {}, const QString& colour = {})
{
    if (scene.bodies.size() >= static_cast<size_t>(kMaxBodies)) {
        return refused(EditMessages::tr("the scene holds %1 bodies, the most a scene may have")
                           .arg(kMaxBodies));
    }
    if (QString e = bodyProblem(def); !e.isEmpty()) {
        return refused(e);
    }
    Scene out = scene;
    out.bodies.push_back(std::move(def));
    out.originalVertices.resize(scene.bodies.size());
    out.originalVertices.push_back(std::move(original));
    if (!colour.isEmpty()) {
        out.colours.resize(scene.bodies.size());
        out.colours.push_back(colour);
    }
    return accepted(std::move(out), static_cast<BodyId>(scene.bodies.size()), warning);
}

/// Checks a shape size against limits::kSize.
QString sizeError(const QString& id, const QString& place, double size)
{
    return rangeError(id, place, size, limits::kSize);
}

/// A world point in the body's frame (the point itself for the world).
Vec2 localPoint(const Scene& scene, BodyId body, const Vec2& point)
{
    if (body == physics::kWorld) {
        return point;
    }
    const BodyDef& def = scene.bodies[static_cast<size_t>(body)];
    return physics::Transform(def.position, def.angle).applyInverse(point);
}

} // namespace

QString uniqueId(const Scene& scene, const QString& stem)
{
    QSet<QString> taken; // lookup only
    for (const BodyDef& def : scene.bodies) {
        taken.insert(bodyId(def));
    }
    for (qsizetype n = 1;; ++n) {
        const QString id = stem + QString::number(n);
        if (!taken.contains(id)) {
            return id;
        }
    }
}

EditResult addCircle(const Scene& scene, const Vec2& center, double radius, physics::BodyType type)
{
    BodyDef def;
    def.name = uniqueId(scene, QStringLiteral("circle")).toStdString();
    if (QString e = sizeError(bodyId(def), QStringLiteral("shape.radius"), radius); !e.isEmpty()) {
        return refused(e);
    }
    def.type = type;
    def.shape = physics::makeCircleShape(radius);
    def.position = center;
    return addBody(scene, std::move(def));
}

namespace {

EditResult addBoxNamed(const Scene& scene, const QString& stem, const Vec2& center, double width,
                       double height, physics::BodyType type)
{
    BodyDef def;
    def.name = uniqueId(scene, stem).toStdString();
    if (QString e = sizeError(bodyId(def), QStringLiteral("shape.width"), width); !e.isEmpty()) {
        return refused(e);
    }
    if (QString e = sizeError(bodyId(def), QStringLiteral("shape.height"), height); !e.isEmpty()) {
        return refused(e);
    }
    def.type = type;
    def.shape = physics::makePolygonShape(physics::makeBox(width, height));
    def.position = center;
    return addBody(scene, std::move(def));
}

} // namespace

EditResult addBox(const Scene& scene, const Vec2& center, double width, double height,
                  physics::BodyType type)
{
    return addBoxNamed(scene, QStringLiteral("box"), center, width, height, type);
}

EditResult addGround(const Scene& scene, const Vec2& center, double width, double height)
{
    return addBoxNamed(scene, QStringLiteral("ground"), center, width, height,
                       physics::BodyType::Static);
}

PolygonPreview previewPolygon(const std::vector<Vec2>& points)
{
    PolygonPreview preview;
    const QString place = QStringLiteral("shape.vertices");
    const QString id = QStringLiteral("polygon");
    if (points.size() < 3 || points.size() > static_cast<size_t>(kMaxPolygonVertices)) {
        preview.error = placedError(
            id, place, rules::polygonVertexCount(static_cast<qsizetype>(points.size())));
        return preview;
    }
    for (const Vec2& p : points) {
        if (!physics::isFinite(p)) {
            preview.error = placedError(id, place, EditMessages::tr("a point is not a number"));
            return preview;
        }
    }
    auto built = physics::makePolygon(points);
    if (!built) {
        preview.error = placedError(id, place, QString::fromStdString(built.error()));
        return preview;
    }
    preview.ok = true;
    preview.hull = built.value().polygon.vertices;
    preview.warning = QString::fromStdString(built.value().warning);
    return preview;
}

EditResult addPolygon(const Scene& scene, const std::vector<Vec2>& points, physics::BodyType type)
{
    const QString id = uniqueId(scene, QStringLiteral("polygon"));
    const QString place = QStringLiteral("shape.vertices");
    const PolygonPreview preview = previewPolygon(points);
    if (!preview.ok) {
        // The same words, under the id the body would have had.
        return refused(placedError(id, place, preview.error.section(QStringLiteral(": "), 2)));
    }
    // The origin goes to the centroid, so that the body turns about its middle.
    const physics::Shape world = physics::makePolygonShape(physics::Polygon{preview.hull, {}});
    const Vec2 centroid = physics::computeMass(world, 1.0).centroid;
    std::vector<Vec2> local;
    local.reserve(preview.hull.size());
    for (const Vec2& p : preview.hull) {
        local.push_back(p - centroid);
    }
    for (size_t i = 0; i < local.size(); ++i) {
        for (int k = 0; k < 2; ++k) {
            if (QString e = rangeError(id, QStringLiteral("%1[%2][%3]").arg(place).arg(i).arg(k),
                                       local[i][k], limits::kVertex);
                !e.isEmpty()) {
                return refused(e);
            }
        }
    }
    auto built = physics::makePolygon(local);
    if (!built) { // only by rounding, as the hull had an area already
        return refused(placedError(id, place, QString::fromStdString(built.error())));
    }
    BodyDef def;
    def.name = id.toStdString();
    def.type = type;
    def.shape = physics::makePolygonShape(std::move(built).value().polygon);
    def.position = centroid;
    std::vector<Vec2> original;
    if (!preview.warning.isEmpty()) {
        for (const Vec2& p : points) {
            original.push_back(p - centroid);
        }
    }
    return addBody(scene, std::move(def), std::move(original),
                   preview.warning.isEmpty() ? QString() : placedError(id, place, preview.warning));
}

EditResult moveBody(const Scene& scene, BodyId body, const Vec2& position)
{
    if (!validBody(scene, body)) {
        return refused(noSuchBody(body));
    }
    Scene out = scene;
    BodyDef& def = out.bodies[static_cast<size_t>(body)];
    def.position = position;
    if (QString e = bodyProblem(def); !e.isEmpty()) {
        return refused(e);
    }
    if (QString e = carryWorldPins(out, body); !e.isEmpty()) {
        return refused(e);
    }
    return accepted(std::move(out), body);
}

EditResult rotateBody(const Scene& scene, BodyId body, double angle)
{
    if (!validBody(scene, body)) {
        return refused(noSuchBody(body));
    }
    Scene out = scene;
    BodyDef& def = out.bodies[static_cast<size_t>(body)];
    def.angle = angle;
    if (QString e = bodyProblem(def); !e.isEmpty()) {
        return refused(e);
    }
    if (QString e = carryWorldPins(out, body); !e.isEmpty()) {
        return refused(e);
    }
    return accepted(std::move(out), body);
}

EditResult deleteBody(const Scene& scene, BodyId body)
{
    if (!validBody(scene, body)) {
        return refused(noSuchBody(body));
    }
    Scene out = scene;
    out.bodies.erase(out.bodies.begin() + body);
    // The lists kept beside `bodies` (each may be shorter) lose the body's entry too.
    const auto eraseEntry = [body](auto& list) {
        if (static_cast<size_t>(body) < list.size()) {
            list.erase(list.begin() + body);
        }
    };
    eraseEntry(out.originalVertices);
    eraseEntry(out.colours);
    eraseEntry(out.labels);
    eraseEntry(out.labelTexts);
    // An end past the deleted body moves down one; the world stays the world.
    const auto renumber = [body](BodyId& end) {
        if (end > body) {
            --end;
        }
    };
    std::erase_if(out.springs,
                  [body](const physics::SpringDef& s) { return s.a == body || s.b == body; });
    std::erase_if(out.joints,
                  [body](const physics::PinJointDef& j) { return j.a == body || j.b == body; });
    for (physics::SpringDef& s : out.springs) {
        renumber(s.a);
        renumber(s.b);
    }
    for (physics::PinJointDef& j : out.joints) {
        renumber(j.a);
        renumber(j.b);
    }
    return accepted(std::move(out));
}

EditResult duplicateBody(const Scene& scene, BodyId body, const Vec2& offset)
{
    if (!validBody(scene, body)) {
        return refused(noSuchBody(body));
    }
    BodyDef def = scene.bodies[static_cast<size_t>(body)];
    // "box3" copies as the next free "boxN"; an id without a number ("ball") as "ball1".
    static const QRegularExpression trailingDigits(QStringLiteral("\\d+$"));
    QString stem = bodyId(def);
    stem.remove(trailingDigits);
    if (stem.isEmpty()) {
        stem = QStringLiteral("body");
    }
    def.name = uniqueId(scene, stem).toStdString();
    def.position += offset;
    std::vector<Vec2> original;
    if (static_cast<size_t>(body) < scene.originalVertices.size()) {
        original = scene.originalVertices[static_cast<size_t>(body)];
    }
    return addBody(scene, std::move(def), std::move(original), {},
                   scene.colourOf(static_cast<size_t>(body)));
}

EditResult deleteSpring(const Scene& scene, int index)
{
    if (index < 0 || static_cast<size_t>(index) >= scene.springs.size()) {
        return refused(EditMessages::tr("there is no spring number %1").arg(index));
    }
    Scene out = scene;
    out.springs.erase(out.springs.begin() + index);
    return accepted(std::move(out));
}

EditResult deletePin(const Scene& scene, int index)
{
    if (index < 0 || static_cast<size_t>(index) >= scene.joints.size()) {
        return refused(EditMessages::tr("there is no pin number %1").arg(index));
    }
    Scene out = scene;
    out.joints.erase(out.joints.begin() + index);
    return accepted(std::move(out));
}

EditResult addPin(const Scene& scene, BodyId a, BodyId b, const Vec2& point)
{
    if (a == physics::kWorld) { // a pin holds a body; the world may only be its second end
        std::swap(a, b);
    }
    const QString source = QStringLiteral("joints[%1]").arg(scene.joints.size());
    if (a == physics::kWorld) {
        return refused(placedError(
            source, QStringLiteral("a"),
            EditMessages::tr("a pin holds a body: start on a body, then click a second body or "
                             "empty space for the world")));
    }
    if ((a != physics::kWorld && !validBody(scene, a)) ||
        (b != physics::kWorld && !validBody(scene, b))) {
        return refused(noSuchBody(validBody(scene, a) ? b : a));
    }
    if (a == b) {
        return refused(placedError(source, QStringLiteral("b"), rules::pinSameBody()));
    }
    if (scene.joints.size() >= static_cast<size_t>(kMaxJoints)) {
        return refused(EditMessages::tr("the scene holds %1 joints, the most a scene may have")
                           .arg(kMaxJoints));
    }
    physics::PinJointDef joint;
    joint.a = a;
    joint.b = b;
    joint.anchorA = localPoint(scene, a, point);
    joint.anchorB = localPoint(scene, b, point);
    for (const auto& [key, anchor] : {std::pair{QStringLiteral("anchorA"), joint.anchorA},
                                      std::pair{QStringLiteral("anchorB"), joint.anchorB}}) {
        if (QString e = anchorError(source, key, anchor); !e.isEmpty()) {
            return refused(e);
        }
    }
    Scene out = scene;
    out.joints.push_back(joint);
    return accepted(std::move(out), a);
}

EditResult addSpring(const Scene& scene, BodyId a, const Vec2& pointA, BodyId b, const Vec2& pointB,
                     double stiffness, double damping)
{
    const QString source = QStringLiteral("springs[%1]").arg(scene.springs.size());
    if ((a != physics::kWorld && !validBody(scene, a)) ||
        (b != physics::kWorld && !validBody(scene, b))) {
        return refused(noSuchBody(validBody(scene, a) || a == physics::kWorld ? b : a));
    }
    const double length = (pointB - pointA).norm();
    // Shorter than the smallest shape is no length to draw or to rest at.
    if (!(length >= limits::kSize.min)) {
        return refused(placedError(source, QStringLiteral("restLength"),
                                   EditMessages::tr("a spring of zero length: drag from one "
                                                    "point to another")));
    }
    if (a == physics::kWorld && b == physics::kWorld) {
        return refused(placedError(source, {}, rules::springBothInWorld()));
    }
    if (a == b) {
        return refused(placedError(source, QStringLiteral("b"), rules::springSameBody()));
    }
    if (scene.springs.size() >= static_cast<size_t>(kMaxSprings)) {
        return refused(EditMessages::tr("the scene holds %1 springs, the most a scene may have")
                           .arg(kMaxSprings));
    }
    physics::SpringDef spring;
    spring.a = a;
    spring.b = b;
    spring.anchorA = localPoint(scene, a, pointA);
    spring.anchorB = localPoint(scene, b, pointB);
    spring.stiffness = stiffness;
    spring.damping = damping;
    spring.restLength = length;
    for (const auto& [key, anchor] : {std::pair{QStringLiteral("anchorA"), spring.anchorA},
                                      std::pair{QStringLiteral("anchorB"), spring.anchorB}}) {
        if (QString e = anchorError(source, key, anchor); !e.isEmpty()) {
            return refused(e);
        }
    }
    for (const auto& [key, value, range] :
         {std::tuple{QStringLiteral("stiffness"), stiffness, limits::kStiffness},
          std::tuple{QStringLiteral("damping"), damping, limits::kDamping},
          std::tuple{QStringLiteral("restLength"), length, limits::kRestLength}}) {
        if (QString e = rangeError(source, key, value, range); !e.isEmpty()) {
            return refused(e);
        }
    }
    Scene out = scene;
    out.springs.push_back(spring);
    return accepted(std::move(out), a == physics::kWorld ? b : a);
}

} // namespace rigidlab::lessons::edit
