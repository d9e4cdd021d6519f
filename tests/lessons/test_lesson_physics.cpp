// SPDX-License-Identifier: GPL-3.0-or-later
// What lessons measure and judge, on real runs (the physics the lessons' texts claim:
// test_lesson_physics_claims.cpp; their wording: test_lesson_physics_texts.cpp).

#include "test_lesson_physics.h"
#include "near.h"
#include "test_lesson.h"
#include "test_main.h"

#include "edit/scene_edits.h"
#include "format/divergence_message.h"

#include <QRegularExpression>

#include "question_kinds.h"
#include <algorithm>
#include <cmath>
#include <set>

using namespace rigidlab;
using namespace rigidlab::test;

void TestLesson::judgeApexRightAndWrong()
{
    ShippedStep drop("restitution", 0);
    const lessons::LessonStep& step = drop.step;
    const lessons::Question& q = step.questions.at(0); // second bounce of the e = 0.8 ball
    StepRun& run = drop.run;

    // Before the run: not measured yet, and the student is told what to wait for.
    lessons::Verdict early = lessons::judge(q, 0.41, run.measurements[0], step.scene);
    QVERIFY(!early.measured);
    QVERIFY(!early.right);
    QCOMPARE(early.message,
             QStringLiteral("Run the simulation past the top of the second bounce first."));

    run.run(2.0);
    const double expected = std::pow(0.8, 4); // e^4 of the 1 m drop
    lessons::Verdict right = lessons::judge(q, 0.41, run.measurements[0], step.scene);
    QVERIFY(right.measured);
    QVERIFY(right.right);
    RL_VERIFY_NEAR(right.value, expected, 1e-4, 0);
    QCOMPARE(right.message,
             QStringLiteral("Right: the simulation measured 0.41\u00a0m (you said 0.41\u00a0m)."));
    lessons::Verdict wrong = lessons::judge(q, 0.5, run.measurements[0], step.scene);
    QVERIFY(wrong.measured);
    QVERIFY(!wrong.right);
    QCOMPARE(
        wrong.message,
        QStringLiteral("Not quite: the simulation measured 0.41\u00a0m (you said 0.5\u00a0m)."));
    // The edge of the tolerance (3 %).
    QVERIFY(lessons::judge(q, expected * 1.029, run.measurements[0], step.scene).right);
    QVERIFY(!lessons::judge(q, expected * 1.031, run.measurements[0], step.scene).right);
    QVERIFY(!lessons::judge(q, std::nan(""), run.measurements[0], step.scene).right);
}

void TestLesson::verdictsOfARunNotYetShownSayWhatItWillMeasure()
{
    // A question that holds the run back is judged against the same run done without a
    // window: at t = 0 in the window, the verdict says what the run will measure.
    const lessons::Lesson lesson = shippedLesson("restitution");
    const lessons::LessonStep& step = stepOf(lesson, 0);
    const lessons::Question& q = step.questions.at(0);
    const std::optional<double> ahead = lessons::measureAhead(step, measuredOf(q).measure);
    QVERIFY(ahead);
    QCOMPARE(lessons::judgeAttempt(q, 0.41, ahead, 1, true).message,
             QStringLiteral("Right: when it runs, the simulation will measure 0.41\u00a0m (you "
                            "said 0.41\u00a0m)."));
    QCOMPARE(lessons::judgeAttempt(q, 0.5, ahead, 2, true).message,
             QStringLiteral("Not quite: when it runs, the simulation will measure 0.41\u00a0m "
                            "(you said 0.5\u00a0m)."));
    QCOMPARE(lessons::showAnswer(q, ahead, true).message,
             QStringLiteral("When it runs, the simulation will measure 0.41\u00a0m."));
    // Measured by the window's own run: in the past tense.
    QCOMPARE(lessons::showAnswer(q, ahead, false).message,
             QStringLiteral("The simulation measured 0.41\u00a0m."));
}

