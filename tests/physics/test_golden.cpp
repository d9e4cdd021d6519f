// SPDX-License-Identifier: GPL-3.0-or-later
// Golden runs: fixed scenes stepped a fixed number of times with every solver and every
// integrator the engine offers, the final state hashed bit for bit and compared with a value
// stored here. Any change to the arithmetic of a step, however small (an operation reordered,
// a product hoisted), changes a hash: a refactoring that keeps every hash is bit-identical.
//
// When a hash may change: only with a deliberate change of the physics (a new force term, a
// changed solver, a fixed bug), never to make a refactoring pass. How to update: run
//   build/tests/physics/test_golden
// read the new value from the failure message of each changed row, paste it into the row
// below, and say in the commit message which physics changed and why. The values hold for
// this build (x86-64, -O2/-O3 without -ffast-math, without FMA contraction, glibc's libm); another
// platform or compiler may need its own.
//
// A second test checks that a copied world steps exactly as its original, for the same rows,
// and a third that the plain paths of every stage (EngineSettings::plainPaths: the textbook
// algorithms of physics/src/stages/ without the accelerations of physics/src/fast/) give the
// same hashes, bit for bit, and on a few more scenes the same contacts at every step.

#include "physics_test_util.h"

#include <rigidlab/physics/world.h>

#include "test_main.h"

#include <QTest>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

using namespace rigidlab::physics;

