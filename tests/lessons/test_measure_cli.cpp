// SPDX-License-Identifier: GPL-3.0-or-later
// `rigidlab-cli fit` as a user meets it: run as a process, judged by its exit status and what
// it prints.
#include "cli_run.h"
#include "test_main.h"
#include "test_measure.h"

#include <QDir>
#include <QRegularExpression>
#include <QTest>

namespace {

/// rigidlab-cli's exit status and what it printed, as text.
struct CliText {
    int exitCode = -1;
    bool crashed = true;
    QString out;
    QString err;
};

CliText runCli(const QStringList& arguments)
{
    const rigidlab::test::CliRun run = rigidlab::test::runCli(arguments);
    return {run.exitCode, run.crashed, QString::fromUtf8(run.out), QString::fromUtf8(run.err)};
}

QString sample(const char* name)
{
    return QDir(rigidlab::test::kMeasureSamples).filePath(QLatin1StringView(name));
}

} // namespace

void TestMeasure::cliHelp()
{
    const CliText run = runCli({QStringLiteral("--help")});
    QCOMPARE(run.exitCode, 0);
    QVERIFY(run.out.contains(QStringLiteral("fit SCENE.json MEASUREMENT.csv")));
    QVERIFY(run.out.contains(QStringLiteral("--bounce-times")));
}

void TestMeasure::cliFitsSamples_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("name");
    // What make_samples.py's exact model was given: it must lie within the 95 % interval.
    QTest::addColumn<double>("truth");
    QTest::newRow("restitution-tracker") << QStringList{sample("ball_floor.json"),
                                                        sample("ball_tracker.csv"),
                                                        "--param",
                                                        "restitution:ball",
                                                        "--quantity",
                                                        "y:ball"}
                                         << "restitution:ball" << 0.72;
    QTest::newRow("friction-phyphox-cm")
        << QStringList{sample("box_slide.json"), sample("box_phyphox_cs.csv"),
                       "--param=friction:box,floor", "--quantity", "x:box"}
        << "friction:box,floor" << 0.33;
    QTest::newRow("friction-and-speed-plain") << QStringList{sample("box_slide.json"),
                                                             sample("box_plain.csv"),
                                                             "--param",
                                                             "friction:box,floor",
                                                             "--param",
                                                             "vx:box",
                                                             "--quantity",
                                                             "x:box"}
                                              << "friction:box,floor" << 0.33;
    QTest::newRow("bounce-times") << QStringList{sample("ball_floor.json"),
                                                 sample("ball_bounces_phyphox.csv"), "--param",
                                                 "restitution:ball", "--bounce-times"}
                                  << "restitution:ball" << 0.72;
}

void TestMeasure::cliFitsSamples()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, name);
    QFETCH(double, truth);
    const CliText run = runCli(QStringList{QStringLiteral("fit")} + arguments);
    QVERIFY2(!run.crashed && run.exitCode == 0, qPrintable(run.err));
    const QRegularExpression line(QRegularExpression::escape(name) +
                                  QStringLiteral(" = (\\S+) ± (\\S+) \\(95 %\\), standard "
                                                 "uncertainty (\\S+)"));
    const auto match = line.match(run.out);
    QVERIFY2(match.hasMatch(), qPrintable(run.out));
    const double value = match.captured(1).toDouble();
    const double halfWidth = match.captured(2).toDouble();
    QVERIFY2(
        std::abs(value - truth) <= halfWidth,
        qPrintable(
            QStringLiteral("fitted %1 ± %2, made with %3").arg(value).arg(halfWidth).arg(truth)));
    QVERIFY(halfWidth > 0 && match.captured(3).toDouble() > 0);
    QVERIFY(run.out.contains(QStringLiteral("residual RMS")));
}

