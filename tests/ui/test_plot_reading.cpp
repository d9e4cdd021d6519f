// SPDX-License-Identifier: GPL-3.0-or-later
// Plots that tell the truth: going back on the timeline keeps the plots up to the
// moment chosen and branches them when the run goes on; a short run gets a short time axis;
// legends in words, and curves that coincide all visible, in the window and in exports.
// (Marks and export folders: test_plot_marks.cpp.)
#include "build_paths.h"
#include "common/display_names.h"
#include "common/export_folder.h"
#include "lesson_player/lesson_player.h"
#include "plots/lesson_export.h"
#include "plots/plot_export.h"
#include "plots/plot_table.h"
#include "plots/plot_widget.h"
#include "simulation/sample_buffer.h"
#include "simulation/simulation_controller.h"
#include "window/main_window.h"

#include "format/lesson.h"

#include <qcustomplot.h>

#include <QApplication>
#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QSettings>
#include <QSlider>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

#include "sourced_plot.h"
#include "test_main.h"

#include <cmath>
#include <memory>

using namespace rigidlab;
using namespace rigidlab::ui;
using rigidlab::test::SourcedPlot;

namespace {

constexpr double kDt = 1.0 / 64; // [s] between samples, exact in binary

Sample sampleAt(double t)
{
    Sample s;
    s.t = t;
    s.kinetic = 1.5 + std::sin(t);
    s.potential = 2.25 - std::sin(t);
    s.total = s.kinetic + s.potential;
    s.px = 0.5 * t;
    s.py = 1.0 - 0.25 * t;
    s.angularMomentum = 0.1 + t * t;
    s.driftPercent = 1e-3 * t;
    return s;
}

/// Samples t = first, first + kDt, ..., up to and with last, drained as they come.
void feed(SampleBuffer& buffer, PlotWidget& plot, double first, double last)
{
    for (int i = 0; first + i * kDt <= last + 1e-12; ++i) {
        buffer.push(sampleAt(first + i * kDt));
        if (i % 256 == 255)
            plot.drain();
    }
    plot.drain();
}

/// What SimulationController::seek does: the plots are told, then a sample at t follows.
void travel(SampleBuffer& buffer, PlotWidget& plot, double t)
{
    plot.rewind(t);
    buffer.push(sampleAt(t));
    plot.drain();
}

QCPRange timeRange(const PlotWidget& plot)
{
    return plot.plot()->xAxis->range();
}

QString lessonPath(const char* name)
{
    return rigidlab::test::sourcePath(u"/lessons/lessons/%1.json").arg(QLatin1String(name));
}

/// Pixels of the image within `tolerance` of `color` in every channel.
int pixelsOf(const QImage& image, const QColor& color, int tolerance = 40)
{
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (std::abs(c.red() - color.red()) <= tolerance &&
                std::abs(c.green() - color.green()) <= tolerance &&
                std::abs(c.blue() - color.blue()) <= tolerance)
                ++n;
        }
    return n;
}

} // namespace

class TestPlotReading : public QObject {
    Q_OBJECT
private slots:
    void scrubBackKeepsPointsAndShowsTheMoment();
    void playingOnBranchesAfterThePoint();
    void scrubBackReachesAsFarAsTheTimeline();
    void ghostIsDrawnFadedOutsideTheLegend();
    void windowTimelineFollowsTheScrub();
    void shortRunGetsShortAxis_data();
    void shortRunGetsShortAxis();
    void namesInWords();
    void comparedCurvesStayVisible();
    void runawayGoesOffScale();
};

