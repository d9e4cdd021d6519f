// SPDX-License-Identifier: GPL-3.0-or-later
// The live plots: data from a SampleBuffer reaches the series, memory stays bounded over long
// runs, time travel and marks behave. (Their export: test_plot_export.cpp.)

#include "plots/plot_export.h"
#include "plots/plot_table.h"
#include "plots/plot_widget.h"
#include "simulation/sample_buffer.h"

#include <qcustomplot.h>

#include <QSignalSpy>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtTest>

#include "plot_test_samples.h"
#include "sourced_plot.h"
#include "test_main.h"

#include <cmath>

using namespace rigidlab::ui;
using rigidlab::test::feed;
using rigidlab::test::sampleAt;
using rigidlab::test::SourcedPlot;

namespace {

double field(const Sample& s, const QString& name)
{
    if (name == "kinetic")
        return s.kinetic;
    if (name == "potential")
        return s.potential;
    if (name == "total")
        return s.total;
    if (name == "px")
        return s.px;
    if (name == "py")
        return s.py;
    if (name == "L")
        return s.angularMomentum;
    if (name == "drift")
        return s.driftPercent;
    if (name == "dissipated")
        return s.dissipated;
    if (name == "balance")
        return s.total + s.dissipated;
    qFatal("unknown sample field %s", qPrintable(name));
}

/// The window's plot by its row in the plots' table, as the window makes it.
PlotWidget* makePlot(const QString& kind, QWidget* parent)
{
    const PlotRow* row = findPlot(kind);
    if (!row || !row->inWindow())
        qFatal("no window plot %s in the plots' table", qPrintable(kind));
    return makeWorldPlot(*row, parent);
}

} // namespace

class TestPlots : public QObject {
    Q_OBJECT
private slots:
    void seriesReceiveSamples_data();
    void seriesReceiveSamples();
    void tableRowsMakeTheirPlots();
    void quantityRowMakesItsPlot();
    void directSeriesRestartWhenTimeGoesBack();
    void drainReplotsOnlyOnChange();
    void memoryStaysBounded_data();
    void memoryStaysBounded();
    void thinningKeepsNewestPointAndEvenSpacing();
    void windowModeScrolls();
    void rewindKeepsLaterPointsAsGhost();
    void sampleGoingBackRewinds();
    void marksAreBounded();
    void userRangeChangePausesFollowing();
    void wheelPausesFollowing();
    void legendWrapsToFitWidth();
    void contextMenuOffersExportsAndRanges();
};

void TestPlots::seriesReceiveSamples_data()
{
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QStringList>("fields");
    QTest::addColumn<QStringList>("headers");
    QTest::newRow("energy") << "energy"
                            << QStringList{"kinetic", "potential", "total", "dissipated", "balance"}
                            << QStringList{"kinetic [J]", "potential [J]", "total [J]",
                                           "dissipated [J]", "total + dissipated [J]"};
    QTest::newRow("momentum") << "momentum" << QStringList{"px", "py", "L"}
                              << QStringList{"px [kg m/s]", "py [kg m/s]", "L [kg m²/s]"};
    QTest::newRow("drift") << "drift" << QStringList{"drift"}
                           << QStringList{"energy drift (numerical error) [%]"};
}

void TestPlots::seriesReceiveSamples()
{
    QFETCH(QString, kind);
    QFETCH(QStringList, fields);
    QFETCH(QStringList, headers);

    QWidget window;
    PlotWidget* plot = makePlot(kind, &window);
    QCOMPARE(plot->parent(), &window);
    QCOMPARE(plot->objectName(), kind); // found by its name: its dock, its file
    QCOMPARE(plot->model().seriesCount(), fields.size());
    for (int i = 0; i < plot->model().seriesCount(); ++i)
        QCOMPARE(plot->model().seriesName(i) + " [" + plot->model().seriesUnit(i) + "]",
                 headers[i]);

    SampleBuffer buffer;
    plot->model().setSource(&buffer);
    QCOMPARE(plot->drain(), 0);
    QCOMPARE(plot->model().pointCount(), 0);

    const double dt = 1.0 / 64; // [s]
    for (int i = 0; i < 300; ++i)
        buffer.push(sampleAt(dt * i));
    QCOMPARE(plot->drain(), 300);
    QCOMPARE(plot->drain(), 0); // the cursor moved on

    for (int c = 0; c < fields.size(); ++c) {
        const std::vector<QPointF> pts = plot->model().points(c);
        QCOMPARE(static_cast<int>(pts.size()), 300);
        for (int i = 0; i < 300; ++i) {
            const Sample s = sampleAt(dt * i);
            QCOMPARE(pts[i].x(), s.t);
            QCOMPARE(pts[i].y(), field(s, fields[c]));
        }
    }
}

