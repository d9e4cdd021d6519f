// SPDX-License-Identifier: GPL-3.0-or-later
// A plot's model alone, with no widget and no QCustomPlot: the samples drained into its series
// with the values pushed, time travel keeping the run's old future as the ghost, the time
// window kept and followed, the marks, and the CSV column heads.

#include "plots/plot_export.h"
#include "plots/plot_model.h"
#include "simulation/sample_buffer.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>
#include <limits>

using namespace rigidlab::ui;

namespace {

/// A sample at t [s] with values that differ at every t.
Sample sampleAt(double t)
{
    Sample s;
    s.t = t;
    s.kinetic = 1.5 + std::sin(t);
    s.total = 4.0 - 0.5 * t;
    return s;
}

/// Pushes samples t = first, first + dt, ... up to `last` [s], and takes them into the model.
int feed(SampleBuffer& buffer, PlotModel& model, double first, double last, double dt)
{
    for (int i = 0; first + i * dt <= last + 1e-9; ++i)
        buffer.push(sampleAt(first + i * dt));
    return model.takeSamples();
}

/// A model reading kinetic (left axis) and total (right axis) energy from its samples.
int addEnergySeries(PlotModel& model)
{
    model.addSeries(QStringLiteral("kinetic"), [](const Sample& s) { return s.kinetic; });
    return model.addSeries(
        QStringLiteral("total"), [](const Sample& s) { return s.total; }, YAxis::Right);
}

} // namespace

class TestPlotModel : public QObject {
    Q_OBJECT

private slots:
    void drainTakesTheValuesPushed();
    void rewindKeepsTheFutureAsGhost();
    void windowKeepsAndFollowsTheNewest();
    void csvHeadsNameTheSeries();
};

void TestPlotModel::drainTakesTheValuesPushed()
{
    PlotModel model;
    SampleBuffer buffer;
    addEnergySeries(model);
    const int byHand = model.addSeries(QStringLiteral("measured"), {});
    model.setSource(&buffer);
    QVERIFY(!model.takeChanged());

    QCOMPARE(feed(buffer, model, 0.0, 0.9, 0.1), 10);
    QVERIFY(model.takeChanged());
    QVERIFY(!model.takeChanged()); // told once
    const std::vector<QPointF> kinetic = model.points(0);
    const std::vector<QPointF> total = model.points(1);
    QCOMPARE(kinetic.size(), std::size_t(10));
    QCOMPARE(total.size(), std::size_t(10));
    for (std::size_t i = 0; i < kinetic.size(); ++i) {
        const Sample pushed = sampleAt(0.1 * static_cast<double>(i));
        QCOMPARE(kinetic[i].x(), pushed.t);
        QCOMPARE(kinetic[i].y(), pushed.kinetic);
        QCOMPARE(total[i].y(), pushed.total);
    }
    QCOMPARE(model.pointCount(byHand), 0); // fed by hand only
    QCOMPARE(model.takeSamples(), 0);      // nothing new

    // A series fed by hand restarts where a point comes not later than its last one.
    model.appendPoint(byHand, 1.0, 10.0);
    model.appendPoint(byHand, 2.0, 20.0);
    model.appendPoint(byHand, 1.5, 15.0);
    const std::vector<QPointF> measured = model.points(byHand);
    QCOMPARE(measured.size(), std::size_t(2));
    QCOMPARE(measured[1], QPointF(1.5, 15.0));
    model.appendPoint(byHand, 3.0, std::numeric_limits<double>::infinity());
    QVERIFY(std::isnan(model.points(byHand).back().y())); // a gap, not an infinite axis
    QCOMPARE(model.pointCount(), 10 + 10 + 3);
}

void TestPlotModel::rewindKeepsTheFutureAsGhost()
{
    // Times in eighths of a second, exact in binary: the branch's times meet the ghost's.
    constexpr double dt = 0.125;
    PlotModel model;
    SampleBuffer buffer;
    addEnergySeries(model);
    model.setSource(&buffer);
    QSignalSpy marks(&model, &PlotModel::marksChanged);
    feed(buffer, model, 0.0, 2.0, dt);
    model.addMark(1.55, QStringLiteral("dt = 5 ms"));
    model.addMark(0.5, QStringLiteral("RK4"));
    QCOMPARE(marks.count(), 2);
    QCOMPARE(model.marks().front().t, 0.5); // sorted by time

    model.rewind(1.0);
    QCOMPARE(marks.count(), 3); // the later mark went ghost
    QVERIFY(!model.markIsGhost(0));
    QVERIFY(model.markIsGhost(1));
    QCOMPARE(*model.latest(), 1.0);
    const std::vector<QPointF> kept = model.points(0);
    const std::vector<QPointF> ghost = model.ghostPoints(0);
    QCOMPARE(kept.size(), std::size_t(9));  // 0, 0.125, ..., 1.0
    QCOMPARE(ghost.size(), std::size_t(8)); // 1.125, ..., 2.0, as they were
    QCOMPARE(kept.back().x(), 1.0);
    for (const QPointF& p : ghost)
        QCOMPARE(p.y(), sampleAt(p.x()).kinetic);

    // The run goes on from 1.0 on a new branch: it replaces the point at 1.0 and overwrites
    // the ghost as far as it comes; the ghost mark goes when the branch passes it.
    feed(buffer, model, 1.0, 1.625, dt);
    QCOMPARE(model.points(0).size(), std::size_t(14));     // 0, ..., 1.625
    QCOMPARE(model.ghostPoints(0).size(), std::size_t(3)); // 1.75, 1.875, 2.0
    QCOMPARE(model.ghostPoints(0).front().x(), 1.75);
    QCOMPARE(model.markCount(), 1);
    QCOMPARE(model.marks().front().text, QStringLiteral("RK4"));

    // Going back again, then forward: the ghost points come back as points.
    model.rewind(0.5);
    QCOMPARE(model.points(1).size(), std::size_t(5)); // 0, ..., 0.5
    model.rewind(1.95);
    QCOMPARE(model.points(1).size(), std::size_t(16)); // 0, ..., 1.875
    QCOMPARE(model.ghostPoints(1).size(), std::size_t(1));
    for (const QPointF& p : model.points(1))
        QCOMPARE(p.y(), sampleAt(p.x()).total);
}