void TestPlotReading::scrubBackKeepsPointsAndShowsTheMoment()
{
    auto [buffer, plot] = SourcedPlot(makeEnergyPlot(nullptr));
    feed(buffer, *plot, 0.0, 8.0);
    plot->model().addMark(2.0, QStringLiteral("dt = 5 ms"));
    plot->model().addMark(6.0, QStringLiteral("RK4"));

    travel(buffer, *plot, 4.0);
    for (int s = 0; s < plot->model().seriesCount(); ++s) {
        const std::vector<QPointF> pts = plot->model().points(s);
        QCOMPARE(pts.front().x(), 0.0);
        QCOMPARE(pts.back().x(), 4.0);
        QCOMPARE(static_cast<int>(pts.size()), 4 * 64 + 1);
        // What came after is kept, as the ghost.
        const std::vector<QPointF> ghost = plot->model().ghostPoints(s);
        QCOMPARE(ghost.front().x(), 4.0 + kDt);
        QCOMPARE(ghost.back().x(), 8.0);
    }
    QCOMPARE(plot->model().points(2).back().y(), sampleAt(4.0).total);
    const QCPRange range = timeRange(*plot);
    QVERIFY2(range.lower <= 4.0 && 4.0 < range.upper,
             qPrintable(QStringLiteral("%1 .. %2").arg(range.lower).arg(range.upper)));
    QVERIFY(range.upper <= 8.0); // the whole run, shorter than the window: its old future too
    QCOMPARE(plot->model().markCount(), 2);
    QVERIFY(!plot->model().markIsGhost(0));
    QVERIFY(plot->model().markIsGhost(1));

    // Forward again along the same timeline: the ghost points are points again.
    travel(buffer, *plot, 6.0);
    QCOMPARE(plot->model().points(0).back().x(), 6.0);
    QCOMPARE(static_cast<int>(plot->model().points(0).size()), 6 * 64 + 1);
    QCOMPARE(plot->model().ghostPoints(0).front().x(), 6.0 + kDt);
    QVERIFY(timeRange(*plot).contains(6.0));
    QVERIFY(!plot->model().markIsGhost(1)); // the mark at 6 s is on the timeline again

    // Back to the start, from a plot the user had dragged aside.
    plot->plot()->xAxis->setRange(6.5, 7.5);
    QVERIFY(!plot->isFollowing());
    travel(buffer, *plot, 0.0);
    QVERIFY(plot->isFollowing());
    QCOMPARE(plot->model().pointCount(0), 1);
    QCOMPARE(static_cast<int>(plot->model().ghostPoints(0).size()), 8 * 64);
    QVERIFY(timeRange(*plot).contains(0.0));
}

void TestPlotReading::playingOnBranchesAfterThePoint()
{
    auto [buffer, plot] = SourcedPlot(makeDriftPlot(nullptr));
    feed(buffer, *plot, 0.0, 8.0);
    plot->model().addMark(6.0, QStringLiteral("RK4"));
    travel(buffer, *plot, 3.0);

    // The run goes on from 3 s: the new points come after the branch point, evenly.
    feed(buffer, *plot, 3.0 + kDt, 5.0);
    std::vector<QPointF> pts = plot->model().points(0);
    QCOMPARE(pts.back().x(), 5.0);
    QCOMPARE(static_cast<int>(pts.size()), 5 * 64 + 1);
    for (std::size_t k = 1; k < pts.size(); ++k)
        QCOMPARE(pts[k].x() - pts[k - 1].x(), kDt);
    // The old future is overwritten as far as the new branch has come, and drawn beyond it.
    QCOMPARE(plot->model().ghostPoints(0).front().x(), 5.0 + kDt);
    QCOMPARE(plot->model().markCount(), 1); // the mark at 6 s is still ahead
    QVERIFY(timeRange(*plot).contains(5.0));

    feed(buffer, *plot, 5.0 + kDt, 7.0);
    QCOMPARE(plot->model().markCount(), 0); // passed by a run that did not make that change
    QCOMPARE(plot->model().ghostPoints(0).front().x(), 7.0 + kDt);
    feed(buffer, *plot, 7.0 + kDt, 9.0);
    QVERIFY(plot->model().ghostPoints(0).empty());
    QCOMPARE(plot->model().points(0).back().x(), 9.0);
    QCOMPARE(timeRange(*plot).upper, 9.0);
}

