// SPDX-License-Identifier: GPL-3.0-or-later
// rigidlab-bench: the benchmark scenes in RigidLab, Box2D v3, Chipmunk 7 and Box2D 2.4, one
// table.
//   rigidlab-bench [--scene NAME] [--steps N] [--runs K] [--profile]
// --profile adds RigidLab's stages (physics::StepProfile): where its step spends the time.
// Built and run by `./lab bench`; not a test (timings depend on the machine).

#include "bench_peers.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#include <unistd.h>

using namespace rigidlab;

namespace {

std::string cpuModel()
{
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0)
            return line.substr(line.find(':') + 2);
    return "unknown CPU";
}

int usage()
{
    std::fputs("usage: rigidlab-bench [--scene NAME] [--steps N] [--runs K] [--profile]\n", stderr);
    return 2;
}

/// RigidLab (both solvers) and every peer this build has; `missing` gets each peer left out,
/// with the reason.
std::vector<std::unique_ptr<bench::BenchEngine>>
makeEngines([[maybe_unused]] std::vector<std::string>& missing)
{
    std::vector<std::unique_ptr<bench::BenchEngine>> engines;
    engines.push_back(bench::makeRigidLabBenchEngine());
    bench::RigidLabBenchSettings soft;
    soft.solver = physics::SolverKind::SoftStep;
    engines.push_back(bench::makeRigidLabBenchEngine(soft));
    soft.singlePrecision = true; // opt-in, measured beside the default
    engines.push_back(bench::makeRigidLabBenchEngine(soft));
#ifdef RIGIDLAB_BENCH_BOX2D_V3
    engines.push_back(bench::makeBox2dV3Engine_sse2());
    engines.push_back(bench::makeBox2dV3Engine_avx2());
#elif defined(RIGIDLAB_BENCH_BOX2D_V3_MISSING)
    missing.push_back(std::string("Box2D v3: ") + RIGIDLAB_BENCH_BOX2D_V3_MISSING);
#endif
#ifdef RIGIDLAB_BENCH_CHIPMUNK
    engines.push_back(bench::makeChipmunkEngine());
#else
    missing.push_back("Chipmunk 7: not found (apt-get install libchipmunk-dev)");
#endif
#ifdef RIGIDLAB_BENCH_BOX2D
    engines.push_back(bench::makeBox2dEngine());
#else
    missing.push_back("Box2D 2.4: not found (apt-get install libbox2d-dev)");
#endif
    return engines;
}

} // namespace

int main(int argc, char** argv)
{
    bench::BenchOptions options;
    std::vector<std::string> scenes = bench::benchSceneNames();
    bool profile = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--profile") {
            profile = true;
            continue;
        }
        if (i + 1 >= argc)
            return usage();
        const char* value = argv[++i];
        if (arg == "--scene") {
            if (!bench::makeBenchScene(value)) {
                std::fprintf(stderr, "rigidlab-bench: unknown scene \"%s\"\n", value);
                return 2;
            }
            scenes = {value};
        } else if (arg == "--steps") {
            options.steps = std::atoi(value);
        } else if (arg == "--runs") {
            options.runs = std::atoi(value);
        } else {
            return usage();
        }
    }
    if (options.steps < 2 || options.runs < 1)
        return usage();

    // Each peer left out of this build, with the reason (said under the table).
    std::vector<std::string> missing;
    std::vector<std::unique_ptr<bench::BenchEngine>> engines = makeEngines(missing);

    std::vector<bench::BenchResult> results;
    for (const std::string& name : scenes) {
        const bench::BenchScene scene = *bench::makeBenchScene(name);
        for (auto& engine : engines) {
            results.push_back(bench::runBench(*engine, scene, options));
            std::fprintf(stderr, "  %-15s %-12s %8.3f ms/step\n", results.back().engine.c_str(),
                         name.c_str(), results.back().msPerStep);
        }
    }
    std::printf("\n%s\n", bench::benchTable(results).c_str());
    if (const std::string targets = bench::softStepTargets(results); !targets.empty())
        std::printf("%s\n", targets.c_str());
    for (const std::string& m : missing)
        std::printf("Column missing: %s\n", m.c_str());
    for (auto& engine : engines)
        std::printf("%-9s %s\n", engine->name().c_str(), engine->settings().c_str());
    std::printf("Every scene: dt 1/60 s, gravity -10 m/s^2, friction 0.6, no restitution; "
                "%d steps per run (the first not timed), median of %d runs.\n",
                options.steps, options.runs);
    if (profile) {
        std::printf("\nRigidLab's step by stage (mean wall time [ms] and share):\n");
        for (const std::string& name : scenes)
            std::printf("%s\n",
                        bench::rigidLabProfile(*bench::makeBenchScene(name), options).c_str());
    }
    std::printf("Machine: %s, %ld cores.\n", cpuModel().c_str(), sysconf(_SC_NPROCESSORS_ONLN));
    return 0;
}
