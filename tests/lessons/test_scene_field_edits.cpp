// SPDX-License-Identifier: GPL-3.0-or-later
// The scene editor's field edits (lessons/edit/): a body's, a spring's and the world's numbers,
// its velocity, colour and id, with the loader's words for each refusal; overlapping bodies.

#include "test_scene_edits.h"

#include "format/scene_overlaps.h"
#include "rigidlab/physics/work_budget.h"

using namespace rigidlab;
using namespace rigidlab::test::scene_edits;

void TestSceneEdits::setsBodyProperties()
{
    Scene scene;
    scene = edit::addBox(scene, Vec2::Zero(), 2.0, 1.0).scene;
    auto r = edit::setBodyNumber(scene, 0, edit::BodyNumber::Mass, 3.0);
    QVERIFY(r.ok);
    QCOMPARE(r.scene.bodies[0].mass, 3.0);
    r = edit::setBodyNumber(r.scene, 0, edit::BodyNumber::Density, 4.0);
    QVERIFY(r.ok);
    QCOMPARE(r.scene.bodies[0].density, 4.0);
    QCOMPARE(r.scene.bodies[0].mass, 0.0); // the density rules again: 8 kg
    r = edit::setBodyNumber(r.scene, 0, edit::BodyNumber::VelocityY, -2.5);
    QVERIFY(r.ok);
    QCOMPARE(r.scene.bodies[0].velocity.y(), -2.5);
    r = edit::setBodyNumber(r.scene, 0, edit::BodyNumber::AngularVelocity, 1.5);
    QCOMPARE(r.scene.bodies[0].angularVelocity, 1.5);
    r = edit::setBodyNumber(r.scene, 0, edit::BodyNumber::Friction, 0.7);
    QCOMPARE(r.scene.bodies[0].friction, 0.7);
    r = edit::setBodyType(r.scene, 0, BodyType::Kinematic);
    QVERIFY(r.ok);
    QCOMPARE(r.scene.bodies[0].type, BodyType::Kinematic);

    const auto bounce = edit::setBodyNumber(scene, 0, edit::BodyNumber::Restitution, 1.5);
    QVERIFY(!bounce.ok);
    QVERIFY2(bounce.error.startsWith(QStringLiteral("box1: restitution: must be from 0 to 1")),
             qPrintable(bounce.error));
    const auto heavy = edit::setBodyNumber(scene, 0, edit::BodyNumber::Mass, 0.0);
    QVERIFY(!heavy.ok);
    QVERIFY2(heavy.error.startsWith(QStringLiteral("box1: mass: ")), qPrintable(heavy.error));
    // Each density is in range, but density times area is not a mass a scene may hold.
    Scene big = edit::addBox(Scene{}, Vec2::Zero(), 1e4, 1e4).scene;
    const auto dense = edit::setBodyNumber(big, 0, edit::BodyNumber::Density, limits::kDensity.max);
    QVERIFY(!dense.ok);
    QVERIFY2(dense.error.startsWith(QStringLiteral("box1: density: the mass works out as")),
             qPrintable(dense.error));
    const auto nan = edit::setBodyNumber(scene, 0, edit::BodyNumber::VelocityX, std::nan(""));
    QVERIFY(!nan.ok);
}