namespace {

constexpr int kSteps = 600;

/// FNV-1a (64 bit) over the bit patterns of every body's position, angle, velocity and
/// angular velocity, in id order.
std::uint64_t stateHash(const World& world)
{
    std::uint64_t h = 14695981039346656037ull;
    auto add = [&h](double x) {
        const auto bits = std::bit_cast<std::uint64_t>(x);
        for (int i = 0; i < 8; ++i) {
            h ^= (bits >> (8 * i)) & 0xffu;
            h *= 1099511628211ull;
        }
    };
    for (const Body& b : world.bodies()) {
        add(b.position.x());
        add(b.position.y());
        add(b.angle);
        add(b.velocity.x());
        add(b.velocity.y());
        add(b.angularVelocity);
    }
    return h;
}

/// FNV-1a (64 bit) over every contact the world holds: its pair, its manifold's normal and
/// points (point, separation, feature id), its material and its impulses, in the world's order.
std::uint64_t contactsHash(const World& world)
{
    std::uint64_t h = 14695981039346656037ull;
    auto add = [&h](std::uint64_t bits) {
        for (int i = 0; i < 8; ++i) {
            h ^= (bits >> (8 * i)) & 0xffu;
            h *= 1099511628211ull;
        }
    };
    auto addDouble = [&add](double x) { add(std::bit_cast<std::uint64_t>(x)); };
    for (const Contact& c : world.contacts()) {
        add(static_cast<std::uint64_t>(c.a));
        add(static_cast<std::uint64_t>(c.b));
        add(static_cast<std::uint64_t>(c.manifold.pointCount));
        addDouble(c.manifold.normal.x());
        addDouble(c.manifold.normal.y());
        for (size_t i = 0; i < static_cast<size_t>(c.manifold.pointCount); ++i) {
            const ContactPoint& p = c.manifold.points[i];
            addDouble(p.point.x());
            addDouble(p.point.y());
            addDouble(p.separation);
            add(p.id);
            addDouble(c.normalImpulse[i]);
            addDouble(c.tangentImpulse[i]);
            addDouble(c.bounceImpulse[i]);
        }
        addDouble(c.restitution);
        addDouble(c.friction);
    }
    return h;
}

/// Contacts, springs and pin joints together: boxes and circles fall on a static ground, two
/// of them joined by a spring, one on a spring to the world; a chain of two pinned links
/// swings down into a tall box (contacts on jointed bodies), with drag.
///
///      o link1 link2                  circles
///      |=====|=====              o  o   o
///      pivot (4, 4)     [] [] boxes
///   ------------------------------------------ ground
World mixedScene(SolverKind solver, IntegratorKind integrator)
{
    WorldDef def;
    def.dt = 1.0 / 240.0;
    def.solver = solver;
    def.integrator = integrator;
    def.drag = 0.05;
    World world(def);
    BodyDef ground = rigidlab::test::boxBody(20.0, 1.0, Vec2(0.0, -0.5));
    ground.type = BodyType::Static;
    world.addBody(ground);
    for (int i = 0; i < 4; ++i)
        world.addBody(rigidlab::test::boxBody(0.8, 0.4, Vec2(0.1 * i, 0.3 + 0.6 * i), 0.05 * i));
    for (int i = 0; i < 3; ++i)
        world.addBody(rigidlab::test::circleBody(0.2 + 0.05 * i, Vec2(-1.5 + 0.3 * i, 1.0 + i),
                                                 Vec2(0.5, 0.0)));
    SpringDef between;
    between.a = 2;
    between.b = 5;
    between.stiffness = 30.0;
    between.damping = 0.5;
    between.restLength = 1.0;
    world.addSpring(between);
    SpringDef toWorld;
    toWorld.a = 6;
    toWorld.anchorA = Vec2(0.1, 0.0);
    toWorld.b = kWorld;
    toWorld.anchorB = Vec2(-2.0, 4.0);
    toWorld.stiffness = 20.0;
    toWorld.restLength = 0.5;
    world.addSpring(toWorld);
    const BodyId link1 = world.addBody(rigidlab::test::boxBody(1.0, 0.1, Vec2(4.5, 4.0)));
    const BodyId link2 = world.addBody(rigidlab::test::boxBody(1.0, 0.1, Vec2(5.5, 4.0)));
    world.addPinJoint({link1, Vec2(-0.5, 0.0), kWorld, Vec2(4.0, 4.0)});
    world.addPinJoint({link2, Vec2(-0.5, 0.0), link1, Vec2(0.5, 0.0)});
    world.addBody(rigidlab::test::boxBody(0.5, 2.6, Vec2(4.3, 1.3)));
    return world;
}

/// Contacts alone (symplectic Euler runs straight on the bodies here): a pile of boxes and
/// circles, a fast small circle that needs continuous collision, sleeping on.
World contactScene(SolverKind solver, IntegratorKind integrator)
{
    WorldDef def;
    def.dt = 1.0 / 120.0;
    def.solver = solver;
    def.integrator = integrator;
    def.drag = 0.02;
    def.sleep = true;
    World world(def);
    BodyDef ground = rigidlab::test::boxBody(12.0, 1.0, Vec2(0.0, -0.5));
    ground.type = BodyType::Static;
    world.addBody(ground);
    BodyDef wall = rigidlab::test::boxBody(0.5, 6.0, Vec2(4.0, 3.0));
    wall.type = BodyType::Static;
    world.addBody(wall);
    for (int i = 0; i < 4; ++i)
        world.addBody(rigidlab::test::boxBody(0.6, 0.6, Vec2(-1.0 + 0.05 * i, 0.3 + 0.7 * i)));
    for (int i = 0; i < 3; ++i)
        world.addBody(rigidlab::test::circleBody(0.25, Vec2(1.0 + 0.6 * i, 0.5 + 0.4 * i),
                                                 Vec2(-0.3 * i, 0.0)));
    world.addBody(rigidlab::test::circleBody(0.05, Vec2(-3.0, 1.0), Vec2(60.0, 0.0)));
    return world;
}

/// Boxes turned 45 degrees, without gravity, on a checkerboard whose diagonal neighbours are
/// 0.2 m apart: their bounding boxes overlap, so the broad phase hands their pairs to the SAT,
/// which finds them apart, step after step, until their drift and spin bring some together.
///
///      <>  <>  <>
///        <>  <>       diagonal neighbours: 1.7 m apart along x + y, the diamonds' corners
///      <>  <>  <>     reach 1.414 m of it
World diamondScene()
{
    WorldDef def;
    def.dt = 1.0 / 60.0;
    def.gravity = Vec2::Zero();
    World world(def);
    constexpr double kSpacing = 0.85; // [m]
    int k = 0;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
            if ((i + j) % 2 != 0)
                continue;
            BodyDef box =
                rigidlab::test::boxBody(1.0, 1.0, Vec2(kSpacing * i, kSpacing * j), 0.25 * M_PI);
            box.velocity = Vec2(0.3 * std::sin(1.0 * k), 0.3 * std::cos(1.7 * k));
            box.angularVelocity = 0.8 * std::sin(2.3 * k);
            world.addBody(box);
            ++k;
        }
    return world;
}