void TestLesson::judgeTimedValue()
{
    ShippedStep spring("energy_drift", 0);
    const lessons::LessonStep& step = spring.step;
    const lessons::Question& q = step.questions.at(0); // Euler's drift at t = 5 s
    StepRun& run = spring.run;
    run.run(4.99);
    lessons::Verdict early = lessons::judge(q, 65, run.measurements[0], step.scene);
    QVERIFY(!early.measured);
    QCOMPARE(early.message, QStringLiteral("Run the simulation until t = 5 s first."));
    run.run(0.01);
    // E(t) = E0 (1 + (wh)^2)^(t/h) for explicit Euler on the oscillator: 64.8 % at 5 s.
    const double expected = (std::pow(1.0 + 10.0 * 0.01 * 0.01, 500) - 1.0) * 100.0;
    lessons::Verdict v = lessons::judge(q, 64.8, run.measurements[0], step.scene);
    QVERIFY(v.measured);
    QVERIFY(v.right);
    QVERIFY2(std::abs(v.value - expected) < 1e-6, qPrintable(QString::number(v.value)));
    QCOMPARE(v.message,
             QStringLiteral("Right: the simulation measured 64.8\u00a0% (you said 64.8\u00a0%)."));
    // The value stays what it was at 5 s while the run goes on.
    run.run(1.0);
    QCOMPARE(*run.measurements[0].value(measuredOf(q).measure, step.scene), v.value);
    QVERIFY(!lessons::judge(q, 70, run.measurements[0], step.scene).right);
}

void TestLesson::judgeMessages_data()
{
    QTest::addColumn<double>("value");
    QTest::addColumn<double>("answer");
    QTest::addColumn<QString>("unit");
    QTest::addColumn<double>("tolerance");
    QTest::addColumn<double>("absolute");
    QTest::addColumn<bool>("right");
    QTest::addColumn<QString>("message");

    QTest::newRow("near-zero-absolute")
        << 1e-17 << 0.01 << "m/s" << 0.02 << 0.02 << true
        << "Right: the simulation measured 0\u00a0m/\u2060s (you said 0.01\u00a0m/\u2060s).";
    QTest::newRow("near-zero-relative-only")
        << 1e-17 << 0.01 << "m/s" << 0.02 << 0.0 << false
        << "Not quite: the simulation measured 0\u00a0m/\u2060s (you said 0.01\u00a0m/\u2060s).";
    QTest::newRow("negative")
        << -1.0 << -1.01 << "m/s" << 0.02 << 0.0 << true
        << "Right: the simulation measured -1\u00a0m/\u2060s (you said -1.01\u00a0m/\u2060s).";
    QTest::newRow("sign-wrong")
        << -1.0 << 1.0 << "m/s" << 0.02 << 0.0 << false
        << "Not quite: the simulation measured -1\u00a0m/\u2060s (you said 1\u00a0m/\u2060s).";
    QTest::newRow("no-unit") << 2.0772 << 2.08 << "" << 0.03 << 0.0 << true
                             << "Right: the simulation measured 2.08 (you said 2.08).";
    QTest::newRow("tight-tolerance")
        << 1.333069 << 1.3331 << "kg·m/s" << 0.0001 << 0.0 << true
        << "Right: the simulation measured 1.3331\u00a0kg·m/\u2060s (you said "
           "1.3331\u00a0kg·m/\u2060s).";
}

void TestLesson::judgeWaitsInWholeSentences()
{
    // Each apex a question may wait for has a sentence of its own (a translator may reorder
    // it), not an English ordinal put into one.
    lessons::Question q;
    measuredOf(q).measure.kind = lessons::Measure::Kind::Apex;
    measuredOf(q).measure.body = QStringLiteral("ball");
    const std::pair<int, const char*> cases[] = {
        {1, "Run the simulation past the top of the first bounce first."},
        {3, "Run the simulation past the top of the third bounce first."},
        {12, "Run the simulation past the top of bounce number 12 first."},
    };
    for (const auto& [n, message] : cases) {
        measuredOf(q).measure.n = n;
        const lessons::Verdict v = lessons::judgeAttempt(q, 1.0, std::nullopt, 1);
        QVERIFY(!v.measured && !v.right);
        QCOMPARE(v.message, QString::fromUtf8(message));
        QCOMPARE(lessons::showAnswer(q, std::nullopt).message, QString::fromUtf8(message));
    }
}

