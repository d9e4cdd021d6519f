// SPDX-License-Identifier: GPL-3.0-or-later
// The scene editor's edits (lessons/edit/): each edit, each refusal with the words the scene
// loader uses for the same mistake in a file, deleting a body with its springs and pins, and
// ids that stay unique.

#include "test_scene_edits.h"
#include "near.h"

using namespace rigidlab;
using namespace rigidlab::test::scene_edits;

void TestSceneEdits::addsBodiesWithUniqueIds()
{
    Scene scene;
    auto r = edit::addCircle(scene, Vec2(1.0, 2.0), 0.5);
    QVERIFY2(r.ok, qPrintable(r.error));
    QCOMPARE(r.body, 0);
    QCOMPARE(idOf(r.scene, 0), QStringLiteral("circle1"));
    QVERIFY(near(r.scene.bodies[0].position, Vec2(1.0, 2.0)));
    QCOMPARE(r.scene.bodies[0].shape.asCircle()->radius, 0.5);
    QCOMPARE(r.scene.bodies[0].type, BodyType::Dynamic);
    QCOMPARE(r.scene.originalVertices.size(), r.scene.bodies.size());

    r = edit::addCircle(r.scene, Vec2(3.0, 2.0), 0.5);
    QVERIFY(r.ok);
    QCOMPARE(idOf(r.scene, 1), QStringLiteral("circle2"));
    r = edit::addBox(r.scene, Vec2(0.0, 5.0), 2.0, 1.0);
    QVERIFY(r.ok);
    QCOMPARE(idOf(r.scene, 2), QStringLiteral("box1"));
    const physics::Polygon* box = r.scene.bodies[2].shape.asPolygon();
    QVERIFY(box);
    QCOMPARE(box->vertices.size(), size_t(4));
    QCOMPARE(physics::computeMass(r.scene.bodies[2].shape, 1.0).area, 2.0);
    r = edit::addGround(r.scene, Vec2(0.0, -0.5), 20.0, 1.0);
    QVERIFY(r.ok);
    QCOMPARE(idOf(r.scene, 3), QStringLiteral("ground1"));
    QCOMPARE(r.scene.bodies[3].type, BodyType::Static);

    // A gap left by a deleted body is filled first; ids never repeat.
    r = edit::deleteBody(r.scene, 0);
    QVERIFY(r.ok);
    r = edit::addCircle(r.scene, Vec2::Zero(), 1.0);
    QCOMPARE(idOf(r.scene, 3), QStringLiteral("circle1"));
    QSet<QString> ids;
    for (int i = 0; i < static_cast<int>(r.scene.bodies.size()); ++i) {
        ids.insert(idOf(r.scene, i));
    }
    QCOMPARE(ids.size(), static_cast<qsizetype>(r.scene.bodies.size()));
}

void TestSceneEdits::refusesSizesWithTheLoadersWords()
{
    const Scene empty;
    const auto circle = edit::addCircle(empty, Vec2::Zero(), 0.0);
    QVERIFY(!circle.ok);
    QVERIFY2(circle.error.startsWith(QStringLiteral("circle1: shape.radius: ")),
             qPrintable(circle.error));
    const auto fromFile =
        loadOneBody({{QStringLiteral("id"), QStringLiteral("c")},
                     {QStringLiteral("shape"),
                      QJsonObject{{QStringLiteral("type"), QStringLiteral("circle")},
                                  {QStringLiteral("radius"), limits::kSize.max * 2}}}});
    QVERIFY(!fromFile.ok);
    const auto tooBig = edit::addCircle(empty, Vec2::Zero(), limits::kSize.max * 2);
    QVERIFY(!tooBig.ok);
    QCOMPARE(what(tooBig.error), what(fromFile.error));

    const auto box = edit::addBox(empty, Vec2::Zero(), 1.0, -1.0);
    QVERIFY(!box.ok);
    QVERIFY2(box.error.startsWith(QStringLiteral("box1: shape.height: ")), qPrintable(box.error));
    const auto far = edit::addBox(empty, Vec2(limits::kCoordinate.max * 2, 0.0), 1.0, 1.0);
    QVERIFY(!far.ok);
    QVERIFY2(far.error.startsWith(QStringLiteral("box1: position[0]: ")), qPrintable(far.error));
    const auto nan = edit::addCircle(empty, Vec2(std::nan(""), 0.0), 1.0);
    QVERIFY(!nan.ok);
}