using SceneFn = World (*)(SolverKind, IntegratorKind);

} // namespace

Q_DECLARE_METATYPE(SceneFn)

class TestGolden : public QObject {
    Q_OBJECT

private slots:
    void goldenRun_data();
    void goldenRun();
    void copyStepsIdentically_data();
    void copyStepsIdentically();
    void narrowPhaseCacheChangesNothing();
    void plainPathsGiveTheGoldenHashes_data();
    void plainPathsGiveTheGoldenHashes();
    void plainPathsStepAsTheFastOnes_data();
    void plainPathsStepAsTheFastOnes();

private:
    void rows(bool withHashes);
    static void checkGoldenRun(bool plain);
};

void TestGolden::rows(bool withHashes)
{
    QTest::addColumn<SceneFn>("scene");
    QTest::addColumn<SolverKind>("solver");
    QTest::addColumn<IntegratorKind>("integrator");
    QTest::addColumn<quint64>("hash");
    struct Row {
        const char* name;
        SceneFn scene;
        SolverKind solver;
        IntegratorKind integrator;
        std::uint64_t hash;
    };
    constexpr SolverKind kPaper = SolverKind::PaperImpulse;
    constexpr SolverKind kSeq = SolverKind::SequentialImpulse;
    const Row table[] = {
        {"mixed-paper-euler", mixedScene, kPaper, IntegratorKind::Euler, 0x6f3e15ddc88bca3eull},
        {"mixed-paper-symplectic", mixedScene, kPaper, IntegratorKind::SymplecticEuler,
         0x4f24bf9971cbeb70ull},
        {"mixed-paper-verlet", mixedScene, kPaper, IntegratorKind::Verlet, 0x3a0c29c4e88074bcull},
        {"mixed-paper-rk4", mixedScene, kPaper, IntegratorKind::RK4, 0xbc88ef7149296f19ull},
        {"mixed-paper-dopri5", mixedScene, kPaper, IntegratorKind::DormandPrince,
         0xc2ce8cddb4757573ull},
        {"mixed-paper-midpoint", mixedScene, kPaper, IntegratorKind::ImplicitMidpoint,
         0xecb3bd9e8f1771f3ull},
        {"mixed-seq-euler", mixedScene, kSeq, IntegratorKind::Euler, 0x3deb43cf339294afull},
        {"mixed-seq-symplectic", mixedScene, kSeq, IntegratorKind::SymplecticEuler,
         0x19f16ea19a269c42ull},
        {"mixed-seq-verlet", mixedScene, kSeq, IntegratorKind::Verlet, 0x265856650d598fdbull},
        {"mixed-seq-rk4", mixedScene, kSeq, IntegratorKind::RK4, 0xec9a30cffd1ff49dull},
        {"mixed-seq-dopri5", mixedScene, kSeq, IntegratorKind::DormandPrince,
         0x1d6c9837bd9f9939ull},
        {"mixed-seq-midpoint", mixedScene, kSeq, IntegratorKind::ImplicitMidpoint,
         0xfe49bf5b1fe2653full},
        {"contact-paper-euler", contactScene, kPaper, IntegratorKind::Euler, 0xbf67f585236f1d21ull},
        {"contact-paper-symplectic", contactScene, kPaper, IntegratorKind::SymplecticEuler,
         0xaafd357cca118044ull},
        {"contact-paper-verlet", contactScene, kPaper, IntegratorKind::Verlet,
         0xc9e3f2b4a9f3d01bull},
        {"contact-paper-rk4", contactScene, kPaper, IntegratorKind::RK4, 0xce8d147fcf0095bfull},
        {"contact-paper-dopri5", contactScene, kPaper, IntegratorKind::DormandPrince,
         0xf46ffb409247ae81ull},
        {"contact-paper-midpoint", contactScene, kPaper, IntegratorKind::ImplicitMidpoint,
         0xd3421122b1cf3cd8ull},
        {"contact-seq-euler", contactScene, kSeq, IntegratorKind::Euler, 0x491bc3cb382d892aull},
        {"contact-seq-symplectic", contactScene, kSeq, IntegratorKind::SymplecticEuler,
         0x2e38e7696a186e97ull},
        {"contact-seq-verlet", contactScene, kSeq, IntegratorKind::Verlet, 0x847bc617a0ff247dull},
        {"contact-seq-rk4", contactScene, kSeq, IntegratorKind::RK4, 0x52651f3b87b4244aull},
        {"contact-seq-dopri5", contactScene, kSeq, IntegratorKind::DormandPrince,
         0xf8d73a8906eab8b0ull},
        {"contact-seq-midpoint", contactScene, kSeq, IntegratorKind::ImplicitMidpoint,
         0x19acf0084adffe1bull},
    };
    for (const Row& r : table)
        QTest::newRow(r.name) << r.scene << r.solver << r.integrator
                              << quint64{withHashes ? r.hash : 0u};
}

