// SPDX-License-Identifier: GPL-3.0-or-later
// rigidlab-bench: the benchmark scenes in RigidLab, Box2D v3, Chipmunk 7 and Box2D 2.4, one
// table.
//   rigidlab-bench [--scene LIST] [--steps N] [--runs K] [--engines LIST] [--substeps N] [--hash]
//                  [--profile]
// --scene runs only the scenes named, comma-separated (pyramid-40,pyramid-100 prints the cost per
// body between them); all by default.
// --engines runs only the engines named, comma-separated: sequential, soft, f32, v3-sse2,
// v3-avx2, chipmunk, box2d (or the table's names, "RigidLab SS"); all of this build's by default.
// --substeps N runs the soft step (soft and f32) in N substeps instead of the library's default
// (SoftStepSettings::substeps); the settings line under the table says the count.
// --hash prints, for each RigidLab engine and scene, a hash of the bits of every body's
// position, angle, velocity and angular velocity after the first run (bench::stateHash): the
// same hash before and after a change is the same bits, e.g.
//   rigidlab-bench --scene pyramid-100 --steps 150 --runs 1 --engines soft --hash
// --profile adds RigidLab's stages (physics::StepProfile): where its step spends the time.
// Built and run by `./lab bench`; not a test (timings depend on the machine).

#include "bench_peers.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>

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
    std::fputs("usage: rigidlab-bench [--scene LIST] [--steps N] [--runs K] [--engines LIST] "
               "[--substeps N] [--hash] [--profile]\n",
               stderr);
    return 2;
}

/// An engine with the short name --engines knows it by.
struct NamedEngine {
    std::string key; ///< "soft"
    std::unique_ptr<bench::BenchEngine> engine;
};

/// RigidLab (both solvers) and every peer this build has; `missing` gets each peer left out,
/// with the reason.
std::vector<NamedEngine> makeEngines(const bench::RigidLabBenchSettings& soft,
                                     [[maybe_unused]] std::vector<std::string>& missing)
{
    std::vector<NamedEngine> engines;
    engines.push_back({"sequential", bench::makeRigidLabBenchEngine()});
    engines.push_back({"soft", bench::makeRigidLabBenchEngine(soft)});
    bench::RigidLabBenchSettings single = soft;
    single.singlePrecision = true; // opt-in, measured beside the default
    engines.push_back({"f32", bench::makeRigidLabBenchEngine(single)});
#ifdef RIGIDLAB_BENCH_BOX2D_V3
    engines.push_back({"v3-sse2", bench::makeBox2dV3Engine_sse2()});
    engines.push_back({"v3-avx2", bench::makeBox2dV3Engine_avx2()});
#elif defined(RIGIDLAB_BENCH_BOX2D_V3_MISSING)
    missing.push_back(std::string("Box2D v3: ") + RIGIDLAB_BENCH_BOX2D_V3_MISSING);
#endif
#ifdef RIGIDLAB_BENCH_CHIPMUNK
    engines.push_back({"chipmunk", bench::makeChipmunkEngine()});
#else
    missing.push_back("Chipmunk 7: not found (apt-get install libchipmunk-dev)");
#endif
#ifdef RIGIDLAB_BENCH_BOX2D
    engines.push_back({"box2d", bench::makeBox2dEngine()});
#else
    missing.push_back("Box2D 2.4: not found (apt-get install libbox2d-dev)");
#endif
    return engines;
}

bool sameName(std::string_view a, std::string_view b)
{
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](char x, char y) {
        return std::tolower(static_cast<unsigned char>(x)) ==
               std::tolower(static_cast<unsigned char>(y));
    });
}

/// Keeps the engines `list` names (comma-separated short names or the table's names), in the
/// order of the table; false, with a message naming the unknown one and the known ones, when
/// a name is none of them.
bool selectEngines(std::string_view list, std::vector<NamedEngine>& engines)
{
    std::vector<bool> wanted(engines.size(), false);
    size_t start = 0;
    while (start <= list.size()) {
        const size_t comma = std::min(list.find(',', start), list.size());
        const std::string_view name = list.substr(start, comma - start);
        start = comma + 1;
        const auto it = std::find_if(engines.begin(), engines.end(), [&](const NamedEngine& e) {
            return sameName(name, e.key) || sameName(name, e.engine->name());
        });
        if (it == engines.end()) {
            std::string known;
            for (const NamedEngine& e : engines)
                known += (known.empty() ? "" : ", ") + e.key + " (" + e.engine->name() + ")";
            std::fprintf(stderr,
                         "rigidlab-bench: --engines: no engine \"%.*s\" in this build; the "
                         "engines: %s\n",
                         static_cast<int>(name.size()), name.data(), known.c_str());
            return false;
        }
        wanted[static_cast<size_t>(it - engines.begin())] = true;
    }
    std::vector<NamedEngine> kept;
    for (size_t i = 0; i < engines.size(); ++i)
        if (wanted[i])
            kept.push_back(std::move(engines[i]));
    engines = std::move(kept);
    return true;
}

/// `value` as a whole number of at least `least`, or nullopt with a message naming the flag.
std::optional<int> wholeNumber(const std::string& flag, const char* value, int least)
{
    int n = 0;
    const char* end = value + std::strlen(value);
    const auto [ptr, error] = std::from_chars(value, end, n);
    if (error != std::errc() || ptr != end || *value == '\0' || n < least) {
        std::fprintf(stderr, "rigidlab-bench: %s needs a whole number of at least %d, not \"%s\"\n",
                     flag.c_str(), least, value);
        return std::nullopt;
    }
    return n;
}