void TestSceneEdits::addsPolygonAtItsCentroid()
{
    // A right triangle with its right angle at (1, 1): centroid (1 + 3/3, 1 + 3/3).
    const std::vector<Vec2> points{{1.0, 1.0}, {4.0, 1.0}, {1.0, 4.0}};
    const auto r = edit::addPolygon(Scene{}, points);
    QVERIFY2(r.ok, qPrintable(r.error));
    QVERIFY(r.warning.isEmpty());
    const physics::BodyDef& def = r.scene.bodies[0];
    QCOMPARE(QString::fromStdString(def.name), QStringLiteral("polygon1"));
    QVERIFY(near(def.position, Vec2(2.0, 2.0), 1e-12));
    const physics::MassProperties mass = physics::computeMass(def.shape, 1.0);
    RL_VERIFY_NEAR(mass.area, 4.5, 1e-12, 0);
    QVERIFY(near(mass.centroid, Vec2::Zero(), 1e-12));
    // Every point drawn is a vertex where it was drawn.
    const physics::Transform xf(def.position, def.angle);
    for (const Vec2& p : points) {
        bool found = false;
        for (const Vec2& v : def.shape.asPolygon()->vertices) {
            found = found || near(xf.apply(v), p, 1e-12);
        }
        QVERIFY(found);
    }
    QVERIFY(r.scene.originalVertices[0].empty());
}

void TestSceneEdits::nonConvexPolygonBecomesItsHull()
{
    // A dart: (2, 1) dents the square-ish outline inwards.
    const std::vector<Vec2> points{{0.0, 0.0}, {4.0, 0.0}, {2.0, 1.0}, {4.0, 4.0}, {0.0, 4.0}};
    const auto preview = edit::previewPolygon(points);
    QVERIFY(preview.ok);
    QCOMPARE(preview.hull.size(), size_t(4));
    const auto r = edit::addPolygon(Scene{}, points);
    QVERIFY2(r.ok, qPrintable(r.error));
    QCOMPARE(r.scene.bodies[0].shape.asPolygon()->vertices.size(), size_t(4));
    QCOMPARE(r.scene.originalVertices[0].size(), points.size());

    QJsonArray vertices;
    for (const Vec2& p : points) {
        vertices.append(QJsonArray{p.x(), p.y()});
    }
    const auto fromFile = loadOneBody(
        {{QStringLiteral("id"), QStringLiteral("p")},
         {QStringLiteral("shape"), QJsonObject{{QStringLiteral("type"), QStringLiteral("polygon")},
                                               {QStringLiteral("vertices"), vertices}}}});
    QVERIFY(fromFile.ok);
    QCOMPARE(fromFile.warnings.size(), 1);
    QVERIFY2(r.warning.startsWith(QStringLiteral("polygon1: shape.vertices: ")),
             qPrintable(r.warning));
    QCOMPARE(what(r.warning), what(fromFile.warnings.front()));
    QCOMPARE(what(r.warning), preview.warning);
}

void TestSceneEdits::degeneratePolygonIsRefused_data()
{
    QTest::addColumn<std::vector<Vec2>>("points");
    QTest::addColumn<QString>("message");
    const QString count =
        QStringLiteral("a polygon needs 3 to %1 vertices, got 2").arg(kMaxPolygonVertices);
    const QString area = QStringLiteral("the polygon has no area");
    QTest::newRow("two points") << std::vector<Vec2>{{0.0, 0.0}, {1.0, 0.0}} << count;
    QTest::newRow("a point repeated")
        << std::vector<Vec2>{{1.0, 1.0}, {1.0, 1.0}, {1.0, 1.0}} << area;
    QTest::newRow("on one line") << std::vector<Vec2>{{0.0, 0.0}, {1.0, 1.0}, {2.0, 2.0}} << area;
    QTest::newRow("two distinct of four")
        << std::vector<Vec2>{{0.0, 0.0}, {0.0, 0.0}, {3.0, 0.0}, {3.0, 0.0}} << area;
}