void TestGolden::goldenRun_data()
{
    rows(true);
}

// Every row must have had contacts and, in the mixed scene, kept its joints: a hash of a
// scene where nothing touched would pin less than it claims.
void TestGolden::checkGoldenRun(bool plain)
{
    QFETCH(SceneFn, scene);
    QFETCH(SolverKind, solver);
    QFETCH(IntegratorKind, integrator);
    QFETCH(quint64, hash);
    World world = scene(solver, integrator);
    world.engineSettings().plainPaths = plain;
    int contactSteps = 0;
    for (int i = 0; i < kSteps; ++i) {
        world.step();
        contactSteps += world.contacts().empty() ? 0 : 1;
    }
    QVERIFY(!world.divergence());
    QVERIFY(contactSteps > kSteps / 2);
    const std::uint64_t actual = stateHash(world);
    QVERIFY2(actual == hash, qPrintable(QStringLiteral("state hash 0x%1, stored 0x%2")
                                            .arg(actual, 16, 16, QLatin1Char('0'))
                                            .arg(hash, 16, 16, QLatin1Char('0'))));
}

void TestGolden::goldenRun()
{
    checkGoldenRun(false);
}

void TestGolden::copyStepsIdentically_data()
{
    rows(false);
}

// A world copied (and one assigned) halfway steps on bit-identically to the original: every
// state that steers a step (the adaptive integrator's proposed substep, warm-start impulses,
// sleep timers) travels with the copy, and the reused buffers do not matter.
void TestGolden::copyStepsIdentically()
{
    QFETCH(SceneFn, scene);
    QFETCH(SolverKind, solver);
    QFETCH(IntegratorKind, integrator);
    World original = scene(solver, integrator);
    for (int i = 0; i < kSteps / 2; ++i)
        original.step();
    World copied(original);
    World assigned = scene(SolverKind::PaperImpulse, IntegratorKind::Euler);
    assigned.step();
    assigned = original;
    QCOMPARE(stateHash(copied), stateHash(original));
    // What the last step did travels too (World's members are copied by = default).
    QCOMPARE(copied.profile().contacts, original.profile().contacts);
    QCOMPARE(copied.profile().pairs, original.profile().pairs);
    QCOMPARE(copied.integrator().substeps(), original.integrator().substeps());
    for (int i = 0; i < kSteps / 2; ++i) {
        original.step();
        copied.step();
        assigned.step();
    }
    QCOMPARE(stateHash(copied), stateHash(original));
    QCOMPARE(stateHash(assigned), stateHash(original));
    QCOMPARE(copied.stepCount(), original.stepCount());
    QCOMPARE(copied.evaluations(), original.evaluations());
}

