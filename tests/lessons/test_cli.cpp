// SPDX-License-Identifier: GPL-3.0-or-later
// rigidlab-cli's usage and refusals: help, bad flags and files, validation, languages, the
// lesson lists.

#include "test_cli.h"
#include "test_main.h"

#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/integrator.h"

#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

using namespace rigidlab::test::cli;
using rigidlab::test::CliRun;
using rigidlab::test::runCli;

void TestCli::help()
{
    const CliRun run = runCli({QStringLiteral("--help")});
    QVERIFY(!run.crashed);
    QCOMPARE(run.exitCode, 0);
    QVERIFY(run.out.startsWith("usage: rigidlab-cli"));
    for (const char* word :
         {"run", "validate", "sat", "--time", "--steps", "--dt", "--integrator", "--solver",
          "--trace", "--diagnostics", "--every", "--lang", "--csv-dialect"}) {
        QVERIFY2(run.out.contains(word), word);
    }
    // The names come from the engine's tables: every integrator and solver, on the flags'
    // lines and in the refusal of an unknown name.
    const CliRun refused = runCli({QStringLiteral("run"), scene("ball_drop"),
                                   QStringLiteral("--integrator"), QStringLiteral("rk5")});
    for (const rigidlab::physics::IntegratorInfo& info : rigidlab::physics::kIntegrators) {
        const QByteArray name(info.name.data(), qsizetype(info.name.size()));
        QVERIFY2(run.out.contains(", " + name) || run.out.contains(" " + name + ","), name);
        QVERIFY2(refused.err.contains(name), refused.err.constData());
    }
    for (const rigidlab::physics::SolverKind kind : rigidlab::physics::kAllSolvers) {
        const std::string_view name = rigidlab::physics::solverName(kind);
        QVERIFY2(run.out.contains(QByteArray(name.data(), qsizetype(name.size()))), name.data());
    }
}

void TestCli::usageErrors_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message"); // a part of stderr

    const QString ball = scene("ball_drop");
    QTest::newRow("no-arguments") << QStringList() << "usage: rigidlab-cli";
    QTest::newRow("unknown-command") << QStringList{"fly"} << "unknown command \"fly\"";
    QTest::newRow("run-no-file") << QStringList{"run"} << "run: which file?";
    QTest::newRow("run-two-files") << QStringList{"run", ball, ball} << "run: one file only, got 2";
    QTest::newRow("time-and-steps") << QStringList{"run", ball, "--time", "1", "--steps", "10"}
                                    << "--time and --steps: give one or the other";
    QTest::newRow("time-not-number") << QStringList{"run", ball, "--time", "abc"}
                                     << "--time: must be a finite number, got \"abc\"";
    QTest::newRow("time-negative")
        << QStringList{"run", ball, "--time=-1"} << "--time: must be >= 0, got \"-1\"";
    QTest::newRow("time-infinite") << QStringList{"run", ball, "--time", "inf"}
                                   << "--time: must be a finite number, got \"inf\"";
    QTest::newRow("time-nan") << QStringList{"run", ball, "--time", "nan"}
                              << "--time: must be a finite number, got \"nan\"";
    QTest::newRow("csv-dialect-unknown")
        << QStringList{"run", ball, "--csv-dialect", "excel"}
        << "run: --csv-dialect: unknown dialect \"excel\" (expected plain, spreadsheet)";
    QTest::newRow("run-lang-unknown") << QStringList{"run", ball, "--lang", "de"}
                                      << "run: --lang: unknown language \"de\" (expected en, cs)";
    QTest::newRow("steps-fraction") << QStringList{"run", ball, "--steps", "1.5"}
                                    << "--steps: must be a whole number from 0 to 100000000";
    QTest::newRow("steps-negative") << QStringList{"run", ball, "--steps", "-3"}
                                    << "--steps: must be a whole number from 0 to 100000000";
    QTest::newRow("dt-zero") << QStringList{"run", ball, "--dt", "0"}
                             << "--dt: must be from 1e-07 to 1 s, got \"0\"";
    QTest::newRow("every-zero") << QStringList{"run", ball, "--every", "0"}
                                << "--every: must be a whole number from 1";
    QTest::newRow("unknown-integrator") << QStringList{"run", ball, "--integrator", "rk5"}
                                        << "--integrator: unknown integrator \"rk5\"";
    QTest::newRow("unknown-solver")
        << QStringList{"run", ball, "--solver", "magic"} << "--solver: unknown solver \"magic\"";
    QTest::newRow("unknown-option")
        << QStringList{"run", ball, "--colour", "red"} << "unknown option --colour";
    QTest::newRow("short-option") << QStringList{"run", ball, "-t", "1"} << "unknown option -t";
    QTest::newRow("missing-value")
        << QStringList{"run", ball, "--trace"} << "--trace: needs a value";
    QTest::newRow("option-twice") << QStringList{"run", ball, "--dt", "0.01", "--dt", "0.02"}
                                  << "--dt: given twice";
    QTest::newRow("too-long") << QStringList{"run", ball, "--time", "1e12"}
                              << "is more than 100000000 steps";
    QTest::newRow("switch-with-value")
        << QStringList{"run", ball, "--profile=3"} << "run: --profile: takes no value";
    QTest::newRow("switch-twice") << QStringList{"run", ball, "--profile", "--profile"}
                                  << "run: --profile: given twice";
    QTest::newRow("lesson-no-file") << QStringList{"lesson"} << "lesson: which lesson file?";
    QTest::newRow("lesson-export-no-folder")
        << QStringList{"lesson", ball, "--export"} << "lesson: --export: needs a folder";
    QTest::newRow("stress-positional")
        << QStringList{"stress", "pendulum"} << "stress: unexpected argument \"pendulum\"";
    QTest::newRow("stress-unknown-case")
        << QStringList{"stress", "--case", "nope"} << "stress: --case: unknown case \"nope\"";
    QTest::newRow("validate-no-file") << QStringList{"validate"} << "validate: which file?";
    QTest::newRow("sat-no-file") << QStringList{"sat"} << "sat: which file?";
}