void TestSceneEdits::degeneratePolygonIsRefused()
{
    QFETCH(std::vector<Vec2>, points);
    QFETCH(QString, message);
    const auto r = edit::addPolygon(Scene{}, points);
    QVERIFY(!r.ok);
    QVERIFY2(r.error.startsWith(QStringLiteral("polygon1: shape.vertices: ") + message),
             qPrintable(r.error));
    QVERIFY(!edit::previewPolygon(points).ok);

    std::vector<Vec2> many;
    for (int i = 0; i <= kMaxPolygonVertices; ++i) {
        const double a = 2 * std::numbers::pi * i / (kMaxPolygonVertices + 1);
        many.emplace_back(std::cos(a), std::sin(a));
    }
    const auto tooMany = edit::addPolygon(Scene{}, many);
    QVERIFY(!tooMany.ok);
    QVERIFY2(tooMany.error.contains(QString::number(kMaxPolygonVertices + 1)),
             qPrintable(tooMany.error));
}

void TestSceneEdits::movesAndRotates()
{
    const Scene scene = fourBodies();
    auto r = edit::moveBody(scene, 2, Vec2(5.0, -3.0));
    QVERIFY(r.ok);
    QVERIFY(near(r.scene.bodies[2].position, Vec2(5.0, -3.0)));
    QVERIFY(near(r.scene.bodies[1].position, scene.bodies[1].position));
    r = edit::rotateBody(r.scene, 2, 0.75);
    QVERIFY(r.ok);
    QCOMPARE(r.scene.bodies[2].angle, 0.75);

    const auto far = edit::moveBody(scene, 1, Vec2(0.0, -limits::kCoordinate.max * 10));
    QVERIFY(!far.ok);
    QVERIFY2(far.error.startsWith(QStringLiteral("b: position[1]: must be ")),
             qPrintable(far.error));
    const auto spin = edit::rotateBody(scene, 1, limits::kAngle.max * 2);
    QVERIFY(!spin.ok);
    QVERIFY2(spin.error.startsWith(QStringLiteral("b: angle: ")), qPrintable(spin.error));
    QVERIFY(!edit::moveBody(scene, 4, Vec2::Zero()).ok);
    QVERIFY(!edit::moveBody(scene, kWorld, Vec2::Zero()).ok);
}

void TestSceneEdits::pinsToTheWorldFollowTheirBody()
{
    Scene scene = fourBodies(); // pins d-b and a-world (at a's centre); spring c-world
    scene.joints.push_back({kWorld, Vec2::Zero(), 2, Vec2(0.0, 0.2)}); // world first: c-world
    const auto onBody = [](const Scene& s, int body, const Vec2& local) {
        const auto& d = s.bodies[static_cast<size_t>(body)];
        return physics::Transform(d.position, d.angle).apply(local);
    };

    // Moving a: its pin to the world moves with it; the pin between d and b is left alone.
    auto r = edit::moveBody(scene, 0, Vec2(4.0, -2.0));
    QVERIFY2(r.ok, qPrintable(r.error));
    QVERIFY(near(r.scene.joints[1].anchorB, Vec2(4.0, -2.0)));
    QVERIFY(near(r.scene.joints[0].anchorB, scene.joints[0].anchorB));
    QVERIFY(near(r.scene.joints[2].anchorA, scene.joints[2].anchorA));

    // Moving and turning c: the pin stays at its point of c, whichever end names the world;
    // the spring's world end stays where it was (the spring stretches).
    r = edit::moveBody(scene, 2, Vec2(-1.0, 3.0));
    QVERIFY(r.ok);
    QVERIFY(near(r.scene.joints[2].anchorA, Vec2(-1.0, 3.2)));
    r = edit::rotateBody(r.scene, 2, std::numbers::pi / 2);
    QVERIFY(r.ok);
    QVERIFY(near(r.scene.joints[2].anchorA, Vec2(-1.2, 3.0)));
    QVERIFY(near(r.scene.joints[2].anchorA, onBody(r.scene, 2, Vec2(0.0, 0.2))));
    QVERIFY(near(r.scene.springs[2].anchorB, Vec2(2.0, 1.0)));
    QCOMPARE(r.scene.springs[2].restLength, scene.springs[2].restLength);

    // So does a position typed in the inspector; a mass typed there moves nothing.
    r = edit::setBodyNumber(scene, 0, edit::BodyNumber::PositionY, 1.5);
    QVERIFY(r.ok);
    QVERIFY(near(r.scene.joints[1].anchorB, Vec2(0.0, 1.5)));
    Scene offset = scene;
    offset.joints[1].anchorB = Vec2(0.0, 0.5); // a file's pin away from its point of the body
    r = edit::setBodyNumber(offset, 0, edit::BodyNumber::Mass, 2.0);
    QVERIFY(r.ok);
    QVERIFY(near(r.scene.joints[1].anchorB, Vec2(0.0, 0.5)));

    // A move that would carry the pin's world end out of the format's coordinates is refused
    // with the loader's words for that anchor, and nothing changes.
    scene.joints[1].anchorA = Vec2(0.0, 0.25);
    r = edit::moveBody(scene, 0, Vec2(0.0, limits::kCoordinate.max));
    QVERIFY(!r.ok);
    QVERIFY2(r.error.startsWith(QStringLiteral("joints[1]: anchorB[1]: ")), qPrintable(r.error));
}

