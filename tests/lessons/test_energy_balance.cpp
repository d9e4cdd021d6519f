// SPDX-License-Identifier: GPL-3.0-or-later
// The energy balance of `rigidlab-cli run --diagnostics`: the columns dissipated and drift.
// The drift is the numerical error alone, (total + dissipated - E0) / |E0|: what contacts,
// friction, drag and dampers take is physics, and is added back.

#include "test_lessons.h"

#include "run/scene_run.h"

#include <QDir>
#include <QTemporaryDir>

#include <algorithm>
#include <vector>

using namespace rigidlab;
using namespace rigidlab::test;

namespace {

/// The diagnostics file as columns by name, each a list of its values by row.
struct Columns {
    QList<QByteArray> names;
    std::vector<std::vector<double>> rows;
    double at(std::size_t row, const char* name) const
    {
        const qsizetype i = names.indexOf(QByteArray(name));
        return i < 0 ? std::nan("") : rows[row][static_cast<std::size_t>(i)];
    }
};

Columns readDiagnostics(const QString& path)
{
    Columns c;
    QList<QByteArray> lines = readAll(path).split('\n');
    if (lines.isEmpty())
        return c;
    c.names = lines.takeFirst().split(',');
    for (const QByteArray& line : lines) {
        if (line.isEmpty())
            continue;
        std::vector<double> row;
        for (const QByteArray& field : line.split(','))
            row.push_back(field.toDouble());
        c.rows.push_back(std::move(row));
    }
    return c;
}

/// Runs the scene for `time` seconds, a row every `every` steps, and reads the diagnostics.
Columns runDiagnostics(const lessons::Scene& scene, double time, long long every)
{
    QTemporaryDir dir;
    lessons::RunOptions options;
    options.time = time;
    options.every = every;
    options.diagnosticsPath = dir.filePath(QStringLiteral("d.csv"));
    const lessons::RunReport report = lessons::runScene(scene, options, QStringLiteral("scene"));
    if (report.status != lessons::RunStatus::Ok) {
        qWarning("%s", qPrintable(report.error));
        return {};
    }
    return readDiagnostics(options.diagnosticsPath);
}

} // namespace

// The welcome scene loses energy in inelastic bounces, friction and its springs' dampers (its
// windmill, a kinematic body, pushes some in). Over 10 s the total falls by more than 10 %,
// while the drift, what is left once that is added back, stays within 1 %.
void TestLessons::welcomeDriftIsTheErrorAlone()
{
    const lessons::SceneLoadResult loaded =
        lessons::loadSceneFile(QDir(kScenesDir).filePath(QStringLiteral("welcome.json")));
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    const Columns d = runDiagnostics(loaded.scene, 10.0, 10);
    QCOMPARE(d.rows.size(), std::size_t{1001});
    const double e0 = d.at(0, "E [J]");
    QVERIFY(e0 > 0);
    QCOMPARE(d.at(0, "E_diss [J]"), 0.0);
    QCOMPARE(d.at(0, "drift [1]"), 0.0);
    double worst = 0;
    for (std::size_t r = 0; r < d.rows.size(); ++r) {
        const double drift = d.at(r, "drift [1]");
        QVERIFY(std::isfinite(drift));
        // The column is what it says it is.
        QVERIFY(isClose(drift, (d.at(r, "E [J]") + d.at(r, "E_diss [J]") - e0) / e0, 1e-12));
        worst = std::max(worst, std::abs(drift));
    }
    const std::size_t last = d.rows.size() - 1;
    const double fell = (e0 - d.at(last, "E [J]")) / e0;
    QVERIFY2(fell > 0.10, qPrintable(QStringLiteral("the total fell by %1 only").arg(fell)));
    QVERIFY2(worst <= 0.01, qPrintable(QStringLiteral("the drift reached %1").arg(worst)));
}

// Where nothing dissipates (elastic contacts without friction, no drag, no dampers), nothing
// is added back: the drift is the plain (total - E0) / |E0|.
void TestLessons::conservativeDriftIsTheEnergyChange_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<double>("time");
    // Two balls meet head on and part again; e = 1, no friction, no gravity.
    QTest::newRow("elastic-collision")
        << sceneWith(
               R"("world": {"gravity": [0, 0], "restitution": 1, "friction": 0},
           "bodies": [
             {"id": "a", "shape": {"type": "circle", "radius": 0.2}, "position": [-1, 0],
              "velocity": [2, 0]},
             {"id": "b", "shape": {"type": "circle", "radius": 0.3}, "position": [1, 0.1],
              "velocity": [-1, 0]}])")
        << 2.0;
    // A ball bounces elastically on a frictionless floor under gravity.
    QTest::newRow("elastic-bounces") << sceneWith(
                                            R"("world": {"restitution": 1, "friction": 0},
           "bodies": [
             {"id": "floor", "type": "static", "shape": {"type": "box", "width": 4,
              "height": 0.2}, "position": [0, -0.1]},
             {"id": "ball", "shape": {"type": "circle", "radius": 0.1}, "position": [0, 1],
              "velocity": [0.5, 0]}])")
                                     << 3.0;
    QTest::newRow("undamped-spring") << sceneWith(
                                            R"("world": {"gravity": [0, 0]},
           "bodies": [{"id": "puck", "shape": {"type": "circle", "radius": 0.1},
                       "position": [0.3, 0]}],
           "springs": [{"a": null, "anchorA": [0, 0], "b": "puck", "stiffness": 10,
                        "restLength": 0}])")
                                     << 3.0;
}

void TestLessons::conservativeDriftIsTheEnergyChange()
{
    QFETCH(QByteArray, json);
    QFETCH(double, time);
    const lessons::SceneLoadResult loaded = lessons::loadSceneJson(json, QStringLiteral("x.json"));
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    const Columns d = runDiagnostics(loaded.scene, time, 10);
    QVERIFY(d.rows.size() > 100);
    const double e0 = d.at(0, "E [J]");
    QVERIFY(e0 > 0);
    for (std::size_t r = 0; r < d.rows.size(); ++r) {
        const double plain = (d.at(r, "E [J]") - e0) / e0;
        QVERIFY2(isClose(d.at(r, "drift [1]"), plain, 1e-9),
                 qPrintable(QStringLiteral("row %1: drift %2, energy change %3")
                                .arg(r)
                                .arg(d.at(r, "drift [1]"))
                                .arg(plain)));
    }
    QVERIFY(d.at(d.rows.size() - 1, "t [s]") >= time - 1e-9);
}