void TestPlots::tableRowsMakeTheirPlots()
{
    // Each row is found by its name, and each of the window's rows makes a plot named after
    // it, with a title and at least one curve (the compared worlds' rows: test_lesson_export).
    int windowRows = 0;
    for (const PlotRow& row : kPlotRows) {
        const QString name = plotName(row);
        QCOMPARE(findPlot(name), &row);
        QVERIFY2(!plotTitle(row).isEmpty() && !plotTitle(row, false).isEmpty(), qPrintable(name));
        // A row says once how its plot is made: a quantity, or make, or makeCompared. (Checked
        // here, not by a static_assert: with the sanitizers on, GCC does not take a function's
        // address as a constant.)
        const bool quantity = row.quantity && row.unit && row.sample;
        QVERIFY2(int(quantity) + int(row.make != nullptr) + int(row.makeCompared != nullptr) == 1,
                 qPrintable(name));
        if (!row.inWindow())
            continue;
        ++windowRows;
        std::unique_ptr<PlotWidget> plot(makeWorldPlot(row, nullptr));
        QCOMPARE(plot->objectName(), name);
        QVERIFY2(plot->model().seriesCount() > 0, qPrintable(name));
    }
    QVERIFY(windowRows > 0);
    QCOMPARE(findPlot(u"energies"), nullptr);
}

void TestPlots::quantityRowMakesItsPlot()
{
    // A plot of one quantity is made from its row alone: title, axis, one curve of the sample.
    static constexpr PlotRow row{.name = "kinetic-alone",
                                 .title = "Kinetic energy",
                                 .shortTitle = "Kinetic",
                                 .quantity = "kinetic energy",
                                 .unit = "J",
                                 .sample = [](const Sample& s) { return s.kinetic; }};
    std::unique_ptr<PlotWidget> plot(makeWorldPlot(row, nullptr));
    QCOMPARE(plot->objectName(), QStringLiteral("kinetic-alone"));
    QCOMPARE(plot->title(), QStringLiteral("Kinetic energy"));
    QCOMPARE(plot->model().seriesCount(), 1);
    QCOMPARE(plot->model().seriesName(0), QStringLiteral("kinetic energy"));
    QCOMPARE(plot->model().unit(YAxis::Left), QStringLiteral("J"));
    SampleBuffer buffer;
    plot->model().setSource(&buffer);
    for (int i = 0; i < 10; ++i)
        buffer.push(sampleAt(0.1 * i));
    QCOMPARE(plot->drain(), 10);
    for (int i = 0; i < 10; ++i)
        QCOMPARE(plot->model().points(0).at(static_cast<std::size_t>(i)).y(),
                 sampleAt(0.1 * i).kinetic);
}

