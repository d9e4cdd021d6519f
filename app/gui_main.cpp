// rigidlab: the lab window. `rigidlab [FILE.json] [--step N]` opens that scene or lesson
// (at step N), or the welcome scene and the lesson list. `rigidlab --measure-frames N
// SCENE.json` runs the scene in the window for N frames and prints their times.

#include "lesson_player.h"
#include "main_window.h"
#include "simulation_controller.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <numeric>
#include <vector>

namespace {

/// Frames run before measuring, so that the first layout and paint do not count.
constexpr int kWarmUpFrames = 30;

/// Median and 95th percentile of the frame times, the share of physics in them, and the
/// process's CPU time per frame (what the frames cost on a machine that is not shared).
void printFrameTimes(std::vector<double> frames, const std::vector<double>& physics,
                     double cpuMsPerFrame)
{
    const double total = std::accumulate(frames.begin(), frames.end(), 0.0);
    const double inPhysics = std::accumulate(physics.begin(), physics.end(), 0.0);
    std::sort(frames.begin(), frames.end());
    const auto at = [&](double q) {
        return frames[std::min(frames.size() - 1,
                               static_cast<size_t>(q * static_cast<double>(frames.size())))];
    };
    std::printf("%zu frames: median %.2f ms, 95th percentile %.2f ms, longest %.2f ms; "
                "physics %.1f %% of the frame time (%.2f ms per frame); CPU %.2f ms per frame\n",
                frames.size(), at(0.5), at(0.95), frames.back(), 100.0 * inPhysics / total,
                inPhysics / static_cast<double>(frames.size()), cpuMsPerFrame);
}

} // namespace

int main(int argc, char** argv)
{
    // Arguments first: --help and mistakes must not need a display.
    QStringList args;
    for (int i = 1; i < argc; ++i)
        args << QString::fromLocal8Bit(argv[i]);
    const QString usage =
        QStringLiteral("usage: rigidlab [FILE.json] [--step N] [--measure-frames N]\n"
                       "  FILE.json  a scene or a lesson to open\n"
                       "  --step N   with a lesson: start at step N (1 = first)\n"
                       "  --measure-frames N  run the scene for N frames, print the median and\n"
                       "             95th-percentile frame time and the physics share, quit\n");
    QString file;
    int step = 1;
    int measureFrames = 0;
    for (qsizetype i = 0; i < args.size(); ++i) {
        const QString& a = args[i];
        if (a == QLatin1String("--help") || a == QLatin1String("-h")) {
            QTextStream(stdout) << usage;
            return 0;
        }
        if (a == QLatin1String("--step")) {
            bool ok = false;
            step = i + 1 < args.size() ? args[i + 1].toInt(&ok) : 0;
            if (!ok || step < 1) {
                QTextStream(stderr) << "rigidlab: --step needs a whole number from 1, got \""
                                    << (i + 1 < args.size() ? args[i + 1] : QString()) << "\"\n";
                return 2;
            }
            ++i;
            continue;
        }
        if (a == QLatin1String("--measure-frames")) {
            bool ok = false;
            measureFrames = i + 1 < args.size() ? args[i + 1].toInt(&ok) : 0;
            if (!ok || measureFrames < 1) {
                QTextStream(stderr) << "rigidlab: --measure-frames needs a whole number from 1\n";
                return 2;
            }
            ++i;
            continue;
        }
        if (a.startsWith(QLatin1Char('-'))) {
            QTextStream(stderr) << "rigidlab: unknown option " << a << "\n" << usage;
            return 2;
        }
        if (!file.isEmpty()) {
            QTextStream(stderr) << "rigidlab: one file at a time (got " << file << " and " << a
                                << ")\n";
            return 2;
        }
        file = a;
    }
    if (measureFrames > 0 && file.isEmpty()) {
        QTextStream(stderr) << "rigidlab: --measure-frames needs a scene to run\n" << usage;
        return 2;
    }

    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("RigidLab"));
    QApplication::setApplicationName(QStringLiteral("RigidLab"));
    rigidlab::ui::MainWindow window;
    window.resize(1500, 920);
    const QString welcome =
        QDir(rigidlab::ui::MainWindow::scenesFolder()).filePath(QStringLiteral("welcome.json"));
    // Open the welcome scene first, so that a broken file leaves something alive behind the
    // error dialog.
    window.openScene(welcome, file.isEmpty() ? false : true);
    if (!file.isEmpty()) {
        // A lesson says so with its top-level key; anything else is read as a scene.
        QFile f(file);
        const bool lesson =
            f.open(QIODevice::ReadOnly) && QJsonDocument::fromJson(f.read(8 << 20))
                                               .object()
                                               .contains(QLatin1String("rigidlab-lesson"));
        const QString error = lesson ? window.openLesson(file) : window.openScene(file);
        if (!error.isEmpty())
            QTextStream(stderr) << error << '\n';
        else if (lesson && step > 1)
            window.lessonPlayer().goToStep(step - 1);
    }
    window.show();
    // A lesson waits for the student to press Run; a measurement runs it at once.
    if (window.lastError().isEmpty() && (!window.lessonPlayer().lesson() || measureFrames > 0))
        window.controller().setRunning(true);
    if (measureFrames > 0) {
        if (!window.lastError().isEmpty()) {
            QTextStream(stderr) << "rigidlab: --measure-frames needs a scene that opens\n";
            return 2;
        }
        rigidlab::ui::SimulationController& controller = window.controller();
        const std::clock_t cpuStart = std::clock();
        QObject::connect(
            &controller, &rigidlab::ui::SimulationController::framesMeasured, &app,
            [cpuStart](const std::vector<double>& frames, const std::vector<double>& physics) {
                const double cpuMs = 1e3 * static_cast<double>(std::clock() - cpuStart) /
                                     CLOCKS_PER_SEC / static_cast<double>(frames.size());
                printFrameTimes({frames.begin() + kWarmUpFrames, frames.end()},
                                {physics.begin() + kWarmUpFrames, physics.end()}, cpuMs);
                QApplication::exit(0);
            });
        controller.measureFrames(measureFrames + kWarmUpFrames);
    }
    return QApplication::exec();
}