void TestPlotReading::scrubBackReachesAsFarAsTheTimeline()
{
    auto [buffer, plot] = SourcedPlot(makeEnergyPlot(nullptr));
    plot->model().setTimelineStart(0.0);
    feed(buffer, *plot, 0.0, 40.0); // four windows
    QCOMPARE(plot->model().points(0).front().x(), 0.0);

    travel(buffer, *plot, 5.0);
    QCOMPARE(plot->model().points(0).front().x(), 0.0);
    QCOMPARE(plot->model().points(0).back().x(), 5.0);
    QCOMPARE(timeRange(*plot).lower, 0.0);
    QVERIFY(timeRange(*plot).contains(5.0));
    QCOMPARE(timeRange(*plot).size(), plot->model().windowSeconds());

    travel(buffer, *plot, 25.0);
    QCOMPARE(timeRange(*plot).size(), plot->model().windowSeconds());
    QVERIFY(timeRange(*plot).contains(25.0));
    QVERIFY(timeRange(*plot).upper < 40.0);

    // Once the timeline forgets its start, so does the plot (a window and its margin kept).
    plot->model().setTimelineStart(20.0);
    feed(buffer, *plot, 25.0 + kDt, 35.0);
    QVERIFY(plot->model().points(0).front().x() >= 20.0 - 1e-9);
    QVERIFY(plot->model().points(0).front().x() < 24.0);

    // A timeline longer than half the point budget: the oldest go, the window is not thinned.
    std::unique_ptr<PlotWidget> small(makeEnergyPlot(nullptr));
    SampleBuffer smallBuffer;
    small->model().setSource(&smallBuffer);
    small->model().setPointBudget(2000); // half of it: 15.6 s at 64 Hz, more than the window
    small->model().setTimelineStart(0.0);
    feed(smallBuffer, *small, 0.0, 60.0); // 3841 samples
    const std::vector<QPointF> pts = small->model().points(0);
    QVERIFY2(pts.size() <= 1001 && pts.size() >= 900, qPrintable(QString::number(pts.size())));
    QCOMPARE(pts.back().x(), 60.0);
    for (std::size_t k = 1; k < pts.size(); ++k)
        QCOMPARE(pts[k].x() - pts[k - 1].x(), kDt);
}

void TestPlotReading::ghostIsDrawnFadedOutsideTheLegend()
{
    std::unique_ptr<PlotWidget> plot(makeMomentumPlot(nullptr));
    plot->model().setRangeMode(RangeMode::WholeRun);
    SampleBuffer buffer;
    plot->model().setSource(&buffer);
    feed(buffer, *plot, 0.0, 4.0);
    const int legendItems = plot->plot()->legend->itemCount();
    travel(buffer, *plot, 2.0);
    QCOMPARE(timeRange(*plot).lower, 0.0);
    QCOMPARE(timeRange(*plot).upper, 4.0); // the whole run, its old future too
    plot->prepareGraphs(400);

    QCustomPlot* qcp = plot->plot();
    QCOMPARE(qcp->graphCount(), 2 * plot->model().seriesCount());
    QCOMPARE(qcp->legend->itemCount(), legendItems);
    int ghosts = 0;
    for (int s = 0; s < plot->model().seriesCount(); ++s) {
        QCPGraph* own = plot->graph(s);
        for (int g = 0; g < qcp->graphCount(); ++g) {
            QCPGraph* other = qcp->graph(g);
            if (other == own || other->pen().color().rgb() != own->pen().color().rgb())
                continue;
            // Same colour, fainter, dotted; holding the points after 2 s.
            QVERIFY(other->pen().color().alphaF() < 0.6);
            QCOMPARE(other->pen().style(), Qt::DotLine);
            QVERIFY(!qcp->legend->hasItemWithPlottable(other));
            QVERIFY(!other->data()->isEmpty());
            QVERIFY(other->data()->constBegin()->key > 2.0);
            QVERIFY((own->data()->constEnd() - 1)->key <= 2.0);
            ++ghosts;
        }
    }
    QCOMPARE(ghosts, plot->model().seriesCount());

    plot->clear();
    QVERIFY(plot->model().ghostPoints(0).empty());
}