void TestPlots::directSeriesRestartWhenTimeGoesBack()
{
    PlotWidget plot(QStringLiteral("Energy per integrator"));
    plot.setYAxisLabel(QStringLiteral("total energy E"), QStringLiteral("J"));
    const int euler = plot.addSeries(QStringLiteral("explicit Euler"), plotColor(0));
    const int verlet = plot.addSeries(QStringLiteral("Verlet"), plotColor(1));
    for (int i = 0; i < 10; ++i) {
        plot.model().appendPoint(euler, 0.5 * i, 1.0 + 0.1 * i);
        plot.model().appendPoint(verlet, 0.5 * i, 1.0);
    }
    plot.model().appendPoint(verlet, 5.0, std::numeric_limits<double>::infinity()); // a gap
    plot.drain();
    QCOMPARE(plot.model().pointCount(euler), 10);
    QCOMPARE(plot.model().pointCount(verlet), 11);
    QVERIFY(std::isnan(plot.model().points(verlet).back().y()));

    plot.model().appendPoint(euler, 2.0, 7.0); // this series starts over at t = 2 s
    const std::vector<QPointF> pts = plot.model().points(euler);
    QCOMPARE(static_cast<int>(pts.size()), 5);
    QCOMPARE(pts.back(), QPointF(2.0, 7.0));
    QCOMPARE(plot.model().pointCount(verlet), 11);
}

void TestPlots::drainReplotsOnlyOnChange()
{
    PlotWidget plot(QStringLiteral("Energy"));
    const int kinetic = plot.addSeries(QStringLiteral("kinetic"), plotColor(0),
                                       [](const Sample& s) { return s.kinetic; });
    Q_UNUSED(kinetic);
    SampleBuffer buffer;
    plot.model().setSource(&buffer);
    plot.resize(640, 400);
    plot.show();
    QVERIFY(QTest::qWaitForWindowExposed(&plot));
    QTest::qWait(100);

    QSignalSpy replots(plot.plot(), &QCustomPlot::afterReplot);
    plot.drain();
    QTest::qWait(100); // several ticks of the plot's own timer, with nothing new
    QCOMPARE(replots.count(), 0);

    buffer.push(sampleAt(0.25));
    QCOMPARE(plot.drain(), 1);
    QTRY_COMPARE(replots.count(), 1);
}

void TestPlots::memoryStaysBounded_data()
{
    QTest::addColumn<bool>("wholeRun");
    QTest::addColumn<bool>("paused");
    QTest::addColumn<double>("dt"); // [s]
    QTest::newRow("window, dt 1 ms") << false << false << 1e-3;
    QTest::newRow("window, dt 0.1 ms (window over budget)") << false << false << 1e-4;
    QTest::newRow("window, paused by the user") << false << true << 1e-3;
    QTest::newRow("whole run, dt 1 ms") << true << false << 1e-3;
}

void TestPlots::memoryStaysBounded()
{
    QFETCH(bool, wholeRun);
    QFETCH(bool, paused);
    QFETCH(double, dt);

    std::unique_ptr<PlotWidget> plot(makeEnergyPlot(nullptr));
    plot->model().setRangeMode(wholeRun ? RangeMode::WholeRun : RangeMode::Window);
    SampleBuffer buffer;
    plot->model().setSource(&buffer);

    const int total = 2'000'000;
    const int chunk = 4096;
    const int budget = plot->model().pointBudget();
    const double viewLower = 100.0 * chunk * dt - 5; // [s] where a paused user looks
    for (int i = 0; i < total; i += chunk) {
        for (int j = i; j < std::min(i + chunk, total); ++j)
            buffer.push(sampleAt(dt * j));
        plot->drain();
        if (paused && i == 100 * chunk)
            plot->plot()->xAxis->setRange(viewLower, viewLower + 2);
        for (int s = 0; s < plot->model().seriesCount(); ++s)
            QVERIFY2(
                plot->model().pointCount(s) <= budget,
                qPrintable(
                    QString("%1 points at sample %2").arg(plot->model().pointCount(s)).arg(i)));
        QCOMPARE(plot->model().markCount(), 0);
    }
    QCOMPARE(plot->isFollowing(), !paused);

    const double last = dt * (total - 1);
    const std::vector<QPointF> pts = plot->model().points(2);
    QCOMPARE(pts.back().x(), last); // the curve reaches the end of the run
    if (wholeRun) {
        QCOMPARE(pts.front().x(), 0.0); // ... and still starts at its beginning
        QVERIFY(pts.size() > std::size_t(budget / 4));
    } else if (paused) {
        QVERIFY(pts.front().x() <= viewLower + 10 * dt); // what the user looks at stays
    } else {
        QVERIFY(pts.front().x() >= last - 1.1 * plot->model().windowSeconds() - dt);
    }
}

