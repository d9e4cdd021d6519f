// SPDX-License-Identifier: GPL-3.0-or-later
// What lessons measure and judge, on real runs; and the physics the shipped lessons claim in
// their texts, checked on the lessons' own scenes and settings.

#include "test_lesson.h"
#include "test_main.h"

#include "edit/scene_edits.h"
#include "format/divergence_message.h"

#include <QRegularExpression>

#include <algorithm>
#include <cmath>

using namespace rigidlab;
using namespace rigidlab::test;

namespace {

const lessons::LessonStep& stepOf(const lessons::Lesson& lesson, std::size_t i)
{
    return lesson.steps.at(i);
}

physics::BodyId bodyId(const lessons::Scene& scene, const char* id)
{
    const auto index = scene.bodyIndex(QString::fromLatin1(id));
    Q_ASSERT(index);
    return *index;
}

/// The relative energy drift of a world since `e0` [%], as the lessons measure it.
double driftPercent(const physics::World& w, double e0)
{
    return (w.diagnostics().total - e0) / std::abs(e0) * 100.0;
}

} // namespace

void TestLesson::judgeApexRightAndWrong()
{
    const lessons::Lesson lesson = shippedLesson("restitution");
    const lessons::LessonStep& step = stepOf(lesson, 0);
    const lessons::Question& q = step.questions.at(0); // second bounce of the e = 0.8 ball
    StepRun run(step);

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
    QVERIFY(std::abs(right.value - expected) < 1e-4);
    QCOMPARE(right.message,
             QStringLiteral("Right: the simulation measured 0.41 m (you said 0.41 m)."));
    lessons::Verdict wrong = lessons::judge(q, 0.5, run.measurements[0], step.scene);
    QVERIFY(wrong.measured);
    QVERIFY(!wrong.right);
    QCOMPARE(wrong.message,
             QStringLiteral("Not quite: the simulation measured 0.41 m (you said 0.5 m)."));
    // The edge of the tolerance (3 %).
    QVERIFY(lessons::judge(q, expected * 1.029, run.measurements[0], step.scene).right);
    QVERIFY(!lessons::judge(q, expected * 1.031, run.measurements[0], step.scene).right);
    QVERIFY(!lessons::judge(q, std::nan(""), run.measurements[0], step.scene).right);
}

void TestLesson::judgeTimedValue()
{
    const lessons::Lesson lesson = shippedLesson("energy_drift");
    const lessons::LessonStep& step = stepOf(lesson, 0);
    const lessons::Question& q = step.questions.at(0); // Euler's drift at t = 5 s
    StepRun run(step);
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
    QCOMPARE(v.message, QStringLiteral("Right: the simulation measured 64.8 % (you said 64.8 %)."));
    // The value stays what it was at 5 s while the run goes on.
    run.run(1.0);
    QCOMPARE(*run.measurements[0].value(q.measure, step.scene), v.value);
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
        << "Right: the simulation measured 0 m/s (you said 0.01 m/s).";
    QTest::newRow("near-zero-relative-only")
        << 1e-17 << 0.01 << "m/s" << 0.02 << 0.0 << false
        << "Not quite: the simulation measured 0 m/s (you said 0.01 m/s).";
    QTest::newRow("negative") << -1.0 << -1.01 << "m/s" << 0.02 << 0.0 << true
                              << "Right: the simulation measured -1 m/s (you said -1.01 m/s).";
    QTest::newRow("sign-wrong") << -1.0 << 1.0 << "m/s" << 0.02 << 0.0 << false
                                << "Not quite: the simulation measured -1 m/s (you said 1 m/s).";
    QTest::newRow("no-unit") << 2.0772 << 2.08 << "" << 0.03 << 0.0 << true
                             << "Right: the simulation measured 2.08 (you said 2.08).";
    QTest::newRow("tight-tolerance") << 1.333069 << 1.3331 << "kg·m/s" << 0.0001 << 0.0 << true
                                     << "Right: the simulation measured 1.3331 kg·m/s (you said "
                                        "1.3331 kg·m/s).";
}