void TestCli::usageErrors()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    QTemporaryDir dir;
    const QString trace = dir.filePath(QStringLiteral("t.csv"));
    if (arguments.size() > 1 && arguments[0] == u"run" && !arguments.contains(u"--trace")) {
        arguments << QStringLiteral("--trace") << trace;
    }
    const CliRun run = runCli(arguments);
    QVERIFY(!run.crashed);
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(QString::fromUtf8(run.err).contains(message), run.err.constData());
    QVERIFY(run.out.isEmpty());
    QVERIFY(filesIn(dir.path()).isEmpty());
}

// Each kind of bad input, through `validate` and through `run --trace`: exit status 2, one
// line `error: FILE: PLACE: what`, no output file.
void TestCli::badInput_data()
{
    QTest::addColumn<QByteArray>("json"); // empty: the file does not exist
    QTest::addColumn<QString>("message"); // after "error: FILE: "

    const auto withBody = [](const char* body) {
        return QByteArray(R"({"rigidlab": 1, "bodies": [)") + body + "]}";
    };
    QTest::newRow("missing-file") << QByteArray() << "cannot read: No such file or directory";
    QTest::newRow("broken-json")
        << QByteArray("{\"rigidlab\": 1, \"bodies\": [\n  {\"id\": \"a\"}\n  {}]}")
        << "line 3, column 4: a ',' is missing between two values";
    QTest::newRow("bare-word") << QByteArray("{\"rigidlab\": 1, \"bodies\": [\n  {\"id\": ball}]}")
                               << "line 2, column 10: not a JSON value (text needs double quotes; "
                                  "true, false and null are lower case)";
    QTest::newRow("wrong-type")
        << withBody(R"({"id": "b", "shape": {"type": "circle", "radius": "0.1"}})")
        << "bodies[0].shape.radius: must be a positive number, got \"0.1\"";
    QTest::newRow("unknown-key")
        << withBody(R"({"id": "b", "color": "red", "shape": {"type": "circle", "radius": 1}})")
        << "bodies[0].color: unknown key (allowed here: id, label, type, shape, position, angle, "
           "velocity, angularVelocity, density, mass, restitution, friction, collide, colour)";
    QTest::newRow("negative-mass")
        << withBody(R"({"id": "b", "mass": -1, "shape": {"type": "circle", "radius": 1}})")
        << "bodies[0].mass: must be a positive number, got -1";
    QTest::newRow("negative-radius")
        << withBody(R"({"id": "b", "shape": {"type": "circle", "radius": -0.5}})")
        << "bodies[0].shape.radius: must be a positive number, got -0.5";
    QTest::newRow("non-finite-number")
        << QByteArray("{\"rigidlab\": 1, \"bodies\": [\n{\"id\": \"b\", \"position\": [1e999, 0],"
                      " \"shape\": {\"type\": \"circle\", \"radius\": 1}}]}")
        << "line 2, column 26: number 1e999 is not a finite double (out of range or malformed)";
    QTest::newRow("collinear-polygon")
        << withBody(R"({"id": "b", "shape": {"type": "polygon",
                        "vertices": [[0, 0], [1, 0.5], [2, 1]]}})")
        << "bodies[0].shape.vertices: the polygon has no area (its vertices are repeated or on "
           "one line)";
    QTest::newRow("two-vertices")
        << withBody(R"({"id": "b", "shape": {"type": "polygon", "vertices": [[0, 0], [1, 0]]}})")
        << "bodies[0].shape.vertices: a polygon needs 3 to 64 vertices, got 2";
    QTest::newRow("unknown-spring-body")
        << QByteArray(R"({"rigidlab": 1, "bodies": [)") + kBall +
               R"(], "springs": [{"a": "ball", "b": "bll", "stiffness": 10}]})"
        << "springs[0].b: no body with id \"bll\"";
    QTest::newRow("unknown-integrator")
        << QByteArray(R"({"rigidlab": 1, "world": {"integrator": "rk5"}, "bodies": []})")
        << "world.integrator: unknown integrator \"rk5\" (expected euler, symplectic-euler, "
           "verlet, rk4, dopri5, implicit-midpoint)";
}

