// SPDX-License-Identifier: GPL-3.0-or-later
// Scene edits: copy, change, check with the loader's rules. A refusal reads like the loader's
// (`ID: PLACE: what is wrong`, PLACE a key of the scene format), so that what the editor refuses
// and what a file may not hold are one list.

#include "edit/scene_edits.h"

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

using physics::BodyDef;
using physics::BodyId;
using physics::Vec2;

namespace {

EditResult refused(const QString& error)
{
    EditResult r;
    r.error = error;
    return r;
}

EditResult accepted(Scene scene, BodyId body = physics::kWorld, const QString& warning = {})
{
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

/// After `body` was moved or turned: each pin holding it to the world keeps its point on the
/// body, so its world anchor goes with the body (a pendulum's pivot moves with its bob, as in
/// Algodoo). Springs are left alone: their world ends stay, and the spring stretches. Returns
/// the loader's words when a moved anchor leaves limits::kCoordinate.
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

/// The body's bounding box in the world [m]: min and max corners.
std::pair<Vec2, Vec2> bounds(const BodyDef& def)
{
    const physics::Transform xf(def.position, def.angle);
    return def.shape.visit(physics::Overloaded{[&](const physics::Circle& c) {
                                                   const Vec2 p = xf.apply(c.center);
                                                   const Vec2 r(c.radius, c.radius);
                                                   return std::pair<Vec2, Vec2>(p - r, p + r);
                                               },
                                               [&](const physics::Polygon& poly) {
                                                   Vec2 lo = xf.apply(poly.vertices.front());
                                                   Vec2 hi = lo;
                                                   for (const Vec2& v : poly.vertices) {
                                                       const Vec2 p = xf.apply(v);
                                                       lo = lo.cwiseMin(p);
                                                       hi = hi.cwiseMax(p);
                                                   }
                                                   return std::pair<Vec2, Vec2>(lo, hi);
                                               }});
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

EditResult setBodyNumber(const Scene& scene, BodyId body, BodyNumber what, double value)
{
    if (!validBody(scene, body)) {
        return refused(noSuchBody(body));
    }
    Scene out = scene;
    BodyDef& def = out.bodies[static_cast<size_t>(body)];
    const QString id = bodyId(def);
    QString place;
    limits::Range range;
    switch (what) {
    case BodyNumber::PositionX:
    case BodyNumber::PositionY: {
        const int i = what == BodyNumber::PositionX ? 0 : 1;
        place = QStringLiteral("position[%1]").arg(i);
        range = limits::kCoordinate;
        def.position[i] = value;
        break;
    }
    case BodyNumber::Angle:
        place = QStringLiteral("angle");
        range = limits::kAngle;
        def.angle = value;
        break;
    case BodyNumber::Density:
        place = QStringLiteral("density");
        range = limits::kDensity;
        def.density = value;
        def.mass = 0.0; // the mass follows from the density again
        break;
    case BodyNumber::Mass:
        place = QStringLiteral("mass");
        range = limits::kMass;
        def.mass = value;
        break;
    case BodyNumber::Restitution:
        place = QStringLiteral("restitution");
        range = limits::kRestitution;
        def.restitution = value;
        break;
    case BodyNumber::Friction:
        place = QStringLiteral("friction");
        range = limits::kFriction;
        def.friction = value;
        break;
    case BodyNumber::VelocityX:
    case BodyNumber::VelocityY: {
        const int i = what == BodyNumber::VelocityX ? 0 : 1;
        place = QStringLiteral("velocity[%1]").arg(i);
        range = limits::kVelocity;
        def.velocity[i] = value;
        break;
    }
    case BodyNumber::AngularVelocity:
        place = QStringLiteral("angularVelocity");
        range = limits::kAngularVelocity;
        def.angularVelocity = value;
        break;
    }
    // The ranges of density and mass start above zero: the loader's "positive" is in them.
    if (QString e = rangeError(id, place, value, range); !e.isEmpty()) {
        return refused(e);
    }
    if (QString e = bodyProblem(def); !e.isEmpty()) {
        return refused(e);
    }
    const bool placed =
        what == BodyNumber::PositionX || what == BodyNumber::PositionY || what == BodyNumber::Angle;
    if (QString e = placed ? carryWorldPins(out, body) : QString(); !e.isEmpty()) {
        return refused(e);
    }
    return accepted(std::move(out), body);
}

EditResult setBodyType(const Scene& scene, BodyId body, physics::BodyType type)
{
    if (!validBody(scene, body)) {
        return refused(noSuchBody(body));
    }
    Scene out = scene;
    out.bodies[static_cast<size_t>(body)].type = type;
    return accepted(std::move(out), body);
}

EditResult setBodyVelocity(const Scene& scene, BodyId body, const Vec2& velocity)
{
    if (!validBody(scene, body)) {
        return refused(noSuchBody(body));
    }
    const QString id = bodyId(scene.bodies[static_cast<size_t>(body)]);
    for (int i = 0; i < 2; ++i) {
        if (QString e = rangeError(id, QStringLiteral("velocity[%1]").arg(i), velocity[i],
                                   limits::kVelocity);
            !e.isEmpty()) {
            return refused(e);
        }
    }
    Scene out = scene;
    out.bodies[static_cast<size_t>(body)].velocity = velocity;
    return accepted(std::move(out), body);
}

EditResult setBodyColour(const Scene& scene, BodyId body, const QString& colour)
{
    if (!validBody(scene, body)) {
        return refused(noSuchBody(body));
    }
    if (!colour.isEmpty()) {
        if (const QString problem = rules::colourProblem(colour); !problem.isEmpty()) {
            return refused(placedError(bodyId(scene.bodies[static_cast<size_t>(body)]),
                                       QStringLiteral("colour"), problem));
        }
    }
    Scene out = scene;
    out.colours.resize(scene.bodies.size());
    out.colours[static_cast<size_t>(body)] = colour.toLower();
    return accepted(std::move(out), body);
}

EditResult setBodyId(const Scene& scene, BodyId body, const QString& id)
{
    if (!validBody(scene, body)) {
        return refused(noSuchBody(body));
    }
    const QString current = bodyId(scene.bodies[static_cast<size_t>(body)]);
    if (const QString problem = rules::idProblem(id); !problem.isEmpty()) {
        return refused(placedError(current, QStringLiteral("id"), problem));
    }
    for (size_t i = 0; i < scene.bodies.size(); ++i) {
        if (static_cast<BodyId>(i) != body && bodyId(scene.bodies[i]) == id) {
            return refused(placedError(current, QStringLiteral("id"),
                                       rules::duplicateId(id, static_cast<int>(i))));
        }
    }
    Scene out = scene;
    out.bodies[static_cast<size_t>(body)].name = id.toStdString();
    return accepted(std::move(out), body);
}

EditResult setSpringNumber(const Scene& scene, int spring, SpringNumber what, double value)
{
    if (spring < 0 || static_cast<size_t>(spring) >= scene.springs.size()) {
        return refused(EditMessages::tr("there is no spring number %1").arg(spring));
    }
    const QString source = QStringLiteral("springs[%1]").arg(spring);
    Scene out = scene;
    physics::SpringDef& def = out.springs[static_cast<size_t>(spring)];
    QString place;
    limits::Range range;
    switch (what) {
    case SpringNumber::Stiffness:
        place = QStringLiteral("stiffness");
        range = limits::kStiffness;
        def.stiffness = value;
        break;
    case SpringNumber::Damping:
        place = QStringLiteral("damping");
        range = limits::kDamping;
        def.damping = value;
        break;
    case SpringNumber::RestLength:
        place = QStringLiteral("restLength");
        range = limits::kRestLength;
        def.restLength = value;
        break;
    }
    if (QString e = rangeError(source, place, value, range); !e.isEmpty()) {
        return refused(e);
    }
    return accepted(std::move(out));
}

EditResult setWorldNumber(const Scene& scene, WorldNumber what, double value)
{
    const QString source = QStringLiteral("world");
    Scene out = scene;
    physics::WorldDef& def = out.world;
    QString place;
    limits::Range range;
    switch (what) {
    case WorldNumber::GravityX:
    case WorldNumber::GravityY: {
        const int i = what == WorldNumber::GravityX ? 0 : 1;
        place = QStringLiteral("gravity[%1]").arg(i);
        range = limits::kGravity;
        def.gravity[i] = value;
        break;
    }
    case WorldNumber::Dt:
        place = QStringLiteral("dt");
        range = limits::kDt;
        def.dt = value;
        break;
    case WorldNumber::Iterations:
        place = QStringLiteral("iterations");
        range = limits::kIterations;
        if (std::isfinite(value) && value == std::floor(value) && range.contains(value)) {
            def.iterations = static_cast<int>(value);
        } else if (std::isfinite(value) && range.contains(value)) {
            return refused(placedError(source, place, EditMessages::tr("must be a whole number")));
        }
        break;
    }
    if (QString e = rangeError(source, place, value, range); !e.isEmpty()) {
        return refused(e);
    }
    return accepted(std::move(out));
}

EditResult setIntegrator(const Scene& scene, physics::IntegratorKind kind)
{
    Scene out = scene;
    out.world.integrator = kind;
    return accepted(std::move(out));
}

EditResult setSolver(const Scene& scene, physics::SolverKind kind)
{
    Scene out = scene;
    out.world.solver = kind;
    return accepted(std::move(out));
}

std::vector<std::pair<BodyId, BodyId>> overlappingPairs(const Scene& scene)
{
    // Penetration the engine itself allows at rest (its linear slop) is not an overlap: a box
    // snapped onto the ground touches it.
    const double allowed = physics::ContactSettings{}.linearSlop;
    std::vector<std::pair<Vec2, Vec2>> boxes;
    boxes.reserve(scene.bodies.size());
    for (const BodyDef& def : scene.bodies) {
        boxes.push_back(bounds(def));
    }
    std::vector<std::pair<BodyId, BodyId>> pairs;
    for (size_t i = 0; i < scene.bodies.size(); ++i) {
        const BodyDef& a = scene.bodies[i];
        for (size_t j = i + 1; j < scene.bodies.size(); ++j) {
            const BodyDef& b = scene.bodies[j];
            if (!a.collide || !b.collide ||
                (a.type != physics::BodyType::Dynamic && b.type != physics::BodyType::Dynamic)) {
                continue;
            }
            if ((boxes[i].second.array() < boxes[j].first.array()).any() ||
                (boxes[j].second.array() < boxes[i].first.array()).any()) {
                continue;
            }
            const physics::Manifold m =
                physics::collideShapes(a.shape, physics::Transform(a.position, a.angle), b.shape,
                                       physics::Transform(b.position, b.angle), 0.0);
            for (int k = 0; k < m.pointCount; ++k) {
                if (m.points[static_cast<size_t>(k)].separation < -allowed) {
                    pairs.emplace_back(static_cast<BodyId>(i), static_cast<BodyId>(j));
                    break;
                }
            }
        }
    }
    return pairs;
}

QString overlapMessage(const Scene& scene)
{
    const auto pairs = overlappingPairs(scene);
    if (pairs.empty()) {
        return {};
    }
    QStringList names;
    for (const auto& [a, b] : pairs) {
        names << EditMessages::tr("%1 overlaps %2")
                     .arg(bodyId(scene.bodies[static_cast<size_t>(a)]),
                          bodyId(scene.bodies[static_cast<size_t>(b)]));
    }
    return EditMessages::tr("%1; overlapping bodies are pushed apart when the scene runs")
        .arg(names.join(QStringLiteral(", ")));
}

} // namespace rigidlab::lessons::edit
