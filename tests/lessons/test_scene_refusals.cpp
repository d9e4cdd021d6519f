// SPDX-License-Identifier: GPL-3.0-or-later
// Damaged scenes: every mistake a scene file can hold, refused with its place and what is
// wrong (format/scene_loader.h).

#include "test_lessons.h"

using namespace rigidlab;
using namespace rigidlab::test;

void TestLessons::rejectsBadScene_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");

    QTest::newRow("empty-file") << QByteArray("  \n") << "line 1, column 1: the file is empty";
    // Qt's parser reports where it stopped, here just past the stray '}'.
    QTest::newRow("broken-json")
        << QByteArray("{\"rigidlab\": 1,\n  \"bodies\": [}")
        << "line 2, column 15: a value is missing here (JSON allows no trailing comma)";
    QTest::newRow("non-finite-number")
        << oneBody(R"("shape": {"type": "circle", "radius": 1e999})")
        << "line 1, column 81: number 1e999 is not a finite double (out of range or malformed)";
    QTest::newRow("top-level-array")
        << QByteArray("[1, 2]") << "the top level must be an object {...}, got an array";
    QTest::newRow("version-missing")
        << QByteArray(R"({"bodies": []})")
        << R"(rigidlab: missing: a scene file starts with "rigidlab": 1 (the format version))";
    QTest::newRow("version-2") << QByteArray(R"({"rigidlab": 2, "bodies": []})")
                               << "rigidlab: unsupported format version 2 (this RigidLab reads "
                                  "version 1)";
    QTest::newRow("unknown-key-top")
        << sceneWith(R"("bodies": [], "bodys": [])")
        << "bodys: unknown key (allowed here: rigidlab, title, description, world, bodies, "
           "springs, joints)";
    QTest::newRow("unknown-key-body")
        << oneBody(R"("shape": {"type": "circle", "radius": 1}, "color": "red")")
        << "bodies[0].color: unknown key (allowed here: id, label, type, shape, position, angle, "
           "velocity, angularVelocity, density, mass, restitution, friction, collide, colour)";
    QTest::newRow("unknown-key-shape")
        << oneBody(R"("shape": {"type": "circle", "radius": 1, "width": 2})")
        << "bodies[0].shape.width: unknown key (allowed here: type, radius)";
    QTest::newRow("title-not-string")
        << sceneWith(R"("title": 5, "bodies": [])") << "title: must be a string \"...\", got 5";
    QTest::newRow("bodies-missing")
        << sceneWith(R"("title": "t")") << "bodies: required, but missing (it may be empty: [])";
    QTest::newRow("bodies-not-array")
        << sceneWith(R"("bodies": {})") << "bodies: must be an array [...], got an object";
    QTest::newRow("wrong-type-radius")
        << oneBody(R"("shape": {"type": "circle", "radius": "big"})")
        << R"(bodies[0].shape.radius: must be a positive number, got "big")";
    QTest::newRow("negative-radius") << oneBody(R"("shape": {"type": "circle", "radius": -0.5})")
                                     << "bodies[0].shape.radius: must be a positive number, got "
                                        "-0.5";
    QTest::newRow("zero-width") << oneBody(R"("shape": {"type": "box", "width": 0, "height": 1})")
                                << "bodies[0].shape.width: must be a positive number, got 0";
    QTest::newRow("shape-type-misspelt")
        << oneBody(R"("shape": {"typ": "circle", "radius": 1})")
        << "bodies[0].shape.typ: unknown key (allowed here: type, radius, width, height, "
           "vertices)";
    QTest::newRow("radius-missing") << oneBody(R"("shape": {"type": "circle"})")
                                    << "bodies[0].shape.radius: required, but missing";
    QTest::newRow("shape-missing")
        << oneBody(R"("mass": 1)") << "bodies[0].shape: required, but missing";
    QTest::newRow("shape-unknown-type")
        << oneBody(R"("shape": {"type": "star"})")
        << R"(bodies[0].shape.type: unknown shape type "star" (expected circle, box, polygon))";
    QTest::newRow("negative-mass")
        << oneBody(R"("shape": {"type": "circle", "radius": 1}, "mass": -2)")
        << "bodies[0].mass: must be a positive number, got -2";
    QTest::newRow("zero-density")
        << oneBody(R"("shape": {"type": "circle", "radius": 1}, "density": 0)")
        << "bodies[0].density: must be a positive number, got 0";
    QTest::newRow("density-and-mass")
        << oneBody(R"("shape": {"type": "circle", "radius": 1}, "density": 1, "mass": 2)")
        << R"(bodies[0].mass: give "density" or "mass", not both)";
    QTest::newRow("restitution-above-one")
        << oneBody(R"("shape": {"type": "circle", "radius": 1}, "restitution": 1.5)")
        << "bodies[0].restitution: must be a number from 0 to 1, got 1.5";
    QTest::newRow("friction-negative")
        << oneBody(R"("shape": {"type": "circle", "radius": 1}, "friction": -0.1)")
        << "bodies[0].friction: must be a number >= 0, got -0.1";
    QTest::newRow("collide-not-bool")
        << oneBody(R"("shape": {"type": "circle", "radius": 1}, "collide": 1)")
        << "bodies[0].collide: must be true or false, got 1";
    QTest::newRow("position-three-numbers")
        << oneBody(R"("shape": {"type": "circle", "radius": 1}, "position": [1, 2, 3])")
        << "bodies[0].position: must be a pair of numbers [x, y], got an array of 3 elements";
    QTest::newRow("velocity-not-number")
        << oneBody(R"("shape": {"type": "circle", "radius": 1}, "velocity": [1, null])")
        << "bodies[0].velocity[1]: must be a number, got null";
    QTest::newRow("body-type-unknown")
        << oneBody(R"("shape": {"type": "circle", "radius": 1}, "type": "ghost")")
        << R"(bodies[0].type: unknown body type "ghost" (expected dynamic, static, kinematic))";
    // A size whose area would overflow is out of the size range (lessons/limits.h).
    QTest::newRow("huge-shape")
        << oneBody(R"("shape": {"type": "circle", "radius": 1e300})")
        << "bodies[0].shape.radius: must be from 1e-06 to 1e+05 m, got 1e+300";
    QTest::newRow("two-vertices")
        << oneBody(R"("shape": {"type": "polygon", "vertices": [[0, 0], [1, 0]]})")
        << "bodies[0].shape.vertices: a polygon needs 3 to 64 vertices, got 2";
    QTest::newRow("collinear-polygon")
        << oneBody(R"("shape": {"type": "polygon", "vertices": [[0, 0], [1, 1], [2, 2]]})")
        << "bodies[0].shape.vertices: the polygon has no area (its vertices are repeated or on "
           "one line)";
    QTest::newRow("repeated-vertices")
        << oneBody(R"("shape": {"type": "polygon", "vertices": [[1, 1], [1, 1], [1, 1]]})")
        << "bodies[0].shape.vertices: the polygon has no area (its vertices are repeated or on "
           "one line)";
    QTest::newRow("vertex-not-pair")
        << oneBody(R"("shape": {"type": "polygon", "vertices": [[0, 0], [1, 0], 7]})")
        << "bodies[0].shape.vertices[2]: must be a pair of numbers [x, y], got 7";
    {
        QByteArray many;
        for (int i = 0; i < 65; ++i) {
            const double a = 2 * 3.141592653589793 * i / 65;
            many += (i ? "," : "") + QByteArray("[") + QByteArray::number(std::cos(a), 'g', 17) +
                    "," + QByteArray::number(std::sin(a), 'g', 17) + "]";
        }
        QTest::newRow("too-many-vertices")
            << oneBody(
                   ("\"shape\": {\"type\": \"polygon\", \"vertices\": [" + many + "]}").constData())
            << "bodies[0].shape.vertices: a polygon needs 3 to 64 vertices, got 65";
    }
    QTest::newRow("empty-id")
        << sceneWith(R"("bodies": [{"id": "", "shape": {"type": "circle", "radius": 1}}])")
        << "bodies[0].id: must not be empty";
    QTest::newRow("id-missing") << sceneWith(
                                       R"("bodies": [{"shape": {"type": "circle", "radius": 1}}])")
                                << "bodies[0].id: required, but missing";
    QTest::newRow("duplicate-id")
        << sceneWith(R"("bodies": [{"id": "a", "shape": {"type": "circle", "radius": 1}},
                                   {"id": "a", "shape": {"type": "circle", "radius": 1}}])")
        << R"(bodies[1].id: duplicate id "a" (bodies[0] has it already))";
    QTest::newRow("duplicate-id-with-percent")
        << sceneWith(R"("bodies": [{"id": "%2", "shape": {"type": "circle", "radius": 1}},
                                   {"id": "%2", "shape": {"type": "circle", "radius": 1}}])")
        << R"(bodies[1].id: duplicate id "%2" (bodies[0] has it already))";
    QTest::newRow("unknown-integrator")
        << sceneWith(R"("world": {"integrator": "rk5"}, "bodies": [])")
        << R"(world.integrator: unknown integrator "rk5" )"
           "(expected euler, symplectic-euler, verlet, rk4, dopri5, implicit-midpoint)";
    QTest::newRow("unknown-solver") << sceneWith(R"("world": {"solver": "magic"}, "bodies": [])")
                                    << R"(world.solver: unknown solver "magic" (expected )"
                                       "seed-impulse, sequential-impulse, soft-step)";
    QTest::newRow("dt-zero") << sceneWith(R"("world": {"dt": 0}, "bodies": [])")
                             << "world.dt: must be a positive number, got 0";
    QTest::newRow("dt-too-small") << sceneWith(R"("world": {"dt": 1e-9}, "bodies": [])")
                                  << "world.dt: must be from 1e-07 to 1 s, got 1e-09";
    QTest::newRow("dt-too-large") << sceneWith(R"("world": {"dt": 2}, "bodies": [])")
                                  << "world.dt: must be from 1e-07 to 1 s, got 2";
    QTest::newRow("iterations-zero") << sceneWith(R"("world": {"iterations": 0}, "bodies": [])")
                                     << "world.iterations: must be a whole number from 1 to "
                                        "1000, got 0";
    QTest::newRow("iterations-fraction")
        << sceneWith(R"("world": {"iterations": 2.5}, "bodies": [])")
        << "world.iterations: must be a whole number from 1 to 1000, got 2.5";
    QTest::newRow("gravity-not-pair") << sceneWith(R"("world": {"gravity": -9.81}, "bodies": [])")
                                      << "world.gravity: must be a pair of numbers [x, y], got "
                                         "-9.81";
    QTest::newRow("unknown-key-world")
        << sceneWith(R"("world": {"gravty": [0, 0]}, "bodies": [])")
        << "world.gravty: unknown key (allowed here: gravity, dt, "
           "integrator, solver, iterations, restitution, "
           "friction, gravitation, drag, sleep, continuous, tolerance)";

    const char* twoBodies = R"("bodies": [{"id": "ball", "shape": {"type": "circle", "radius": 1}},
        {"id": "wall", "type": "static", "shape": {"type": "box", "width": 1, "height": 1}}], )";
    QTest::newRow("unknown-spring-body")
        << sceneWith(
               (QByteArray(twoBodies) + R"("springs": [{"a": "ball", "b": "bll"}])").constData())
        << R"(springs[0].b: no body with id "bll")";
    QTest::newRow("spring-body-not-string")
        << sceneWith((QByteArray(twoBodies) + R"("springs": [{"a": 3}])").constData())
        << "springs[0].a: must be a body id (a string) or null, got 3";
    QTest::newRow("spring-both-world")
        << sceneWith((QByteArray(twoBodies) + R"("springs": [{"a": null, "b": null}])").constData())
        << "springs[0]: both ends are fixed in the world (a and b are null): a spring needs a "
           "body at one end";
    QTest::newRow("spring-same-body")
        << sceneWith(
               (QByteArray(twoBodies) + R"("springs": [{"a": "ball", "b": "ball"}])").constData())
        << R"(springs[0].b: the same body as "a": a spring joins two bodies)";
    QTest::newRow("stiffness-negative")
        << sceneWith((QByteArray(twoBodies) + R"("springs": [{"a": "ball", "stiffness": -1}])")
                         .constData())
        << "springs[0].stiffness: must be a number >= 0, got -1";
    QTest::newRow("damping-negative")
        << sceneWith(
               (QByteArray(twoBodies) + R"("springs": [{"a": "ball", "damping": -1}])").constData())
        << "springs[0].damping: must be a number >= 0, got -1";
    QTest::newRow("joint-a-null")
        << sceneWith(
               (QByteArray(twoBodies) + R"("joints": [{"type": "pin", "a": null}])").constData())
        << "joints[0].a: must be a body id, not null";
    QTest::newRow("joint-a-missing")
        << sceneWith(
               (QByteArray(twoBodies) + R"("joints": [{"type": "pin", "b": "ball"}])").constData())
        << "joints[0].a: required, but missing (a body id)";
    QTest::newRow("joint-unknown-type")
        << sceneWith((QByteArray(twoBodies) + R"("joints": [{"type": "hinge", "a": "ball"}])")
                         .constData())
        << R"(joints[0].type: unknown joint type "hinge" (expected pin))";
    QTest::newRow("joint-unknown-body")
        << sceneWith(
               (QByteArray(twoBodies) + R"("joints": [{"type": "pin", "a": "bal"}])").constData())
        << R"(joints[0].a: no body with id "bal")";
}

void TestLessons::rejectsBadScene()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    const lessons::SceneLoadResult result = lessons::loadSceneJson(json, QStringLiteral("x.json"));
    QVERIFY(!result.ok);
    QCOMPARE(result.error, QStringLiteral("x.json: ") + message);
    QVERIFY(!result.error.contains(u'\n'));
}
