// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Benchmarks: the same scenes built in any engine, stepped and timed by one harness, so that
// RigidLab and its peers (Box2D, Chipmunk: bench/) are measured on equal terms.
//
// A scene is described here without reference to an engine (shapes, poses, densities,
// friction); an engine adapter builds it in its own world. The harness times the steps
// (the first step is not timed: it pays for setting up contacts) over several runs and takes
// the median, and measures a stability figure on the final state:
//   - the top box's rise (+) or sink (-) after the run [m];
//   - how many boxes moved more than 0.5 m sideways or turned more than 0.2 rad;
//   - for the rain into a box: how many bodies left the box.
// Plain C++: no Qt, so that the peers' adapters need nothing but their engine.

#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/math.h"
#include "rigidlab/physics/world.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rigidlab::bench {

enum class BenchShapeKind { Box, Circle, Polygon };

struct BenchShape {
    BenchShapeKind kind = BenchShapeKind::Box;
    double width = 1.0;  ///< box [m]
    double height = 1.0; ///< box [m]
    double radius = 0.5; ///< circle [m]
    /// Convex polygon, counter-clockwise, centroid at the origin (so that the body origin is
    /// the centre of mass in every engine) [m].
    std::vector<physics::Vec2> vertices;
};

struct BenchBody {
    bool isStatic = false;
    BenchShape shape;                               ///< centred on the body origin
    physics::Vec2 position = physics::Vec2::Zero(); ///< [m]
    double angle = 0.0;                             ///< [rad]
    double density = 1.0;                           ///< [kg/m^2]
    double friction = 0.6;
};

/// What the stability figure looks at.
enum class BenchCheck {
    Stack, ///< top box drift, boxes moved or turned
    Rain,  ///< bodies that left the container
};

struct BenchScene {
    std::string name;                  ///< "pyramid-40"
    std::string description;           ///< one line
    physics::Vec2 gravity{0.0, -10.0}; ///< [m/s^2]
    double dt = 1.0 / 60.0;            ///< [s]
    std::vector<BenchBody> bodies;
    BenchCheck check = BenchCheck::Stack;
    int topBody = -1; ///< index of the top box (Stack)
    /// The container's inside (Rain): a body whose centre is outside has escaped [m].
    physics::Vec2 containerLo = physics::Vec2::Zero(), containerHi = physics::Vec2::Zero();
    int dynamicCount() const;
};

/// The scenes, in the order the table lists them.
std::vector<std::string> benchSceneNames();
/// A scene by name, or nullopt.
std::optional<BenchScene> makeBenchScene(std::string_view name);

/// A body's pose as the harness reads it back.
struct BenchPose {
    physics::Vec2 position = physics::Vec2::Zero(); ///< centre of mass [m]
    double angle = 0.0;                             ///< [rad]
};

/// One engine, behind the harness.
class BenchEngine {
public:
    virtual ~BenchEngine() = default;
    virtual std::string name() const = 0;
    /// The settings the engine runs with, in words ("8 velocity / 3 position iterations").
    virtual std::string settings() const = 0;
    /// Builds the scene in a fresh world (replacing any earlier one).
    virtual void build(const BenchScene& scene) = 0;
    virtual void step() = 0;
    /// Poses of every body, in the scene's order.
    virtual void poses(std::vector<BenchPose>& out) const = 0;
    /// A hash of the bits of every body's state (stateHash()), for engines that give one
    /// (RigidLab's); nullopt for the others.
    virtual std::optional<std::uint64_t> stateHash() const { return std::nullopt; }
};

/// FNV-1a (64 bits) over the bytes of `values`, continuing from `hash`.
std::uint64_t fnv1a(const double* values, size_t count, std::uint64_t hash = 0xcbf29ce484222325ull);
/// The bits of a world's state: FNV-1a over each body's position (x, y), angle, velocity (x, y)
/// and angular velocity, in body order. Equal hashes after the same steps: the same bits.
std::uint64_t stateHash(const physics::World& world);

struct BenchOptions {
    int steps = 600; ///< steps per run, the first one not timed (600: 10 s at 1/60 s)
    int runs = 3;    ///< runs; the table gives the median
};

