// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/sat_report.h"

#include "format/json_reader.h"

#include "format/scene_loader.h"
#include "rigidlab/physics/shape.h"

#include <QJsonArray>

namespace rigidlab::lessons {

using detail::indexPlace;
using detail::joinPlace;
using detail::JsonReader;
using physics::Vec2;

namespace {

QJsonArray toJson(const Vec2& v)
{
    return QJsonArray{v.x(), v.y()};
}

/// A placed convex polygon.
struct PlacedPolygon {
    physics::Polygon polygon;
    physics::Transform transform;
};

bool readPolygon(JsonReader& in, const QJsonObject& pair, QStringView key, const QString& place,
                 PlacedPolygon& out)
{
    const QString at = joinPlace(place, key);
    QJsonObject object;
    QJsonArray list;
    Vec2 position = Vec2::Zero();
    double angle = 0;
    if (!pair.contains(key)) {
        return in.fail(at, QStringLiteral("required, but missing"));
    }
    if (!in.asObject(pair.value(key), at, object) ||
        !in.checkKeys(object, at, {u"vertices", u"position", u"angle"}) ||
        !in.vec2(object, u"position", at, position) || !in.number(object, u"angle", at, angle)) {
        return false;
    }
    const QString verticesAt = joinPlace(at, u"vertices");
    if (!object.contains(u"vertices")) {
        return in.fail(verticesAt, QStringLiteral("required, but missing"));
    }
    if (!in.asArray(object.value(u"vertices"), verticesAt, list)) {
        return false;
    }
    if (list.size() < 3 || list.size() > kMaxPolygonVertices) {
        return in.fail(verticesAt, QStringLiteral("a polygon needs 3 to %1 vertices, got %2")
                                       .arg(kMaxPolygonVertices)
                                       .arg(list.size()));
    }
    std::vector<Vec2> vertices(static_cast<size_t>(list.size()));
    for (qsizetype i = 0; i < list.size(); ++i) {
        if (!in.vec2Value(list[i], indexPlace(verticesAt, i), vertices[static_cast<size_t>(i)])) {
            return false;
        }
    }
    auto built = physics::makePolygon(vertices);
    if (!built) {
        return in.fail(verticesAt, QString::fromStdString(built.error()));
    }
    if (!built.value().warning.empty()) {
        in.warn(verticesAt, QString::fromStdString(built.value().warning));
    }
    out.polygon = std::move(built).value().polygon;
    out.transform = physics::Transform(position, angle);
    return true;
}

bool readPair(JsonReader& in, const QJsonValue& value, const QString& place, QJsonObject& out)
{
    const QString at = place.isEmpty() ? QStringLiteral("(top level)") : place;
    QJsonObject pair;
    PlacedPolygon a;
    PlacedPolygon b;
    if (!in.asObject(value, at, pair) || !in.checkKeys(pair, place, {u"a", u"b"}) ||
        !readPolygon(in, pair, u"a", place, a) || !readPolygon(in, pair, u"b", place, b)) {
        return false;
    }
    // margin 0: the textbook verdict (touching counts as intersecting); record every axis.
    const physics::SatResult result =
        physics::satPolygons(a.polygon, a.transform, b.polygon, b.transform, 0.0, true);
    out = satResultToJson(result);
    return true;
}

} // namespace

QJsonObject satResultToJson(const physics::SatResult& result)
{
    QJsonArray axes;
    for (const physics::SatAxis& axis : result.axes) {
        axes.append(QJsonObject{
            {QStringLiteral("owner"), axis.owner == 0 ? QStringLiteral("a") : QStringLiteral("b")},
            {QStringLiteral("edge"), axis.edge},
            {QStringLiteral("axis"), toJson(axis.axis)},
            {QStringLiteral("a"), QJsonArray{axis.minA, axis.maxA}},
            {QStringLiteral("b"), QJsonArray{axis.minB, axis.maxB}},
            {QStringLiteral("overlap"), axis.overlap},
        });
    }
    QJsonArray contacts;
    if (result.intersects) {
        for (int i = 0; i < result.manifold.pointCount; ++i) {
            contacts.append(toJson(result.manifold.points[static_cast<size_t>(i)].point));
        }
    }
    const auto indexOrNull = [](int index) {
        return index >= 0 ? QJsonValue(index) : QJsonValue(QJsonValue::Null);
    };
    return QJsonObject{
        {QStringLiteral("intersects"), result.intersects},
        {QStringLiteral("axes"), axes},
        {QStringLiteral("separatingAxis"), indexOrNull(result.separatingAxis)},
        {QStringLiteral("leastAxis"), indexOrNull(result.intersects ? result.leastAxis : -1)},
        {QStringLiteral("normal"),
         result.intersects ? QJsonValue(toJson(result.normal)) : QJsonValue(QJsonValue::Null)},
        {QStringLiteral("depth"),
         result.intersects ? QJsonValue(result.depth) : QJsonValue(QJsonValue::Null)},
        {QStringLiteral("contacts"), contacts},
    };
}

SatReport satReportJson(const QByteArray& bytes, const QString& sourceName)
{
    SatReport report;
    const detail::ParsedJson parsed = detail::parseJson(bytes, sourceName, kMaxSceneFileBytes);
    if (!parsed.ok) {
        report.error = parsed.error;
        return report;
    }
    JsonReader in(sourceName);
    QJsonDocument output;
    if (parsed.document.isArray()) {
        const QJsonArray pairs = parsed.document.array();
        if (pairs.size() > kMaxSatPairs) {
            in.fail(QStringLiteral("(top level)"),
                    QStringLiteral("%1 pairs, more than the limit of %2")
                        .arg(pairs.size())
                        .arg(kMaxSatPairs));
        }
        QJsonArray results;
        for (qsizetype i = 0; i < pairs.size() && !in.failed(); ++i) {
            QJsonObject one;
            if (readPair(in, pairs[i], indexPlace(QString(), i), one)) {
                results.append(one);
            }
        }
        output.setArray(results);
    } else {
        QJsonObject one;
        readPair(in, parsed.document.object(), QString(), one);
        output.setObject(one);
    }
    report.warnings = in.warnings();
    if (in.failed()) {
        report.error = in.error();
        return report;
    }
    report.ok = true;
    report.json = output.toJson(QJsonDocument::Indented);
    return report;
}

SatReport satReportFile(const QString& path)
{
    const detail::FileBytes file = detail::readFileBytes(path, kMaxSceneFileBytes);
    if (!file.ok) {
        SatReport report;
        report.error = file.error;
        return report;
    }
    return satReportJson(file.bytes, path);
}

} // namespace rigidlab::lessons
