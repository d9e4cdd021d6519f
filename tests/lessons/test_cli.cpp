// SPDX-License-Identifier: GPL-3.0-or-later
// rigidlab-cli as a user meets it: run as a process, judged by its exit status, its output
// and the files it leaves (or must not leave).

#include "cli_run.h"
#include "test_main.h"

#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/integrator.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

namespace {

const QString kScenesDir = QStringLiteral(RIGIDLAB_SOURCE_DIR "/lessons/scenes");

using rigidlab::test::CliRun;
using rigidlab::test::runCli;

QString scene(const char* name)
{
    return QDir(kScenesDir).filePath(QLatin1StringView(name) + QStringLiteral(".json"));
}

QByteArray readAll(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

void writeFile(const QString& path, const QByteArray& bytes)
{
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    QCOMPARE(file.write(bytes), bytes.size());
}

/// The files in a directory, hidden ones (temporary files) included.
QStringList filesIn(const QString& dir)
{
    return QDir(dir).entryList(QDir::Files | QDir::Hidden | QDir::NoDotAndDotDot);
}

const char* kBall = R"({"id": "ball", "shape": {"type": "circle", "radius": 0.1}})";

} // namespace

class TestCli : public QObject {
    Q_OBJECT

private slots:
    void help();
    void usageErrors_data();
    void usageErrors();
    void badInput_data();
    void badInput();
    void shippedScenesValidate_data();
    void shippedScenesValidate();
    void validateWarns();
    void lessonLanguages();
    void runWritesHeaders();
    void runIsByteIdentical();
    void runSummary();
    void runFailsOnUnwritableOutput();
    void runStopsOnNonFinite();
    void satOutput();
    void satArray();
    void runProfile();
    void bench();
    void lessonsListsOwn();
};

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
        writeFile(path, json);
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
    writeFile(path, R"({"rigidlab": 1, "bodies": [{"id": "l", "shape": {"type": "polygon",
                        "vertices": [[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]]}}]})");
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
    writeFile(path, R"({"rigidlab-lesson": 1, "title": {"en": "Bounces", "cs": "Odrazy"},
        "minutes": 5, "steps": [{"title": {"en": "Four balls"}, "scene": {"rigidlab": 1,
        "bodies": [{"id": "b", "shape": {"type": "circle", "radius": 0.1}}]}}]})");

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

void TestCli::runWritesHeaders()
{
    QTemporaryDir dir;
    const QString trace = dir.filePath(QStringLiteral("t.csv"));
    const QString diagnostics = dir.filePath(QStringLiteral("d.csv"));
    const CliRun run = runCli({QStringLiteral("run"), scene("ball_drop"), QStringLiteral("--time"),
                               QStringLiteral("0.05"), QStringLiteral("--trace"), trace,
                               QStringLiteral("--diagnostics"), diagnostics});
    QVERIFY(!run.crashed);
    QCOMPARE(run.exitCode, 0);
    const QList<QByteArray> t = readAll(trace).split('\n');
    const QList<QByteArray> d = readAll(diagnostics).split('\n');
    // Every quantity names its unit; English without --lang.
    QCOMPARE(QString::fromUtf8(t.front()),
             QStringLiteral("step,t [s],body,x [m],y [m],angle [rad],v_x [m/s],v_y [m/s],"
                            "ω [rad/s]"));
    QCOMPARE(QString::fromUtf8(d.front()),
             QStringLiteral("step,t [s],E_k [J],E_p [J],E [J],p_x [kg m/s],p_y [kg m/s],"
                            "L [kg m²/s],contacts,E_diss [J],drift [1]"));
    QVERIFY(t[1].startsWith("0,0,"));
    QVERIFY(d[1].startsWith("0,0,"));
    QVERIFY(d[d.size() - 2].startsWith("50,"));
    QCOMPARE(d.size(), 1 + 51 + 1);
}

void TestCli::runIsByteIdentical()
{
    QTemporaryDir dir;
    QByteArray traces[2];
    QByteArray diagnostics[2];
    for (int i = 0; i < 2; ++i) {
        const QString t = dir.filePath(QStringLiteral("t%1.csv").arg(i));
        const QString d = dir.filePath(QStringLiteral("d%1.csv").arg(i));
        const CliRun run =
            runCli({QStringLiteral("run"), scene("billiards_break"), QStringLiteral("--time"),
                    QStringLiteral("0.5"), QStringLiteral("--every"), QStringLiteral("7"),
                    QStringLiteral("--trace"), t, QStringLiteral("--diagnostics"), d});
        QCOMPARE(run.exitCode, 0);
        traces[i] = readAll(t);
        diagnostics[i] = readAll(d);
    }
    QVERIFY(traces[0].size() > 10000);
    QVERIFY(traces[0] == traces[1]);
    QVERIFY(diagnostics[0] == diagnostics[1]);
}

