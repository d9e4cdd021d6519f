// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What test_fields shares between its tests: the window on ball_drop, its number fields by
// name, what the controller holds for each, and a frame of the running simulation.

#include "build_paths.h"
#include "panels/inspector_panel.h"
#include "panels/number_field.h"
#include "simulation/simulation_controller.h"
#include "window/main_window.h"

#include <QDockWidget>
#include <QtTest>

#include <algorithm>
#include <cmath>

namespace rigidlab::test::fields {

using rigidlab::ui::MainWindow;
using rigidlab::ui::NumberField;

inline QString scene(const char* name)
{
    return rigidlab::test::sourcePath(u"/lessons/scenes/") + QLatin1String(name);
}

inline QString lesson(const char* name)
{
    return rigidlab::test::sourcePath(u"/lessons/lessons/") + QLatin1String(name);
}

/// |a - b| within a relative tolerance; near zero qFuzzyCompare would fail.
inline bool near(double a, double b, double rel = 1e-12)
{
    return std::abs(a - b) <= rel * std::max(std::abs(a), std::abs(b));
}

/// Lets the running simulation take at least one more frame of steps.
inline bool nextFrame(const ui::SimulationController& c)
{
    const long long s = c.world().stepCount();
    return QTest::qWaitFor([&] { return c.world().stepCount() > s; }, 5000);
}

/// A field by its name: "dt", "restitution", ... in the panel, "mass" in the inspector.
inline NumberField* field(MainWindow& w, const QString& name)
{
    NumberField* f = w.controls().findChild<NumberField*>(name);
    return f ? f : w.inspector().findChild<NumberField*>(name);
}

/// Brings the dock that holds `w` to the front of its tab group, as a click on its tab does.
inline void showDockOf(QWidget* w)
{
    for (QWidget* p = w; p; p = p->parentWidget())
        if (auto* dock = qobject_cast<QDockWidget*>(p)) {
            dock->raise();
            QCoreApplication::processEvents();
            return;
        }
}

/// What the controller holds for a field, in the field's unit.
inline double held(const MainWindow& w, const QString& name, physics::BodyId body)
{
    const physics::World& world = const_cast<MainWindow&>(w).controller().world();
    if (name == QLatin1String("dt"))
        return world.def().dt * 1e3;
    if (name == QLatin1String("restitution"))
        return world.def().restitution;
    if (name == QLatin1String("friction"))
        return world.def().friction;
    if (name == QLatin1String("timeScale"))
        return const_cast<MainWindow&>(w).controller().timeScale();
    if (name == QLatin1String("iterations"))
        return world.def().iterations;
    if (name == QLatin1String("mass"))
        return world.body(body).mass;
    return std::nan("");
}

/// Opens ball_drop with its first ball ("bouncy", dynamic) in the inspector, the window
/// shown and active (shortcuts need an active window).
inline bool openBallDrop(MainWindow& w)
{
    if (!w.openScene(scene("ball_drop.json"), true).isEmpty())
        return false;
    // The sequential solver, whose iterations field the tests type into (the scene's is the
    // soft step, where the field is disabled).
    w.controller().setSolver(physics::SolverKind::SequentialImpulse);
    w.show();
    if (!QTest::qWaitForWindowExposed(&w))
        return false;
    w.activateWindow();
    if (!QTest::qWaitForWindowActive(&w))
        return false;
    w.inspector().setBody(1);
    return w.controller().world().body(1).isDynamic();
}

} // namespace rigidlab::test::fields
