// SPDX-License-Identifier: GPL-3.0-or-later
// The step as the world builds it from the scene (world_step.cpp, islands.cpp): stages a scene
// does not need are left out, the direct integration gives the same bits as the general one,
// sleeping islands cost nearly nothing and wake when touched or pulled, the broad phase finds
// every touching pair. And the exact physics the speed work must keep: a face-on-face bounce
// of two boxes (kinetic energy kept at e = 1, e^2 of it at e = 0.5) and a 100:1 stack.

#include "physics_test_util.h"

#include <rigidlab/physics/sat.h>
#include <rigidlab/physics/world.h>

#include "test_main.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <optional>
#include <set>
#include <utility>
#include <vector>

using namespace rigidlab::physics;
using rigidlab::test::boxBody;
using rigidlab::test::circleBody;

namespace {

std::vector<double> stateOf(const World& w)
{
    std::vector<double> s;
    for (const Body& b : w.bodies())
        s.insert(s.end(), {b.position.x(), b.position.y(), b.angle, b.velocity.x(), b.velocity.y(),
                           b.angularVelocity});
    return s;
}

bool bitIdentical(const std::vector<double>& a, const std::vector<double>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

BodyDef staticBox(double w, double h, const Vec2& at)
{
    BodyDef d = boxBody(w, h, at);
    d.type = BodyType::Static;
    return d;
}

/// Boxes and circles dropped on a static floor, with drag: contacts, friction, spin.
World dropScene(const WorldDef& def)
{
    World world(def);
    world.addBody(staticBox(20.0, 1.0, Vec2(0.0, -0.5)));
    for (int i = 0; i < 12; ++i) {
        world.addBody(boxBody(0.6, 0.4, Vec2(-2.0 + 0.37 * i, 0.4 + 0.5 * i), 0.2 * i));
        world.addBody(circleBody(0.2, Vec2(1.5 - 0.29 * i, 0.6 + 0.45 * i), Vec2(0.3, 0.0)));
    }
    return world;
}

/// A pile of n boxes in a few columns on a floor.
World pileScene(int n, std::optional<bool> sleep)
{
    WorldDef def;
    def.solver = SolverKind::SequentialImpulse; // the path this test is about
    def.dt = 1.0 / 60.0;
    def.restitution = 0.0;
    def.friction = 0.6;
    def.sleep = sleep;
    World world(def);
    world.addBody(staticBox(40.0, 1.0, Vec2(0.0, -0.5)));
    for (int i = 0; i < n; ++i)
        world.addBody(boxBody(1.0, 1.0, Vec2(1.5 * (i % 6) - 4.0, 0.5 + (i / 6))));
    return world;
}

double kineticEnergyInCentreOfMassFrame(const World& w)
{
    double m = 0;
    Vec2 p = Vec2::Zero();
    for (const Body& b : w.bodies()) {
        m += b.mass;
        p += b.mass * b.velocity;
    }
    const Vec2 vc = p / m;
    double e = 0;
    for (const Body& b : w.bodies())
        e += 0.5 * b.mass * (b.velocity - vc).squaredNorm() +
             0.5 * b.inertia * b.angularVelocity * b.angularVelocity;
    return e;
}

} // namespace

class TestStep : public QObject {
    Q_OBJECT
private slots:
    void pendulumLeavesOutCollision_data();
    void pendulumLeavesOutCollision();
    void stagesOfAContactScene();
    void directIntegrationIsTheGeneralOneBitForBit();
    void sleepingPileCostsNearlyNothing();
    void sleepingIslandWakes_data();
    void sleepingIslandWakes();
    void sleepIsOnInLargeScenesOnly();
    void broadPhaseFindsEveryTouchingPair();
    void boxFaceBounce_data();
    void boxFaceBounce();
    void heavyBoxOnLightBoxStands();
    void keptFacesChangeNothing_data();
    void keptFacesChangeNothing();
};

// A pendulum (one bob pinned to the world) and a double pendulum (two links pinned to each
// other): no two bodies can collide, so the step has no broad phase, narrow phase or contact
// solve at all (not run, 0 ms), and still the forces and the integration.
void TestStep::pendulumLeavesOutCollision_data()
{
    QTest::addColumn<bool>("twoLinks");
    QTest::newRow("pendulum") << false;
    QTest::newRow("double pendulum") << true;
}

void TestStep::pendulumLeavesOutCollision()
{
    QFETCH(bool, twoLinks);
    World world = rigidlab::test::makePendulum(IntegratorKind::SymplecticEuler, 1e-3);
    if (twoLinks) {
        const BodyId second =
            world.addBody(circleBody(0.05, world.body(0).origin() + Vec2(0.0, -1.0)));
        world.addPinJoint({second, Vec2(0.0, 1.0), 0, Vec2::Zero()});
    }
    for (int i = 0; i < 100; ++i) {
        world.step();
        const StepProfile& p = world.profile();
        for (Stage s : {Stage::BroadPhase, Stage::NarrowPhase, Stage::ContactSolve}) {
            QVERIFY2(!p.stageRan(s), stageName(s));
            QCOMPARE(p.stage(s), 0.0);
        }
        QVERIFY(p.stageRan(Stage::Forces) && p.stageRan(Stage::Integration));
        QVERIFY(!p.directIntegration); // a joint needs the ODE system
        QCOMPARE(p.pairs, 0);
    }
    QVERIFY(world.contacts().empty());
}

// Bodies on a floor: every stage but the islands runs; the stage times add up to at most the
// step's; symplectic Euler without springs or joints integrates directly.
void TestStep::stagesOfAContactScene()
{
    WorldDef def;
    def.solver = SolverKind::SequentialImpulse; // the path this test is about
    def.dt = 1.0 / 120.0;
    def.sleep = false;
    World world = dropScene(def);
    for (int i = 0; i < 240; ++i)
        world.step();
    const StepProfile& p = world.profile();
    for (Stage s : {Stage::BroadPhase, Stage::NarrowPhase, Stage::Forces, Stage::Integration,
                    Stage::ContactSolve, Stage::Diagnostics})
        QVERIFY2(p.stageRan(s), stageName(s));
    QVERIFY(!p.stageRan(Stage::Islands) && !p.stageRan(Stage::Sleep));
    QVERIFY(p.directIntegration);
    QVERIFY(p.contacts > 10 && p.solved == p.contacts && p.pairs >= p.contacts);
    double sum = 0;
    for (double ms : p.ms)
        sum += ms;
    RL_VERIFY_AT_MOST(sum, p.total * 1.0001 + 1e-6);
}

// The direct integration (symplectic Euler straight on the bodies) and the general one (the
// ODE system, state gathered into vectors) give the same bits, with contacts, friction, drag
// and spin. A spring of stiffness 0 sends a world through the general path.
void TestStep::directIntegrationIsTheGeneralOneBitForBit()
{
    WorldDef def;
    def.solver = SolverKind::SequentialImpulse; // the path this test is about
    def.dt = 1.0 / 240.0;
    def.drag = 0.05;
    World direct = dropScene(def);
    World general = dropScene(def);
    SpringDef nothing;
    nothing.a = 1;
    nothing.b = 2;
    nothing.restLength = 1.0;
    general.addSpring(nothing);
    int contactSteps = 0;
    for (int i = 1; i <= 1200; ++i) {
        direct.step();
        general.step();
        QVERIFY(direct.profile().directIntegration && !general.profile().directIntegration);
        contactSteps += direct.contacts().empty() ? 0 : 1;
        if (i % 100 == 0)
            QVERIFY2(bitIdentical(stateOf(direct), stateOf(general)),
                     qPrintable(QString("differ at step %1").arg(i)));
    }
    QVERIFY(contactSteps > 1000);
    QCOMPARE(direct.evaluations(), general.evaluations());
}

// A pile of 60 boxes with sleeping on comes to rest and falls asleep: then no contact is
// solved, nothing is integrated, and a step costs a small part of an awake one. (Times are
// compared, not bounded, so that a slow machine passes as well; medians, so that a loaded
// one does.)
void TestStep::sleepingPileCostsNearlyNothing()
{
    World asleep = pileScene(60, true);
    World awake = pileScene(60, false);
    for (int i = 0; i < 300; ++i) {
        asleep.step();
        awake.step();
    }
    QCOMPARE(asleep.profile().awake, 0);
    QCOMPARE(asleep.profile().asleep, 60);
    QVERIFY(!asleep.contacts().empty());
    // Medians of the per-step times: a step of either that the machine preempted (a test
    // beside it, a build) must not decide the comparison, as a sum lets it.
    std::vector<double> sleepingMs, awakeMs;
    for (int i = 0; i < 60; ++i) {
        asleep.step();
        awake.step();
        const StepProfile& p = asleep.profile();
        QCOMPARE(p.solved, 0);
        QVERIFY(!p.stageRan(Stage::ContactSolve));
        QCOMPARE(p.stage(Stage::ContactSolve), 0.0);
        QCOMPARE(awake.profile().solved, awake.profile().contacts);
        sleepingMs.push_back(p.total);
        awakeMs.push_back(awake.profile().total);
    }
    const auto median = [](std::vector<double> v) {
        std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
        return v[v.size() / 2];
    };
    RL_VERIFY_AT_MOST(median(sleepingMs), 0.25 * median(awakeMs));
    for (const Body& b : asleep.bodies())
        QVERIFY(!b.isActive() && b.velocity == Vec2::Zero() && b.angularVelocity == 0.0);
}

// Once asleep, the pile wakes when the user pulls a box (a force through the accumulators,
// as the window's drag), when World::wakeBody names one, or when a ball dropped on it touches
// it; the island the woken body touches wakes with it, at the next step.
void TestStep::sleepingIslandWakes_data()
{
    QTest::addColumn<int>("how");
    QTest::newRow("force") << 0;
    QTest::newRow("wakeBody") << 1;
    QTest::newRow("touched") << 2;
}

void TestStep::sleepingIslandWakes()
{
    QFETCH(int, how);
    World world = pileScene(12, true);
    BodyId ball = -1;
    if (how == 2) {
        BodyDef def = circleBody(0.3, Vec2(-4.0, 12.0));
        ball = world.addBody(def);
    }
    for (int i = 0; i < 400; ++i) {
        if (ball >= 0)
            world.mutableBody(ball).velocity = Vec2::Zero(); // held in the air
        world.step();
    }
    for (BodyId id = 1; id <= 12; ++id)
        QVERIFY(!world.body(id).awake);
    const BodyId bottom = 1; // the first column: boxes 1, 7 at x = -4
    if (how == 0)
        world.mutableBody(bottom).force = Vec2(50.0, 0.0);
    else if (how == 1)
        world.wakeBody(bottom);
    // The woken body's island follows at the next step; the ball needs a second and a half.
    bool woke = false;
    for (int i = 0; i < 150 && !woke; ++i) {
        world.step();
        woke = world.body(bottom).awake && world.body(7).awake; // 7 stands on 1
    }
    QVERIFY(woke);
    for (BodyId id = 2; id <= 6; ++id) // the other columns: islands of their own
        QVERIFY(!world.body(id).awake);
}

// Sleeping left unset: on with kLargeSceneBodies dynamic bodies, off with fewer.
void TestStep::sleepIsOnInLargeScenesOnly()
{
    World small = pileScene(kLargeSceneBodies - 1, std::nullopt);
    World large = pileScene(kLargeSceneBodies, std::nullopt);
    QVERIFY(!small.sleepEnabled());
    QVERIFY(large.sleepEnabled());
    small.setSleep(true);
    QVERIFY(small.sleepEnabled());
    large.setSleep(false);
    QVERIFY(!large.sleepEnabled());
}

// The broad phase (a tree of fat boxes, pairs kept from step to step) misses nothing: at every
// step, the contacts the world found are exactly the pairs that collideShapes finds on all
// pairs where the bodies stood, for 150 shapes falling into a box.
void TestStep::broadPhaseFindsEveryTouchingPair()
{
    WorldDef def;
    def.solver = SolverKind::SequentialImpulse; // the path this test is about
    def.dt = 1.0 / 60.0;
    def.continuous = false; // continuous collision adds pairs for fast bodies on purpose
    def.sleep = false;
    World world(def);
    world.addBody(staticBox(12.0, 1.0, Vec2(0.0, -0.5)));
    world.addBody(staticBox(1.0, 20.0, Vec2(-6.5, 10.0)));
    world.addBody(staticBox(1.0, 20.0, Vec2(6.5, 10.0)));
    for (int i = 0; i < 150; ++i) {
        const Vec2 at(-5.0 + 0.7 * (i % 15), 1.0 + 0.8 * (i / 15));
        world.addBody(i % 2 ? circleBody(0.25, at) : boxBody(0.5, 0.4, at, 0.3 * i));
    }
    const double margin = world.contactSettings().margin;
    for (int step = 0; step < 240; ++step) {
        std::set<std::pair<int, int>> expected;
        const auto& bodies = world.bodies();
        for (size_t i = 0; i < bodies.size(); ++i)
            for (size_t j = i + 1; j < bodies.size(); ++j) {
                if (!bodies[i].isDynamic() && !bodies[j].isDynamic())
                    continue;
                const Manifold m = collideShapes(bodies[i].shape, bodies[i].transform(),
                                                 bodies[j].shape, bodies[j].transform(), margin);
                if (m.pointCount > 0)
                    expected.insert({static_cast<int>(i), static_cast<int>(j)});
            }
        world.step();
        std::set<std::pair<int, int>> found;
        for (const Contact& c : world.contacts())
            found.insert({c.a, c.b});
        QVERIFY2(found == expected, qPrintable(QString("step %1: %2 found, %3 expected")
                                                   .arg(step)
                                                   .arg(found.size())
                                                   .arg(expected.size())));
    }
}

// Two equal boxes meet face on face (no gravity, no friction), head on, each at 2 m/s: a
// two-point manifold, solved as a block. At e = 1 the kinetic energy comes back whole; at
// e = 0.5, e^2 = 1/4 of it (in the centre-of-mass frame, so also for unequal masses); no spin
// appears. Box2D 2.4 gets this right; v3's soft contacts do not.
void TestStep::boxFaceBounce_data()
{
    QTest::addColumn<double>("e");
    QTest::addColumn<double>("massB");
    QTest::addColumn<double>("dt");
    QTest::newRow("e=1 equal") << 1.0 << 1.0 << 1.0 / 60.0;
    QTest::newRow("e=0.5 equal") << 0.5 << 1.0 << 1.0 / 60.0;
    QTest::newRow("e=1 3:1") << 1.0 << 3.0 << 1.0 / 240.0;
    QTest::newRow("e=0.5 3:1") << 0.5 << 3.0 << 1e-3;
}

void TestStep::boxFaceBounce()
{
    QFETCH(double, e);
    QFETCH(double, massB);
    QFETCH(double, dt);
    WorldDef def = rigidlab::test::quietWorldDef(IntegratorKind::SymplecticEuler, dt);
    def.restitution = e;
    def.friction = 0.0;
    World world(def);
    BodyDef a = boxBody(1.0, 1.0, Vec2(-1.0, 0.0));
    a.velocity = Vec2(2.0, 0.0);
    a.mass = 1.0;
    BodyDef b = boxBody(1.0, 1.0, Vec2(1.0, 0.0));
    b.velocity = Vec2(-2.0, 0.0);
    b.mass = massB;
    world.addBody(a);
    world.addBody(b);
    const double before = kineticEnergyInCentreOfMassFrame(world);
    bool touched = false;
    for (int i = 0; i < static_cast<int>(1.5 / dt); ++i) {
        world.step();
        touched = touched || !world.contacts().empty();
    }
    QVERIFY(touched);
    QVERIFY(world.body(1).velocity.x() > world.body(0).velocity.x()); // apart again
    RL_VERIFY_NEAR(kineticEnergyInCentreOfMassFrame(world), e * e * before, 0.0, 1e-9);
    RL_VERIFY_NEAR(world.body(0).angularVelocity, 0.0, 1e-9, 0.0);
    RL_VERIFY_NEAR(world.body(1).angularVelocity, 0.0, 1e-9, 0.0);
    RL_VERIFY_NEAR(world.body(0).velocity.y(), 0.0, 1e-9, 0.0);
}

// A 100 kg box on a 1 kg box on the ground, 10 s at 1/60 s with the default iterations: it
// stands, sinking no more than a few linear slops. (The warm start holds it; when contact
// ids changed with round-off, the light box was crushed.)
void TestStep::heavyBoxOnLightBoxStands()
{
    WorldDef def;
    def.solver = SolverKind::SequentialImpulse; // the path this test is about
    def.dt = 1.0 / 60.0;
    def.restitution = 0.0;
    def.friction = 0.6;
    World world(def);
    world.addBody(staticBox(40.0, 2.0, Vec2(0.0, -1.0)));
    BodyDef light = boxBody(1.0, 1.0, Vec2(0.0, 0.5));
    light.mass = 1.0;
    BodyDef heavy = boxBody(1.0, 1.0, Vec2(0.0, 1.5));
    heavy.mass = 100.0;
    world.addBody(light);
    world.addBody(heavy);
    for (int i = 0; i < 600; ++i)
        world.step();
    RL_VERIFY_NEAR(world.body(2).position.y(), 1.5, 0.03, 0.0);
    RL_VERIFY_NEAR(world.body(1).position.x(), 0.0, 0.01, 0.0);
    RL_VERIFY_AT_MOST(std::abs(world.body(1).angle), 0.01);
}

RIGIDLAB_TEST_GUILESS_MAIN(TestStep)
// The narrow phase clips a touching pair that barely moved from the faces the SAT chose before,
// without the SAT (narrow_phase.cpp): the same contacts, bit for bit. A pile of boxes with
// boxes, triangles and hexagons tumbling onto it, with every solver, run with that on and off:
// the states and every contact point agree bit for bit at every step, and on the resting pile
// most pairs were clipped from kept faces, while the tumbling ones needed the SAT.
void TestStep::keptFacesChangeNothing_data()
{
    QTest::addColumn<SolverKind>("solver");
    QTest::newRow("sequential impulses") << SolverKind::SequentialImpulse;
    QTest::newRow("soft step") << SolverKind::SoftStep;
    QTest::newRow("paper's impulse") << SolverKind::PaperImpulse;
}

void TestStep::keptFacesChangeNothing()
{
    QFETCH(SolverKind, solver);
    const auto scene = [solver] {
        World world = pileScene(30, false);
        world.setSolver(solver);
        // The kept faces alone: a recycled manifold (the soft step's) needs no faces at all.
        world.contactSettings().soft.recycleDistance = 0.0;
        const auto polygon = [](int sides, double r) {
            std::vector<Vec2> pts;
            for (int k = 0; k < sides; ++k) {
                const double t = 2.0 * std::numbers::pi * k / sides;
                pts.emplace_back(r * std::cos(t), r * std::sin(t));
            }
            return makePolygonShape(makePolygon(pts).value().polygon);
        };
        for (int i = 0; i < 12; ++i) {
            BodyDef d = boxBody(0.7, 0.4, Vec2(-4.0 + 0.8 * i, 8.0 + 0.6 * i), 0.3 * i);
            if (i % 3 == 1)
                d.shape = polygon(3, 0.4);
            else if (i % 3 == 2)
                d.shape = polygon(6, 0.35);
            d.angularVelocity = 2.0 - 0.4 * i;
            world.addBody(d);
        }
        return world;
    };
    World kept = scene();
    World fresh = scene();
    fresh.contactSettings().reuseFaces = false;
    const auto pointsOf = [](const World& w) {
        std::vector<double> v;
        for (const Contact& c : w.contacts())
            for (int k = 0; k < c.manifold.pointCount; ++k) {
                const ContactPoint& p = c.manifold.points[static_cast<size_t>(k)];
                v.insert(v.end(), {double(c.a), double(c.b), p.point.x(), p.point.y(), p.separation,
                                   double(p.id), c.manifold.normal.x(), c.manifold.normal.y()});
            }
        return v;
    };
    long reusedLate = 0, contactsLate = 0, fullEarly = 0;
    const int steps = 480;
    for (int i = 1; i <= steps; ++i) {
        kept.step();
        fresh.step();
        QCOMPARE(fresh.profile().reusedFaces, 0);
        if (!bitIdentical(stateOf(kept), stateOf(fresh)) ||
            !bitIdentical(pointsOf(kept), pointsOf(fresh)))
            QFAIL(qPrintable(QString("kept faces changed the contacts at step %1").arg(i)));
        if (i <= steps / 2)
            fullEarly += kept.profile().contacts - kept.profile().reusedFaces;
        else {
            reusedLate += kept.profile().reusedFaces;
            contactsLate += kept.profile().contacts;
        }
    }
    QVERIFY2(
        reusedLate > contactsLate / 2,
        qPrintable(QString("%1 of %2 contacts from kept faces").arg(reusedLate).arg(contactsLate)));
    QVERIFY(fullEarly > 100);
}

#include "test_step.moc"