void TestSceneEdits::movedPendulumSwingsAboutItsNewPivot()
{
    // A ball pinned to the world 1 m above its centre, built by hand, then moved and turned
    // as a user would drag and turn it: the pivot goes with the ball, so the ball swings as a
    // compound pendulum about the new pivot, with the period of small swings
    // T = 2 pi sqrt(I_pivot / (m g L)), I_pivot = m (r^2/2 + L^2) (Kleppner & Kolenkow 6.6).
    constexpr double kRadius = 0.1;   // [m]
    constexpr double kArm = 1.0;      // pivot to centre [m]
    constexpr double kSwing = 0.1;    // the turn given, the swing's amplitude [rad]
    constexpr double kGravity = 9.81; // [m/s^2]
    Scene scene;
    scene.world.gravity = Vec2(0.0, -kGravity);
    auto r = edit::addCircle(scene, Vec2::Zero(), kRadius);
    QVERIFY2(r.ok, qPrintable(r.error));
    r = edit::addPin(r.scene, r.body, kWorld, Vec2(0.0, kArm));
    QVERIFY2(r.ok, qPrintable(r.error));
    const Vec2 centre(3.0, -2.0);
    r = edit::moveBody(r.scene, 0, centre);
    QVERIFY2(r.ok, qPrintable(r.error));
    r = edit::rotateBody(r.scene, 0, kSwing);
    QVERIFY2(r.ok, qPrintable(r.error));
    const Vec2 pivot = centre + kArm * Vec2(-std::sin(kSwing), std::cos(kSwing));
    QVERIFY(near(r.scene.joints[0].anchorB, pivot, 1e-12));

    physics::World world = buildWorld(r.scene);
    const double dt = r.scene.world.dt;
    const double period = 2.0 * std::numbers::pi *
                          std::sqrt((0.5 * kRadius * kRadius + kArm * kArm) / (kGravity * kArm));
    double minX = centre.x();
    double maxX = centre.x();
    double worstArm = 0.0;
    std::vector<double> upCrossings; // times the ball passes under the pivot moving right [s]
    double lastDx = centre.x() - pivot.x();
    const int steps = static_cast<int>(std::ceil(3.0 * period / dt));
    for (int i = 0; i < steps; ++i) {
        world.step();
        const Vec2 p = world.body(0).position;
        minX = std::min(minX, p.x());
        maxX = std::max(maxX, p.x());
        worstArm = std::max(worstArm, std::abs((p - pivot).norm() - kArm));
        const double dx = p.x() - pivot.x();
        if (lastDx < 0.0 && dx >= 0.0) {
            upCrossings.push_back(world.time() - dt * dx / (dx - lastDx));
        }
        lastDx = dx;
    }
    // It hangs from the new pivot at its arm's length...
    QVERIFY2(worstArm < 1e-3, qPrintable(QString::number(worstArm)));
    // ...swings symmetrically about it, as far as it was turned...
    const double reach = kArm * std::sin(kSwing);
    QVERIFY2(std::abs(minX - (pivot.x() - reach)) < 0.02 * reach,
             qPrintable(QString::number(minX)));
    QVERIFY2(std::abs(maxX - (pivot.x() + reach)) < 0.02 * reach,
             qPrintable(QString::number(maxX)));
    // ...with the pendulum's period (small swings: the amplitude adds theta^2/16 = 0.06 %).
    QVERIFY(upCrossings.size() >= 2);
    const double measured = upCrossings[1] - upCrossings[0];
    QVERIFY2(std::abs(measured - period) < 0.01 * period,
             qPrintable(QStringLiteral("%1 vs %2").arg(measured).arg(period)));
}