void TestPlotReading::windowTimelineFollowsTheScrub()
{
    // The window as wired: dragging the timeline back keeps each plot up to the chosen step,
    // the label says the step, and playing on appends after it.
    ui::MainWindow w;
    QCOMPARE(w.openScene(rigidlab::test::sourcePath(u"/lessons/scenes/ball_drop.json"), true),
             QString());
    SimulationController& c = w.controller();
    for (int i = 0; i < 600; ++i)
        c.stepForward();
    PlotWidget* energy = w.plot(u"energy");
    energy->drain();
    const double end = c.world().time();
    QVERIFY(end > 0.5);
    QCOMPARE(energy->model().points(0).back().x(), end);

    auto* timeline = w.findChild<QSlider*>(QStringLiteral("timeline"));
    auto* label = w.findChild<QLabel*>(QStringLiteral("timelineLabel"));
    QVERIFY(timeline && label);
    const int target = 250;
    timeline->setSliderDown(true); // a hand on it
    timeline->setValue(target);
    timeline->setSliderDown(false);
    QCOMPARE(c.world().stepCount(), target);
    QVERIFY2(label->text().contains(QStringLiteral("step %1 ").arg(target)),
             qPrintable(label->text()));
    QVERIFY2(label->text().contains(QLocale().toString(c.world().time(), 'f', 3)),
             qPrintable(label->text()));

    const double chosen = c.world().time();
    QVERIFY(chosen < end);
    energy->drain();
    for (PlotWidget* plot : w.plots()) {
        plot->drain();
        QVERIFY(plot->model().points(0).front().x() < 0.05); // from the start of the run
        QCOMPARE(plot->model().points(0).back().x(), chosen);
        QVERIFY(plot->model().pointCount(0) > 50);
        QVERIFY(!plot->model().ghostPoints(0).empty());
        QVERIFY2(timeRange(*plot).contains(chosen), qPrintable(plot->objectName()));
    }

    // Play on from there: the new points come after the branch point.
    for (int i = 0; i < 40; ++i)
        c.stepForward();
    energy->drain();
    const std::vector<QPointF> pts = energy->model().points(0);
    QCOMPARE(pts.back().x(), c.world().time());
    QVERIFY(pts.back().x() > chosen);
    for (std::size_t k = 1; k < pts.size(); ++k)
        QVERIFY(pts[k].x() > pts[k - 1].x());
    QVERIFY(!energy->model().ghostPoints(0).empty()); // the rest of the old future, faded
    QVERIFY(energy->model().ghostPoints(0).front().x() > pts.back().x());
    QVERIFY(timeRange(*energy).contains(c.world().time()));
}

void TestPlotReading::shortRunGetsShortAxis_data()
{
    QTest::addColumn<double>("run"); // [s]
    QTest::newRow("1 s") << 1.0;
    QTest::newRow("3 s") << 3.0;
    QTest::newRow("4.75 s") << 4.75;
    QTest::newRow("9 s") << 9.0;
}

void TestPlotReading::shortRunGetsShortAxis()
{
    QFETCH(double, run);
    auto [buffer, plot] = SourcedPlot(makeEnergyPlot(nullptr));
    feed(buffer, *plot, 0.0, run);
    const QCPRange range = timeRange(*plot);
    QCOMPARE(range.lower, 0.0);
    // The run fills the axis (within a round step), not the first part of a 10 s window.
    QVERIFY2(range.upper >= run && range.upper <= run * 1.1 + 1e-9,
             qPrintable(QStringLiteral("%1 .. %2").arg(range.lower).arg(range.upper)));
    QVERIFY(range.upper <= plot->model().windowSeconds());

    // It grows to the window, then scrolls.
    feed(buffer, *plot, run + kDt, 15.0);
    QCOMPARE(timeRange(*plot).size(), plot->model().windowSeconds());
    QCOMPARE(timeRange(*plot).upper, 15.0);
}