void TestPlots::thinningKeepsNewestPointAndEvenSpacing()
{
    PlotWidget plot(QStringLiteral("Energy"));
    plot.model().setRangeMode(RangeMode::WholeRun);
    const int total = plot.addSeries(QStringLiteral("total"), plotColor(0),
                                     [](const Sample& s) { return s.total; });
    plot.model().setPointBudget(64);
    SampleBuffer buffer(16);
    plot.model().setSource(&buffer);
    for (int i = 0; i < 5000; ++i) {
        buffer.push(sampleAt(i));
        plot.drain();
        const std::vector<QPointF> pts = plot.model().points(total);
        QVERIFY(static_cast<int>(pts.size()) <= 64);
        QCOMPARE(pts.front().x(), 0.0);
        QCOMPARE(pts.back().x(), double(i));
        // All but the newest point lie on one stride.
        for (std::size_t k = 2; k + 1 < pts.size(); ++k)
            QCOMPARE(pts[k].x() - pts[k - 1].x(), pts[1].x() - pts[0].x());
    }
}

void TestPlots::windowModeScrolls()
{
    std::unique_ptr<PlotWidget> plot(makeEnergyPlot(nullptr));
    QCOMPARE(plot->model().windowSeconds(), 10.0);
    SampleBuffer buffer;
    plot->model().setSource(&buffer);
    feed(buffer, *plot, 0.0, 1.0 / 64, 64 * 4); // 4 s: fewer than a window, which it fits
    QCOMPARE(plot->plot()->xAxis->range().lower, 0.0);
    QVERIFY(plot->plot()->xAxis->range().upper >= 4.0 - 1.0 / 64);
    QVERIFY(plot->plot()->xAxis->range().upper <= 4.2);

    feed(buffer, *plot, 4.0, 1.0 / 64, 64 * 26 + 1); // on to 30 s
    QCOMPARE(plot->plot()->xAxis->range().upper, 30.0);
    QCOMPARE(plot->plot()->xAxis->range().lower, 20.0);
    QVERIFY(plot->model().points(0).front().x() >= 30.0 - 11.0);

    plot->model().setWindowSeconds(2.5);
    plot->drain();
    QCOMPARE(plot->plot()->xAxis->range().lower, 27.5);

    plot->model().setRangeMode(RangeMode::WholeRun);
    feed(buffer, *plot, 30.0 + 1.0 / 64, 1.0 / 64, 64);
    QCOMPARE(plot->plot()->xAxis->range().upper, 31.0);
    QVERIFY(plot->plot()->xAxis->range().lower <= 27.5);
}

void TestPlots::rewindKeepsLaterPointsAsGhost()
{
    auto [buffer, plot] = SourcedPlot(makeEnergyPlot(nullptr));
    feed(buffer, *plot, 0.0, 1.0 / 64, 64 * 8); // 0 .. 8 s
    plot->model().addMark(2.0, QStringLiteral("dt = 5 ms"));
    plot->model().addMark(6.0, QStringLiteral("RK4"));

    plot->rewind(4.0);
    plot->drain();
    for (int s = 0; s < plot->model().seriesCount(); ++s) {
        QCOMPARE(plot->model().pointCount(s), 64 * 4 + 1);
        QCOMPARE(plot->model().points(s).back().x(), 4.0);
        QCOMPARE(static_cast<int>(plot->model().ghostPoints(s).size()), 64 * 4 - 1);
    }
    QCOMPARE(plot->model().markCount(), 2); // the one at 6 s in the ghost
    QVERIFY(plot->model().markIsGhost(1));

    // The run goes on from t = 4 s on a new branch, overwriting the ghost as it goes.
    feed(buffer, *plot, 4.0 + 1.0 / 64, 1.0 / 64, 64);
    QCOMPARE(plot->model().pointCount(0), 64 * 5 + 1);
    QCOMPARE(plot->model().points(0).back().x(), 5.0);
    QCOMPARE(plot->model().ghostPoints(0).front().x(), 5.0 + 1.0 / 64);

    plot->clear();
    QCOMPARE(plot->model().pointCount(), 0);
    QCOMPARE(plot->model().markCount(), 0);
    QCOMPARE(plot->plot()->itemCount(), 0);
}