void TestLesson::judgeMessages()
{
    QFETCH(double, value);
    QFETCH(double, answer);
    QFETCH(QString, unit);
    QFETCH(double, tolerance);
    QFETCH(double, absolute);
    QFETCH(bool, right);
    QFETCH(QString, message);

    // A weightless ball moving at `value` m/s: its velocity-x, read at t = 0.
    lessons::Scene scene;
    physics::BodyDef ball;
    ball.name = "ball";
    ball.shape = physics::makeCircleShape(0.1);
    ball.velocity = physics::Vec2(value, 0);
    scene.bodies.push_back(ball);
    scene.world.gravity = physics::Vec2::Zero();
    physics::World world = lessons::buildWorld(scene);
    world.updateDiagnostics();
    lessons::Question q;
    measuredOf(q).measure.kind = lessons::Measure::Kind::VelocityX;
    measuredOf(q).measure.body = QStringLiteral("ball");
    measuredOf(q).unit = unit;
    measuredOf(q).tolerance = tolerance;
    measuredOf(q).absoluteTolerance = absolute;
    lessons::Measurements m;
    m.reset(world, {measuredOf(q).measure});
    const lessons::Verdict v = lessons::judge(q, answer, m, scene);
    QVERIFY(v.measured);
    QCOMPARE(v.right, right);
    QCOMPARE(v.message, message);
}

void TestLesson::judgeAttemptGivesHintThenValue()
{
    lessons::Question q;
    measuredOf(q).unit = QStringLiteral("m/s");
    measuredOf(q).tolerance = 0.02;
    q.hint = QStringLiteral("Momentum is conserved.");
    const double value = -1.0;
    // A wrong first try reads the hint and not the value; the second gives it.
    const lessons::Verdict first = lessons::judgeAttempt(q, 1.0, value, 1);
    QVERIFY(first.measured && !first.right && !first.shown);
    QCOMPARE(first.message,
             QStringLiteral("Not quite (you said 1\u00a0m/\u2060s). Hint: Momentum is "
                            "conserved."));
    QVERIFY(!first.message.contains(QStringLiteral("-1")));
    const lessons::Verdict second = lessons::judgeAttempt(q, 2.0, value, 2);
    QVERIFY(!second.right && second.shown);
    QCOMPARE(
        second.message,
        QStringLiteral(
            "Not quite: the simulation measured -1\u00a0m/\u2060s (you said 2\u00a0m/\u2060s)."));
    // A right first try gives it at once.
    const lessons::Verdict right = lessons::judgeAttempt(q, -1.01, value, 1);
    QVERIFY(right.right && right.shown);
    QVERIFY(right.message.startsWith(
        QStringLiteral("Right: the simulation measured -1\u00a0m/\u2060s")));
    // Without a hint the student is still asked to try again, without the value.
    q.hint.clear();
    const lessons::Verdict bare = lessons::judgeAttempt(q, 1.0, value, 1);
    QCOMPARE(bare.message, QStringLiteral("Not quite (you said 1\u00a0m/\u2060s). Try once more."));
    QVERIFY(!bare.shown);
    // Not measured yet: no try is spent, and Show me says what to do first.
    measuredOf(q).measure.time = 1.5;
    measuredOf(q).measure.kind = lessons::Measure::Kind::VelocityX;
    const lessons::Verdict early = lessons::judgeAttempt(q, 1.0, std::nullopt, 1);
    QVERIFY(!early.measured && !early.shown);
    QCOMPARE(early.message, QStringLiteral("Run the simulation until t = 1.5 s first."));
    QCOMPARE(lessons::showAnswer(q, std::nullopt).message, early.message);
    const lessons::Verdict shown = lessons::showAnswer(q, value);
    QVERIFY(shown.shown && !shown.right);
    QCOMPARE(shown.message, QStringLiteral("The simulation measured -1\u00a0m/\u2060s."));
}