/// The scenes of `list`, comma-separated, into `scenes`; false after naming an unknown one.
bool sceneList(std::string_view list, std::vector<std::string>& scenes)
{
    scenes.clear();
    size_t start = 0;
    while (start <= list.size()) {
        const size_t comma = std::min(list.find(',', start), list.size());
        const std::string name(list.substr(start, comma - start));
        start = comma + 1;
        if (!bench::makeBenchScene(name)) {
            std::string known;
            for (const std::string& s : bench::benchSceneNames())
                known += (known.empty() ? "" : ", ") + s;
            std::fprintf(stderr, "rigidlab-bench: --scene: unknown scene \"%s\"; the scenes: %s\n",
                         name.c_str(), known.c_str());
            return false;
        }
        scenes.push_back(name);
    }
    return true;
}

/// The command line's choices.
struct Flags {
    bench::BenchOptions options;
    std::vector<std::string> scenes = bench::benchSceneNames();
    bool profile = false, hash = false;
    /// The soft step's settings (--substeps) for the engines soft and f32.
    bench::RigidLabBenchSettings soft{.solver = physics::SolverKind::SoftStep};
    const char* engineList = nullptr; ///< --engines' value, or null for every engine
};

/// The flags of `argv`, or nullopt after saying which flag or value is wrong.
std::optional<Flags> parseFlags(int argc, char** argv)
{
    Flags f;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--profile" || arg == "--hash") {
            (arg == "--hash" ? f.hash : f.profile) = true;
            continue;
        }
        if (arg != "--scene" && arg != "--steps" && arg != "--runs" && arg != "--engines" &&
            arg != "--substeps") {
            std::fprintf(stderr, "rigidlab-bench: unknown option \"%s\"\n", arg.c_str());
            return std::nullopt;
        }
        if (i + 1 >= argc) {
            std::fprintf(stderr, "rigidlab-bench: %s needs a value\n", arg.c_str());
            return std::nullopt;
        }
        const char* value = argv[++i];
        if (arg == "--scene") {
            if (!sceneList(value, f.scenes))
                return std::nullopt;
        } else if (arg == "--steps" || arg == "--runs") {
            const bool steps = arg == "--steps";
            const std::optional<int> n = wholeNumber(arg, value, steps ? 2 : 1);
            if (!n)
                return std::nullopt;
            (steps ? f.options.steps : f.options.runs) = *n;
        } else if (arg == "--substeps") {
            const std::optional<int> n = wholeNumber(arg, value, 1);
            if (!n)
                return std::nullopt;
            f.soft.substeps = *n;
        } else {
            f.engineList = value;
        }
    }
    return f;
}

} // namespace

int main(int argc, char** argv)
{
    const std::optional<Flags> flags = parseFlags(argc, argv);
    if (!flags) {
        usage();
        return 2;
    }
    const auto& [options, scenes, profile, hash, soft, engineList] = *flags;

    // Each peer left out of this build, with the reason (said under the table).
    std::vector<std::string> missing;
    std::vector<NamedEngine> engines = makeEngines(soft, missing);
    if (engineList) {
        if (!selectEngines(engineList, engines))
            return 2;
        missing.clear(); // the engines were named: the others are not missing
    }

    std::vector<bench::BenchEngine*> turns;
    for (auto& [key, engine] : engines)
        turns.push_back(engine.get());
    std::vector<bench::BenchResult> results;
    for (const std::string& name : scenes) {
        const bench::BenchScene scene = *bench::makeBenchScene(name);
        for (bench::BenchResult& r : bench::runInTurns(turns, scene, options)) {
            std::fprintf(stderr, "  %-15s %-12s %8.3f ms/step\n", r.engine.c_str(), name.c_str(),
                         r.msPerStep);
            results.push_back(std::move(r));
        }
    }
    std::printf("\n%s\n", bench::benchTable(results).c_str());
    if (const std::string targets = bench::softStepTargets(results); !targets.empty())
        std::printf("%s\n", targets.c_str());
    for (const std::string& m : missing)
        std::printf("Column missing: %s\n", m.c_str());
    for (auto& [key, engine] : engines)
        std::printf("%-9s %s\n", engine->name().c_str(), engine->settings().c_str());
    std::printf(
        "Every scene: dt 1/60 s, gravity -10 m/s^2, friction 0.6, no restitution; "
        "%d steps per run (the first not timed), median of %d runs, the engines taking turns.\n",
        options.steps, options.runs);
    if (hash) {
        std::printf("\nState hash after %d steps (FNV-1a 64 over each body's position, angle, "
                    "velocity and angular velocity bits; the first run):\n",
                    options.steps);
        for (const bench::BenchResult& r : results)
            if (r.hash)
                std::printf("  %-15s %-12s %016" PRIx64 "\n", r.engine.c_str(), r.scene.c_str(),
                            *r.hash);
    }
    if (profile) {
        std::printf("\nRigidLab's step by stage (mean wall time [ms] and share):\n");
        for (const std::string& name : scenes)
            std::printf("%s\n",
                        bench::rigidLabProfile(*bench::makeBenchScene(name), options).c_str());
    }
    std::printf("Machine: %s, %ld cores.\n", cpuModel().c_str(), sysconf(_SC_NPROCESSORS_ONLN));
    return 0;
}
