// SPDX-License-Identifier: GPL-3.0-or-later
// Plots that tell the truth and cost little: rounding noise is drawn flat on an axis with
// distinct ticks (niceRange), the points handed to QCustomPlot stay bounded by the plot's
// pixel width whatever the data, CSV times are the step times, and a conserved quantity of a
// real run is drawn as conserved.

#include "plots/plot_export.h"
#include "plots/plot_range.h"
#include "plots/plot_table.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "simulation/step_sampler.h"

#include "format/scene_loader.h"

#include <qcustomplot.h>

#include "near.h"
#include "test_main.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <cstdint>
#include <set>

using namespace rigidlab::ui;

namespace {

/// A deterministic noise in [-1, 1] (a 64-bit LCG), so that a failure can be replayed.
class Noise {
public:
    double next()
    {
        m_state = m_state * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(m_state >> 11) / static_cast<double>(1ULL << 53) * 2.0 - 1.0;
    }

private:
    std::uint64_t m_state = 42;
};

/// The labels of the ticks an axis shows, after a replot.
QStringList tickLabels(const QCPAxis* axis)
{
    const QVector<QString> labels = axis->tickVectorLabels(); // a copy: one begin() and end()
    return QStringList(labels.begin(), labels.end());
}

bool allDistinct(const QStringList& labels)
{
    return std::set<QString>(labels.begin(), labels.end()).size() ==
           static_cast<std::size_t>(labels.size());
}

/// The smallest and largest value of a series' kept points.
std::pair<double, double> extremes(const PlotWidget& plot, int series)
{
    double lo = INFINITY, hi = -INFINITY;
    for (const QPointF& p : plot.model().points(series)) {
        lo = std::min(lo, p.y());
        hi = std::max(hi, p.y());
    }
    return {lo, hi};
}

} // namespace

class TestPlotAxes : public QObject {
    Q_OBJECT

private slots:
    void niceRangeRule_data();
    void niceRangeRule();
    void niceRangeMinimumSpan();
    void niceRangeLabelsAreDistinct_data();
    void niceRangeLabelsAreDistinct();
    void noisyConstantIsDrawnFlat_data();
    void noisyConstantIsDrawnFlat();
    void tickLabelsAreFixedNotation();
    void pointsHandedToGraphStayBounded();
    void csvTimesAreStepTimes();
    void conservedMomentumIsDrawnFlat();
};

void TestPlotAxes::niceRangeRule_data()
{
    QTest::addColumn<double>("min");
    QTest::addColumn<double>("max");
    QTest::addColumn<double>("scale");
    QTest::addColumn<bool>("flat");
    QTest::addColumn<double>("halfSpan"); // expected half height of a flat axis; 0: not flat

    QTest::newRow("zero ± 5e-16, no scale") << -5e-16 << 5e-16 << 0.0 << true << 1.0;
    QTest::newRow("zero ± 5e-16, scale 30 kg m/s") << -5e-16 << 5e-16 << 30.0 << true << 1.5;
    QTest::newRow("exact zero") << 0.0 << 0.0 << 0.0 << true << 1.0;
    QTest::newRow("L = -0.00206182 ± 1e-12, scale 1")
        << -0.0020618210 << -0.0020618205 << 1.0 << true << 0.05;
    QTest::newRow("2 kg m/s ± 4e-16") << 2.0 - 4e-16 << 2.0 + 4e-16 << 2.0 << true << 0.1;
    QTest::newRow("L jumps by 1e-4 of 0.002") << -0.002159 << -0.002062 << 0.0 << false << 0.0;
    QTest::newRow("energy oscillates") << 0.5 << 4.5 << 5.0 << false << 0.0;
    QTest::newRow("swapped") << 4.5 << 0.5 << 5.0 << false << 0.0;
    QTest::newRow("variation just above the floor") << 1.0 << 1.0 + 1e-8 << 1.0 << false << 0.0;
}

void TestPlotAxes::niceRangeRule()
{
    QFETCH(double, min);
    QFETCH(double, max);
    QFETCH(double, scale);
    QFETCH(bool, flat);
    QFETCH(double, halfSpan);

    const AxisRange r = niceRange(min, max, scale);
    QCOMPARE(r.flat, flat);
    QVERIFY(r.lower < r.upper);
    // The data is always inside the axis.
    QVERIFY(r.lower < std::min(min, max) && r.upper > std::max(min, max));
    if (flat) {
        // Centred on the data, as tall as its magnitude says.
        RL_VERIFY_NEAR(0.5 * (r.lower + r.upper), 0.5 * (min + max), 1e-15 * halfSpan, 0);
        RL_VERIFY_NEAR(0.5 * (r.upper - r.lower), halfSpan, 1e-12 * halfSpan, 0);
    } else {
        // Fitted: the data fills all but the margins.
        const double span = std::abs(max - min);
        const double ulps = 1e-15 * std::max(std::abs(min), std::abs(max));
        QVERIFY(std::abs((r.upper - r.lower) - span * (1 + 2 * kValueMargin)) <=
                1e-9 * span + ulps);
    }
}

