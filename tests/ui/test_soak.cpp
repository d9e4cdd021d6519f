// SPDX-License-Identifier: GPL-3.0-or-later
// The soak test: a 200-body scene run for a long stretch of simulated time in the lab window
// (offscreen), as fast as it will go, with every plot live: the controller steps, the view
// follows, the plots drain and replot on their own timers (events are processed every 1/60 s
// of wall time, as the window's frames would be, however many steps fit in between). Memory
// must stay flat and the step rate must not fall.
//
// The scene is a gas of 200 bodies (circles and boxes) bouncing elastically in a closed box
// without gravity: its contacts are as many at the end as at the start, so a change in the
// step rate is the program's, not the physics'.
//
// Memory: the time-travel history keeps world snapshots up to its budget (ui/history.h), so
// the resident size grows at first by design. It is measured (VmRSS, /proc/self/status) once
// the history is full and the first tenth is over, and again at the end: the two must be
// within kMaxGrowthBytes. The step rate is steps per second of this process's CPU time spent
// stepping (so that other work on the machine does not count, nor the plots' redrawing, which
// grows by design until the whole-run plot holds its point budget), in the first and the last
// tenth of the run.
//
// RIGIDLAB_SOAK_SECONDS sets the simulated time: `./lab soak` runs the whole hour (3600 s) and
// judges memory and step rate; ./lab test runs kDefaultSeconds and judges memory only (the rate
// is printed: a speed measured beside other tests is not a verdict).

#include "plots/plot_widget.h"
#include "simulation/history.h"
#include "simulation/simulation_controller.h"
#include "window/main_window.h"

#include "format/divergence_message.h"
#include "format/scene.h"
#include "format/scene_loader.h"

#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QRandomGenerator>
#include <QtTest>

#include "test_main.h"

#include <time.h>

#include <cmath>
#include <deque>

using namespace rigidlab;

namespace {

#if defined(__SANITIZE_ADDRESS__)
// Under AddressSanitizer freed memory waits in a quarantine (256 MiB) and every step is several
// times slower: the run only has to finish cleanly (LeakSanitizer judges the memory).
constexpr bool kMeasure = false;
constexpr double kDefaultSeconds = 30.0;
#else
constexpr bool kMeasure = true;
constexpr double kDefaultSeconds = 150.0; ///< simulated, for ./lab test [s]
#endif
/// The time-travel history's budget in ./lab test: small enough that it fills within the first
/// half of the run (about 180 snapshots of this scene, one per 100 steps), so that what is
/// measured after it is the steady state. ./lab soak keeps the window's own 96 MiB.
constexpr std::size_t kTestHistoryBudget = 16u << 20;
constexpr qint64 kFrameNs = 16'666'667; ///< events are processed this often, wall time [ns]
constexpr long kMaxGrowthBytes = 8L << 20;
constexpr double kMinRateRatio = 0.8; ///< last tenth's step rate over the first's, at least

/// This process's resident memory [bytes], from /proc/self/status.
long residentBytes()
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray& line : status.readAll().split('\n'))
        if (line.startsWith("VmRSS:"))
            return line.mid(6).trimmed().split(' ').first().toLong() * 1024;
    return -1;
}