void TestLesson::rewindForgetsLaterEvents()
{
    ShippedStep drop("restitution", 0);
    const lessons::LessonStep& step = drop.step;
    const physics::BodyId ball = bodyId(step.scene, "e08");
    StepRun& run = drop.run;
    run.run(1.0);
    const physics::World atOne = run.worlds[0];
    const std::size_t apexesAtOne = run.measurements[0].apexes(ball).size();
    const std::size_t collisionsAtOne = run.measurements[0].collisions().size();
    run.run(1.5);
    const std::vector<lessons::ApexEvent> straight = run.measurements[0].apexes(ball);
    const std::size_t collisionsStraight = run.measurements[0].collisions().size();
    QVERIFY(straight.size() > apexesAtOne);

    // Back to t = 1 s, then forward again: the same events, once each.
    run.worlds[0] = atOne;
    run.measurements[0].rewind(run.worlds[0]);
    QCOMPARE(run.measurements[0].apexes(ball).size(), apexesAtOne);
    QCOMPARE(run.measurements[0].collisions().size(), collisionsAtOne);
    run.run(1.5);
    const std::vector<lessons::ApexEvent>& replayed = run.measurements[0].apexes(ball);
    QCOMPARE(replayed.size(), straight.size());
    for (std::size_t i = 0; i < straight.size(); ++i) {
        QCOMPARE(replayed[i].t, straight[i].t);
        QCOMPARE(replayed[i].y, straight[i].y);
        QCOMPARE(replayed[i].bounceY, straight[i].bounceY);
    }
    QCOMPARE(run.measurements[0].collisions().size(), collisionsStraight);
    QCOMPARE(run.measurements[0].bounces(ball).size(), straight.size());
}

void TestLesson::measurementsKeepTheFirstEvents()
{
    // Two elastic balls in a vertical tube without gravity, 20 m/s apart: a collision every
    // few hundredths of a second, and a bounce of the lower ball on the floor as often. The
    // logs stop at their caps, keeping the first events, and the run goes on.
    lessons::Scene scene;
    scene.world.gravity = physics::Vec2::Zero();
    scene.world.dt = 0.005;
    scene.world.restitution = 1.0;
    scene.world.friction = 0.0;
    const auto wall = [&](double y) {
        physics::BodyDef w;
        w.type = physics::BodyType::Static;
        w.shape = physics::makePolygonShape(physics::makeBox(1.0, 0.2));
        w.position = physics::Vec2(0, y);
        scene.bodies.push_back(w);
    };
    wall(-0.6);
    wall(0.6);
    const auto ball = [&](const char* name, double y, double vy) {
        physics::BodyDef b;
        b.name = name;
        b.shape = physics::makeCircleShape(0.1);
        b.position = physics::Vec2(0, y);
        b.velocity = physics::Vec2(0, vy);
        scene.bodies.push_back(b);
    };
    ball("low", -0.2, 10.0);
    ball("high", 0.2, -10.0);
    physics::World world = lessons::buildWorld(scene);
    lessons::Measurements m;
    m.reset(world, {});
    const physics::BodyId low = 2;
    std::optional<lessons::CollisionEvent> first;
    for (int i = 0; i < 24000; ++i) {
        world.step();
        m.observe(world);
        if (!first && !m.collisions().empty())
            first = m.collisions().front();
    }
    QVERIFY(first);
    QCOMPARE(m.collisions().size(), lessons::Measurements::kMaxCollisions);
    QCOMPARE(m.collisions().front().t, first->t);
    QCOMPARE(m.bounces(low).size(), lessons::Measurements::kMaxBouncesPerBody);
    QVERIFY(m.apexes(low).size() <= lessons::Measurements::kMaxBouncesPerBody);
    QVERIFY(m.apexes(low).size() >= lessons::Measurements::kMaxBouncesPerBody - 1);
    QVERIFY(world.time() > 100.0);
}

