// SPDX-License-Identifier: GPL-3.0-or-later
// What rigidlab-cli's commands write: run (heads, bytes, summary, refusals), sat, profile,
// bench.

#include "test_cli.h"

#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/settings.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>

using namespace rigidlab::test::cli;
using rigidlab::test::CliRun;
using rigidlab::test::runCli;

namespace {

QString solverText(rigidlab::physics::SolverKind kind)
{
    const std::string_view name = rigidlab::physics::solverName(kind);
    return QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
}

} // namespace

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
    QVERIFY(writeFile(path, R"({"rigidlab": 1,
        "world": {"integrator": "euler", "dt": 0.1, "gravity": [0, 0]},
        "bodies": [{"id": "m", "shape": {"type": "circle", "radius": 0.1}, "mass": 0.001,
                    "position": [1, 0]}],
        "springs": [{"a": "m", "b": null, "stiffness": 100000, "restLength": 0.5}]})"));
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
    QVERIFY(writeFile(path, R"({"a": {"vertices": [[-1, -1], [1, -1], [1, 1], [-1, 1]]},
                        "b": {"vertices": [[-1, -1], [1, -1], [1, 1], [-1, 1]],
                              "position": [1.5, 0.5], "angle": 0.1}})"));
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
    QVERIFY(writeFile(path, R"([
        {"a": {"vertices": [[0, 0], [1, 0], [0, 1]]},
         "b": {"vertices": [[0, 0], [1, 0], [0, 1]], "position": [5, 0]}},
        {"a": {"vertices": [[0, 0], [1, 0], [0, 1]]},
         "b": {"vertices": [[0, 0], [1, 0], [0, 1]], "position": [0.2, 0.2]}}])"));
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
    QVERIFY(writeFile(bad, R"({"a": {"vertices": [[0, 0], [1, 0]]}, "b": {"vertices": []}})"));
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
    // The row of RigidLab on the scene, its bodies counted (the columns' widths are the table's).
    QVERIFY2(out.contains(QRegularExpression(QStringLiteral("(^|\\n)RigidLab +stack-12 +12 "))),
             qPrintable(out));
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

// bench --export writes the solver a scene file names for the window: the lab's default, the
// one a scene that names none runs with, unless --solver names another; an unknown one is
// refused, naming the flag.
void TestCli::benchExportNamesTheSolver_data()
{
    using rigidlab::physics::SolverKind;
    QTest::addColumn<QStringList>("flags");
    QTest::addColumn<QString>("written");
    QTest::newRow("default") << QStringList{} << solverText(rigidlab::physics::WorldDef{}.solver);
    for (const SolverKind kind : rigidlab::physics::kAllSolvers)
        QTest::newRow(qPrintable(solverText(kind)))
            << QStringList{QStringLiteral("--solver"), solverText(kind)} << solverText(kind);
}

void TestCli::benchExportNamesTheSolver()
{
    QFETCH(QStringList, flags);
    QFETCH(QString, written);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("pyramid.json"));
    const CliRun run =
        runCli(QStringList{QStringLiteral("bench"), QStringLiteral("--scene"),
                           QStringLiteral("pyramid-20"), QStringLiteral("--export"), path} +
               flags);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject world =
        QJsonDocument::fromJson(readAll(path)).object().value(QStringLiteral("world")).toObject();
    QCOMPARE(world.value(QStringLiteral("solver")).toString(), written);
    if (!flags.isEmpty())
        return;
    const CliRun wrong = runCli(QStringList{
        QStringLiteral("bench"), QStringLiteral("--scene"), QStringLiteral("pyramid-20"),
        QStringLiteral("--export"), path, QStringLiteral("--solver"), QStringLiteral("nope")});
    QCOMPARE(wrong.exitCode, 2);
    QVERIFY2(wrong.err.contains("--solver: unknown solver \"nope\""), wrong.err.constData());
}