double cpuSeconds()
{
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// 200 bodies in a 12 m x 8 m box, no gravity, elastic and frictionless, with fixed random
/// velocities (seeded: every run is the same run).
QByteArray gasScene()
{
    QByteArray bodies;
    const auto wall = [&bodies](const char* id, double x, double y, double w, double h) {
        bodies += QStringLiteral(R"({"id": "%1", "type": "static", "shape": {"type": "box",)"
                                 R"("width": %2, "height": %3}, "position": [%4, %5]},)")
                      .arg(QLatin1String(id))
                      .arg(w)
                      .arg(h)
                      .arg(x)
                      .arg(y)
                      .toUtf8();
    };
    wall("floor", 0, -4.5, 14, 1);
    wall("ceiling", 0, 4.5, 14, 1);
    wall("left", -6.5, 0, 1, 10);
    wall("right", 6.5, 0, 1, 10);
    QRandomGenerator random(7);
    for (int i = 0; i < 200; ++i) {
        const double x = -5.5 + 0.55 * (i % 20);
        const double y = -3.5 + 0.7 * (i / 20);
        const double vx = random.generateDouble() * 30 - 15;
        const double vy = random.generateDouble() * 30 - 15;
        const QString shape =
            i % 3 == 0 ? QStringLiteral(R"({"type": "box", "width": 0.3, "height": 0.2})")
                       : QStringLiteral(R"({"type": "circle", "radius": 0.15})");
        bodies += QStringLiteral(R"(%1{"id": "b%2", "shape": %3, "position": [%4, %5],)"
                                 R"("velocity": [%6, %7]})")
                      .arg(i ? QStringLiteral(",") : QString())
                      .arg(i)
                      .arg(shape)
                      .arg(x)
                      .arg(y)
                      .arg(vx)
                      .arg(vy)
                      .toUtf8();
    }
    return R"({"rigidlab": 1, "title": "Soak: a gas of 200 bodies",)"
           R"("world": {"gravity": [0, 0], "dt": 0.005, "restitution": 1, "friction": 0},)"
           R"("bodies": [)" +
           bodies + "]}";
}

/// The simulated time of the soak: RIGIDLAB_SOAK_SECONDS, or the suite's short run [s].
double soakSeconds()
{
    bool ok = false;
    const double seconds = qEnvironmentVariable("RIGIDLAB_SOAK_SECONDS").toDouble(&ok);
    return ok && seconds > 0 ? seconds : kDefaultSeconds;
}

/// The window with the soak's scene and every plot live, one of them keeping the whole run
/// (thinned to its point budget); the suite's short run keeps a smaller history.
void showLive(ui::MainWindow& window, const lessons::Scene& scene)
{
    window.resize(1400, 900);
    window.show();
    window.controller().loadScene(scene, QStringLiteral("soak.json"));
    if (qEnvironmentVariableIsEmpty("RIGIDLAB_SOAK_SECONDS"))
        window.controller().setHistoryBudget(kTestHistoryBudget);
    window.plot(u"energy")->model().setRangeMode(ui::RangeMode::WholeRun);
    // The plots share one place in the window, behind tabs: each is floated out, so that every
    // one is drawn as it runs (the heaviest the window gets).
    for (QWidget* plot : window.plots())
        for (QWidget* p = plot; p; p = p->parentWidget())
            if (auto* dock = qobject_cast<QDockWidget*>(p)) {
                dock->setFloating(true);
                dock->show();
                break;
            }
    QCoreApplication::processEvents();
}

/// One line of the soak's progress: memory, history, contacts, bodies that left the box.
void reportProgress(const ui::SimulationController& controller, long long step)
{
    int outside = 0;
    for (const physics::Body& b : controller.world().bodies())
        outside += b.isDynamic() && (std::abs(b.position.x()) > 6 || std::abs(b.position.y()) > 4);
    qInfo("soak: step %lld (t = %.0f s): %.1f MiB resident, history from step %lld, "
          "%d contacts, %d bodies outside the box, E = %.1f J",
          step, controller.world().time(), residentBytes() / 1048576.0,
          controller.history().earliest(), controller.world().diagnostics().contacts, outside,
          controller.world().diagnostics().total);
}

/// The step rates of the first and last tenth, and what each plot holds.
void reportRates(ui::MainWindow& window, double firstRate, double lastRate)
{
    qInfo("soak: %.0f steps per CPU second in the first tenth, %.0f in the last (ratio %.2f)",
          firstRate, lastRate, lastRate / firstRate);
    for (const auto* plot : window.plots())
        qInfo("soak: plot %s holds %d points", qPrintable(plot->objectName()),
              plot->model().pointCount());
}

} // namespace

class TestSoak : public QObject {
    Q_OBJECT

private slots:
    /// The history bounds its memory by an estimate of a snapshot's size: copies of the soak
    /// world must take about what the estimate says (else the budget means nothing).
    void snapshotEstimateMatchesMemory()
    {
        if (!kMeasure)
            QSKIP("built with AddressSanitizer: its allocator pads every block");
        const lessons::SceneLoadResult loaded =
            lessons::loadSceneJson(gasScene(), QStringLiteral("soak.json"));
        QVERIFY2(loaded.ok, qPrintable(loaded.error));
        physics::World world = lessons::buildWorld(loaded.scene);
        for (int i = 0; i < 200; ++i)
            world.step();
        constexpr int kCopies = 600;
        const long before = residentBytes();
        std::deque<physics::World> copies;
        for (int i = 0; i < kCopies; ++i)
            copies.push_back(world);
        const double measured = static_cast<double>(residentBytes() - before) / kCopies;
        const double estimate = static_cast<double>(ui::History::snapshotBytes(world));
        qInfo("soak: a snapshot of 204 bodies and %zu contacts takes %.0f bytes; estimated %.0f",
              world.contacts().size(), measured, estimate);
        QVERIFY2(estimate >= 0.75 * measured && estimate <= 1.5 * measured,
                 qPrintable(QStringLiteral("estimate %1 bytes, measured %2 bytes per snapshot")
                                .arg(estimate)
                                .arg(measured)));
    }

