// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The scene editor's edits (lessons/edit/), tested in test_scene_edits.cpp (adding, moving,
// deleting) and test_scene_field_edits.cpp (setting fields, overlaps): the test class and the
// scenes and helpers they share.

#include "edit/scene_edits.h"
#include "format/scene_loader.h"

#include "rigidlab/physics/world.h"

#include "test_main.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rigidlab::test::scene_edits {

using namespace rigidlab::lessons;
using physics::BodyType;
using physics::kWorld;
using physics::Vec2;

inline constexpr double kTolerance = 1e-12;

inline bool near(const Vec2& a, const Vec2& b, double tol = kTolerance)
{
    return (a - b).norm() <= tol;
}

/// What the loader says about one body given as JSON: its error, or its first warning.
inline SceneLoadResult loadOneBody(const QJsonObject& body)
{
    QJsonObject root{{QStringLiteral("rigidlab"), 1}, {QStringLiteral("bodies"), QJsonArray{body}}};
    return loadSceneObject(root, QStringLiteral("scene.json"));
}

/// The words after `SOURCE: PLACE: `, where messages of file and editor must agree.
inline QString what(const QString& message)
{
    return message.section(QStringLiteral(": "), 2);
}

inline QString idOf(const Scene& scene, int i)
{
    return QString::fromStdString(scene.bodies[static_cast<size_t>(i)].name);
}

/// A scene with bodies a, b, c, d in a row, springs a-c, b-d, c-world and pins d-b, a-world.
inline Scene fourBodies()
{
    Scene scene;
    for (const char* id : {"a", "b", "c", "d"}) {
        physics::BodyDef def;
        def.name = id;
        def.shape = physics::makeCircleShape(0.25);
        def.position = Vec2(static_cast<double>(scene.bodies.size()), 0.0);
        scene.bodies.push_back(def);
        scene.originalVertices.emplace_back();
    }
    scene.springs.push_back({0, Vec2::Zero(), 2, Vec2::Zero(), 10.0, 0.0, 2.0});
    scene.springs.push_back({1, Vec2::Zero(), 3, Vec2::Zero(), 20.0, 0.0, 2.0});
    scene.springs.push_back({2, Vec2::Zero(), kWorld, Vec2(2.0, 1.0), 30.0, 0.0, 1.0});
    scene.joints.push_back({3, Vec2(-0.5, 0.0), 1, Vec2(1.5, 0.0)});
    scene.joints.push_back({0, Vec2::Zero(), kWorld, Vec2::Zero()});
    scene.colours = {QString(), QStringLiteral("#ff0000"), QStringLiteral("#00ff00")};
    return scene;
}

} // namespace rigidlab::test::scene_edits

class TestSceneEdits : public QObject {
    Q_OBJECT
private slots:
    void addsBodiesWithUniqueIds();
    void refusesSizesWithTheLoadersWords();
    void addsPolygonAtItsCentroid();
    void nonConvexPolygonBecomesItsHull();
    void degeneratePolygonIsRefused_data();
    void degeneratePolygonIsRefused();
    void movesAndRotates();
    void pinsToTheWorldFollowTheirBody();
    void movedPendulumSwingsAboutItsNewPivot();
    void deleteRenumbersSpringsAndPins();
    void duplicateTakesANewId();
    void addsPins();
    void addsSprings();
    void setsBodyProperties();
    void renamesBodies();
    void setsVelocityAndColour();
    void setsSpringAndWorldProperties();
    void listsOverlaps();
    void refusesCrowding();
};
