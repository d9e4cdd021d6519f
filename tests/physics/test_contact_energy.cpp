// SPDX-License-Identifier: GPL-3.0-or-later
// Contacts never make energy between bodies that are not kinematic: once they have added as
// much as the energy in play, the world's total energy is held to its start plus that, and
// growing past it stops the run as diverged. Balls heaped at one point, thrown apart by their
// contacts, are the case: the default solver reports the divergence at once. An elastic ball
// bouncing, a resting stack and a kinematic paddle that pushes a ball (energy brought in, not
// made) run on.

#include "physics_test_util.h"
#include "test_main.h"

using namespace rigidlab;
using namespace rigidlab::physics;
using rigidlab::test::boxBody;
using rigidlab::test::circleBody;

namespace {

World withFloor(SolverKind solver)
{
    WorldDef def;
    def.solver = solver;
    def.dt = 1.0 / 120.0;
    World w(def);
    BodyDef floor = boxBody(40.0, 1.0, Vec2(0.0, -0.5));
    floor.type = BodyType::Static;
    w.addBody(floor);
    return w;
}

/// Runs until the world diverges or `steps` pass; the energy the contacts added [J].
double run(World& w, int steps)
{
    for (int i = 0; i < steps && !w.divergence(); ++i)
        w.step();
    return -w.diagnostics().collisionLoss;
}

} // namespace

class TestContactEnergy : public QObject {
    Q_OBJECT

private slots:
    void heapIsThrownApartOrDiverges()
    {
        // The soft step, the default solver (the sequential-impulse solver's position pass
        // moves the balls apart without contact impulses, outside the contacts' books).
        // Fifty-two balls: 1,326 overlapping pairs, within a step's work budget of 1,424 (a
        // heap of 1,000 stops before its first step: test_work_budget).
        World w = withFloor(SolverKind::SoftStep);
        for (int i = 0; i < 52; ++i)
            w.addBody(circleBody(0.1, Vec2(0.001 * (i % 7), 1.0 + 0.001 * (i % 11))));
        w.step(); // the first step fixes the energy at the start
        const double start = w.diagnostics().total;
        const double added = run(w, 60);
        const double total = w.diagnostics().total;
        if (const auto& d = w.divergence()) {
            QCOMPARE(d->kind, Divergence::Kind::EnergyGrowth);
            // Held to the tight bound: less growth allowed than the contacts made.
            QVERIFY2(d->value > d->bound && d->bound - d->start < added,
                     qPrintable(QStringLiteral("total %1 J, bound %2 J, start %3 J, contacts "
                                               "added %4 J")
                                    .arg(d->value)
                                    .arg(d->bound)
                                    .arg(d->start)
                                    .arg(added)));
            qInfo("diverged at step %lld: contacts added %g J, the total grew from %g J to %g J",
                  d->step, added, d->start, d->value);
        } else {
            // Not diverged: then no energy was made.
            RL_VERIFY_AT_MOST(total, start + 1e-6 * std::abs(start));
        }
    }

    void ordinaryContactsRunOn_data()
    {
        QTest::addColumn<SolverKind>("solver");
        QTest::addColumn<QString>("scene");
        for (const auto& [solver, name] :
             {std::pair{SolverKind::SoftStep, "soft step"},
              std::pair{SolverKind::SequentialImpulse, "sequential impulses"}}) {
            QTest::newRow(qPrintable(QStringLiteral("%1: elastic ball").arg(name)))
                << solver << "ball";
            QTest::newRow(qPrintable(QStringLiteral("%1: stack").arg(name))) << solver << "stack";
            QTest::newRow(qPrintable(QStringLiteral("%1: paddle").arg(name))) << solver << "paddle";
        }
    }
    void ordinaryContactsRunOn()
    {
        QFETCH(SolverKind, solver);
        QFETCH(QString, scene);
        World w = withFloor(solver);
        if (scene == u"ball") {
            BodyDef ball = circleBody(0.1, Vec2(0.0, 2.0));
            ball.restitution = 1.0;
            w.addBody(ball);
        } else if (scene == u"stack") {
            for (int i = 0; i < 8; ++i)
                w.addBody(boxBody(0.5, 0.5, Vec2(0.0, 0.25 + 0.5 * i)));
        } else {
            w.addBody(circleBody(0.1, Vec2(0.0, 0.1)));
            BodyDef paddle = boxBody(0.2, 0.2, Vec2(-1.0, 0.1));
            paddle.type = BodyType::Kinematic;
            paddle.velocity = Vec2(3.0, 0.0);
            w.addBody(paddle);
        }
        run(w, 600);
        QVERIFY2(!w.divergence(), w.divergence() ? "diverged" : "");
    }
};

RIGIDLAB_TEST_GUILESS_MAIN(TestContactEnergy)
#include "test_contact_energy.moc"