void TestPlotReading::namesInWords()
{
    QCOMPARE(integratorDisplayName(physics::IntegratorKind::SymplecticEuler),
             QStringLiteral("Symplectic Euler"));
    QCOMPARE(methodDisplayName(QStringLiteral("rk4")), QStringLiteral("Runge–Kutta 4"));
    QCOMPARE(methodDisplayName(QStringLiteral("verlet")), QStringLiteral("Velocity Verlet"));
    QCOMPARE(methodDisplayName(QStringLiteral("euler")), QStringLiteral("Explicit Euler"));
    QCOMPARE(methodDisplayName(QStringLiteral("sequential-impulse")),
             QStringLiteral("Sequential impulse"));
    QCOMPARE(methodDisplayName(QStringLiteral("something else")), QStringLiteral("something else"));
    // Every method has words, and no two share them.
    QStringList seen;
    for (physics::IntegratorKind k : physics::kAllIntegrators) {
        const QString words = integratorDisplayName(k);
        QVERIFY2(words != QString::fromUtf8(physics::integratorName(k).data()), qPrintable(words));
        QVERIFY(!seen.contains(words));
        seen << words;
    }

    // A compared lesson step's legend, in the window and in the exported file.
    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(lessonPath("energy_drift"));
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    QWidget parent;
    PlotWidget* plot =
        makeStepPlot(loaded.lesson.steps[0], QStringLiteral("compare-energy"), &parent);
    QVERIFY(plot);
    QStringList legend;
    for (int i = 0; i < plot->plot()->legend->itemCount(); ++i)
        if (auto* item = qobject_cast<QCPPlottableLegendItem*>(plot->plot()->legend->item(i)))
            legend << item->plottable()->name();
    QCOMPARE(legend,
             (QStringList{QStringLiteral("Explicit Euler"), QStringLiteral("Symplectic Euler"),
                          QStringLiteral("Velocity Verlet"), QStringLiteral("Runge–Kutta 4")}));
    QTemporaryDir dir;
    const QString svg = dir.filePath(QStringLiteral("compare.svg"));
    QVERIFY(exportPlot(*plot, svg, ExportFormat::Svg).ok);
    QFile file(svg);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(file.readAll());
    QVERIFY(text.contains(QStringLiteral("Velocity Verlet")));
    QVERIFY(!text.contains(QStringLiteral(">verlet<")));
    // The handout's caption too.
    const QString caption =
        stepCaption(loaded.lesson, 0, lessons::buildStepWorlds(loaded.lesson.steps[0])[0].def());
    QVERIFY2(caption.contains(QStringLiteral("Runge–Kutta 4")), qPrintable(caption));
}