void TestCli::badInput()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("x.json"));
    if (!json.isEmpty()) {
        QVERIFY(writeFile(path, json));
    }
    const QString expected =
        QStringLiteral("error: ") + path + QStringLiteral(": ") + message + u'\n';

    const CliRun validate = runCli({QStringLiteral("validate"), path});
    QVERIFY(!validate.crashed);
    QCOMPARE(validate.exitCode, 2);
    QCOMPARE(QString::fromUtf8(validate.err), expected);
    QVERIFY(validate.out.isEmpty());

    const QString trace = dir.filePath(QStringLiteral("t.csv"));
    const QString diagnostics = dir.filePath(QStringLiteral("d.csv"));
    const CliRun run = runCli({QStringLiteral("run"), path, QStringLiteral("--trace"), trace,
                               QStringLiteral("--diagnostics"), diagnostics});
    QVERIFY(!run.crashed);
    QCOMPARE(run.exitCode, 2);
    QCOMPARE(QString::fromUtf8(run.err), expected);
    QVERIFY(run.out.isEmpty());
    QCOMPARE(filesIn(dir.path()), json.isEmpty() ? QStringList() : QStringList{"x.json"});
}

void TestCli::shippedScenesValidate_data()
{
    QTest::addColumn<QString>("path");
    const QStringList files =
        QDir(kScenesDir).entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    QVERIFY(files.size() >= 10);
    for (const QString& file : files) {
        QTest::newRow(qPrintable(file)) << QDir(kScenesDir).filePath(file);
    }
}

void TestCli::shippedScenesValidate()
{
    QFETCH(QString, path);
    const CliRun run = runCli({QStringLiteral("validate"), path});
    QVERIFY(!run.crashed);
    QCOMPARE(run.exitCode, 0);
    // The one scene that shows the separating axis test a non-convex polygon is meant to be
    // warned of (its hull is used); every other is clean.
    if (path.endsWith(QStringLiteral("sat_non_convex.json")))
        QVERIFY2(run.err.contains("the polygon is not convex") && run.err.count('\n') == 1,
                 run.err.constData());
    else
        QVERIFY2(run.err.isEmpty(), run.err.constData());
    const QString out = QString::fromUtf8(run.out);
    QVERIFY2(out.startsWith(QStringLiteral("ok: ") + path + QStringLiteral(": ")), qPrintable(out));
    QVERIFY(out.contains(QStringLiteral(" bod")));
    QVERIFY(out.contains(QStringLiteral(" spring")));
    QVERIFY(out.contains(QStringLiteral(" joint")));
}