void TestLesson::measurementsFindEveryNewTouch()
{
    // Balls and boxes poured into a box, on each of the solvers: pairs touch, part and touch
    // again, many in one step. Every step's new collisions are the pairs a positive normal
    // impulse pushed apart, between bodies that count (not both static, not kinematic), that
    // were not pushed apart in the step before, in the contacts' order: found here by a
    // std::set of the step before's pairs, against Measurements' walk along them.
    for (const physics::SolverKind solver : physics::kAllSolvers) {
        lessons::Scene scene;
        scene.world.solver = solver;
        scene.world.dt = 1.0 / 120;
        scene.world.restitution = 0.6;
        const auto add = [&](physics::BodyType type, physics::Shape shape, double x, double y) {
            physics::BodyDef b;
            b.type = type;
            b.shape = std::move(shape);
            b.position = physics::Vec2(x, y);
            scene.bodies.push_back(b);
        };
        add(physics::BodyType::Static, physics::makePolygonShape(physics::makeBox(1.2, 0.1)), 0,
            -0.1);
        add(physics::BodyType::Static, physics::makePolygonShape(physics::makeBox(0.1, 1.0)), -1.1,
            0.9);
        add(physics::BodyType::Static, physics::makePolygonShape(physics::makeBox(0.1, 1.0)), 1.1,
            0.9);
        for (int i = 0; i < 24; ++i) {
            const double x = -0.8 + 0.16 * (i % 11) + 0.03 * (i / 11);
            const double y = 0.3 + 0.25 * (i / 11) + 0.02 * (i % 3);
            add(physics::BodyType::Dynamic,
                i % 2 ? physics::makeCircleShape(0.07)
                      : physics::makePolygonShape(physics::makeBox(0.06, 0.05)),
                x, y);
        }
        physics::World world = lessons::buildWorld(scene);
        lessons::Measurements m;
        m.reset(world, {});
        using Pair = std::pair<physics::BodyId, physics::BodyId>;
        const auto pushed = [](const physics::Contact& c) {
            return c.normalImpulse[0] > 0 || c.normalImpulse[1] > 0;
        };
        std::set<Pair> before;
        for (const physics::Contact& c : world.contacts())
            if (pushed(c))
                before.insert({c.a, c.b});
        std::vector<Pair> expected;
        std::size_t stepsWithTwo = 0;
        for (int step = 0; step < 300; ++step) {
            world.step();
            m.observe(world);
            std::set<Pair> now;
            std::size_t fresh = 0;
            for (const physics::Contact& c : world.contacts()) {
                if (!pushed(c))
                    continue;
                now.insert({c.a, c.b});
                const physics::Body& a = world.body(c.a);
                const physics::Body& b = world.body(c.b);
                if (a.type == physics::BodyType::Kinematic ||
                    b.type == physics::BodyType::Kinematic || (!a.isDynamic() && !b.isDynamic()) ||
                    before.count({c.a, c.b}))
                    continue;
                expected.emplace_back(c.a, c.b);
                ++fresh;
            }
            stepsWithTwo += fresh >= 2;
            before = std::move(now);
        }
        const auto& found = m.collisions();
        QVERIFY2(expected.size() >= 20 && stepsWithTwo >= 3,
                 qPrintable(QStringLiteral("%1 collisions, %2 steps with two or more")
                                .arg(expected.size())
                                .arg(stepsWithTwo)));
        QCOMPARE(found.size(), std::min(expected.size(), lessons::Measurements::kMaxCollisions));
        for (std::size_t i = 0; i < found.size(); ++i) {
            QCOMPARE(found[i].a, expected[i].first);
            QCOMPARE(found[i].b, expected[i].second);
        }
    }
}