void TestPlots::sampleGoingBackRewinds()
{
    auto [buffer, plot] = SourcedPlot(makeDriftPlot(nullptr));
    plot->model().addMark(2.0, QStringLiteral("Verlet"));
    plot->model().addMark(5.0, QStringLiteral("RK4"));
    feed(buffer, *plot, 0.0, 0.5, 13); // 0 .. 6 s
    // Stepped back to 2 s without a rewind() call: the samples say so themselves.
    feed(buffer, *plot, 2.0, 0.5, 3); // 2, 2.5, 3 s
    const std::vector<QPointF> pts = plot->model().points(0);
    QCOMPARE(static_cast<int>(pts.size()), 7);
    QCOMPARE(pts.back().x(), 3.0);
    for (std::size_t k = 1; k < pts.size(); ++k)
        QCOMPARE(pts[k].x() - pts[k - 1].x(), 0.5);
    QCOMPARE(plot->model().markCount(), 1); // the mark at 2 s starts the new branch

    // A new scene in the same buffer starts over at t = 0.
    feed(buffer, *plot, 0.0, 0.5, 2);
    QCOMPARE(plot->model().pointCount(), 2);
}

void TestPlots::marksAreBounded()
{
    std::unique_ptr<PlotWidget> plot(makeEnergyPlot(nullptr));
    plot->model().setRangeMode(RangeMode::WholeRun);
    for (int i = 0; i < 500; ++i)
        plot->model().addMark(0.1 * i, QStringLiteral("mark %1").arg(i));
    QCOMPARE(plot->model().markCount(), PlotModel::kMaxMarks);
    QCOMPARE(plot->plot()->itemCount(), 2 * PlotModel::kMaxMarks);

    plot->clear();
    plot->model().setRangeMode(RangeMode::Window);
    SampleBuffer buffer;
    plot->model().setSource(&buffer);
    for (int second = 0; second < 100; ++second) {
        feed(buffer, *plot, second, 0.25, 4);
        plot->model().addMark(second + 0.5, QStringLiteral("dt = %1 ms").arg(second));
    }
    // Marks that scrolled out of the window (and its margin) are gone.
    QVERIFY(plot->model().markCount() <= 12);
    QVERIFY(plot->model().markCount() >= 10);
    QCOMPARE(plot->plot()->itemCount(), 2 * plot->model().markCount());
}

void TestPlots::userRangeChangePausesFollowing()
{
    auto [buffer, plot] = SourcedPlot(makeEnergyPlot(nullptr));
    QSignalSpy following(plot.get(), &PlotWidget::followingChanged);
    feed(buffer, *plot, 0.0, 1.0 / 64, 64 * 30);
    QVERIFY(plot->isFollowing());
    QCOMPARE(following.count(), 0); // our own range changes do not count

    plot->plot()->xAxis->setRange(22, 25); // what a drag does
    QVERIFY(!plot->isFollowing());
    QCOMPARE(following.count(), 1);
    QCOMPARE(following.first().first().toBool(), false);

    feed(buffer, *plot, 30.0, 1.0 / 64, 64 * 30); // data keeps arriving
    QCOMPARE(plot->plot()->xAxis->range(), QCPRange(22, 25));
    QCOMPARE(plot->model().points(0).back().x(), 60.0 - 1.0 / 64);
    QCOMPARE(plot->model().points(0).front().x(), 22.0); // what the user looks at stays

    plot->follow();
    plot->drain();
    QVERIFY(plot->isFollowing());
    QCOMPARE(following.count(), 2);
    QCOMPARE(plot->plot()->xAxis->range().upper, 60.0 - 1.0 / 64);
    QVERIFY(plot->model().points(0).front().x() >= 60.0 - 11.0 - 1.0 / 64);
}