void TestCli::validateWarns()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("l.json"));
    QVERIFY(writeFile(path, R"({"rigidlab": 1, "bodies": [{"id": "l", "shape": {"type": "polygon",
                        "vertices": [[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]]}}]})"));
    const CliRun run = runCli({QStringLiteral("validate"), path});
    QCOMPARE(run.exitCode, 0);
    QCOMPARE(QString::fromUtf8(run.out),
             QStringLiteral("ok: ") + path + QStringLiteral(": 1 body, 0 springs, 0 joints\n"));
    QVERIFY2(run.err.startsWith(("warning: " + path + ": bodies[0].shape.vertices: ").toUtf8()),
             run.err.constData());
    QCOMPARE(run.err.count('\n'), 1);
}

void TestCli::lessonLanguages()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("l.json"));
    QVERIFY(writeFile(path, R"({"rigidlab-lesson": 1, "title": {"en": "Bounces", "cs": "Odrazy"},
        "minutes": 5, "steps": [{"title": {"en": "Four balls"}, "scene": {"rigidlab": 1,
        "bodies": [{"id": "b", "shape": {"type": "circle", "radius": 0.1}}]}}]})"));

    // The outline in each language; a text without Czech is shown in English.
    CliRun run =
        runCli({QStringLiteral("lesson"), path, QStringLiteral("--lang"), QStringLiteral("cs")});
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.out.startsWith("Odrazy (5 min, any level)\n1. Four balls\n"), run.out.constData());
    run = runCli({QStringLiteral("lesson"), path});
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.out.startsWith("Bounces (5 min"), run.out.constData());
    // The step title lacks Czech: a warning line, and the exit status of a good file. (The
    // lesson command starts a GUI application, which may say things of its own first.)
    QVERIFY2(run.err.contains(("warning: " + path +
                               R"(: steps[0].title: no Czech text ("cs"): it will show in )"
                               "English\n")
                                  .toUtf8()),
             run.err.constData());
    QCOMPARE(run.err.count("warning: "), 1);

    run = runCli({QStringLiteral("validate"), path, QStringLiteral("--lang=cs")});
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.out.startsWith(("ok: " + path + R"(: lesson "Odrazy": 1 step)").toUtf8()),
             run.out.constData());
    QCOMPARE(run.err.count("warning: "), 1);

    // A language the lab does not ship is a usage error.
    run = runCli({QStringLiteral("lesson"), path, QStringLiteral("--lang"), QStringLiteral("de")});
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains(R"(lesson: --lang: unknown language "de" (expected en, cs))"),
             run.err.constData());
    run = runCli({QStringLiteral("validate"), path, QStringLiteral("--lang"), QStringLiteral("")});
    QCOMPARE(run.exitCode, 2);
    QVERIFY(run.out.isEmpty());
}

void TestCli::lessonsListsOwn()
{
    // rigidlab-cli is no test: its user folder is the documented ~/.local/share/rigidlab, under
    // this run's fresh $HOME (test_main.h).
    const QString own = QDir::homePath() + QStringLiteral("/.local/share/rigidlab/lessons");
    const CliRun help = runCli({QStringLiteral("--help")});
    QVERIFY2(help.out.contains("(" + own.toUtf8() + ")"), help.out.constData()); // this system's
    const CliRun before = runCli({QStringLiteral("lessons")});
    QCOMPARE(before.exitCode, 0);
    QVERIFY2(!before.out.contains("your own"), before.out.constData());
    const qsizetype shipped = before.out.count('\n');
    QVERIFY(shipped >= 1);

    QVERIFY(QDir().mkpath(own + QStringLiteral("/scenes")));
    QVERIFY(QFile::copy(scene("ball_drop"), own + QStringLiteral("/scenes/drop.json")));
    const QString lesson = own + QStringLiteral("/mine.json");
    QVERIFY(writeFile(lesson, R"({"rigidlab-lesson": 1, "title": "My drop", "order": 1,
                          "steps": [{"title": "s", "scene": "scenes/drop.json"}]})"));
    const CliRun after = runCli({QStringLiteral("lessons")});
    QCOMPARE(after.exitCode, 0);
    QVERIFY2(after.err.isEmpty(), after.err.constData());
    // The shipped lessons as before, then the user's, marked in a third column.
    QVERIFY2(after.out.startsWith(before.out), after.out.constData());
    const QByteArray added = after.out.mid(before.out.size());
    QCOMPARE(added,
             QFile::encodeName(QFileInfo(lesson).absoluteFilePath()) + "\tMy drop\tyour own\n");
}

RIGIDLAB_TEST_GUILESS_MAIN(TestCli)
