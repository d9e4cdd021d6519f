// SPDX-License-Identifier: GPL-3.0-or-later
// The plots take turns after the run's frames (plots/plot_turns.h): on the frames of a 60 Hz
// run, with the timer's jitter and late frames, no frame replots more than half of the plots
// (rounded up), each plot still drains about every refresh interval, and a plot that is
// closed leaves the turns. The frames' times are given, not waited for.

#include "plots/plot_table.h"
#include "plots/plot_turns.h"
#include "plots/plot_widget.h"

#include <qcustomplot.h>

#include <QtTest>

#include "plot_test_samples.h"
#include "sourced_plot.h"
#include "test_main.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

using namespace rigidlab::ui;
using rigidlab::test::sampleAt;
using rigidlab::test::SourcedPlot;

namespace {

/// The window's three plots, shown (a hidden plot keeps its replot for when it is shown), each
/// reading a buffer of its own, their replots counted.
struct ThreePlots {
    std::vector<std::unique_ptr<SourcedPlot>> plots;
    std::array<int, 3> replots{};

    ThreePlots()
    {
        int i = 0;
        for (const PlotRow& row : kPlotRows) {
            if (!row.inWindow() || plots.size() == replots.size())
                continue;
            auto& p =
                plots.emplace_back(std::make_unique<SourcedPlot>(makeWorldPlot(row, nullptr)));
            p->plot->resize(480, 300);
            p->plot->show();
            QObject::connect(p->plot->plot(), &QCustomPlot::afterReplot,
                             [this, i] { ++replots[static_cast<std::size_t>(i)]; });
            ++i;
        }
    }
    int total() const { return replots[0] + replots[1] + replots[2]; }
};

/// The frame times of a 60 Hz run [ms]: 16.7 ms apart with ±3 ms of jitter, and a frame late
/// by a slot (33 ms) every 17 frames and by two every 29, as on a busy machine.
std::vector<qint64> framesAt60Hz(int count)
{
    std::vector<qint64> at;
    double t = 0.0;
    for (int k = 0; k < count; ++k) {
        at.push_back(std::llround(t));
        const double jitter = 3.0 * std::sin(1.7 * k);
        t += 1000.0 / 60.0 + jitter + (k % 17 == 16 ? 1000.0 / 60.0 : 0.0) +
             (k % 29 == 28 ? 2000.0 / 60.0 : 0.0);
    }
    return at;
}

} // namespace

class TestPlotTurns : public QObject {
    Q_OBJECT
private slots:
    void framesCarryAtMostTwoOfThreeReplots();
    void onePlotDrainsEveryIntervalOrLater();
    void aClosedPlotLeaves();
    void eachOwnerStaggersItsOwnPlots();
};

void TestPlotTurns::framesCarryAtMostTwoOfThreeReplots()
{
    ThreePlots three;
    QCOMPARE(three.plots.size(), std::size_t(3));
    for (auto& p : three.plots)
        QVERIFY(QTest::qWaitForWindowExposed(p->plot.get()));
    PlotTurns turns;
    for (auto& p : three.plots)
        turns.add(p->plot.get());
    QCoreApplication::processEvents();
    three.replots = {};

    const std::vector<qint64> at = framesAt60Hz(240);
    std::array<qint64, 3> lastDrain{-1, -1, -1};
    std::array<int, 4> framesWith{}; // frames that replotted 0, 1, 2 or 3 plots
    for (std::size_t k = 0; k < at.size(); ++k) {
        for (auto& p : three.plots)
            p->buffer.push(sampleAt(static_cast<double>(k) / 60.0));
        const int before = three.total();
        const std::vector<PlotWidget*> drained = turns.frame(at[k]);
        QCoreApplication::processEvents(); // the queued replots
        const int replotted = three.total() - before;
        QVERIFY2(replotted <= 2, qPrintable(QStringLiteral("frame %1 at %2 ms replotted %3 plots")
                                                .arg(k)
                                                .arg(at[k])
                                                .arg(replotted)));
        QCOMPARE(replotted, static_cast<int>(drained.size()));
        ++framesWith[static_cast<std::size_t>(replotted)];
        for (std::size_t i = 0; i < three.plots.size(); ++i) {
            if (std::find(drained.begin(), drained.end(), three.plots[i]->plot.get()) ==
                drained.end())
                continue;
            // Never sooner than a refresh interval less the slack of a frame's jitter.
            QVERIFY2(lastDrain[i] < 0 || at[k] - lastDrain[i] >= PlotWidget::kRefreshIntervalMs - 8,
                     qPrintable(QStringLiteral("plot %1 drained %2 ms after its last")
                                    .arg(i)
                                    .arg(at[k] - lastDrain[i])));
            lastDrain[i] = at[k];
        }
    }
    // Every frame but the late ones replots one or two: none is left empty while another
    // carries all three, as when they all started on the first frame.
    QCOMPARE(framesWith[3], 0);
    QVERIFY2(framesWith[0] <= 8, qPrintable(QString::number(framesWith[0])));
    // Each plot at about 30 Hz: 240 frames over some 4.9 s, 2 frames a drain at 60 Hz.
    const double seconds = static_cast<double>(at.back()) / 1000.0;
    for (std::size_t i = 0; i < three.plots.size(); ++i)
        QVERIFY2(three.replots[i] >= 0.85 * 30.0 * seconds,
                 qPrintable(QStringLiteral("plot %1: %2 replots in %3 s")
                                .arg(i)
                                .arg(three.replots[i])
                                .arg(seconds)));
    // And each shows every sample pushed.
    for (auto& p : three.plots) {
        p->plot->drain();
        QCOMPARE(p->plot->model().points(0).size(), at.size());
    }
}