void TestLesson::judgeWaitsInWholeSentences()
{
    // Each apex a question may wait for has a sentence of its own (a translator may reorder
    // it), not an English ordinal put into one.
    lessons::Question q;
    q.measure.kind = lessons::Measure::Kind::Apex;
    q.measure.body = QStringLiteral("ball");
    const std::pair<int, const char*> cases[] = {
        {1, "Run the simulation past the top of the first bounce first."},
        {3, "Run the simulation past the top of the third bounce first."},
        {12, "Run the simulation past the top of bounce number 12 first."},
    };
    for (const auto& [n, message] : cases) {
        q.measure.n = n;
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
    q.measure.kind = lessons::Measure::Kind::VelocityX;
    q.measure.body = QStringLiteral("ball");
    q.unit = unit;
    q.tolerance = tolerance;
    q.absoluteTolerance = absolute;
    lessons::Measurements m;
    m.reset(world, {q.measure});
    const lessons::Verdict v = lessons::judge(q, answer, m, scene);
    QVERIFY(v.measured);
    QCOMPARE(v.right, right);
    QCOMPARE(v.message, message);
}

void TestLesson::judgeAttemptGivesHintThenValue()
{
    lessons::Question q;
    q.unit = QStringLiteral("m/s");
    q.tolerance = 0.02;
    q.hint = QStringLiteral("Momentum is conserved.");
    const double value = -1.0;
    // A wrong first try reads the hint and not the value; the second gives it.
    const lessons::Verdict first = lessons::judgeAttempt(q, 1.0, value, 1);
    QVERIFY(first.measured && !first.right && !first.shown);
    QCOMPARE(first.message, QStringLiteral("Not quite (you said 1 m/s). Hint: Momentum is "
                                           "conserved."));
    QVERIFY(!first.message.contains(QStringLiteral("-1")));
    const lessons::Verdict second = lessons::judgeAttempt(q, 2.0, value, 2);
    QVERIFY(!second.right && second.shown);
    QCOMPARE(second.message,
             QStringLiteral("Not quite: the simulation measured -1 m/s (you said 2 m/s)."));
    // A right first try gives it at once.
    const lessons::Verdict right = lessons::judgeAttempt(q, -1.01, value, 1);
    QVERIFY(right.right && right.shown);
    QVERIFY(right.message.startsWith(QStringLiteral("Right: the simulation measured -1 m/s")));
    // Without a hint the student is still asked to try again, without the value.
    q.hint.clear();
    const lessons::Verdict bare = lessons::judgeAttempt(q, 1.0, value, 1);
    QCOMPARE(bare.message, QStringLiteral("Not quite (you said 1 m/s). Try once more."));
    QVERIFY(!bare.shown);
    // Not measured yet: no try is spent, and Show me says what to do first.
    q.measure.time = 1.5;
    q.measure.kind = lessons::Measure::Kind::VelocityX;
    const lessons::Verdict early = lessons::judgeAttempt(q, 1.0, std::nullopt, 1);
    QVERIFY(!early.measured && !early.shown);
    QCOMPARE(early.message, QStringLiteral("Run the simulation until t = 1.5 s first."));
    QCOMPARE(lessons::showAnswer(q, std::nullopt).message, early.message);
    const lessons::Verdict shown = lessons::showAnswer(q, value);
    QVERIFY(shown.shown && !shown.right);
    QCOMPARE(shown.message, QStringLiteral("The simulation measured -1 m/s."));
}

void TestLesson::rewindForgetsLaterEvents()
{
    const lessons::Lesson lesson = shippedLesson("restitution");
    const lessons::LessonStep& step = stepOf(lesson, 0);
    const physics::BodyId ball = bodyId(step.scene, "e08");
    StepRun run(step);
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

void TestLesson::collisionPredictionsOfOffCentreHit()
{
    const lessons::Lesson lesson = shippedLesson("restitution");
    const lessons::LessonStep& step = stepOf(lesson, 3);
    StepRun run(step);
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
    QVERIFY(std::abs(hit.predictedFull[0] - 0.8 * jFull / inertia) < 1e-3);
    QVERIFY(std::abs(hit.predictedWithoutRotation[0] - 0.8 * jWithout / inertia) < 1e-3);
    // The engine does what the full formula predicts.
    QVERIFY(std::abs(hit.angularAfter[0] - hit.predictedFull[0]) < 1e-3);
    QCOMPARE(hit.angularBefore[0], 0.0);
    QVERIFY(std::abs(hit.velocityBefore[1].y() - 3.0) < 1e-9);
    QVERIFY(std::abs(hit.velocityAfter[0].y() - jFull / 1.0) < 1e-3);
    QVERIFY(std::abs(hit.velocityAfter[1].y() - (3.0 - jFull / 0.25)) < 1e-3);
    // Kinetic energy is kept by the full formula (e = 1).
    const physics::World& w = run.worlds[0];
    QVERIFY(std::abs(w.diagnostics().kinetic - 0.5 * 0.25 * 9.0) < 1e-6);
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
    const lessons::Lesson l = shippedLesson("stiff_springs");
    struct Expect {
        std::size_t step;
        std::vector<bool> diverges; // implicit-midpoint, symplectic-euler, verlet, rk4
    };
    const std::vector<Expect> expected{{1, {false, false, false, false}},
                                       {2, {false, true, true, false}},
                                       {3, {false, true, true, true}}};
    for (const Expect& e : expected) {
        const lessons::LessonStep& s = stepOf(l, e.step);
        std::vector<physics::World> worlds = lessons::buildStepWorlds(s);
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
    const lessons::LessonStep& s = stepOf(l, static_cast<std::size_t>(step));
    const lessons::Question& q = s.questions.at(static_cast<std::size_t>(question));
    StepRun run(s);
    // Long enough for every question of the step: its export time covers them.
    run.run(s.exportTime);
    const lessons::Verdict v = lessons::judge(q, answer, run.measurements[0], s.scene);
    QVERIFY2(v.measured, qPrintable(v.message));
    QVERIFY2(v.right, qPrintable(v.message));
    // Run without a window from the start, the measure comes out the same: bit for bit, as
    // the physics is deterministic.
    const std::optional<double> ahead = lessons::measureAhead(s, q.measure);
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

void TestLesson::restitutionBounceRatiosAreESquared()
{
    const lessons::Lesson lesson = shippedLesson("restitution");
    const lessons::LessonStep& step = stepOf(lesson, 0);
    StepRun run(step);
    run.run(step.exportTime);
    const lessons::Measurements& m = run.measurements[0];
    const double floorTop = 0.1; // centre height of a ball resting on the floor [m]
    for (const auto& [id, e] :
         {std::pair{"e05", 0.5}, std::pair{"e08", 0.8}, std::pair{"e1", 1.0}}) {
        const std::vector<lessons::ApexEvent>& apexes = m.apexes(bodyId(step.scene, id));
        QVERIFY2(apexes.size() >= 3, id);
        double before = 1.0; // dropped from 1 m
        for (std::size_t n = 0; n < 3; ++n) {
            const double h = apexes[n].y - floorTop;
            const double ratio = h / before;
            QVERIFY2(
                std::abs(ratio / (e * e) - 1.0) < 0.02,
                qPrintable(QStringLiteral("%1 bounce %2: ratio %3").arg(id).arg(n + 1).arg(ratio)));
            before = h;
        }
    }
    // e = 0 does not bounce at all.
    QVERIFY(m.apexes(bodyId(step.scene, "e0")).empty());
}

void TestLesson::energyDriftClaims()
{
    const lessons::Lesson lesson = shippedLesson("energy_drift");
    // Step 1, the spring at h = 0.01 s: Euler grows, symplectic Euler and Verlet stay in their
    // bands, RK4 is flat at this scale.
    {
        const lessons::LessonStep& step = stepOf(lesson, 0);
        StepRun run(step);
        const double e0 = run.worlds[0].diagnostics().total;
        QVERIFY(std::abs(e0 - 0.45) < 1e-12);
        std::vector<double> low(4, 0), high(4, 0);
        run.run(10.0, [&](std::size_t i) {
            const double d = driftPercent(run.worlds[i], e0);
            low[i] = std::min(low[i], d);
            high[i] = std::max(high[i], d);
        });
        QVERIFY(driftPercent(run.worlds[0], e0) > 150); // Euler: +172 %
        QVERIFY(high[1] < 1.7 && low[1] > -1.7);        // symplectic Euler: 1.6 %
        QVERIFY(high[2] <= 1e-6 && low[2] > -0.026);    // Verlet: 0.025 %
        QVERIFY(std::max(high[3], -low[3]) < 2e-6);     // RK4: 1.4e-6 %
    }
    // Step 2, h = 0.1 s: Verlet's error stays in its band, RK4's creeps one way.
    {
        const lessons::LessonStep& step = stepOf(lesson, 1);
        StepRun run(step);
        const double e0 = run.worlds[0].diagnostics().total;
        double verletFirst = 0, verletLast = 0, rk4Previous = 0;
        bool rk4Monotone = true;
        long long n = 0;
        run.run(30.0, [&](std::size_t i) {
            const double d = driftPercent(run.worlds[i], e0);
            if (i == 0) {
                ++n;
                (n <= 100 ? verletFirst : verletLast) =
                    std::min(n <= 100 ? verletFirst : verletLast, d);
            } else {
                rk4Monotone = rk4Monotone && d <= rk4Previous + 1e-12;
                rk4Previous = d;
            }
        });
        QVERIFY(verletFirst > -2.6 && verletLast > -2.6);  // bounded by 2.5 %
        QVERIFY(verletLast > verletFirst - 0.01);          // no worse after 30 s than in 10 s
        QVERIFY(rk4Monotone);                              // creeps down...
        QVERIFY(rk4Previous < -0.3 && rk4Previous > -0.5); // ...by 0.41 % in 30 s
    }
}

void TestLesson::pendulumEulerGoesOverTheTop()
{
    const lessons::Lesson lesson = shippedLesson("energy_drift");
    const lessons::LessonStep& step = stepOf(lesson, 2);
    StepRun run(step);
    const double e0 = run.worlds[0].diagnostics().total;
    const physics::BodyId bob = bodyId(step.scene, "bob");
    double highestEuler = -1;
    double overTheTopAt = -1;
    std::vector<double> worst(4, 0);
    run.run(step.exportTime, [&](std::size_t i) {
        const physics::World& w = run.worlds[i];
        worst[i] = std::max(worst[i], std::abs(driftPercent(w, e0)));
        if (i == 0) {
            highestEuler = std::max(highestEuler, w.body(bob).position.y());
            if (overTheTopAt < 0 && w.body(bob).position.y() > 0.99)
                overTheTopAt = w.time();
        }
    });
    // Euler's bob reaches the top (1 m above the pin) after about 11 s, and nobody diverged
    // within the step's export time.
    QVERIFY(highestEuler > 0.99);
    QVERIFY2(overTheTopAt > 10 && overTheTopAt < 12, qPrintable(QString::number(overTheTopAt)));
    for (const physics::World& w : run.worlds)
        QVERIFY(!w.divergence());
    // Symplectic Euler stays in a band of about +-1.5 % (the text says so); Verlet and RK4
    // stay closer still.
    QVERIFY2(worst[1] > 0.5 && worst[1] < 2.0, qPrintable(QString::number(worst[1])));
    QVERIFY(worst[2] < 0.1);  // Verlet: a few hundredths of a percent
    QVERIFY(worst[3] < 1e-5); // RK4: a few millionths
}

void TestLesson::smallerStepShrinksDrift()
{
    // Steps 1 and 4 run the same spring at h = 0.01 and 0.001 s: every integrator's largest
    // error in 10 s shrinks, by about 10 for the first-order ones and 100 for Verlet.
    const lessons::Lesson lesson = shippedLesson("energy_drift");
    std::vector<double> worst[2];
    for (int k = 0; k < 2; ++k) {
        const lessons::LessonStep& step = stepOf(lesson, k == 0 ? 0 : 3);
        StepRun run(step);
        const double e0 = run.worlds[0].diagnostics().total;
        worst[k].assign(4, 0);
        run.run(10.0, [&](std::size_t i) {
            worst[k][i] = std::max(worst[k][i], std::abs(driftPercent(run.worlds[i], e0)));
        });
    }
    QVERIFY(worst[0][0] / worst[1][0] > 10);                // Euler
    QVERIFY(std::abs(worst[0][1] / worst[1][1] - 10) < 1);  // symplectic Euler
    QVERIFY(std::abs(worst[0][2] / worst[1][2] - 100) < 5); // Verlet
    QVERIFY(worst[0][3] / worst[1][3] > 1e4);               // RK4
    for (int i = 0; i < 4; ++i)
        QVERIFY(worst[1][i] > 0); // smaller, never none
}

void TestLesson::sequentialImpulseStackMovesLess()
{
    const lessons::Lesson lesson = shippedLesson("stacks");
    for (std::size_t s : {std::size_t{0}, std::size_t{2}}) {
        const lessons::LessonStep& step = stepOf(lesson, s);
        StepRun run(step);
        const std::vector<physics::Body> start = run.worlds[0].bodies();
        // How far the boxes moved, summed, and the largest speed seen after the first second.
        std::vector<double> fastest(2, 0);
        // When the contact-by-contact stack falls: its energy drops below half.
        const double e0 = run.worlds[0].diagnostics().total;
        double fellAt = -1;
        run.run(3.0, [&](std::size_t i) {
            if (i == 0 && fellAt < 0 && run.worlds[0].diagnostics().total < 0.5 * e0)
                fellAt = run.worlds[0].time();
            if (run.worlds[i].time() < 1.0)
                return;
            for (const physics::Body& b : run.worlds[i].bodies())
                fastest[i] = std::max(fastest[i], b.velocity.norm());
        });
        double moved[2] = {0, 0};
        for (std::size_t i = 0; i < 2; ++i)
            for (std::size_t b = 0; b < start.size(); ++b)
                moved[i] += (run.worlds[i].bodies()[b].position - start[b].position).norm();
        QVERIFY2(moved[1] < 0.01, qPrintable(QString::number(moved[1]))); // stands still
        QVERIFY2(moved[0] > 1.0, qPrintable(QString::number(moved[0])));  // topples
        QVERIFY(fastest[1] < 1e-3);
        QVERIFY(fastest[0] > 100 * fastest[1]);
        // The texts: five boxes topple after about 2.5 s, ten after about two seconds.
        const double said = s == 0 ? 2.5 : 2.0;
        QVERIFY2(std::abs(fellAt - said) < 0.4, qPrintable(QString::number(fellAt)));
    }
    // Step 2: one iteration with warm starting still stands.
    const lessons::LessonStep& one = stepOf(lesson, 1);
    QCOMPARE(*one.settings.iterations, 1);
    StepRun run(one);
    const std::vector<physics::Body> start = run.worlds[0].bodies();
    run.run(5.0);
    for (std::size_t b = 0; b < start.size(); ++b)
        QVERIFY((run.worlds[0].bodies()[b].position - start[b].position).norm() < 1e-3);
}

void TestLesson::softStepPyramidStands()
{
    // Step 4 runs the base-40 pyramid at 1/60 s with the soft step (main world) and sequential
    // impulses; step 5 explains it. What their texts claim, on the lesson's own worlds.
    const lessons::Lesson lesson = shippedLesson("stacks");
    const lessons::LessonStep& step = stepOf(lesson, 3);
    QCOMPARE(step.compare->label(0), QStringLiteral("soft-step"));
    QCOMPARE(step.compare->label(1), QStringLiteral("sequential-impulse"));
    QVERIFY(stepOf(lesson, 4).settings.solver == physics::SolverKind::SoftStep);
    StepRun run(step);
    const physics::World& soft = run.worlds[0];
    const physics::World& sequential = run.worlds[1];
    QCOMPARE(soft.def().solver, physics::SolverKind::SoftStep);
    QCOMPARE(sequential.def().solver, physics::SolverKind::SequentialImpulse);
    // The soft step runs only where the step integrates directly (the text says so).
    QCOMPARE(soft.def().integrator, physics::IntegratorKind::SymplecticEuler);

    // "5 substeps of 1/300 s", "vibrate 75 times a second between two boxes": the numbers of
    // the text, from the world's own settings.
    const physics::SoftStepSettings& settings = soft.contactSettings().soft;
    const QRegularExpressionMatch said =
        QRegularExpression(QStringLiteral("into (\\d+) \\*\\*substeps\\*\\* of 1/(\\d+)"))
            .match(step.text);
    QVERIFY2(said.hasMatch(), qPrintable(step.text));
    QCOMPARE(said.captured(1).toInt(), settings.substeps);
    QCOMPARE(said.captured(2).toDouble(), std::round(settings.substeps / soft.def().dt));
    const QRegularExpressionMatch hertz =
        QRegularExpression(QStringLiteral("vibrate (\\d+) times a second")).match(step.text);
    QVERIFY(hertz.hasMatch());
    const double contactHertz = settings.contactFrequency * settings.substeps / soft.def().dt;
    QVERIFY2(std::abs(hertz.captured(1).toDouble() - contactHertz) < 1e-9,
             qPrintable(QString::number(contactHertz)));

    const physics::BodyId top = bodyId(step.scene, "top");
    const double y0 = soft.body(top).position.y();
    const std::vector<physics::Body> start = soft.bodies();
    const double e0 = soft.diagnostics().total;
    double softFarthest = 0;    // the soft top's largest distance from its start [m]
    double sequentialAt2 = 0;   // the sequential top's sink at t = 2 s [m]
    double softWorstChange = 0; // the soft step's largest |E - E0| / |E0|
    run.run(step.exportTime, [&](std::size_t i) {
        const physics::World& w = run.worlds[i];
        if (i == 0) {
            softFarthest = std::max(softFarthest, std::abs(w.body(top).position.y() - y0));
            softWorstChange =
                std::max(softWorstChange, std::abs(w.diagnostics().total - e0) / std::abs(e0));
        } else if (std::abs(w.time() - 2.0) < 0.5 * w.def().dt) {
            sequentialAt2 = y0 - w.body(top).position.y();
        }
    });
    const double softSink = y0 - soft.body(top).position.y();
    const double sequentialSink = y0 - sequential.body(top).position.y();
    const QString figures = QStringLiteral("soft: sank %1 m, farthest %2 m; sequential: %3 m, "
                                           "%4 m at 2 s")
                                .arg(softSink)
                                .arg(softFarthest)
                                .arg(sequentialSink)
                                .arg(sequentialAt2);
    // Step 5: "only about two centimetres lower", "in the first second its top bobs up and
    // down by up to twice that before it comes to rest".
    QVERIFY2(std::abs(softSink) > 0.01 && std::abs(softSink) < 0.025, qPrintable(figures));
    QVERIFY2(softFarthest < 2 * 0.025, qPrintable(figures));
    // "sank by almost 0.2 m, most of it in the first two seconds".
    QVERIFY2(sequentialSink > 0.15 && sequentialSink < 0.2, qPrintable(figures));
    QVERIFY2(sequentialAt2 > 0.5 * sequentialSink, qPrintable(figures));
    QVERIFY2(sequentialSink > 5 * std::abs(softSink), qPrintable(figures));
    // Standing, by the measure: no box moved more than 0.5 m sideways or turned more
    // than 0.2 rad.
    for (std::size_t b = 0; b < start.size(); ++b) {
        QVERIFY(std::abs(soft.bodies()[b].position.x() - start[b].position.x()) < 0.5);
        QVERIFY(std::abs(soft.bodies()[b].angle - start[b].angle) < 0.2);
    }
    // "Watch the total energy: it stays flat (within two tenths of a per cent: the little the
    // pyramid settles)", and its change is a small part of what the sinking sequential pyramid
    // loses.
    QVERIFY2(softWorstChange < 2e-3, qPrintable(QString::number(softWorstChange)));
    const double softLoss = std::abs(soft.diagnostics().total - e0);
    const double sequentialLoss = std::abs(sequential.diagnostics().total - e0);
    QVERIFY2(softLoss < 0.2 * sequentialLoss,
             qPrintable(QStringLiteral("%1 J against %2 J").arg(softLoss).arg(sequentialLoss)));

    // The question: "it stays" is right, "it sinks as the other one does" is not.
    const lessons::Question& q = step.questions.at(0);
    QVERIFY(lessons::judge(q, y0, run.measurements[0], step.scene).right);
    QVERIFY(!lessons::judge(q, y0 - sequentialSink, run.measurements[0], step.scene).right);
}

void TestLesson::billiardsBreakConservesMomentum()
{
    const lessons::Lesson lesson = shippedLesson("billiards_momentum");
    // Without cushions and cloth, with either solver: px and py stay what the cue ball brought.
    const lessons::LessonStep& step = stepOf(lesson, 2);
    StepRun run(step);
    double lowestPx[2] = {1e9, 1e9}, highestPx[2] = {-1e9, -1e9};
    run.run(2.0, [&](std::size_t i) {
        const double px = run.worlds[i].diagnostics().momentum.x();
        lowestPx[i] = std::min(lowestPx[i], px);
        highestPx[i] = std::max(highestPx[i], px);
    });
    for (std::size_t i = 0; i < 2; ++i) {
        // The cue ball's 0.17 kg × (4, 0.01) m/s.
        QVERIFY(std::abs(lowestPx[i] - 0.68) < 1e-9 && std::abs(highestPx[i] - 0.68) < 1e-9);
        QVERIFY(std::abs(run.worlds[i].diagnostics().momentum.y() - 0.0017) < 1e-9);
        // Many collisions happened.
        QVERIFY(run.measurements[i].collisions().size() > 20);
    }
    // With e = 0.93 sequential impulses end the break below the cue ball's kinetic energy.
    // The seed's contact-by-contact impulse ends it elsewhere: which way depends on the
    // order round-off gives the simultaneous contacts (a Release and a sanitizer build
    // differ), and in some orders it still ends above the start, an open problem of the
    // seed solver with many simultaneous contacts. What the lesson claims is only that the
    // two differ while both keep the momentum.
    const double k0 = 0.5 * 0.17 * (16 + 0.0001);
    const double k[2] = {run.worlds[0].diagnostics().kinetic, run.worlds[1].diagnostics().kinetic};
    QVERIFY2(k[1] < k0, qPrintable(QStringLiteral("%1 of %2").arg(k[1]).arg(k0)));
    QVERIFY2(std::abs(k[0] - k[1]) > 0.01 * k0, "the two solvers end the break differently");
}

// The step that opens the editor ("make the heavier ball the one at rest"): its answer is
// reached by the edit the text asks for, done as the student does it (the one property the
// step unlocks), and is wrong for the scene left as it is.
void TestLesson::editorStepIsAnsweredByEditing()
{
    const lessons::Lesson lesson = shippedLesson("billiards_momentum");
    const auto found =
        std::find_if(lesson.steps.begin(), lesson.steps.end(),
                     [](const lessons::LessonStep& s) { return s.editor.has_value(); });
    QVERIFY(found != lesson.steps.end());
    const lessons::LessonStep& step = *found;
    QCOMPARE(step.editor->tools, QStringList{QStringLiteral("select")});
    QCOMPARE(step.editor->properties, QStringList{QStringLiteral("mass")});
    QCOMPARE(step.questions.size(), std::size_t(1));
    const lessons::Question& q = step.questions[0];

    const auto moving = step.scene.bodyIndex(QStringLiteral("moving"));
    const auto resting = step.scene.bodyIndex(QStringLiteral("resting"));
    QVERIFY(moving && resting);
    const physics::BodyDef& ball = step.scene.bodies[static_cast<std::size_t>(*moving)];
    constexpr double kHeavy = 3.0; // [kg], the mass the text asks for
    // Momentum and an elastic hit (relative velocity reversed), solved for the moving ball:
    // v1 = (m1 - m2) / (m1 + m2) u.
    const double answer = (ball.mass - kHeavy) / (ball.mass + kHeavy) * ball.velocity.x();
    QVERIFY(answer < 0); // it bounces back

    const lessons::edit::EditResult edited =
        lessons::edit::setBodyNumber(step.scene, *resting, lessons::edit::BodyNumber::Mass, kHeavy);
    QVERIFY2(edited.ok, qPrintable(edited.error));
    lessons::LessonStep built = step;
    built.scene = edited.scene;
    StepRun run(built);
    run.run(built.exportTime);
    const lessons::Verdict right = lessons::judge(q, answer, run.measurements[0], built.scene);
    QVERIFY2(right.measured, qPrintable(right.message));
    QVERIFY2(right.right, qPrintable(right.message));

    // Unedited, the moving ball stops dead: the same answer is wrong.
    StepRun asOpened(step);
    asOpened.run(step.exportTime);
    const lessons::Verdict wrong = lessons::judge(q, answer, asOpened.measurements[0], step.scene);
    QVERIFY2(wrong.measured, qPrintable(wrong.message));
    QVERIFY2(!wrong.right, qPrintable(wrong.message));
    QVERIFY2(std::abs(wrong.value) < 1e-6, qPrintable(QString::number(wrong.value)));
    // The hint helps without giving the value away.
    QVERIFY(!q.hint.contains(QString::number(answer, 'f', 1)));
}

void TestLesson::billiardsCushionsWhereTheTextSays()
{
    // The cushion step says when the balls start to hit the cushions, and asks for px "just
    // after the break (before any ball reaches a cushion)": the break and that question come
    // before the first cushion hit, which comes when the text says, to a tenth of a second.
    const lessons::Lesson lesson = shippedLesson("billiards_momentum");
    const lessons::LessonStep& step = stepOf(lesson, 1);
    const QRegularExpressionMatch said =
        QRegularExpression(QStringLiteral("From about t = ([0-9.]+) s on, balls start to hit "
                                          "the cushions"))
            .match(step.text);
    QVERIFY2(said.hasMatch(), "the text says when");
    const double stated = said.captured(1).toDouble();
    StepRun run(step);
    run.run(3.0, [](std::size_t) {});
    const physics::World& w = run.worlds[0];
    double breakAt = -1, cushionAt = -1;
    for (const lessons::CollisionEvent& e : run.measurements[0].collisions()) {
        const bool cushion = !w.body(e.a).moves() || !w.body(e.b).moves();
        if (!cushion && breakAt < 0)
            breakAt = e.t;
        if (cushion && cushionAt < 0)
            cushionAt = e.t;
    }
    QVERIFY(breakAt > 0 && cushionAt > breakAt);
    double lastQuestion = 0;
    for (const lessons::Question& q : step.questions)
        lastQuestion = std::max(lastQuestion, q.measure.time);
    QVERIFY2(breakAt < lastQuestion && lastQuestion < cushionAt,
             qPrintable(QStringLiteral("break %1 s, question %2 s, cushion %3 s")
                            .arg(breakAt)
                            .arg(lastQuestion)
                            .arg(cushionAt)));
    QVERIFY2(std::abs(cushionAt - stated) <= 0.1,
             qPrintable(QStringLiteral("first cushion hit at %1 s, the text says %2 s")
                            .arg(cushionAt)
                            .arg(stated)));
    // The cue ball reaches the rack when the question says.
    QVERIFY2(step.questions.at(0).prompt.contains(
                 QStringLiteral("at about t = %1 s").arg(std::round(breakAt * 10) / 10)),
             qPrintable(QStringLiteral("the break at %1 s").arg(breakAt)));
}

RIGIDLAB_TEST_GUILESS_MAIN(TestLesson)

void TestLesson::worldsStopWhereTheTextSays_data()
{
    // A step whose text says a world stops: the phrase it says it in (holding the time, in
    // seconds), and which worlds stop there. Times are stated as "about", to two figures: a
    // world must stop within `slack` of the stated time, and not before the others that
    // the phrase names.
    QTest::addColumn<QString>("lesson");
    QTest::addColumn<int>("step");
    QTest::addColumn<QString>("phrase");
    QTest::addColumn<QList<int>>("worlds");
    QTest::addColumn<double>("slack"); // [s]
    QTest::newRow("stiff-euler") << "stiff_springs" << 0 << "at about 30 s" << QList<int>{0} << 1.0;
    QTest::newRow("stiff-verlet") << "stiff_springs" << 2 << "Verlet after about 0.05 s"
                                  << QList<int>{2} << 0.005;
    QTest::newRow("stiff-symplectic-euler")
        << "stiff_springs" << 2 << "symplectic Euler after about 0.24 s" << QList<int>{1} << 0.005;
    QTest::newRow("stiff-rk4") << "stiff_springs" << 3 << "stops it after about 0.28 s"
                               << QList<int>{3} << 0.005;
    QTest::newRow("stiff-four-steps")
        << "stiff_springs" << 3 << "after four steps, 0.02 s" << QList<int>{1, 2} << 1e-9;
    QTest::newRow("pendulum-euler")
        << "energy_drift" << 2 << "at about 16 s" << QList<int>{0} << 0.5;
}

void TestLesson::worldsStopWhereTheTextSays()
{
    QFETCH(QString, lesson);
    QFETCH(int, step);
    QFETCH(QString, phrase);
    QFETCH(QList<int>, worlds);
    QFETCH(double, slack);
    const lessons::Lesson l = shippedLesson(qPrintable(lesson));
    const lessons::LessonStep& s = stepOf(l, static_cast<std::size_t>(step));
    QVERIFY2(s.text.contains(phrase), qPrintable(s.text));
    const QRegularExpressionMatch number =
        QRegularExpression(QStringLiteral("(\\d+(\\.\\d+)?) s")).match(phrase);
    QVERIFY(number.hasMatch());
    const double stated = number.captured(1).toDouble();
    // The step's text says so only where the world stops: the lab shows why (the main world's
    // banner, a compared world's label), tested in the window (tests/ui/test_readable).
    QVERIFY(s.text.contains(QStringLiteral("diverge")));
    StepRun run(s);
    const double dt = run.worlds[0].def().dt;
    run.run(stated + slack + dt);
    for (int i : worlds) {
        const auto& d = run.worlds[static_cast<std::size_t>(i)].divergence();
        QVERIFY2(d, qPrintable(QStringLiteral("world %1 still runs at %2 s")
                                   .arg(i)
                                   .arg(run.worlds[static_cast<std::size_t>(i)].time())));
        QVERIFY2(std::abs(d->time - stated) <= slack + 0.5 * dt,
                 qPrintable(QStringLiteral("world %1 stopped at %2 s, the text says %3 s")
                                .arg(i)
                                .arg(d->time)
                                .arg(stated)));
    }
}

void TestLesson::stiffSpringsEulerTenfoldWhereTheorySays()
{
    // Step 1: explicit Euler multiplies a spring's energy by 1 + (w dt)^2 per step, so it is
    // ten times its start after n = ln 10 / ln(1 + (w dt)^2) steps: the text says "about 4.6 s".
    const lessons::Lesson l = shippedLesson("stiff_springs");
    const lessons::LessonStep& s = stepOf(l, 0);
    QVERIFY(s.text.contains(QStringLiteral("after about 4.6 s its energy is ten times")));
    physics::World w = lessons::buildStepWorlds(s).at(0);
    QCOMPARE(w.def().integrator, physics::IntegratorKind::Euler);
    const double wdt2 =
        s.scene.springs.at(0).stiffness / w.bodies()[0].mass * w.def().dt * w.def().dt;
    const long long predicted =
        static_cast<long long>(std::ceil(std::log(10.0) / std::log1p(wdt2)));
    w.updateDiagnostics();
    const double e0 = w.diagnostics().total;
    while (w.diagnostics().total < 10 * e0 && w.stepCount() < 10 * predicted)
        w.step();
    QCOMPARE(w.stepCount(), predicted);
    QVERIFY2(std::abs(w.time() - 4.6) < 0.05, qPrintable(QString::number(w.time())));
    QVERIFY(!w.divergence()); // ten times is not yet the lab's bound
}

void TestLesson::divergenceMessageWords()
{
    // The command line words the physics' diagnosis (data) in one English line.
    physics::Divergence d;
    d.kind = physics::Divergence::Kind::NonFinite;
    d.quantity = physics::Divergence::Quantity::Velocity;
    d.body = 0;
    d.bodyName = "ball";
    d.time = 0.125;
    d.step = 125;
    d.dt = 0.001;
    d.integrator = physics::IntegratorKind::Euler;
    QCOMPARE(lessons::divergenceMessage(d),
             QStringLiteral("diverged at t = 0.125 s (step 125, dt = 0.001 s, euler): body "
                            "\"ball\": velocity is no longer finite"));
    d.kind = physics::Divergence::Kind::EnergyGrowth;
    d.quantity = physics::Divergence::Quantity::TotalEnergy;
    d.value = 2.5e6;
    d.bound = 1e6;
    QCOMPARE(lessons::divergenceMessage(d),
             QStringLiteral("diverged at t = 0.125 s (step 125, dt = 0.001 s, euler): the total "
                            "energy grew to 2.5e+06 J, past the bound of 1e+06 J (body \"ball\" "
                            "holds the most kinetic energy)"));
}