void TestPlotAxes::niceRangeMinimumSpan()
{
    // The billiards' L changes by 1e-4 kg m^2/s at the break, in a scene that holds about
    // 1.4 kg m^2/s: on an axis 2 % of that tall the step is 0.35 % of the height.
    const double scale = 1.4;
    const AxisRange r = niceRange(-0.002159, -0.002062, scale, 0.02);
    QVERIFY(!r.flat);
    RL_VERIFY_NEAR((r.upper - r.lower), 0.02 * scale, 1e-15, 0);
    RL_VERIFY_NEAR(0.5 * (r.upper + r.lower), 0.5 * (-0.002159 - 0.002062), 1e-15, 0);
    // Without it, the same data fills the axis (the energy drift wants that).
    const AxisRange fitted = niceRange(-0.002159, -0.002062, scale);
    QVERIFY((-0.002062 + 0.002159) > 0.8 * (fitted.upper - fitted.lower));
    // A variation larger than the minimum is fitted as usual.
    const AxisRange large = niceRange(0.0, 1.0, 1.0, 0.02);
    RL_VERIFY_NEAR((large.upper - large.lower), (1 + 2 * kValueMargin), 1e-12, 0);
}

void TestPlotAxes::niceRangeLabelsAreDistinct_data()
{
    QTest::addColumn<double>("min");
    QTest::addColumn<double>("max");
    QTest::newRow("L in the billiards") << -0.0020618215 << -0.0020618205;
    QTest::newRow("energy 1e6 J ± 1e-2") << 1e6 - 1e-2 << 1e6 + 1e-2;
    QTest::newRow("drift") << -3e-5 << 1e-4;
    QTest::newRow("momentum 12.5 ± 1e-7") << 12.5 - 1e-7 << 12.5 + 1e-7;
}

void TestPlotAxes::niceRangeLabelsAreDistinct()
{
    QFETCH(double, min);
    QFETCH(double, max);
    const AxisRange r = niceRange(min, max, 0.0);
    QVERIFY(!r.flat);
    // Ticks at the finest step a ticker would take (2.5 or 1 times a power of ten, a tenth
    // of the axis), printed with the digits niceRange asks for, all read differently.
    for (double fraction : {0.1, 0.25}) {
        const double step = niceStep(r.upper - r.lower, 5) * fraction * 2;
        QStringList labels;
        for (double t = std::ceil(r.lower / step) * step; t <= r.upper; t += step)
            labels << QString::number(t, 'g', r.labelDigits);
        QVERIFY2(labels.size() >= 3, qPrintable(labels.join(' ')));
        QVERIFY2(allDistinct(labels), qPrintable(labels.join(' ')));
    }
}

void TestPlotAxes::noisyConstantIsDrawnFlat_data()
{
    QTest::addColumn<double>("value");
    QTest::addColumn<double>("noise"); // absolute amplitude
    QTest::addColumn<double>("scale");
    QTest::addColumn<bool>("flat");
    QTest::newRow("py of a box stack") << 0.0 << 5e-16 << 30.0 << true;
    QTest::newRow("py, no scale given") << 0.0 << 5e-16 << 0.0 << true;
    QTest::newRow("L of the billiards") << -0.00206182 << 1e-16 << 1.0 << true;
    QTest::newRow("L wandering by 1e-11, scale 1") << -0.00206182 << 1e-11 << 1.0 << true;
    // Real at its own magnitude: fitted, and the ticks need ten digits to differ.
    QTest::newRow("L wandering by 1e-11, no scale") << -0.00206182 << 1e-11 << 0.0 << false;
    QTest::newRow("total energy 42 J") << 42.0 << 1e-14 << 42.0 << true;
}