void TestSceneEdits::deleteRenumbersSpringsAndPins()
{
    const Scene scene = fourBodies();
    const auto r = edit::deleteBody(scene, 1); // "b"
    QVERIFY(r.ok);
    const Scene& out = r.scene;
    QCOMPARE(out.bodies.size(), size_t(3));
    QCOMPARE(idOf(out, 0), QStringLiteral("a"));
    QCOMPARE(idOf(out, 1), QStringLiteral("c"));
    QCOMPARE(idOf(out, 2), QStringLiteral("d"));
    QCOMPARE(out.originalVertices.size(), size_t(3));
    QCOMPARE(out.colourOf(1), QStringLiteral("#00ff00")); // c's colour moved down with it
    // The spring b-d and the pin d-b went with b; a-c is now 0-1, c-world 1-world.
    QCOMPARE(out.springs.size(), size_t(2));
    QCOMPARE(out.springs[0].a, 0);
    QCOMPARE(out.springs[0].b, 1);
    QCOMPARE(out.springs[0].stiffness, 10.0);
    QCOMPARE(out.springs[1].a, 1);
    QCOMPARE(out.springs[1].b, kWorld);
    QCOMPARE(out.springs[1].stiffness, 30.0);
    QCOMPARE(out.joints.size(), size_t(1));
    QCOMPARE(out.joints[0].a, 0);
    QCOMPARE(out.joints[0].b, kWorld);

    // Deleting the last body leaves the others' numbers alone.
    const auto last = edit::deleteBody(scene, 3);
    QVERIFY(last.ok);
    QCOMPARE(last.scene.springs.size(), size_t(2));
    QCOMPARE(last.scene.springs[1].a, 2);
    QCOMPARE(last.scene.joints.size(), size_t(1));
    QVERIFY(!edit::deleteBody(scene, 7).ok);

    const auto spring = edit::deleteSpring(scene, 0);
    QVERIFY(spring.ok);
    QCOMPARE(spring.scene.springs.size(), size_t(2));
    QCOMPARE(spring.scene.springs[0].stiffness, 20.0);
    const auto pin = edit::deletePin(scene, 1);
    QVERIFY(pin.ok);
    QCOMPARE(pin.scene.joints.size(), size_t(1));
    QCOMPARE(pin.scene.joints[0].a, 3);
    QVERIFY(!edit::deletePin(scene, 2).ok);
}

void TestSceneEdits::duplicateTakesANewId()
{
    Scene scene;
    scene = edit::addBox(scene, Vec2(0.0, 1.0), 1.0, 2.0).scene;
    scene.bodies[0].restitution = 0.9;
    auto r = edit::duplicateBody(scene, 0, Vec2(0.5, 0.0));
    QVERIFY(r.ok);
    QCOMPARE(r.body, 1);
    QCOMPARE(idOf(r.scene, 1), QStringLiteral("box2"));
    QVERIFY(near(r.scene.bodies[1].position, Vec2(0.5, 1.0)));
    QCOMPARE(r.scene.bodies[1].restitution, 0.9);
    r = edit::duplicateBody(r.scene, 1, Vec2(0.5, 0.0));
    QCOMPARE(idOf(r.scene, 2), QStringLiteral("box3"));

    Scene named = fourBodies();
    r = edit::duplicateBody(named, 0, Vec2(0.0, 1.0));
    QVERIFY(r.ok);
    QCOMPARE(idOf(r.scene, 4), QStringLiteral("a1"));
    QCOMPARE(r.scene.springs.size(), named.springs.size()); // springs are not copied
    r = edit::duplicateBody(named, 1, Vec2(0.0, 1.0));
    QCOMPARE(r.scene.colourOf(4), QStringLiteral("#ff0000"));
}