void TestPlotReading::runawayGoesOffScale()
{
    // Stiff springs, step 3: two of four compared runs blow up to 1e10 J while two stay near
    // 1000 J. The axis fits the two that survive (they read as curves, not a line at 0), and
    // the two others are said to go off the top.
    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(lessonPath("stiff_springs"));
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    QWidget parent;
    PlotWidget* plot =
        makeStepPlot(loaded.lesson.steps[2], QStringLiteral("compare-energy"), &parent);
    QVERIFY(plot);
    QCOMPARE(plot->model().seriesCount(), 4);
    plot->model().setRangeMode(RangeMode::WholeRun);
    SampleBuffer buffer;
    plot->model().setSource(&buffer);
    const double e0 = 1000.0;
    auto sampleAt = [e0](double t, double growth) {
        Sample s;
        s.t = t;
        s.variants = 4;
        const double wobble = e0 * (1 + 0.02 * std::sin(40 * t));
        const double runaway = e0 * std::exp(growth * t);
        s.variantTotal = {wobble, runaway, 1.5 * runaway, e0, 0, 0};
        s.energyScale = e0;
        return s;
    };
    for (int k = 0; k <= 256; ++k)
        buffer.push(sampleAt(k * 0.001, 7.0 * std::log(10.0) / 0.256));
    plot->drain();
    const QCPRange y = plot->plot()->yAxis->range();
    QVERIFY2(y.lower < 0.98 * e0 && y.upper > 1.02 * e0 && y.upper < 2 * e0,
             qPrintable(QStringLiteral("%1 .. %2").arg(y.lower).arg(y.upper)));
    QVERIFY(!plot->offScale(0));
    QVERIFY(plot->offScale(1));
    QVERIFY(plot->offScale(2));
    QVERIFY(!plot->offScale(3));
    QVERIFY2(plot->graph(1)->name().contains(QStringLiteral("off scale")),
             qPrintable(plot->graph(1)->name()));
    QVERIFY(!plot->graph(0)->name().contains(QStringLiteral("off scale")));

    // Runs that only drift (three times the start) stay on the axis, and lose the mark.
    plot->rewind(0);
    for (int k = 0; k <= 256; ++k)
        buffer.push(sampleAt(k * 0.001, std::log(3.0) / 0.256));
    plot->drain();
    for (int i = 0; i < 4; ++i)
        QVERIFY2(!plot->offScale(i) &&
                     !plot->graph(i)->name().contains(QStringLiteral("off scale")),
                 qPrintable(plot->graph(i)->name()));
    QVERIFY(plot->plot()->yAxis->range().upper >= 1.5 * 3.0 * e0 * 0.99);
}

void TestPlotReading::comparedCurvesStayVisible()
{
    // Four worlds whose curves lie on one another: each stays visible, in the PNG export.
    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(lessonPath("energy_drift"));
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    QWidget parent;
    PlotWidget* plot =
        makeStepPlot(loaded.lesson.steps[0], QStringLiteral("compare-energy"), &parent);
    QVERIFY(plot);
    QCOMPARE(plot->model().seriesCount(), 4);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < i; ++j)
            QVERIFY(plot->graph(i)->pen().style() != plot->graph(j)->pen().style());
    plot->model().setRangeMode(RangeMode::WholeRun);
    SampleBuffer buffer;
    plot->model().setSource(&buffer);
    for (int k = 0; k <= 256; ++k) {
        Sample s;
        s.t = k * kDt;
        s.variants = 4;
        const double e = 1.0 + 0.5 * std::sin(s.t);
        s.variantTotal = {e, e, e, e, 0, 0}; // the same curve four times
        s.energyScale = 1.0;
        buffer.push(s);
    }
    plot->drain();
    plot->setTitleShown(false);
    QTemporaryDir dir;
    const QString png = dir.filePath(QStringLiteral("coincide.png"));
    ExportOptions options;
    options.pngPixelRatio = 1.0;
    QVERIFY(exportPlot(*plot, png, ExportFormat::Png, options).ok);
    QImage image(png);
    QVERIFY(!image.isNull());
    // Crop away the legend's row (its icons show every colour whatever the curves do).
    const QImage curves = image.copy(0, image.height() / 3, image.width(), image.height() * 2 / 3);
    for (int i = 0; i < 4; ++i)
        QVERIFY2(pixelsOf(curves, plotColor(i)) > 100,
                 qPrintable(
                     QStringLiteral("curve %1: %2 px").arg(i).arg(pixelsOf(curves, plotColor(i)))));
}

RIGIDLAB_TEST_MAIN(TestPlotReading)
#include "test_plot_reading.moc"