void TestPlotAxes::noisyConstantIsDrawnFlat()
{
    QFETCH(double, value);
    QFETCH(double, noise);
    QFETCH(double, scale);
    QFETCH(bool, flat);

    PlotWidget plot(QStringLiteral("flat"));
    plot.resize(640, 400);
    plot.show();
    QVERIFY(QTest::qWaitForWindowExposed(&plot));
    plot.model().setRangeMode(RangeMode::WholeRun);
    plot.model().setValueScale(YAxis::Left, scale);
    const int s = plot.addSeries(QStringLiteral("q"), Qt::black);
    Noise rng;
    for (int k = 0; k < 2000; ++k)
        plot.model().appendPoint(s, k * 0.005, value + noise * rng.next());
    plot.drain();
    plot.plot()->replot();

    const QCPAxis* axis = plot.plot()->yAxis;
    const auto [lo, hi] = extremes(plot, s);
    QVERIFY(hi > lo); // the noise is there
    QVERIFY(axis->range().contains(lo) && axis->range().contains(hi));
    // Drawn flat: the noise is less than a millionth of the axis (far below a pixel); or,
    // where it is real, fitted to it.
    if (!flat)
        QVERIFY((hi - lo) > 0.5 * axis->range().size());
    QVERIFY2(
        !flat || (hi - lo) < 1e-6 * axis->range().size(),
        qPrintable(QString("axis %1 .. %2").arg(axis->range().lower).arg(axis->range().upper)));
    const QStringList labels = tickLabels(axis);
    QVERIFY2(labels.size() >= 3, qPrintable(labels.join(' ')));
    QVERIFY2(allDistinct(labels), qPrintable(labels.join(' ')));
}

/// A small quantity (a drift of 4·10⁻⁵ %) is labelled as people write it, in the window's
/// locale, never "4E-05"; each label reads back as its tick's value.
void TestPlotAxes::tickLabelsAreFixedNotation()
{
    QLocale::setDefault(QLocale(QLocale::Czech));
    PlotWidget plot(QStringLiteral("drift"));
    QLocale::setDefault(QLocale::c());
    plot.resize(640, 400);
    plot.show();
    QVERIFY(QTest::qWaitForWindowExposed(&plot));
    plot.model().setRangeMode(RangeMode::WholeRun);
    const int s = plot.addSeries(QStringLiteral("q"), Qt::black);
    for (int k = 0; k <= 100; ++k)
        plot.model().appendPoint(s, k * 0.01, 4e-5 * k / 100.0);
    plot.drain();
    plot.plot()->replot();
    const QCPAxis* axis = plot.plot()->yAxis;
    const QStringList labels = tickLabels(axis);
    QVERIFY2(labels.size() >= 3, qPrintable(labels.join(' ')));
    const QVector<double> ticks = axis->tickVector();
    QCOMPARE(ticks.size(), labels.size());
    const QLocale czech(QLocale::Czech);
    for (int i = 0; i < labels.size(); ++i) {
        QVERIFY2(!labels[i].contains(u'E') && !labels[i].contains(u'e'), qPrintable(labels[i]));
        bool ok = false;
        const double read = czech.toDouble(labels[i], &ok);
        QVERIFY2(ok, qPrintable(labels[i]));
        QVERIFY2(
            std::abs(read - ticks[i]) <= 1e-3 * axis->range().size(),
            qPrintable(
                QStringLiteral("%1 reads %2, tick %3").arg(labels[i]).arg(read).arg(ticks[i])));
    }
}

void TestPlotAxes::pointsHandedToGraphStayBounded()
{
    PlotWidget plot(QStringLiteral("dense"));
    plot.resize(600, 300);
    plot.show();
    QVERIFY(QTest::qWaitForWindowExposed(&plot));
    plot.model().setRangeMode(RangeMode::WholeRun);
    plot.model().setPointBudget(200000); // keep every point: the graph must still get few
    const int s = plot.addSeries(QStringLiteral("noise"), Qt::black);
    Noise rng;
    constexpr int kSamples = 100000;
    double lo = INFINITY, hi = -INFINITY;
    for (int k = 0; k < kSamples; ++k) {
        const double v = rng.next();
        lo = std::min(lo, v);
        hi = std::max(hi, v);
        plot.model().appendPoint(s, k * 1e-3, v);
    }
    QCOMPARE(plot.model().pointCount(s), kSamples); // the CSV still has them all
    plot.drain();
    plot.plot()->replot();

    const int width = plot.plot()->width();
    QVERIFY(width > 0);
    const QCPGraph* graph = plot.graph(s);
    QVERIFY2(graph->dataCount() <= 3 * width + 6,
             qPrintable(QString("%1 points for %2 px").arg(graph->dataCount()).arg(width)));
    QVERIFY(graph->dataCount() > width); // and dense enough to cover every column
    // The extremes of the data are drawn: nothing is clipped by decimation.
    bool found = false;
    QCOMPARE(graph->getValueRange(found).lower, lo);
    QCOMPARE(graph->getValueRange(found).upper, hi);
}