void TestSceneEdits::setsVelocityAndColour()
{
    const Scene scene = fourBodies();
    auto r = edit::setBodyVelocity(scene, 1, Vec2(1.5, -2.0));
    QVERIFY2(r.ok, qPrintable(r.error));
    QCOMPARE(r.scene.bodies[1].velocity, Vec2(1.5, -2.0));
    QCOMPARE(r.scene.bodies[0].velocity, Vec2::Zero());
    // Out of range: refused with the loader's words and place, nothing clamped.
    const double fast = limits::kVelocity.max * 2.0;
    const auto tooFast = edit::setBodyVelocity(scene, 1, Vec2(0.0, fast));
    QVERIFY(!tooFast.ok);
    QJsonObject body{
        {QStringLiteral("id"), QStringLiteral("b")},
        {QStringLiteral("shape"), QJsonObject{{QStringLiteral("type"), QStringLiteral("circle")},
                                              {QStringLiteral("radius"), 0.25}}},
        {QStringLiteral("velocity"), QJsonArray{0.0, fast}}};
    const auto loaded = loadOneBody(body);
    QVERIFY(!loaded.ok);
    QVERIFY2(tooFast.error.startsWith(QStringLiteral("b: velocity[1]: ")),
             qPrintable(tooFast.error));
    QCOMPARE(what(tooFast.error), what(loaded.error));
    QVERIFY(!edit::setBodyVelocity(scene, 1, Vec2(std::nan(""), 0.0)).ok);
    QVERIFY(!edit::setBodyVelocity(scene, 7, Vec2::Zero()).ok);

    // A colour is kept in lower case, "" takes it away; the body with none gets one.
    r = edit::setBodyColour(scene, 3, QStringLiteral("#D04030"));
    QVERIFY2(r.ok, qPrintable(r.error));
    QCOMPARE(r.scene.colourOf(3), QStringLiteral("#d04030"));
    QCOMPARE(r.scene.colourOf(1), QStringLiteral("#ff0000"));
    r = edit::setBodyColour(r.scene, 1, QString());
    QVERIFY(r.ok);
    QVERIFY(r.scene.colourOf(1).isEmpty());
    body.remove(QStringLiteral("velocity"));
    for (const char* bad : {"red", "#12345", "#1234567", "d04030", "#gg0000"}) {
        const auto refused = edit::setBodyColour(scene, 0, QString::fromLatin1(bad));
        QVERIFY2(!refused.ok, bad);
        body[QStringLiteral("colour")] = QString::fromLatin1(bad);
        const auto file = loadOneBody(body);
        QVERIFY(!file.ok);
        QVERIFY2(refused.error.startsWith(QStringLiteral("a: colour: must be a colour")),
                 qPrintable(refused.error));
        QCOMPARE(what(refused.error), what(file.error));
    }
}

void TestSceneEdits::renamesBodies()
{
    const Scene scene = fourBodies();
    auto r = edit::setBodyId(scene, 2, QStringLiteral("bob"));
    QVERIFY(r.ok);
    QCOMPARE(idOf(r.scene, 2), QStringLiteral("bob"));
    QCOMPARE(r.scene.springs[0].b, 2);
    const auto taken = edit::setBodyId(scene, 2, QStringLiteral("a"));
    QVERIFY(!taken.ok);
    QCOMPARE(taken.error, QStringLiteral("c: id: duplicate id \"a\" (bodies[0] has it already)"));
    QVERIFY(edit::setBodyId(scene, 2, QStringLiteral("c")).ok); // its own id
    const auto empty = edit::setBodyId(scene, 2, QString());
    QVERIFY(!empty.ok);
    QCOMPARE(empty.error, QStringLiteral("c: id: must not be empty"));
    QVERIFY(!edit::setBodyId(scene, 2, QString(kMaxBodyIdLength + 1, u'x')).ok);
}

void TestSceneEdits::setsSpringAndWorldProperties()
{
    const Scene scene = fourBodies();
    auto r = edit::setSpringNumber(scene, 1, edit::SpringNumber::RestLength, 0.75);
    QVERIFY(r.ok);
    QCOMPARE(r.scene.springs[1].restLength, 0.75);
    r = edit::setSpringNumber(r.scene, 1, edit::SpringNumber::Damping, 0.2);
    QCOMPARE(r.scene.springs[1].damping, 0.2);
    const auto soft = edit::setSpringNumber(scene, 1, edit::SpringNumber::Stiffness, -5.0);
    QVERIFY(!soft.ok);
    QVERIFY2(soft.error.startsWith(QStringLiteral("springs[1]: stiffness: must be ")),
             qPrintable(soft.error));
    QVERIFY(!edit::setSpringNumber(scene, 3, edit::SpringNumber::Stiffness, 1.0).ok);

    r = edit::setWorldNumber(scene, edit::WorldNumber::GravityY, -1.62);
    QVERIFY(r.ok);
    QCOMPARE(r.scene.world.gravity.y(), -1.62);
    r = edit::setWorldNumber(r.scene, edit::WorldNumber::Iterations, 25.0);
    QCOMPARE(r.scene.world.iterations, 25);
    r = edit::setIntegrator(r.scene, physics::IntegratorKind::Verlet);
    QCOMPARE(r.scene.world.integrator, physics::IntegratorKind::Verlet);
    const auto dt = edit::setWorldNumber(scene, edit::WorldNumber::Dt, limits::kDt.max * 2);
    QVERIFY(!dt.ok);
    QVERIFY2(dt.error.startsWith(QStringLiteral("world: dt: must be from ")), qPrintable(dt.error));
    const auto half = edit::setWorldNumber(scene, edit::WorldNumber::Iterations, 2.5);
    QVERIFY(!half.ok);
    QCOMPARE(half.error, QStringLiteral("world: iterations: must be a whole number"));
}

