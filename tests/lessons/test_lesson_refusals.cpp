// SPDX-License-Identifier: GPL-3.0-or-later
// Damaged lessons: every mistake a lesson file can hold, refused with its place and what is
// wrong, in the words a teacher reads.

#include "test_lesson.h"
#include "test_lesson_json.h"

#include "format/document.h"

#include <QTemporaryDir>

using namespace rigidlab;
using namespace rigidlab::test;
using namespace rigidlab::test::lesson_json;

void TestLesson::rejectsBadLesson_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");

    const QString steps0 = QStringLiteral("steps[0].");
    QTest::newRow("broken-json")
        << QByteArray("{\"rigidlab-lesson\": 1,\n \"title\": \"x\" \"steps\": []}")
        << "line 2, column 16: unterminated object: a ',' or the closing '}' is missing";
    QTest::newRow("version-missing")
        << QByteArray(R"({"title": "x", "steps": []})")
        << R"(rigidlab-lesson: missing: a lesson file starts with "rigidlab-lesson": 1 (the format version))";
    QTest::newRow("version-2") << QByteArray(R"({"rigidlab-lesson": 2})")
                               << "rigidlab-lesson: unsupported format version 2 (this RigidLab "
                                  "reads version 1)";
    QTest::newRow("unknown-key-top")
        << QByteArray(R"({"rigidlab-lesson": 1, "titel": "x"})")
        << "titel: unknown key (allowed here: rigidlab-lesson, title, summary, level, minutes, "
           "order, description, goals, steps)";
    QTest::newRow("title-missing")
        << QByteArray(R"({"rigidlab-lesson": 1, "steps": []})") << "title: required, but missing";
    QTest::newRow("minutes-fraction")
        << QByteArray(R"({"rigidlab-lesson": 1, "title": "t", "minutes": 2.5})")
        << "minutes: must be a whole number from 0 to 1000, got 2.5";
    QTest::newRow("order-zero") << QByteArray(R"({"rigidlab-lesson": 1, "title": "t", "order": 0})")
                                << "order: must be a whole number from 1 to 999, got 0";
    QTest::newRow("order-text") << QByteArray(
                                       R"({"rigidlab-lesson": 1, "title": "t", "order": "1"})")
                                << "order: must be a whole number from 1 to 999, got \"1\"";
    QTest::newRow("description-two-lines")
        << QByteArray(R"({"rigidlab-lesson": 1, "title": "t", "description": "a\nb"})")
        << "description: must be one line (it is shown in the lesson menu); put longer text in "
           "\"summary\"";
    QTest::newRow("description-long")
        << QByteArray(R"({"rigidlab-lesson": 1, "title": "t", "description": ")") +
               QByteArray(101, 'x') + QByteArray(R"("})")
        << "description: is 101 characters long; at most 100 fit a menu line (put longer text "
           "in \"summary\")";
    QTest::newRow("description-blank")
        << QByteArray(R"({"rigidlab-lesson": 1, "title": "t", "description": "  "})")
        << "description: must not be empty (leave the key out instead)";
    QTest::newRow("goal-empty")
        << QByteArray(R"({"rigidlab-lesson": 1, "title": "t", "goals": ["a", ""]})")
        << "goals[1]: must be a non-empty string \"...\", got \"\"";
    QTest::newRow("no-steps") << QByteArray(R"({"rigidlab-lesson": 1, "title": "t", "steps": []})")
                              << "steps: a lesson needs 1 to 100 steps, got 0";
    QTest::newRow("unknown-key-step")
        << oneStep(R"("colour": "red")")
        << steps0 + "colour: unknown key (allowed here: title, text, scene, settings, compare, "
                    "plots, overlays, panels, allow, sat, editor, questions, exportTime, "
                    "endTime, autoplay)";
    QTest::newRow("scene-missing")
        << QByteArray(R"({"rigidlab-lesson": 1, "title": "t", "steps": [{"title": "s"}]})")
        << steps0 + "scene: required, but missing (a scene object, or the path of a scene file)";
    QTest::newRow("text-array-of-numbers")
        << oneStep(R"("text": ["a", 5])") << steps0 + R"(text[1]: must be a string "...", got 5)";
    QTest::newRow("bad-body-in-question")
        << oneStep(R"("questions": [{"prompt": "p", "measure": {"kind": "apex", "body": "bal"}}])")
        << steps0 + R"(questions[0].measure.body: no body with id "bal")";
    QTest::newRow("static-body-measured")
        << oneStep(
               R"("questions": [{"prompt": "p", "measure": {"kind": "speed", "body": "floor", "time": 1}}])")
        << steps0 + R"(questions[0].measure.body: body "floor" is static: it never moves)";
    QTest::newRow("measure-unknown-kind")
        << oneStep(
               R"("questions": [{"prompt": "p", "measure": {"kind": "height", "body": "ball"}}])")
        << steps0 + R"(questions[0].measure.kind: unknown measure "height" (expected apex, speed, )"
                    "velocity-x, velocity-y, angular-velocity, position-x, position-y, "
                    "energy-drift, momentum-x, momentum-y)";
    QTest::newRow("measure-key-of-other-kind")
        << oneStep(
               R"("questions": [{"prompt": "p", "measure": {"kind": "apex", "body": "ball", "time": 2}}])")
        << steps0 + "questions[0].measure.time: unknown key (allowed here: kind, body, n, above)";
    QTest::newRow("measure-time-missing")
        << oneStep(R"("questions": [{"prompt": "p", "measure": {"kind": "energy-drift"}}])")
        << steps0 + "questions[0].measure.time: required, but missing";
    QTest::newRow("tolerances-zero")
        << oneStep(
               R"("questions": [{"prompt": "p", "measure": {"kind": "momentum-x", "time": 1}, "tolerance": 0}])")
        << steps0 + "questions[0].tolerance: 0, and so is absoluteTolerance: no typed answer "
                    "would ever be right";
    QTest::newRow("path-escaping-folder")
        << stepWithScene(R"("../scenes/ball_drop.json")")
        << steps0 + R"(scene: must not leave the lesson's folder, got "../scenes/ball_drop.json")";
    QTest::newRow("path-escaping-inside")
        << stepWithScene(R"("scenes/../../x.json")")
        << steps0 + R"(scene: must not leave the lesson's folder, got "scenes/../../x.json")";
    QTest::newRow("path-absolute")
        << stepWithScene(R"("/etc/passwd")")
        << steps0 + R"(scene: must be a path relative to the lesson's folder, got "/etc/passwd")";
    QTest::newRow("path-backslash")
        << stepWithScene(R"("scenes\\ok.json")")
        << steps0 + R"(scene: use '/' between folders, got "scenes\ok.json")";
    QTest::newRow("unknown-plot")
        << oneStep(R"("plots": ["energies"])")
        << steps0 + R"(plots[0]: unknown plot "energies" (expected energy, momentum, drift, )"
                    "compare-energy, compare-drift)";
    QTest::newRow("plot-twice") << oneStep(R"("plots": ["energy", "energy"])")
                                << steps0 + R"(plots[1]: "energy" is listed twice)";
    QTest::newRow("compare-plot-without-compare")
        << oneStep(R"("plots": ["compare-drift"])")
        << steps0 +
               R"(plots[0]: "compare-drift" plots the worlds of "compare", and this step has none)";
    QTest::newRow("unknown-overlay")
        << oneStep(R"("overlays": ["forces"])")
        << steps0 + R"(overlays[0]: unknown overlay "forces" (expected velocities, contacts, )"
                    "boxes, centres, trails, springs)";
    QTest::newRow("unknown-panel")
        << oneStep(R"("panels": ["table"])")
        << steps0 + R"(panels[0]: unknown panel "table" (expected controls, inspector, sat, )"
                    "bounces, collision, measurement)";
    QTest::newRow("unknown-control")
        << oneStep(R"("allow": ["mass"])")
        << steps0 + R"(allow[0]: unknown control "mass" (expected integrator, dt, solver, )"
                    "iterations, restitution, friction, gravity, timeScale)";
    QTest::newRow("unknown-tool")
        << oneStep(R"("editor": {"tools": ["select", "hammer"]})")
        << steps0 + R"(editor.tools[1]: unknown tool "hammer" (expected select, rotate, circle, )"
                    "box, polygon, ground, pin, spring, delete, duplicate)";
    QTest::newRow("tool-twice") << oneStep(R"("editor": {"tools": ["box", "box"]})")
                                << steps0 + R"(editor.tools[1]: "box" is listed twice)";
    QTest::newRow("unknown-property")
        << oneStep(R"("editor": {"properties": ["colour", "size"]})")
        << steps0 + R"(editor.properties[1]: unknown property "size" (expected id, label, )"
                    "type, width, height, radius, position, angle, velocity, angularVelocity, "
                    "density, mass, restitution, friction, colour, stiffness, damping, "
                    "restLength, gravity, dt, integrator, solver, iterations, title, "
                    "description)";
    QTest::newRow("editor-unknown-key")
        << oneStep(R"("editor": {"tool": ["box"]})")
        << steps0 + "editor.tool: unknown key (allowed here: tools, properties)";
    QTest::newRow("editor-not-object") << oneStep(R"("editor": ["box"])")
                                       << steps0 + "editor: must be an object {...}, got an array";
    QTest::newRow("sat-panel-without-pair")
        << oneStep(R"("panels": ["sat"])")
        << steps0 +
               R"(panels[0]: the "sat" panel needs the pair it looks at: add "sat": {"a": ID, "b": ID} to the step)";
    QTest::newRow("sat-circle")
        << oneStep(R"("sat": {"a": "ball", "b": "box"})")
        << steps0 + R"(sat.a: body "ball" is a circle: the separating axis test steps through )"
                    "polygons (boxes and polygons)";
    QTest::newRow("sat-same-body")
        << oneStep(R"("sat": {"a": "box", "b": "box"})")
        << steps0 + R"(sat.b: the same body as "a": the test needs two bodies)";
    QTest::newRow("compare-both")
        << oneStep(
               R"("compare": {"integrators": ["euler", "rk4"], "solvers": ["seed-impulse", "sequential-impulse"]})")
        << steps0 + R"(compare.solvers: compare "integrators" or "solvers", not both)";
    QTest::newRow("compare-one") << oneStep(R"("compare": {"integrators": ["euler"]})")
                                 << steps0 + "compare.integrators: compares 2 to 6 worlds, got 1";
    QTest::newRow("compare-unknown-integrator")
        << oneStep(R"("compare": {"integrators": ["euler", "rk5"]})")
        << steps0 + R"(compare.integrators[1]: unknown integrator "rk5" (expected euler, )"
                    "symplectic-euler, verlet, rk4, dopri5, implicit-midpoint)";
    QTest::newRow("compare-and-setting")
        << oneStep(
               R"("settings": {"integrator": "rk4"}, "compare": {"integrators": ["euler", "rk4"]})")
        << steps0 + "compare.integrators: settings.integrator is given too: the main world runs "
                    "the first of this list, so leave settings.integrator out";
    QTest::newRow("settings-dt") << oneStep(R"("settings": {"dt": 2})")
                                 << steps0 + "settings.dt: must be from 1e-07 to 1 s, got 2";
    QTest::newRow("settings-restitution")
        << oneStep(R"("settings": {"restitution": 1.5})")
        << steps0 + "settings.restitution: must be a number from 0 to 1, got 1.5";
    QTest::newRow("settings-time-scale")
        << oneStep(R"("settings": {"timeScale": 10})")
        << steps0 + "settings.timeScale: must be from 0.1 to 4, got 10";
    QTest::newRow("settings-gravity") << oneStep(R"("settings": {"gravity": 1})")
                                      << steps0 + "settings.gravity: must be true or false, got 1";
    const char* speed = R"("measure": {"kind": "speed", "body": "ball", "time": 1})";
    const auto question = [speed](const char* before, const char* fields) {
        return oneStep(qPrintable(QString::fromUtf8(before) +
                                  QStringLiteral(R"("questions": [{"prompt": "p", %1, %2}])")
                                      .arg(QString::fromUtf8(speed), QString::fromUtf8(fields))));
    };
    const QString q0 = steps0 + QStringLiteral("questions[0].");
    QTest::newRow("hold-back-unknown")
        << question(R"("panels": ["collision"], )", R"("holdBack": ["panel:collision", "table"])")
        << q0 + R"(holdBack[1]: unknown name "table" (expected run, panel:NAME, plot:NAME, )"
                "column:collision.after, column:bounces.heights)";
    QTest::newRow("hold-back-panel-not-shown")
        << question(R"("panels": ["collision"], )", R"("holdBack": ["panel:bounces"])")
        << q0 + R"(holdBack[0]: "panel:bounces": this step shows no panel "bounces" (its )"
                "panels: collision)";
    QTest::newRow("hold-back-panel-misspelt")
        << question(R"("panels": ["collision"], )", R"("holdBack": ["panel:colision"])")
        << q0 + R"(holdBack[0]: "panel:colision": this step shows no panel "colision" (its )"
                "panels: collision)";
    QTest::newRow("hold-back-plot-not-shown")
        << question("", R"("holdBack": ["plot:energy"])")
        << q0 + R"(holdBack[0]: "plot:energy": this step shows no plot "energy" (its plots: )"
                "none)";
    QTest::newRow("hold-back-column-without-panel")
        << question(R"("panels": ["bounces"], )", R"("holdBack": ["column:collision.after"])")
        << q0 + R"(holdBack[0]: "column:collision.after" is a column of the collision panel, )"
                "which this step does not show";
    QTest::newRow("hold-back-twice") << question("", R"("holdBack": ["run", "run"])")
                                     << q0 + R"(holdBack[1]: "run" is listed twice)";
    QTest::newRow("hold-back-number")
        << question("", R"("holdBack": [1])") << q0 + R"(holdBack[0]: must be a name "...", got 1)";
    QTest::newRow("hint-empty") << question("", R"("hint": " ")")
                                << q0 + "hint: must not be empty (leave the key out instead)";
    QTest::newRow("set-empty") << question("", R"("set": {})")
                               << q0 + "set: sets nothing (leave the key out when the student "
                                       "sets nothing)";
    QTest::newRow("set-time-scale")
        << question("", R"("set": {"timeScale": 2})")
        << q0 + "set.timeScale: slow motion does not change what is measured: leave it out";
    QTest::newRow("set-bad-value") << question("", R"("set": {"restitution": 2})")
                                   << q0 + "set.restitution: must be a number from 0 to 1, got 2";
    QTest::newRow("set-unknown-key")
        << question("", R"("set": {"colour": 1})")
        << q0 + "set.colour: unknown key (allowed here: integrator, dt, solver, iterations, "
                "restitution, friction, gravity, timeScale)";
    QTest::newRow("set-compared-integrator")
        << question(R"("compare": {"integrators": ["euler", "rk4"]}, )",
                    R"("set": {"integrator": "rk4"})")
        << q0 + "set.integrator: this step compares integrators, each world its own: the "
                "student cannot choose one";
    QTest::newRow("export-time") << oneStep(R"("exportTime": 1000)")
                                 << steps0 + "exportTime: must be from 0 to 600 s, got 1000";
    QTest::newRow("end-time") << oneStep(R"("endTime": 5000)")
                              << steps0 + "endTime: must be from 0 to 3600 s, got 5000";
    QTest::newRow("end-time-text") << oneStep(R"("endTime": "5")")
                                   << steps0 + R"(endTime: must be a positive number, got "5")";
    QTest::newRow("export-steps")
        << oneStep(R"("settings": {"dt": 1e-7}, "exportTime": 10)")
        << steps0 + "exportTime: 10 s at a step of 1e-07 s is more than 10000000 steps";
}

void TestLesson::rejectsBadLesson()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("scenes")));
    QVERIFY(writeFile(dir.filePath(QStringLiteral("scenes/ok.json")), kScene));
    const QString path = dir.filePath(QStringLiteral("lesson.json"));
    QVERIFY(writeFile(path, json));
    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(path);
    QVERIFY(!loaded.ok);
    QCOMPARE(loaded.error, path + QStringLiteral(": ") + message);
    // validate says the same for a lesson it recognises.
    if (json.contains("\"rigidlab-lesson\"") && !json.contains('\n')) {
        const lessons::DocumentCheck check = lessons::checkDocumentFile(path);
        QVERIFY(!check.ok);
        QCOMPARE(check.error, loaded.error);
    }
}