void TestCli::runSummary()
{
    const CliRun run =
        runCli({QStringLiteral("run"), scene("pendulum"), QStringLiteral("--steps"),
                QStringLiteral("100"), QStringLiteral("--integrator"), QStringLiteral("rk4"),
                QStringLiteral("--dt"), QStringLiteral("0.002")});
    QCOMPARE(run.exitCode, 0);
    QVERIFY(run.err.isEmpty());
    const QString out = QString::fromUtf8(run.out);
    QCOMPARE(out.count(u'\n'), 1);
    QVERIFY2(out.contains(QStringLiteral("100 steps of 0.002 s (0.2 s simulated)")),
             qPrintable(out));
    QVERIFY(out.contains(QStringLiteral("rk4 integrator")));
    QVERIFY(out.contains(QStringLiteral("drift of ")));
}

void TestCli::runFailsOnUnwritableOutput()
{
    QTemporaryDir dir;
    const QString diagnostics = dir.filePath(QStringLiteral("d.csv"));
    const CliRun run =
        runCli({QStringLiteral("run"), scene("ball_drop"), QStringLiteral("--time"),
                QStringLiteral("0.1"), QStringLiteral("--diagnostics"), diagnostics,
                QStringLiteral("--trace"), QStringLiteral("/nonexistent/dir/x.csv")});
    QVERIFY(!run.crashed);
    QCOMPARE(run.exitCode, 1);
    QVERIFY2(run.err.contains("cannot write /nonexistent/dir/x.csv"), run.err.constData());
    QVERIFY(run.out.isEmpty());
    QVERIFY(!QFile::exists(QStringLiteral("/nonexistent/dir/x.csv")));
    QVERIFY(filesIn(dir.path()).isEmpty());
}

void TestCli::runStopsOnNonFinite()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("stiff.json"));
    writeFile(path, R"({"rigidlab": 1,
        "world": {"integrator": "euler", "dt": 0.1, "gravity": [0, 0]},
        "bodies": [{"id": "m", "shape": {"type": "circle", "radius": 0.1}, "mass": 0.001,
                    "position": [1, 0]}],
        "springs": [{"a": "m", "b": null, "stiffness": 100000, "restLength": 0.5}]})");
    const QString trace = dir.filePath(QStringLiteral("t.csv"));
    const CliRun run = runCli({QStringLiteral("run"), path, QStringLiteral("--steps"),
                               QStringLiteral("5000"), QStringLiteral("--trace"), trace});
    QVERIFY(!run.crashed);
    QCOMPARE(run.exitCode, 3);
    QVERIFY2(run.err.startsWith(("error: " + path + ": the simulation blew up at step ").toUtf8()),
             run.err.constData());
    QCOMPARE(filesIn(dir.path()), QStringList{"stiff.json"});
}

void TestCli::satOutput()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("pair.json"));
    writeFile(path, R"({"a": {"vertices": [[-1, -1], [1, -1], [1, 1], [-1, 1]]},
                        "b": {"vertices": [[-1, -1], [1, -1], [1, 1], [-1, 1]],
                              "position": [1.5, 0.5], "angle": 0.1}})");
    const CliRun run = runCli({QStringLiteral("sat"), path});
    QCOMPARE(run.exitCode, 0);
    QVERIFY(run.err.isEmpty());
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(run.out, &error);
    QCOMPARE(error.error, QJsonParseError::NoError);
    QVERIFY(doc.isObject());
    const QJsonObject o = doc.object();
    QCOMPARE(o[u"intersects"].toBool(), true);
    QVERIFY(o[u"axes"].isArray());
    QVERIFY(o[u"separatingAxis"].isNull());
    QVERIFY(o[u"normal"].isArray());
    QVERIFY(o[u"depth"].toDouble() > 0);
    QVERIFY(o[u"contacts"].isArray());
    QVERIFY(!o[u"contacts"].toArray().isEmpty());
    for (const QJsonValue& axis : o[u"axes"].toArray()) {
        const QJsonObject a = axis.toObject();
        QVERIFY(a[u"owner"].toString() == u"a" || a[u"owner"].toString() == u"b");
        QVERIFY(a[u"edge"].isDouble());
        QCOMPARE(a[u"axis"].toArray().size(), 2);
        QCOMPARE(a[u"a"].toArray().size(), 2);
        QCOMPARE(a[u"b"].toArray().size(), 2);
        QVERIFY(a[u"overlap"].isDouble());
    }
}