void TestMeasure::cliRefuses_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    const QString ball = sample("ball_floor.json");
    const QString tracker = sample("ball_tracker.csv");
    const QString damaged =
        QDir(rigidlab::test::kMeasureDamaged).filePath(QStringLiteral("nan.csv"));
    QTest::newRow("no-files") << QStringList{"--param", "restitution"}
                              << "rigidlab-cli: fit: expected SCENE.json MEASUREMENT.csv";
    QTest::newRow("no-param") << QStringList{ball, tracker, "--quantity", "y:ball"}
                              << "rigidlab-cli: fit: name one to three --param";
    QTest::newRow("param-without-value")
        << QStringList{ball, tracker, "--param"} << "rigidlab-cli: fit: --param: needs a parameter";
    QTest::newRow("no-quantity") << QStringList{ball, tracker, "--param", "restitution:ball"}
                                 << "rigidlab-cli: fit: --quantity: which quantity of which body?";
    QTest::newRow("bad-flag") << QStringList{ball,         tracker,  "--param",  "restitution",
                                             "--quantity", "y:ball", "--colour", "red"}
                              << "rigidlab-cli: fit: unknown option --colour";
    QTest::newRow("unknown-body")
        << QStringList{ball, tracker, "--param", "restitution:nope", "--quantity", "y:ball"}
        << "rigidlab-cli: fit: --param: unknown body \"nope\" (the scene has: floor, ball)";
    QTest::newRow("unknown-param")
        << QStringList{ball, tracker, "--param", "mass:ball", "--quantity", "y:ball"}
        << "rigidlab-cli: fit: --param: unknown parameter \"mass\" (expected restitution, "
           "friction, vx or vy)";
    QTest::newRow("bad-quantity")
        << QStringList{ball, tracker, "--param", "restitution:ball", "--quantity", "z:ball"}
        << "rigidlab-cli: fit: --quantity: \"z:ball\": expected QUANTITY:BODY with QUANTITY x, "
           "y, vx, vy or v, as in y:ball";
    QTest::newRow("bad-file") << QStringList{ball,         damaged, "--param", "restitution:ball",
                                             "--quantity", "y:ball"}
                              << "error: " + damaged +
                                     ": line 3, column 2 (\"y\"): \"NaN\" is not a finite number";
    QTest::newRow("missing-file") << QStringList{ball,         "nowhere.csv",
                                                 "--param",    "restitution:ball",
                                                 "--quantity", "y:ball"}
                                  << "error: nowhere.csv: cannot read: No such file or directory";
    QTest::newRow("quantity-not-measured")
        << QStringList{ball, tracker, "--param", "restitution:ball", "--quantity", "vy:ball"}
        << "error: " + tracker +
               ": no column holds vy (columns: t, x, y, vx, vy, v or their "
               "phyphox names)";
    QTest::newRow("bounce-times-two-params")
        << QStringList{ball,      tracker,    "--param",       "restitution",
                       "--param", "friction", "--bounce-times"}
        << "rigidlab-cli: fit: --bounce-times: fits one --param restitution, without --quantity";
    QTest::newRow("param-twice") << QStringList{ball,         tracker,
                                                "--param",    "restitution:ball",
                                                "--param",    "restitution:ball",
                                                "--quantity", "y:ball"}
                                 << "rigidlab-cli: fit: --param: restitution:ball is named twice";
    QTest::newRow("quantity-of-static-body")
        << QStringList{ball, tracker, "--param", "restitution:ball", "--quantity", "y:floor"}
        << "rigidlab-cli: fit: --quantity: \"y:floor\": floor does not move by itself (it is not "
           "a dynamic body): measure one that does";
    QTest::newRow("huge-time-zero")
        << QStringList{ball,         tracker,  "--param",     "restitution:ball",
                       "--quantity", "y:ball", "--time-zero", "1e300"}
        << "error: " + tracker +
               ": line 4, column 1 (\"t\"): time zero (1e+300 s) is so far from the file's "
               "times that they cannot be told apart";
    QTest::newRow("bad-origin") << QStringList{ball,         tracker,  "--param",  "restitution",
                                               "--quantity", "y:ball", "--origin", "1"}
                                << "rigidlab-cli: fit: --origin: expected X,Y in metres, got \"1\"";
    QTest::newRow("bad-unit") << QStringList{ball,         tracker,  "--param",       "restitution",
                                             "--quantity", "y:ball", "--length-unit", "ft"}
                              << "rigidlab-cli: fit: --length-unit: unknown unit \"ft\" (expected "
                                 "m, cm, mm)";
}

void TestMeasure::cliRefuses()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    const CliText run = runCli(QStringList{QStringLiteral("fit")} + arguments);
    QVERIFY(!run.crashed);
    QCOMPARE(run.exitCode, 2);
    QVERIFY(run.out.isEmpty());
    QCOMPARE(run.err.section(u'\n', 0, 0), message);
}

RIGIDLAB_TEST_GUILESS_MAIN(TestMeasure)