// The narrow phase keeps work from step to step (each pair's last separating axis, tried
// first): it must not change a result. A world stepped on, and one stepped each time from a
// fresh copy (a copy starts with none of that kept work), stay bit-identical, in a scene
// where the SAT finds pairs apart and pairs in contact.
void TestGolden::narrowPhaseCacheChangesNothing()
{
    World kept = diamondScene();
    World fresh = diamondScene();
    int stepsWithPairsApart = 0, stepsWithContacts = 0;
    for (int i = 0; i < kSteps; ++i) {
        kept.step();
        World next(fresh);
        next.step();
        fresh = next;
        QCOMPARE(stateHash(fresh), stateHash(kept));
        QCOMPARE(fresh.profile().contacts, kept.profile().contacts);
        if (kept.profile().pairs > kept.profile().contacts)
            ++stepsWithPairsApart;
        if (kept.profile().contacts > 0)
            ++stepsWithContacts;
    }
    // The scene does what the test needs: pairs apart for most of the run, contacts too.
    QVERIFY2(stepsWithPairsApart > kSteps / 2, qPrintable(QString::number(stepsWithPairsApart)));
    QVERIFY2(stepsWithContacts > 0, "no contact in the run");
}

void TestGolden::plainPathsGiveTheGoldenHashes_data()
{
    rows(true);
}

// The same stored hashes with every stage on its plain path: the accelerations change no bit.
void TestGolden::plainPathsGiveTheGoldenHashes()
{
    checkGoldenRun(true);
}

namespace {

World softContactScene()
{
    return contactScene(SolverKind::SoftStep, IntegratorKind::SymplecticEuler);
}

World softMixedScene()
{
    // Springs and joints: the integrator carries the smooth motion, the substeps the contacts.
    return mixedScene(SolverKind::SoftStep, IntegratorKind::SymplecticEuler);
}

World sequentialDiamonds()
{
    return diamondScene();
}

World softDiamonds()
{
    World world = diamondScene();
    world.setSolver(SolverKind::SoftStep);
    return world;
}

using PlainSceneFn = World (*)();

} // namespace

Q_DECLARE_METATYPE(PlainSceneFn)

void TestGolden::plainPathsStepAsTheFastOnes_data()
{
    QTest::addColumn<PlainSceneFn>("scene");
    QTest::newRow("soft-contact") << PlainSceneFn{softContactScene};
    QTest::newRow("soft-mixed") << PlainSceneFn{softMixedScene};
    QTest::newRow("diamonds-seq") << PlainSceneFn{sequentialDiamonds};
    QTest::newRow("diamonds-soft") << PlainSceneFn{softDiamonds};
}

// The scenes the golden rows leave out (the soft step, its SIMD kernel and colouring; pairs
// the SAT finds apart step after step): the plain paths and the fast ones stay bit-identical
// at every step, and the fast run did use its accelerations.
void TestGolden::plainPathsStepAsTheFastOnes()
{
    QFETCH(PlainSceneFn, scene);
    World fast = scene();
    World plain = scene();
    plain.engineSettings().plainPaths = true;
    int contactSteps = 0;
    for (int i = 0; i < kSteps; ++i) {
        fast.step();
        plain.step();
        QCOMPARE(stateHash(plain), stateHash(fast));
        QCOMPARE(plain.profile().contacts, fast.profile().contacts);
        // The contacts themselves: the fast path writes this step's over last step's in
        // place (fast/contact_rewrite.h), the plain path into fresh arrays.
        QCOMPARE(contactsHash(plain), contactsHash(fast));
        QCOMPARE(plain.profile().reusedFaces, 0);
        contactSteps += fast.contacts().empty() ? 0 : 1;
    }
    QVERIFY(!fast.divergence());
    QVERIFY2(contactSteps > 0, "no contact in the run");
}

RIGIDLAB_TEST_GUILESS_MAIN(TestGolden)
#include "test_golden.moc"