void TestLesson::collisionPredictionsOfOffCentreHit()
{
    ShippedStep offCentre("restitution", 3);
    const lessons::LessonStep& step = offCentre.step;
    StepRun& run = offCentre.run;
    run.run(1.0);
    const std::vector<lessons::CollisionEvent>& hits = run.measurements[0].collisions();
    QCOMPARE(hits.size(), std::size_t{1});
    const lessons::CollisionEvent& hit = hits[0];
    const physics::BodyId rod = bodyId(step.scene, "rod");
    QCOMPARE(hit.a, rod);
    // The textbook numbers of the step's text: I = m (a^2 + b^2) / 12, r = 0.8 m.
    const double inertia = (4.0 + 0.01) / 12.0;
    const double jFull = 2 * 3 / (1 / 0.25 + 1 + 0.64 / inertia);
    const double jWithout = 2 * 3 / (1 / 0.25 + 1.0);
    RL_VERIFY_NEAR(hit.predictedFull[0], 0.8 * jFull / inertia, 1e-3, 0);
    RL_VERIFY_NEAR(hit.predictedWithoutRotation[0], 0.8 * jWithout / inertia, 1e-3, 0);
    // The engine does what the full formula predicts.
    RL_VERIFY_NEAR(hit.angularAfter[0], hit.predictedFull[0], 1e-3, 0);
    QCOMPARE(hit.angularBefore[0], 0.0);
    RL_VERIFY_NEAR(hit.velocityBefore[1].y(), 3.0, 1e-9, 0);
    RL_VERIFY_NEAR(hit.velocityAfter[0].y(), jFull / 1.0, 1e-3, 0);
    RL_VERIFY_NEAR(hit.velocityAfter[1].y(), (3.0 - jFull / 0.25), 1e-3, 0);
    // Kinetic energy is kept by the full formula (e = 1).
    const physics::World& w = run.worlds[0];
    RL_VERIFY_NEAR(w.diagnostics().kinetic, 0.5 * 0.25 * 9.0, 1e-6, 0);
}

void TestLesson::shippedQuestionsHaveTheirTextbookAnswers_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::addColumn<int>("step");
    QTest::addColumn<int>("question");
    QTest::addColumn<double>("answer"); // what a student who follows the text works out

    const double e5 = std::pow(1.001, 500) - 1;
    QTest::newRow("euler-drift-h-0.01") << "energy_drift" << 0 << 0 << e5 * 100;
    QTest::newRow("euler-drift-h-0.001")
        << "energy_drift" << 3 << 0 << (std::pow(1.00001, 5000) - 1) * 100;
    QTest::newRow("second-bounce-e-0.8") << "restitution" << 0 << 0 << std::pow(0.8, 4);
    QTest::newRow("third-bounce-e-0.5") << "restitution" << 0 << 1 << std::pow(0.5, 6);
    QTest::newRow("heavy-ball") << "restitution" << 1 << 0 << 2.0;
    QTest::newRow("light-ball") << "restitution" << 1 << 1 << -1.0;
    QTest::newRow("light-ball-e-0.5") << "restitution" << 2 << 0 << 0.0;
    // Set to e = 0 by the student, the balls stick: 3 kg m/s shared by 3 kg.
    QTest::newRow("stuck-together-e-0") << "restitution" << 2 << 1 << 1.0;
    const double inertia = (4.0 + 0.01) / 12.0;
    QTest::newRow("rod-spin") << "restitution" << 3 << 0
                              << 0.8 * (6.0 / (4 + 1 + 0.64 / inertia)) / inertia;
    // The cue ball: 0.17 kg at 4 m/s.
    QTest::newRow("break-px") << "billiards_momentum" << 0 << 0 << 0.17 * 4;
    QTest::newRow("drag-before-break")
        << "billiards_momentum" << 1 << 0 << 0.17 * 4 * std::exp(-0.2 * 0.1);
    QTest::newRow("drag-after-break")
        << "billiards_momentum" << 1 << 1 << 0.17 * 4 * std::exp(-0.2 * 0.35);
    // Explicit Euler on a spring: (1 + (w dt)^2)^n with (w dt)^2 = 100 * 0.005^2, n = 200.
    QTest::newRow("stiff-euler-growth")
        << "stiff_springs" << 0 << 0 << (std::pow(1.0025, 200) - 1) * 100;
    // The soft step keeps the pyramid standing: the top box (row 40 of 1 m boxes) stays where
    // it started, its centre 39 m + half a box above the floor.
    QTest::newRow("soft-step-pyramid-top") << "stacks" << 3 << 0 << 39.0 + 0.5;
}