void TestSceneEdits::listsOverlaps()
{
    Scene scene;
    scene = edit::addGround(scene, Vec2(0.0, -0.5), 10.0, 1.0).scene; // top at y = 0
    scene = edit::addBox(scene, Vec2(0.0, 0.5), 1.0, 1.0).scene;      // resting on it
    scene = edit::addCircle(scene, Vec2(3.0, 1.0), 0.5).scene;        // clear of all
    scene = edit::addGround(scene, Vec2(5.0, -0.5), 1.0, 3.0).scene;  // static in static
    QVERIFY(edit::overlappingPairs(scene).empty());
    QVERIFY(edit::overlapMessage(scene).isEmpty());

    scene = edit::addCircle(scene, Vec2(3.6, 1.0), 0.5).scene; // into circle1 by 0.4 m
    const auto pairs = edit::overlappingPairs(scene);
    QCOMPARE(pairs.size(), size_t(1));
    QCOMPARE(pairs[0], std::make_pair(2, 4));
    QVERIFY2(edit::overlapMessage(scene).startsWith(QStringLiteral("circle1 overlaps circle2")),
             qPrintable(edit::overlapMessage(scene)));
    // Passing through everything is no overlap.
    scene.bodies[4].collide = false;
    QVERIFY(edit::overlappingPairs(scene).empty());
}

void TestSceneEdits::refusesCrowding()
{
    // Duplicate pressed again and again on one ball puts every copy at one place: once their
    // boxes make more pairs than the engine's budget for a step, the edit is refused with the
    // loader's words, and the scene stays as it was.
    Scene scene = edit::addGround(Scene{}, Vec2(0.0, -0.5), 20.0, 1.0).scene;
    scene = edit::addCircle(scene, Vec2(0.0, 1.0), 0.1).scene;
    edit::EditResult r;
    int copies = 0;
    for (; copies < 1000; ++copies) {
        r = edit::duplicateBody(scene, 1, Vec2::Zero());
        if (!r.ok)
            break;
        scene = std::move(r.scene);
    }
    QVERIFY2(!r.ok, "never refused");
    QVERIFY2(r.error.contains(QStringLiteral(": bodies: more than %1 pairs of bodies")
                                  .arg(lessons::boxPairBudget(scene) + physics::kPairsPerBody)),
             qPrintable(r.error));
    QVERIFY2(r.error.contains(QStringLiteral("spread them out")), qPrintable(r.error));
    // n balls at one point make n (n - 1) / 2 pairs: refused at the first n past the budget.
    const std::size_t balls = scene.bodies.size(); // the ground and the balls kept
    const std::size_t n = balls;                   // with the refused copy
    QVERIFY2(n * (n - 1) / 2 > physics::pairBudget(balls + 1) &&
                 (n - 1) * (n - 2) / 2 <= physics::pairBudget(balls),
             qPrintable(QStringLiteral("%1 balls kept").arg(n - 1)));
    QVERIFY(!lessons::surveyOverlaps(scene, 0).crowded);

    // The editor's own Duplicate places each copy beside the one before: a row of 300 balls
    // is never crowded.
    Scene row = edit::addCircle(Scene{}, Vec2(0.0, 1.0), 0.1).scene;
    for (int i = 0; i < 300; ++i) {
        r = edit::duplicateBody(row, i, Vec2(0.2, 0.0));
        QVERIFY2(r.ok, qPrintable(r.error));
        row = std::move(r.scene);
    }
}