struct BenchResult {
    std::string engine;
    std::string settings;
    std::string scene;
    int bodies = 0; ///< dynamic bodies
    /// Median over the runs of the mean CPU time of this thread per timed step [ms].
    double msPerStep = 0;
    std::vector<double> runs; ///< each run's mean [ms]
    double simulated = 0;     ///< simulated time of a run [s]
    BenchCheck check = BenchCheck::Stack;
    double topDrift = 0; ///< top box: final minus initial height [m]
    int moved = 0;       ///< boxes moved more than 0.5 m sideways or turned more than 0.2 rad
    int escaped = 0;     ///< bodies outside the container at the end (Rain)
    bool finite = true;  ///< every pose finite at the end
    /// The engine's stateHash() at the end of the first run (RigidLab's engines).
    std::optional<std::uint64_t> hash;
};

/// Runs the scene `options.runs` times in the engine and measures it.
BenchResult runBench(BenchEngine& engine, const BenchScene& scene, const BenchOptions& options);
/// The same for several engines taking turns, a run each, `options.runs` rounds: a machine whose
/// speed drifts over the minutes slows each engine alike, so the ratios between them keep
/// (run by run, one engine's time moved by 70 % between runs minutes apart on an idle
/// machine). A result per engine, in `engines`' order; each one's stability and hash are
/// its first run's, as runBench's.
std::vector<BenchResult> runInTurns(const std::vector<BenchEngine*>& engines,
                                    const BenchScene& scene, const BenchOptions& options);

/// The stability figure in words: "top +0.012 m, 0 moved" or "0 escaped".
std::string stabilityText(const BenchResult& r);
/// True when `a`'s stability figure is at least as good as `b`'s (a comparison of speed
/// between the two counts only then): top drift no larger (within 1 mm), no more boxes
/// moved or escaped.
bool atLeastAsStable(const BenchResult& a, const BenchResult& b);

/// The engine the table compares every row with: the lab's default solver ("RigidLab SS")
/// when it ran, else the first RigidLab engine that ran; empty when none did.
std::string referenceEngine(const std::vector<BenchResult>& results);
/// The table: engine, scene, bodies, ms per step, ratio to the reference (referenceEngine(),
/// named in the header line) on the same scene, stability, and whether the ratio counts (the
/// reference at least as stable). Rows in the order given.
std::string benchTable(const std::vector<BenchResult>& results);

/// The ratio of `a`'s time to `b`'s round by round (a.runs[i] / b.runs[i], the engines having
/// taken turns: runInTurns), for the rounds both ran; empty when either has none.
std::vector<double> pairedRatios(const BenchResult& a, const BenchResult& b);

/// The speed and stability targets for the soft step ("RigidLab SS"), each with its
/// ratio in these results and whether it is met: on each pyramid no slower than Box2D v3 as it
/// builds by default (SSE2) and within 1.25 times its AVX2 build, 1.5 times faster than
/// Chipmunk and 2 times faster than Box2D 2.4, and the base-100 pyramid standing with its top
/// sunk less than Box2D v3's (SSE2); each ratio to Box2D v3 also round by round (the median
/// of pairedRatios() and their range), so that the line says how much it moved in the run; the
/// cost per body from base 40 to
/// base 100 growing no faster than n log n. Empty without a soft-step pyramid.
std::string softStepTargets(const std::vector<BenchResult>& results);

/// The RigidLab settings the benchmark uses (what the table's note says).
struct RigidLabBenchSettings {
    physics::SolverKind solver = physics::SolverKind::SequentialImpulse;
    int iterations = 8;         ///< velocity iterations
    int positionIterations = 3; ///< position correction passes (at most)
    bool sleep = false;
    /// The soft step's contact passes in single precision (SoftStepSettings::singlePrecision):
    /// the row "RigidLab SS f32", opt-in, not the default solver.
    bool singlePrecision = false;
    /// The soft step's substeps (SoftStepSettings::substeps; the library's default unless the
    /// bench is told otherwise: `--substeps N`).
    int substeps = physics::SoftStepSettings{}.substeps;
};
std::unique_ptr<BenchEngine> makeRigidLabBenchEngine(const RigidLabBenchSettings& settings = {});

/// RigidLab's step on the scene, stage by stage (physics::StepProfile), as one line: the mean
/// wall time of each stage that ran over `options.steps` steps (the first not counted) [ms]
/// and its share of the whole step, and the mean number of pairs and contacts.
std::string rigidLabProfile(const BenchScene& scene, const BenchOptions& options,
                            const RigidLabBenchSettings& settings = {});

/// The RigidLab world of a benchmark scene (what the adapter steps).
physics::World buildBenchWorld(const BenchScene& scene, const RigidLabBenchSettings& settings);

/// The scene as a RigidLab scene file (format v1), to open it in the window.
std::string benchSceneJson(const BenchScene& scene, const RigidLabBenchSettings& settings);

} // namespace rigidlab::bench