    void longRunStaysFlat()
    {
        const double seconds = soakSeconds();

        const lessons::SceneLoadResult loaded =
            lessons::loadSceneJson(gasScene(), QStringLiteral("soak.json"));
        QVERIFY2(loaded.ok, qPrintable(loaded.error));
        QCOMPARE(loaded.scene.bodies.size(), std::size_t{204});

        ui::MainWindow window;
        showLive(window, loaded.scene);
        auto& controller = window.controller();
        for (const auto* plot : window.plots())
            QVERIFY(plot->isVisible());

        const double dt = controller.world().def().dt;
        const long long steps = std::llround(seconds / dt);
        const long long tenth = steps / 10;

        QElapsedTimer frame;
        frame.start();
        long rssStart = residentBytes();
        long rssWarm = -1;
        long long historyFullAt = -1;
        double firstTenthCpu = 0;
        double lastTenthCpu = 0;
        for (long long i = 1; i <= steps; ++i) {
            const bool timed = i <= tenth || i > steps - tenth;
            const double before = timed ? cpuSeconds() : 0.0;
            controller.stepForward();
            if (i <= tenth)
                firstTenthCpu += cpuSeconds() - before;
            else if (i > steps - tenth)
                lastTenthCpu += cpuSeconds() - before;
            if (frame.nsecsElapsed() >= kFrameNs) {
                QCoreApplication::processEvents();
                frame.start();
            }
            if (historyFullAt < 0 && controller.history().earliest() > 0)
                historyFullAt = i;
            // Warm: the history at its budget and the first tenth over.
            if (rssWarm < 0 && i >= tenth && historyFullAt > 0)
                rssWarm = residentBytes();
            if (i % tenth == 0)
                reportProgress(controller, i);
            if (const auto& d = controller.world().divergence())
                QFAIL(qPrintable(lessons::divergenceMessage(*d)));
        }
        QCoreApplication::processEvents();
        const long rssEnd = residentBytes();

        const double firstRate = static_cast<double>(tenth) / firstTenthCpu;
        const double lastRate = static_cast<double>(tenth) / lastTenthCpu;
        qInfo("soak: %.0f s simulated, %lld steps of %g s, 204 bodies", seconds, steps, dt);
        qInfo("soak: resident memory %.1f MiB at the start, %.1f MiB when warm (history full "
              "at step %lld), %.1f MiB at the end",
              rssStart / 1048576.0, rssWarm / 1048576.0, historyFullAt, rssEnd / 1048576.0);
        reportRates(window, firstRate, lastRate);

        QCOMPARE(controller.world().stepCount(), steps);
        if (!kMeasure)
            QSKIP("built with AddressSanitizer: the run is checked, its memory and speed are not");
        if (rssWarm < 0)
            QSKIP("the run ended before the history reached its budget: set "
                  "RIGIDLAB_SOAK_SECONDS higher to measure flat memory");
        QVERIFY2(rssEnd - rssWarm <= kMaxGrowthBytes,
                 qPrintable(QStringLiteral("memory grew by %1 MiB after warm-up")
                                .arg((rssEnd - rssWarm) / 1048576.0)));
        // The step rate is a speed, and speeds are not judged by the suite, where other tests
        // share the processor (a busy machine slows the last tenth as much as a leak would):
        // ./lab test reports it above, ./lab soak, alone on the machine, also judges it.
        if (qEnvironmentVariableIsEmpty("RIGIDLAB_SOAK_SECONDS"))
            return;
        QVERIFY2(lastRate >= kMinRateRatio * firstRate,
                 qPrintable(QStringLiteral("the step rate fell from %1 to %2 per CPU second")
                                .arg(firstRate)
                                .arg(lastRate)));
    }
};

RIGIDLAB_TEST_MAIN(TestSoak)
#include "test_soak.moc"