void TestPlotTurns::onePlotDrainsEveryIntervalOrLater()
{
    SourcedPlot one(makeWorldPlot(kPlotRows[0], nullptr));
    PlotTurns turns;
    turns.add(one.plot.get());
    // Frames 10 ms apart: the plot drains in the first, then whenever 25 ms have passed.
    std::vector<qint64> drainedAt;
    for (qint64 t = 0; t <= 200; t += 10) {
        one.buffer.push(sampleAt(static_cast<double>(t) / 1000.0));
        if (!turns.frame(t).empty())
            drainedAt.push_back(t);
    }
    const std::vector<qint64> expected{0, 30, 60, 90, 120, 150, 180};
    QCOMPARE(drainedAt, expected);
    // Frames 40 ms apart (a slow run): every frame.
    drainedAt.clear();
    for (qint64 t = 1000; t <= 1200; t += 40)
        if (!turns.frame(t).empty())
            drainedAt.push_back(t);
    QCOMPARE(drainedAt.size(), std::size_t(6));
}

void TestPlotTurns::aClosedPlotLeaves()
{
    PlotTurns turns;
    auto a = std::make_unique<SourcedPlot>(makeWorldPlot(kPlotRows[0], nullptr));
    auto b = std::make_unique<SourcedPlot>(makeWorldPlot(kPlotRows[0], nullptr));
    turns.add(a->plot.get());
    turns.add(b->plot.get());
    QCOMPARE(turns.count(), 2);
    QCOMPARE(turns.frame(0).size(), std::size_t(1)); // two plots: one a frame
    a.reset();
    QCOMPARE(turns.count(), 1);
    // The one left drains in the next frame: room for one of one.
    QCOMPARE(turns.frame(17), std::vector<PlotWidget*>{b->plot.get()});
}

// The plots' own timers (while no frames come) start a third of the interval apart within
// one window's turns, whatever other windows or tests made plots before: a second window's
// first plot starts at once, as the first window's did.
void TestPlotTurns::eachOwnerStaggersItsOwnPlots()
{
    const auto plotOf = [](PlotTurns& turns) {
        auto p = std::make_unique<SourcedPlot>(makeWorldPlot(kPlotRows[0], nullptr));
        turns.add(p->plot.get());
        return p;
    };
    constexpr int third = PlotWidget::kRefreshIntervalMs / 3;
    PlotTurns first;
    std::vector<std::unique_ptr<SourcedPlot>> plots;
    for (int i = 0; i < 4; ++i)
        plots.push_back(plotOf(first));
    for (int i = 0; i < 4; ++i)
        QCOMPARE(plots[static_cast<std::size_t>(i)]->plot->refreshPhaseMs(), (i % 3) * third);
    PlotTurns second;
    const auto other = plotOf(second);
    QCOMPARE(other->plot->refreshPhaseMs(), 0);
    QCOMPARE(plotOf(second)->plot->refreshPhaseMs(), third);
}

RIGIDLAB_TEST_MAIN(TestPlotTurns)
#include "test_plot_turns.moc"