void TestPlots::wheelPausesFollowing()
{
    PlotWidget* plot = makeMomentumPlot(nullptr);
    std::unique_ptr<PlotWidget> owner(plot);
    SampleBuffer buffer;
    plot->model().setSource(&buffer);
    plot->resize(800, 500);
    plot->show();
    QVERIFY(QTest::qWaitForWindowExposed(plot));
    feed(buffer, *plot, 0.0, 1.0 / 64, 64 * 5);
    plot->plot()->replot(QCustomPlot::rpImmediateRefresh);

    const QPointF center = plot->plot()->axisRect()->rect().center();
    QWheelEvent wheel(center, plot->plot()->mapToGlobal(center), QPoint(), QPoint(0, 120),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(plot->plot(), &wheel);
    QVERIFY(!plot->isFollowing());

    // The button that resumes shows while paused.
    auto* button = plot->findChild<QToolButton*>();
    QVERIFY(button && button->isVisible());
    QTest::mouseClick(button, Qt::LeftButton);
    QVERIFY(plot->isFollowing());
    QVERIFY(!button->isVisible());
}

void TestPlots::legendWrapsToFitWidth()
{
    PlotWidget plot(QStringLiteral("Total energy per integrator"));
    const char* names[] = {"explicit Euler", "symplectic Euler", "velocity Verlet", "RK4"};
    for (int i = 0; i < 4; ++i)
        plot.addSeries(QString::fromLatin1(names[i]), plotColor(i));
    QCPLegend* legend = plot.plot()->legend;

    plot.resize(1400, 500);
    plot.show();
    QVERIFY(QTest::qWaitForWindowExposed(&plot));
    QCOMPARE(legend->wrap(), 4); // one line

    plot.resize(360, 300);
    QTRY_VERIFY(legend->wrap() < 4);
    plot.plot()->replot(QCustomPlot::rpImmediateRefresh);
    QVERIFY(legend->outerRect().right() <= plot.plot()->width());

    // An export is laid out for its own width, and the screen gets its layout back.
    QTemporaryDir dir;
    ExportOptions wide;
    wide.logicalSize = QSize(1400, 500);
    QVERIFY(exportPlot(plot, dir.filePath("wide.png"), ExportFormat::Png, wide).ok);
    QVERIFY(legend->wrap() < 4);
}

void TestPlots::contextMenuOffersExportsAndRanges()
{
    std::unique_ptr<PlotWidget> plot(makeEnergyPlot(nullptr));
    plot->resize(640, 400);
    plot->show();
    QVERIFY(QTest::qWaitForWindowExposed(plot.get()));

    auto openMenu = [&] {
        emit plot->plot()->customContextMenuRequested(QPoint(100, 100));
        return plot->findChild<QMenu*>();
    };
    auto action = [](QMenu* menu, const QString& text) -> QAction* {
        for (QAction* a : menu->actions())
            if (a->text() == text)
                return a;
        return nullptr;
    };

    QMenu* menu = openMenu();
    QVERIFY(menu);
    for (const char* text : {"Export as PNG…", "Export as PDF…", "Export as SVG…",
                             "Export data as CSV…", "Follow", "Last 10 s", "Whole run"})
        QVERIFY2(action(menu, QString::fromUtf8(text)), text);
    QVERIFY(action(menu, "Last 10 s")->isChecked());
    action(menu, "Whole run")->trigger();
    QCOMPARE(plot->model().rangeMode(), RangeMode::WholeRun);
    menu->close();
    QTRY_VERIFY(!plot->findChild<QMenu*>()); // deleted on close

    menu = openMenu();
    QVERIFY(action(menu, "Whole run")->isChecked());
    action(menu, "Last 30 s")->trigger();
    QCOMPARE(plot->model().rangeMode(), RangeMode::Window);
    QCOMPARE(plot->model().windowSeconds(), 30.0);
    action(menu, "Follow")->trigger(); // unchecks: pauses
    QVERIFY(!plot->isFollowing());
    menu->close();
}

RIGIDLAB_TEST_MAIN(TestPlots)
#include "test_plots.moc"
