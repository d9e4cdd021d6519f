// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzz target: the scene loader (loadSceneJson) on any bytes, then the world it builds.
//
// Whatever the bytes, the loader returns: a scene or one error line naming the source. A scene
// it accepts is within the limits (lessons/limits.h), so its world starts with finite energy
// and momentum (a finite number that overflows the physics must be refused at load, not
// found later as NaN), its bodies do not crowd past the engine's budget of pairs for a step
// (work_budget.h), and a few steps of it run without a sanitizer report, each within that
// budget.

#include "fuzz_check.h"

#include "format/scene_loader.h"
#include "format/scene_overlaps.h"
#include "rigidlab/physics/work_budget.h"
#include "rigidlab/physics/world.h"

#include <QByteArray>
#include <QString>

#include <cmath>
#include <cstddef>
#include <cstdint>

using namespace rigidlab;

namespace {

/// Worlds this small are stepped; larger ones are only built (each input must stay fast).
constexpr std::size_t kMaxBodiesStepped = 64;
constexpr int kSteps = 3;

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const QString source = QStringLiteral("fuzz.json");
    const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    const lessons::SceneLoadResult r = lessons::loadSceneJson(bytes, source);
    if (!r.ok) {
        FUZZ_CHECK(r.error.startsWith(source + QStringLiteral(": ")));
        FUZZ_CHECK(!r.error.contains(u'\n'));
        return 0;
    }
    const lessons::Scene& scene = r.scene;
    FUZZ_CHECK(scene.bodies.size() <= static_cast<std::size_t>(lessons::kMaxBodies));
    FUZZ_CHECK(scene.originalVertices.size() == scene.bodies.size());
    FUZZ_CHECK(!lessons::surveyOverlaps(scene, 0).crowded);

    physics::World world = lessons::buildWorld(scene);
    world.updateDiagnostics();
    const physics::Diagnostics& d = world.diagnostics();
    FUZZ_CHECK(std::isfinite(d.kinetic) && std::isfinite(d.potential) && std::isfinite(d.total));
    FUZZ_CHECK(std::isfinite(d.momentum.x()) && std::isfinite(d.momentum.y()));
    FUZZ_CHECK(std::isfinite(d.angularMomentum));
    for (const physics::Body& b : world.bodies()) {
        FUZZ_CHECK(std::isfinite(b.mass) && std::isfinite(b.inertia));
        FUZZ_CHECK(std::isfinite(b.position.x()) && std::isfinite(b.position.y()));
    }
    if (world.bodies().size() <= kMaxBodiesStepped) {
        for (int i = 0; i < kSteps && !world.divergence(); ++i) {
            world.step();
            FUZZ_CHECK(static_cast<std::size_t>(world.profile().pairs) <=
                       physics::pairBudget(world.bodies().size()));
        }
    }
    return 0;
}
