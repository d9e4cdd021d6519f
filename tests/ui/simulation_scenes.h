// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The small scenes the simulation tests run (test_simulation.cpp, test_compared_worlds.cpp):
// a ball alone and a ball bouncing on a floor, at a dt that fits a frame exactly.

#include "format/scene_loader.h"

#include <QByteArray>
#include <QString>

namespace rigidlab::test {

/// A dt that is an exact binary fraction, so that whole numbers of steps fit a frame exactly.
inline constexpr double kDt = 1.0 / 128.0;

/// A scene from its JSON; fails the test when it does not load.
inline lessons::Scene sceneOf(const QByteArray& json)
{
    const auto loaded = lessons::loadSceneJson(json, QStringLiteral("test.json"));
    if (!loaded.ok)
        qFatal("test scene does not load: %s", qPrintable(loaded.error));
    return loaded.scene;
}

/// One ball at the origin; `gravity` on or off, dt = kDt, the integrator named.
inline lessons::Scene ballScene(bool gravity, const char* integrator = "symplectic-euler")
{
    return sceneOf(QByteArray(R"({"rigidlab": 1, "title": "ball",
        "world": {"gravity": )") +
                   (gravity ? "[0, -9.81]" : "[0, 0]") + R"(, "dt": 0.0078125, "integrator": ")" +
                   integrator + R"("},
        "bodies": [{"id": "b", "shape": {"type": "circle", "radius": 0.1}, "mass": 2}]})");
}

/// A ball dropped from 1 m onto a static floor (velocity Verlet, e = 0.5).
inline lessons::Scene bouncingBall()
{
    return sceneOf(R"({"rigidlab": 1, "title": "bounce",
        "world": {"gravity": [0, -9.81], "dt": 0.0078125, "integrator": "verlet",
                  "restitution": 0.5},
        "bodies": [
          {"id": "floor", "type": "static", "shape": {"type": "box", "width": 10, "height": 1},
           "position": [0, -0.5]},
          {"id": "ball", "shape": {"type": "circle", "radius": 0.1}, "mass": 1,
           "position": [0, 1.1]}]})");
}

} // namespace rigidlab::test
