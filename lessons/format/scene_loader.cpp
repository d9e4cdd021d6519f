// SPDX-License-Identifier: GPL-3.0-or-later
// Scene files, format v1: reading and checking. The order of the checks is the order of the
// file's sections (version, world, bodies, springs, joints), so the first problem reported is
// the first one a reader of the file would meet. Springs and joints are read in
// scene_links_reader.cpp.

#include "format/scene_loader.h"
#include "format/view_text.h"

#include "format/scene_reader.h"

#include "format/field_reading.h"
#include "format/limits.h"
#include "format/scene_overlaps.h"
#include "format/scene_rules.h"
#include "format/scene_schema.h"

#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/integrator.h"
#include "rigidlab/physics/shape.h"

#include <QFileInfo>
#include <QHash>

#include <array>
#include <cmath>

namespace rigidlab::lessons {

using detail::FileMessages;

using detail::indexPlace;
using detail::joinPlace;
using detail::JsonReader;
using detail::NumberRule;
using physics::BodyId;
using physics::Vec2;

namespace detail {

SceneLoadResult SceneReader::read(const QJsonObject& root)
{
    const bool ok = m_in.formatVersion(root, QStringLiteral("rigidlab"),
                                       FileMessages::tr("a scene file"), kSceneFormatVersion) &&
                    m_in.checkKeys(root, {}, schema::keys(schema::Object::Scene)) &&
                    readFields(schema::Object::Scene, root, {}, 0) && readWorld(root) &&
                    readBodies(root) && readSprings(root) && readJoints(root);
    if (ok) {
        m_texts.warnMissing();
    }

    SceneLoadResult result;
    result.warnings = m_in.warnings();
    if (!ok) {
        result.error = m_in.error();
        return result;
    }
    if (m_scene.title.isEmpty()) {
        m_scene.title = QFileInfo(m_in.sourceName()).completeBaseName();
    }
    if (const QString crowded = checkCrowding(m_scene, m_in.sourceName(), result.warnings);
        !crowded.isEmpty()) {
        result.error = crowded;
        return result;
    }
    result.ok = true;
    result.scene = std::move(m_scene);
    return result;
}

bool SceneReader::readText(const QJsonObject& root, QStringView key, QString& out,
                           LocalTextMap& all)
{
    m_scene.language = m_texts.language();
    const auto it = root.constFind(key);
    if (it != root.constEnd() && !it.value().isString() && !it.value().isObject()) {
        // Neither form: the message of a plain string, as before scenes had languages.
        return m_in.string(root, key, {}, out);
    }
    if (!m_texts.line(root, key, {}, out)) {
        return false;
    }
    if (it != root.constEnd() && it.value().isObject()) {
        // Each variant's place is KEY.CODE.
        for (const detail::LocalTexts::Variant& v : m_texts.variants()) {
            all.insert(v.place.section(u'.', -1), v.text);
        }
    }
    return true;
}

bool SceneReader::readColour(const QJsonObject& body, const QString& place, QString& out)
{
    if (!body.contains(u"colour")) {
        return true;
    }
    QString text;
    if (!m_in.string(body, u"colour", place, text)) {
        return false;
    }
    if (const QString problem = rules::colourProblem(text); !problem.isEmpty()) {
        return m_in.fail(joinPlace(place, u"colour"), problem);
    }
    out = text.toLower();
    return true;
}

bool SceneReader::readFields(schema::Object object, const QJsonObject& json, const QString& place,
                             std::size_t index)
{
    for (const schema::Field& field : schema::fields(object)) {
        if (!readField(field, json, place, index)) {
            return false;
        }
    }
    return true;
}

bool SceneReader::readField(const schema::Field& field, const QJsonObject& json,
                            const QString& place, std::size_t index)
{
    using schema::Kind;
    const QString key = QString::fromLatin1(field.key.data(), qsizetype(field.key.size()));
    switch (field.kind) {
    case Kind::Text:
        return readId(json, place, index);
    case Kind::LocalText:
        if (place.isEmpty()) {
            return key == u"title" ? readText(json, key, m_scene.title, m_scene.titles)
                                   : readText(json, key, m_scene.description, m_scene.descriptions);
        }
        return readLabel(json, place, m_scene.labels[index], m_scene.labelTexts[index]);
    case Kind::Colour:
        return readColour(json, place, m_scene.colours[index]);
    case Kind::Shape:
        if (!json.contains(key)) {
            return m_in.fail(joinPlace(place, key), FileMessages::tr("required, but missing"));
        }
        return readShape(json.value(key), joinPlace(place, key), m_scene.bodies[index].shape,
                         m_scene.originalVertices[index]);
    case Kind::Size: // a part of the shape
        return true;
    case Kind::End: {
        BodyId end = physics::kWorld;
        if (!readEnd(json, key, place, end, field.optional)) {
            return false;
        }
        field.set(m_scene, index, static_cast<int>(end));
        return true;
    }
    default:
        return detail::readPlainField(m_in, field, json, place, m_scene, index);
    }
}

bool SceneReader::readWorld(const QJsonObject& root)
{
    if (!root.contains(u"world")) {
        return true;
    }
    const QString place = QStringLiteral("world");
    QJsonObject world;
    return m_in.asObject(root.value(u"world"), place, world) &&
           m_in.checkKeys(world, place, schema::keys(schema::Object::World)) &&
           readFields(schema::Object::World, world, place, 0);
}

bool SceneReader::readBodies(const QJsonObject& root)
{
    const QString place = QStringLiteral("bodies");
    if (!root.contains(u"bodies")) {
        return m_in.fail(place, FileMessages::tr("required, but missing (it may be empty: [])"));
    }
    QJsonArray bodies;
    if (!m_in.asArray(root.value(u"bodies"), place, bodies)) {
        return false;
    }
    if (bodies.size() > kMaxBodies) {
        return m_in.fail(place, FileMessages::tr("%1 bodies, more than the limit of %2")
                                    .arg(bodies.size())
                                    .arg(kMaxBodies));
    }
    const auto n = static_cast<size_t>(bodies.size());
    m_scene.bodies.reserve(n);
    // The lists beside `bodies` have an entry for every body, empty unless the file fills it.
    m_scene.originalVertices.resize(n);
    m_scene.labels.resize(n);
    m_scene.labelTexts.resize(n);
    m_scene.colours.resize(n);
    for (qsizetype i = 0; i < bodies.size(); ++i) {
        m_scene.bodies.emplace_back();
        if (!readBody(bodies[i], indexPlace(place, i), static_cast<size_t>(i))) {
            return false;
        }
        m_ids.insert(QString::fromStdString(m_scene.bodies.back().name), static_cast<BodyId>(i));
    }
    return true;
}

bool SceneReader::readLabel(const QJsonObject& body, const QString& place, QString& label,
                            LocalTextMap& all)
{
    if (!body.contains(u"label")) {
        return true;
    }
    const auto value = body.value(u"label");
    if (!value.isString() && !value.isObject()) {
        // Neither form: the message of a plain string, the form most labels have.
        return m_in.string(body, u"label", place, label);
    }
    if (!m_texts.line(body, u"label", place, label)) {
        return false;
    }
    // Each language's label is checked, whichever is shown.
    for (const detail::LocalTexts::Variant& v : m_texts.variants()) {
        if (v.text.trimmed().isEmpty()) {
            return m_in.fail(v.place, FileMessages::tr("must not be empty (leave \"label\" out "
                                                       "to show the id)"));
        }
        if (v.text.size() > kMaxBodyLabelLength) {
            return m_in.fail(
                v.place, FileMessages::tr("longer than %1 characters").arg(kMaxBodyLabelLength));
        }
        for (QChar c : v.text) {
            if (c.category() == QChar::Other_Control) {
                return m_in.fail(v.place, FileMessages::tr("must not hold control characters"));
            }
        }
    }
    if (value.isObject()) {
        for (const detail::LocalTexts::Variant& v : m_texts.variants()) {
            all.insert(v.place.section(u'.', -1), v.text.trimmed());
        }
    }
    label = label.trimmed();
    return true;
}

bool SceneReader::readId(const QJsonObject& body, const QString& place, std::size_t index)
{
    QString id;
    if (!m_in.string(body, u"id", place, id, true)) {
        return false;
    }
    const QString idPlace = joinPlace(place, u"id");
    if (const QString problem = rules::idProblem(id); !problem.isEmpty()) {
        return m_in.fail(idPlace, problem);
    }
    if (const auto other = m_ids.constFind(id); other != m_ids.constEnd()) {
        return m_in.fail(idPlace, rules::duplicateId(id, other.value()));
    }
    m_scene.bodies[index].name = id.toStdString();
    return true;
}

bool SceneReader::readBody(const QJsonValue& value, const QString& place, std::size_t index)
{
    QJsonObject body;
    if (!m_in.asObject(value, place, body) ||
        !m_in.checkKeys(body, place, schema::keys(schema::Object::Body))) {
        return false;
    }
    if (body.contains(u"density") && body.contains(u"mass")) {
        return m_in.fail(joinPlace(place, u"mass"),
                         FileMessages::tr("give \"density\" or \"mass\", not both"));
    }
    if (!readFields(schema::Object::Body, body, place, index)) {
        return false;
    }
    const physics::BodyDef& def = m_scene.bodies[index];
    if (const auto problem = rules::checkMass(def)) {
        return m_in.fail(joinPlace(place, problem->key), problem->what);
    }
    if (def.type == physics::BodyType::Static &&
        (def.velocity != Vec2::Zero() || def.angularVelocity != 0)) {
        m_in.warn(place, FileMessages::tr("a static body never moves: its velocity is ignored "
                                          "(make it \"kinematic\" to move it)"));
    }
    return true;
}

bool SceneReader::readShape(const QJsonValue& value, const QString& place, physics::Shape& shape,
                            std::vector<Vec2>& original)
{
    QJsonObject object;
    QString type;
    // Keys of any shape first, so that a misspelt "type" is reported as what it is; each type
    // then checks its own.
    if (!m_in.asObject(value, place, object) ||
        !m_in.checkKeys(object, place, {u"type", u"radius", u"width", u"height", u"vertices"}) ||
        !m_in.string(object, u"type", place, type, true)) {
        return false;
    }
    if (type == u"circle") {
        double radius = 0;
        if (!m_in.checkKeys(object, place, {u"type", u"radius"}) ||
            !m_in.number(object, u"radius", place, radius, NumberRule::Positive, limits::kSize,
                         true)) {
            return false;
        }
        shape = physics::makeCircleShape(radius);
        return true;
    }
    if (type == u"box") {
        double width = 0;
        double height = 0;
        if (!m_in.checkKeys(object, place, {u"type", u"width", u"height"}) ||
            !m_in.number(object, u"width", place, width, NumberRule::Positive, limits::kSize,
                         true) ||
            !m_in.number(object, u"height", place, height, NumberRule::Positive, limits::kSize,
                         true)) {
            return false;
        }
        shape = physics::makePolygonShape(physics::makeBox(width, height));
        return true;
    }
    if (type == u"polygon") {
        const QString at = joinPlace(place, u"vertices");
        QJsonArray list;
        if (!m_in.checkKeys(object, place, {u"type", u"vertices"})) {
            return false;
        }
        if (!object.contains(u"vertices")) {
            return m_in.fail(at, FileMessages::tr("required, but missing"));
        }
        if (!m_in.asArray(object.value(u"vertices"), at, list)) {
            return false;
        }
        if (list.size() < 3 || list.size() > kMaxPolygonVertices) {
            return m_in.fail(at, rules::polygonVertexCount(list.size()));
        }
        std::vector<Vec2> vertices(static_cast<size_t>(list.size()));
        for (qsizetype i = 0; i < list.size(); ++i) {
            if (!m_in.vec2Value(list[i], indexPlace(at, i), vertices[static_cast<size_t>(i)],
                                limits::kVertex)) {
                return false;
            }
        }
        auto built = physics::makePolygon(vertices);
        if (!built) {
            return m_in.fail(at, QString::fromStdString(built.error()));
        }
        if (!built.value().warning.empty()) {
            m_in.warn(at, QString::fromStdString(built.value().warning));
            original = vertices;
        }
        shape = physics::makePolygonShape(std::move(built).value().polygon);
        return true;
    }
    return m_in.fail(
        joinPlace(place, u"type"),
        FileMessages::tr("unknown shape type \"%1\" (expected circle, box, polygon)").arg(type));
}

} // namespace detail

SceneLoadResult loadSceneObject(const QJsonObject& root, const QString& sourceName,
                                const SceneLoadOptions& options)
{
    return detail::SceneReader(sourceName, options).read(root);
}

SceneLoadResult loadSceneJson(const QByteArray& bytes, const QString& sourceName,
                              const SceneLoadOptions& options)
{
    const detail::ParsedJson parsed = detail::parseJson(bytes, sourceName, kMaxSceneFileBytes);
    SceneLoadResult result;
    if (!parsed.ok) {
        result.error = parsed.error;
        return result;
    }
    if (!parsed.document.isObject()) {
        result.error = sourceName + FileMessages::tr(": the top level must be an object {...}, "
                                                     "got an array");
        return result;
    }
    return loadSceneObject(parsed.document.object(), sourceName, options);
}

SceneLoadResult loadSceneFile(const QString& path, const SceneLoadOptions& options)
{
    const detail::FileBytes file = detail::readFileBytes(path, kMaxSceneFileBytes);
    if (!file.ok) {
        SceneLoadResult result;
        result.error = file.error;
        return result;
    }
    return loadSceneJson(file.bytes, path, options);
}

} // namespace rigidlab::lessons
