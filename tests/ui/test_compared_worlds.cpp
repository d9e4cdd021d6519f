// SPDX-License-Identifier: GPL-3.0-or-later
// Worlds compared side by side (a lesson's compare step): a setting changed mid-run reaches
// every world while each keeps its own integrator, going back replays each world with the
// change at its step, a reset keeps the change, and the compared worlds are drawn clear of the
// first world's floor.

#include "simulation/simulation_controller.h"
#include "simulation/variant_layout.h"

#include <QtTest>

#include "simulation_scenes.h"
#include "test_main.h"

using namespace rigidlab;
using namespace rigidlab::ui;
using rigidlab::test::ballScene;
using rigidlab::test::bouncingBall;

class TestComparedWorlds : public QObject {
    Q_OBJECT

private slots:
    void comparedWorldsFollowTheSettingsBackAndReset()
    {
        // The ball dropped in two worlds side by side, the second with RK4: e and μ changed at
        // step 20 reach both, the integrator stays each world's own. Going back replays the
        // compared world with the change at its step (as the main world's history has it), and
        // a reset keeps the change in both.
        const lessons::Scene scene = bouncingBall();
        std::vector<physics::World> worlds{lessons::buildWorld(scene), lessons::buildWorld(scene)};
        worlds[1].setIntegrator(physics::IntegratorKind::RK4);
        physics::World alone = worlds[1]; // the compared world run by hand, for the replay
        SimulationController c;
        c.loadWorlds(scene, QStringLiteral("bounce.json"), worlds, {}, physics::Vec2(3, 0));
        QCOMPARE(c.variantCount(), 1);
        for (int i = 0; i < 20; ++i)
            c.stepForward();
        c.setRestitution(0.9);
        c.setFriction(0.7);
        for (int i = 0; i < 20; ++i)
            c.stepForward();
        for (int i = 0; i < 30; ++i) {
            if (i == 20) {
                alone.setRestitution(0.9);
                alone.setFriction(0.7);
            }
            alone.step();
        }
        const auto ball = [](const physics::World& w) { return w.body(1).origin(); };
        c.seek(30);
        QCOMPARE(c.variant(0).stepCount(), 30LL);
        QCOMPARE(c.variant(0).def().restitution, 0.9);
        QCOMPARE(c.variant(0).def().friction, 0.7);
        QCOMPARE(c.variant(0).def().integrator, physics::IntegratorKind::RK4);
        QCOMPARE(ball(c.variant(0)), ball(alone)); // the same run, bit for bit
        c.seek(10);
        QCOMPARE(c.variant(0).def().restitution, scene.world.restitution);
        QCOMPARE(c.variant(0).def().friction, scene.world.friction);
        c.seek(25);
        c.reset();
        for (const physics::World* w : {&c.world(), &c.variant(0)}) {
            QCOMPARE(w->stepCount(), 0LL);
            QCOMPARE(w->def().restitution, 0.9);
            QCOMPARE(w->def().friction, 0.7);
        }
        QCOMPARE(c.world().def().integrator, physics::IntegratorKind::Verlet);
        QCOMPARE(c.variant(0).def().integrator, physics::IntegratorKind::RK4);
    }

    void comparedWorldsAreDrawnClearOfTheFloor()
    {
        const physics::World floor = lessons::buildWorld(bouncingBall());
        // The floor is 10 m wide: a 3 m shift would overlap it, so the shift grows past it.
        const physics::Vec2 shifted = besideOffset(floor, physics::Vec2(3, 0));
        QVERIFY2(shifted.x() > 10.0 && shifted.y() == 0.0,
                 qPrintable(QStringLiteral("(%1, %2)").arg(shifted.x()).arg(shifted.y())));
        // Far enough already, or nothing static: the lesson's shift as it is.
        QCOMPARE(besideOffset(floor, physics::Vec2(20, 0)), physics::Vec2(20, 0));
        const physics::World open = lessons::buildWorld(ballScene(true));
        QCOMPARE(besideOffset(open, physics::Vec2(3, 0)), physics::Vec2(3, 0));
    }
};

RIGIDLAB_TEST_MAIN(TestComparedWorlds)
#include "test_compared_worlds.moc"