void TestPlotModel::windowKeepsAndFollowsTheNewest()
{
    PlotModel model;
    SampleBuffer buffer(4096);
    addEnergySeries(model);
    model.setSource(&buffer);
    model.setWindowSeconds(2.0);

    // A run shorter than the window is drawn across the axis, from its start.
    feed(buffer, model, 0.0, 1.5, 0.01);
    std::optional<PlotRange> shown = model.followedRange(false);
    QVERIFY(shown);
    QCOMPARE(shown->lower, 0.0);
    QVERIFY2(shown->upper >= 1.5 && shown->upper <= 1.5 * 20 / 19 + 1e-9,
             qPrintable(QString::number(shown->upper)));

    // Longer: the axis scrolls with the newest time, and the points older than the window
    // and its margin (10 %) go.
    feed(buffer, model, 1.51, 10.0, 0.01);
    shown = model.followedRange(false);
    QVERIFY2(std::abs(shown->upper - 10.0) < 1e-9 && std::abs(shown->lower - 8.0) < 1e-9,
             qPrintable(QStringLiteral("%1 .. %2").arg(shown->lower).arg(shown->upper)));
    const double oldest = model.points(0).front().x();
    QVERIFY2(oldest >= 10.0 - 2.0 * 1.1 - 1e-9 && oldest < 8.0,
             qPrintable(QString::number(oldest)));
    QCOMPARE(model.points(0, PlotRange{8.995, 10.005}).size(), std::size_t(101));

    // A view paused on older times keeps what it shows (from 8 s; the window alone would
    // keep from 9.8 s on).
    model.setHeldFrom(8.0);
    feed(buffer, model, 10.01, 12.0, 0.01);
    QVERIFY2(model.points(0).front().x() < 8.02,
             qPrintable(QString::number(model.points(0).front().x())));
    model.setHeldFrom(std::nullopt);
    QVERIFY2(model.points(0).front().x() >= 12.0 - 2.2 - 1e-9,
             qPrintable(QString::number(model.points(0).front().x())));

    // The whole run from its first point kept.
    model.setRangeMode(RangeMode::WholeRun);
    feed(buffer, model, 12.01, 13.0, 0.01);
    shown = model.followedRange(false);
    QCOMPARE(shown->lower, model.points(0).front().x());
    QVERIFY2(std::abs(shown->upper - 13.0) < 1e-9, qPrintable(QString::number(shown->upper)));
}

void TestPlotModel::csvHeadsNameTheSeries()
{
    PlotModel model;
    const int kinetic = model.addSeries(QStringLiteral("kinetic"), {});
    const int drift = model.addSeries(QStringLiteral("euler"), {}, YAxis::Right);
    const int count = model.addSeries(QStringLiteral("contacts"), {}, YAxis::Right);
    model.setUnit(YAxis::Left, QStringLiteral("J"));
    model.setUnit(YAxis::Right, QString());
    model.setSeriesLegend(kinetic, QStringLiteral("kinetic energy"));
    model.setSeriesColumn(drift, QStringLiteral("drift [%]"));

    QCOMPARE(model.csvHead(kinetic, false), QStringLiteral("kinetic [J]"));
    QCOMPARE(model.csvHead(kinetic, true), QStringLiteral("kinetic energy [J]"));
    QCOMPARE(model.csvHead(drift, true), QStringLiteral("drift [%]")); // the one set wins
    QCOMPARE(model.csvHead(count, false), QStringLiteral("contacts")); // no unit, no brackets

    model.appendPoint(kinetic, 0.5, 2.0);
    model.appendPoint(drift, 0.25, 1.0);
    const QByteArray table = plotTable(model, rigidlab::lessons::CsvConventions{}, false);
    const QList<QByteArray> lines = table.trimmed().split('\n');
    QCOMPARE(lines.size(), 3);
    QCOMPARE(lines[0].trimmed(), QByteArray("t [s],kinetic [J],drift [%],contacts"));
    QCOMPARE(lines[1].trimmed(), QByteArray("0.25,,1,"));
    QCOMPARE(lines[2].trimmed(), QByteArray("0.5,2,,"));
}

QTEST_GUILESS_MAIN(TestPlotModel)
#include "test_plot_model.moc"