void TestCli::satArray()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("pairs.json"));
    writeFile(path, R"([
        {"a": {"vertices": [[0, 0], [1, 0], [0, 1]]},
         "b": {"vertices": [[0, 0], [1, 0], [0, 1]], "position": [5, 0]}},
        {"a": {"vertices": [[0, 0], [1, 0], [0, 1]]},
         "b": {"vertices": [[0, 0], [1, 0], [0, 1]], "position": [0.2, 0.2]}}])");
    const CliRun run = runCli({QStringLiteral("sat"), path});
    QCOMPARE(run.exitCode, 0);
    const QJsonArray list = QJsonDocument::fromJson(run.out).array();
    QCOMPARE(list.size(), 2);
    QCOMPARE(list[0].toObject()[u"intersects"].toBool(), false);
    QVERIFY(list[0].toObject()[u"separatingAxis"].isDouble());
    QVERIFY(list[0].toObject()[u"normal"].isNull());
    QCOMPARE(list[1].toObject()[u"intersects"].toBool(), true);

    // Bad input: same rules as scenes.
    const QString bad = dir.filePath(QStringLiteral("bad.json"));
    writeFile(bad, R"({"a": {"vertices": [[0, 0], [1, 0]]}, "b": {"vertices": []}})");
    const CliRun failed = runCli({QStringLiteral("sat"), bad});
    QCOMPARE(failed.exitCode, 2);
    QCOMPARE(QString::fromUtf8(failed.err),
             QStringLiteral("error: ") + bad +
                 QStringLiteral(": a.vertices: a polygon needs 3 to 64 vertices, got 2\n"));
    QVERIFY(failed.out.isEmpty());
}

// run --profile: one row per stage; a pendulum leaves out the collision stages, a box stack
// runs them all but the islands (a small scene does not sleep).
void TestCli::runProfile()
{
    const CliRun pendulum =
        runCli({QStringLiteral("run"), scene("pendulum"), QStringLiteral("--steps"),
                QStringLiteral("50"), QStringLiteral("--profile")});
    QCOMPARE(pendulum.exitCode, 0);
    const QString out = QString::fromUtf8(pendulum.out);
    for (const char* stage : {"broad phase", "narrow phase", "contact solve"})
        QVERIFY2(out.contains(QString::fromLatin1(stage).leftJustified(16) +
                              QStringLiteral(" left out")),
                 qPrintable(out));
    QVERIFY(out.contains(QStringLiteral("forces  ")));
    QVERIFY(!out.contains(QStringLiteral("forces           left out")));

    const CliRun stack =
        runCli({QStringLiteral("run"), scene("box_stack"), QStringLiteral("--steps"),
                QStringLiteral("50"), QStringLiteral("--profile")});
    QCOMPARE(stack.exitCode, 0);
    const QString stackOut = QString::fromUtf8(stack.out);
    QVERIFY2(!stackOut.contains(QStringLiteral("contact solve    left out")), qPrintable(stackOut));
    QVERIFY(stackOut.contains(QStringLiteral("islands          left out")));
}

// bench: the table's columns for RigidLab alone; --export writes a scene that validates.
void TestCli::bench()
{
    const CliRun run =
        runCli({QStringLiteral("bench"), QStringLiteral("--scene"), QStringLiteral("stack-12"),
                QStringLiteral("--steps"), QStringLiteral("60"), QStringLiteral("--runs"),
                QStringLiteral("1")});
    QCOMPARE(run.exitCode, 0);
    const QString out = QString::fromUtf8(run.out);
    QVERIFY2(out.startsWith(QStringLiteral("engine")), qPrintable(out));
    QVERIFY(out.contains(QStringLiteral("RigidLab       stack-12     12")));
    QVERIFY(out.contains(QStringLiteral("0 moved")));

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("pyramid.json"));
    QCOMPARE(runCli({QStringLiteral("bench"), QStringLiteral("--scene"),
                     QStringLiteral("pyramid-20"), QStringLiteral("--export"), path})
                 .exitCode,
             0);
    const CliRun validate = runCli({QStringLiteral("validate"), path});
    QCOMPARE(validate.exitCode, 0);
    QVERIFY2(validate.out.contains("211 bodies"), validate.out.constData());

    QCOMPARE(runCli({QStringLiteral("bench"), QStringLiteral("--scene"), QStringLiteral("nope")})
                 .exitCode,
             2);
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
    writeFile(lesson, R"({"rigidlab-lesson": 1, "title": "My drop", "order": 1,
                          "steps": [{"title": "s", "scene": "scenes/drop.json"}]})");
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
#include "test_cli.moc"