void TestLesson::stiffSpringsDivergeWhereTheoryPredicts()
{
    // The stiff-springs lesson raises k at dt = 5 ms. Symplectic Euler and Verlet are stable
    // on a spring while w dt < 2, RK4 while w dt < 2 sqrt 2, implicit midpoint always. Each
    // step's worlds (in its compare order) must diverge exactly where its text says.
    struct Expect {
        std::size_t step;
        std::vector<bool> diverges; // implicit-midpoint, symplectic-euler, verlet, rk4
    };
    const std::vector<Expect> expected{{1, {false, false, false, false}},
                                       {2, {false, true, true, false}},
                                       {3, {false, true, true, true}}};
    for (const Expect& e : expected) {
        ShippedStep stiff("stiff_springs", e.step);
        const lessons::LessonStep& s = stiff.step;
        std::vector<physics::World>& worlds = stiff.run.worlds;
        QCOMPARE(worlds.size(), e.diverges.size());
        const double k = s.scene.springs.at(0).stiffness;
        const double wdt = std::sqrt(k / worlds[0].bodies()[0].mass) * worlds[0].def().dt;
        for (std::size_t i = 0; i < worlds.size(); ++i) {
            for (int n = 0; n < 400 && !worlds[i].divergence(); ++n) // 2 s
                worlds[i].step();
            QVERIFY2(worlds[i].divergence().has_value() == e.diverges[i],
                     qPrintable(QStringLiteral("step %1 (w dt = %2), world %3: %4")
                                    .arg(e.step)
                                    .arg(wdt)
                                    .arg(s.compare->label(static_cast<int>(i)))
                                    .arg(worlds[i].divergence() ? "diverged" : "stable")));
        }
    }
}

void TestLesson::shippedQuestionsHaveTheirTextbookAnswers()
{
    QFETCH(QString, lesson);
    QFETCH(int, step);
    QFETCH(int, question);
    QFETCH(double, answer);
    const lessons::Lesson l = shippedLesson(qPrintable(lesson));
    const lessons::LessonStep& shipped = stepOf(l, static_cast<std::size_t>(step));
    const lessons::Question& q = shipped.questions.at(static_cast<std::size_t>(question));
    // The run the question asks for: its "set" on top of the step's settings.
    const lessons::LessonStep s = lessons::askedStep(shipped, q);
    StepRun run(s);
    // Long enough for every question of the step: its export time covers them.
    run.run(s.exportTime);
    const lessons::Verdict v = lessons::judge(q, answer, run.measurements[0], s.scene);
    QVERIFY2(v.measured, qPrintable(v.message));
    QVERIFY2(v.right, qPrintable(v.message));
    // Run without a window from the start, the measure comes out the same: bit for bit, as
    // the physics is deterministic.
    const std::optional<double> ahead = lessons::measureAhead(s, measuredOf(q).measure);
    QVERIFY(ahead);
    QCOMPARE(*ahead, v.value);
    // The hint helps without giving the value away.
    QVERIFY(!q.hint.isEmpty());
    for (const QString& written : {QString::number(answer, 'f', 2), QString::number(answer, 'f', 1),
                                   QString::number(v.value, 'f', 2)})
        if (written.contains(u'.') && written != QStringLiteral("0.0"))
            QVERIFY2(!q.hint.contains(written),
                     qPrintable(written + QStringLiteral(": ") + q.hint));
}

RIGIDLAB_TEST_GUILESS_MAIN(TestLesson)