void TestPlotAxes::csvTimesAreStepTimes()
{
    // dt = 0.01 s: summed step by step, the time reads 0.010000000000000002 and worse.
    const QByteArray json = R"({"rigidlab": 1, "title": "ball",
        "world": {"gravity": [0, -9.81], "dt": 0.01},
        "bodies": [{"id": "b", "shape": {"type": "circle", "radius": 0.1}, "mass": 1}]})";
    const auto loaded = rigidlab::lessons::loadSceneJson(json, QStringLiteral("ball.json"));
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    SimulationController controller;
    controller.loadScene(loaded.scene, QStringLiteral("ball.json"));
    const double dt = controller.world().def().dt;
    PlotWidget* plot = makeEnergyPlot(nullptr);
    std::unique_ptr<PlotWidget> owner(plot);
    plot->model().setRangeMode(RangeMode::WholeRun);
    plot->model().setSource(&controller.recorder().samples());

    constexpr int kSteps = 300;
    double summed = 0;
    int summedDiffers = 0;
    for (int k = 1; k <= kSteps; ++k) {
        controller.stepForward();
        summed += dt;
        summedDiffers += summed != stepTime(k, dt);
    }
    QVERIFY(summedDiffers > 0); // the test would be empty otherwise
    plot->drain();

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("energy.csv"));
    QVERIFY(exportPlot(*plot, path, ExportFormat::Csv).ok);
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = file.readAll().split('\n');
    int rows = 0;
    for (qsizetype i = 1; i < lines.size(); ++i) {
        if (lines[i].isEmpty())
            continue;
        const QByteArray cell = lines[i].split(',').front();
        bool ok = false;
        const double t = cell.toDouble(&ok);
        QVERIFY2(ok, cell.constData());
        QCOMPARE(t, rows * dt);                       // exactly: the same double as k * dt
        QVERIFY2(cell.size() <= 5, cell.constData()); // "2.99", not "2.9899999999999"
        ++rows;
    }
    QCOMPARE(rows, kSteps + 1);
}

void TestPlotAxes::conservedMomentumIsDrawnFlat()
{
    // Two equal balls, no gravity, elastic: the first stops and the second moves on at 2 m/s;
    // p = (2, 0) kg m/s throughout.
    const QByteArray json = R"({"rigidlab": 1, "title": "collision",
        "world": {"gravity": [0, 0], "dt": 0.001, "restitution": 1, "friction": 0},
        "bodies": [
          {"id": "a", "shape": {"type": "circle", "radius": 0.2}, "position": [-1.5, 0.3],
           "velocity": [2, 0], "mass": 1, "restitution": 1, "friction": 0},
          {"id": "b", "shape": {"type": "circle", "radius": 0.2}, "position": [0.5, 0.3],
           "mass": 1, "restitution": 1, "friction": 0}]})";
    const auto loaded = rigidlab::lessons::loadSceneJson(json, QStringLiteral("two.json"));
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    SimulationController controller;
    controller.loadScene(loaded.scene, QStringLiteral("two.json"));
    std::unique_ptr<PlotWidget> plot(makeMomentumPlot(nullptr));
    plot->resize(640, 400);
    plot->show();
    QVERIFY(QTest::qWaitForWindowExposed(plot.get()));
    plot->model().setRangeMode(RangeMode::WholeRun);
    plot->model().setSource(&controller.recorder().samples());
    for (int k = 0; k < 2000; ++k)
        controller.stepForward();
    QVERIFY(controller.world().bodies()[1].velocity.x() > 1.9); // they did collide
    plot->drain();
    plot->plot()->replot();

    // px and py on the left axis, L on the right: each drawn flat, with distinct ticks.
    for (const auto& [axis, series] :
         {std::pair{plot->plot()->yAxis, std::vector{0, 1}}, {plot->plot()->yAxis2, {2}}}) {
        double lo = INFINITY, hi = -INFINITY;
        for (int s : series) {
            const auto [l, h] = extremes(*plot, s);
            lo = std::min(lo, l);
            hi = std::max(hi, h);
        }
        QVERIFY(axis->range().contains(lo) && axis->range().contains(hi));
        for (int s : series) {
            const auto [l, h] = extremes(*plot, s);
            QVERIFY2(h - l < 1e-6 * axis->range().size(),
                     qPrintable(QString("%1: %2 .. %3 on %4 .. %5")
                                    .arg(plot->model().seriesName(s))
                                    .arg(l, 0, 'g', 17)
                                    .arg(h, 0, 'g', 17)
                                    .arg(axis->range().lower)
                                    .arg(axis->range().upper)));
        }
        QVERIFY(allDistinct(tickLabels(axis)));
    }
}

RIGIDLAB_TEST_MAIN(TestPlotAxes)
#include "test_plot_axes.moc"