void TestSceneEdits::addsPins()
{
    Scene scene = fourBodies();
    scene.bodies[1].angle = 0.5;
    const Vec2 point(1.2, 0.1);
    auto r = edit::addPin(scene, 1, 2, point);
    QVERIFY2(r.ok, qPrintable(r.error));
    const physics::PinJointDef& pin = r.scene.joints.back();
    QCOMPARE(pin.a, 1);
    QCOMPARE(pin.b, 2);
    // Both anchors are the point clicked, each in its body's frame.
    const auto world = [&](int body, const Vec2& anchor) {
        const auto& d = scene.bodies[static_cast<size_t>(body)];
        return physics::Transform(d.position, d.angle).apply(anchor);
    };
    QVERIFY(near(world(1, pin.anchorA), point, 1e-12));
    QVERIFY(near(world(2, pin.anchorB), point, 1e-12));

    // The world as the first end: the body holds, the world is the second end.
    r = edit::addPin(scene, kWorld, 3, Vec2(3.0, 1.0));
    QVERIFY(r.ok);
    QCOMPARE(r.scene.joints.back().a, 3);
    QCOMPARE(r.scene.joints.back().b, kWorld);
    QVERIFY(near(r.scene.joints.back().anchorB, Vec2(3.0, 1.0)));

    const auto self = edit::addPin(scene, 2, 2, point);
    QVERIFY(!self.ok);
    QCOMPARE(self.error, QStringLiteral("joints[2]: b: the same body as \"a\": a pin joins two "
                                        "bodies"));
    QVERIFY(!edit::addPin(scene, kWorld, kWorld, point).ok);
    QVERIFY(!edit::addPin(scene, 0, 9, point).ok);
}

void TestSceneEdits::addsSprings()
{
    const Scene scene = fourBodies();
    const Vec2 pa(0.0, 0.2);
    const Vec2 pb(3.0, 4.2);
    auto r = edit::addSpring(scene, 0, pa, kWorld, pb, 50.0, 0.5);
    QVERIFY2(r.ok, qPrintable(r.error));
    const physics::SpringDef& s = r.scene.springs.back();
    QCOMPARE(s.restLength, 5.0);
    QCOMPARE(s.stiffness, 50.0);
    QCOMPARE(s.damping, 0.5);
    QVERIFY(near(s.anchorA, Vec2(0.0, 0.2)));
    QVERIFY(near(s.anchorB, pb));

    const auto zero = edit::addSpring(scene, 0, pa, 1, pa, 50.0);
    QVERIFY(!zero.ok);
    QVERIFY2(zero.error.startsWith(QStringLiteral("springs[3]: restLength: a spring of zero "
                                                  "length")),
             qPrintable(zero.error));
    const auto same = edit::addSpring(scene, 2, pa, 2, pb, 50.0);
    QVERIFY(!same.ok);
    QVERIFY2(same.error.endsWith(QStringLiteral("a spring joins two bodies")),
             qPrintable(same.error));
    const auto world = edit::addSpring(scene, kWorld, pa, kWorld, pb, 50.0);
    QVERIFY(!world.ok);
    QVERIFY2(world.error.contains(QStringLiteral("a spring needs a body at one end")),
             qPrintable(world.error));
    const auto stiff = edit::addSpring(scene, 0, pa, 1, pb, -1.0);
    QVERIFY(!stiff.ok);
    QVERIFY2(stiff.error.startsWith(QStringLiteral("springs[3]: stiffness: must be ")),
             qPrintable(stiff.error));
}

RIGIDLAB_TEST_GUILESS_MAIN(TestSceneEdits)
