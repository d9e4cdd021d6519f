// SPDX-License-Identifier: GPL-3.0-or-later
// The physics the shipped lessons claim in their texts, checked on the lessons' own scenes and
// settings: bounces and restitution, energy drift, stacks. The billiards lesson's claims are in
// test_lesson_physics_billiards.cpp, the worlds that stop where a text says in
// test_lesson_physics_divergence.cpp.

#include "physics/physics_test_util.h"
#include "test_lesson.h"
#include "test_lesson_physics.h"

#include <QRegularExpression>

#include <algorithm>
#include <cmath>

using namespace rigidlab;
using namespace rigidlab::test;

void TestLesson::restitutionBounceRatiosAreESquared()
{
    ShippedStep drop("restitution", 0);
    const lessons::LessonStep& step = drop.step;
    const lessons::Measurements& m = drop.runToExport();
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

void TestLesson::bounceHeightsAreExactMechanics()
{
    // The bounces panel's heights, where the text measures them: the ball's lowest point above
    // the floor at the top of its flight, each bounce from where it touched down. Exact
    // mechanics: h_n = e^(2n) h_0 with h_0 = 1 m. The stepped apex lies at most g dt²/8 below
    // the true top (the top is within dt/2 of a step); each bounce is timed within its step,
    // and where the flight starts again is off by less than the g dt²/2 a step's fall adds.
    // (Measured: within 3 µm at dt = 1 ms.)
    ShippedStep drop("restitution", 0);
    const lessons::LessonStep& step = drop.step;
    const lessons::Measurements& m = drop.runToExport();
    const double dt = drop.run.worlds[0].def().dt;
    const double g = -drop.run.worlds[0].def().gravity.y();
    for (const auto& [id, e] :
         {std::pair{"e05", 0.5}, std::pair{"e08", 0.8}, std::pair{"e1", 1.0}}) {
        const physics::BodyId body = bodyId(step.scene, id);
        const std::vector<lessons::ApexEvent>& apexes = m.apexes(body);
        QVERIFY2(apexes.size() >= 3, id);
        const double drop =
            step.scene.bodies[static_cast<std::size_t>(body)].position.y() - apexes.front().bounceY;
        RL_VERIFY_NEAR(drop, 1.0, 1e-9, 0.0);
        for (std::size_t n = 0; n < 3; ++n) {
            const double h = apexes[n].y - apexes[n].bounceY;
            const double exact = std::pow(e, 2.0 * static_cast<double>(n + 1)) * drop;
            const double tolerance = g * dt * dt / 8 + static_cast<double>(n + 1) * g * dt * dt / 2;
            qInfo("%s bounce %zu: measured %.7f m, exact %.7f m, tolerance %.7f m", id, n + 1, h,
                  exact, tolerance);
            RL_VERIFY_NEAR(h, exact, tolerance, 0.0);
        }
    }
}

void TestLesson::restitutionDriftStaysAtZero()
{
    // The text: velocity Verlet follows a free flight exactly, so the energy drift the status
    // bar shows (the numerical error, with what the contacts took added back) does not change
    // in the steps without a contact; the floor's push on a ball at rest is held through the
    // step as gravity is, so the steps with a contact keep it too, below the bound the text
    // gives for the step's end.
    ShippedStep drop("restitution", 0);
    const lessons::LessonStep& step = drop.step;
    StepRun& run = drop.run;
    physics::World& world = run.worlds[0];
    const double e0 = world.diagnostics().total;
    const double d0 = world.diagnostics().dissipated;
    const auto drift = [&] {
        return (world.diagnostics().total + world.diagnostics().dissipated - d0 - e0) /
               std::abs(e0) * 100.0;
    };
    double before = 0, inFlight = 0, inContact = 0; // [%]
    int contactSteps = 0;
    run.run(step.exportTime, [&](std::size_t) {
        const bool touching = std::any_of(
            world.contacts().begin(), world.contacts().end(), [](const physics::Contact& c) {
                return c.normalImpulse[0] > 0 || c.normalImpulse[1] > 0;
            });
        contactSteps += touching ? 1 : 0;
        (touching ? inContact : inFlight) += std::abs(drift() - before);
        before = drift();
    });
    qInfo("drift at %.0f s: %.3g %%; changed by %.3g %% in the steps without a contact, by "
          "%.3g %% in the %d with one",
          world.time(), drift(), inFlight, inContact, contactSteps);
    QVERIFY(contactSteps > 0); // the balls do land and rest
    QVERIFY2(inFlight < 1e-9, qPrintable(QString::number(inFlight)));
    const QRegularExpressionMatch said =
        QRegularExpression(QStringLiteral("below ([0-9.]+)\\x{00A0}% after 6\\x{00A0}s"))
            .match(step.text);
    QVERIFY2(said.hasMatch(), qPrintable(step.text));
    RL_VERIFY_AT_MOST(std::abs(drift()), said.captured(1).toDouble());
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
        RL_VERIFY_NEAR(e0, 0.45, 1e-12, 0);
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
    ShippedStep pendulum("energy_drift", 2);
    const lessons::LessonStep& step = pendulum.step;
    StepRun& run = pendulum.run;
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
    QVERIFY(worst[0][0] / worst[1][0] > 10);              // Euler
    RL_VERIFY_NEAR(worst[0][1] / worst[1][1], 10, 1, 0);  // symplectic Euler
    RL_VERIFY_NEAR(worst[0][2] / worst[1][2], 100, 5, 0); // Verlet
    QVERIFY(worst[0][3] / worst[1][3] > 1e4);             // RK4
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
    QCOMPARE(*one.settings.get<int>("iterations"), 1);
    StepRun run(one);
    const std::vector<physics::Body> start = run.worlds[0].bodies();
    run.run(5.0);
    for (std::size_t b = 0; b < start.size(); ++b)
        QVERIFY((run.worlds[0].bodies()[b].position - start[b].position).norm() < 1e-3);
}

namespace {

/// The soft step's figures in step 4's text, "5 substeps of 1/300 s" and "vibrate 75 times
/// a second between two boxes", against the world's own settings.
void verifySoftStepFigures(const lessons::LessonStep& step, const physics::World& soft)
{
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
}

} // namespace

void TestLesson::softStepPyramidStands()
{
    // Step 4 runs the base-40 pyramid at 1/60 s with the soft step (main world) and sequential
    // impulses; step 5 explains it. What their texts claim, on the lesson's own worlds.
    const lessons::Lesson lesson = shippedLesson("stacks");
    const lessons::LessonStep& step = stepOf(lesson, 3);
    QCOMPARE(step.compare->label(0), QStringLiteral("soft-step"));
    QCOMPARE(step.compare->label(1), QStringLiteral("sequential-impulse"));
    QVERIFY(
        physics::solverFromName(
            stepOf(lesson, 4).settings.get<QString>("solver").value_or(QString()).toStdString()) ==
        physics::SolverKind::SoftStep);
    StepRun run(step);
    const physics::World& soft = run.worlds[0];
    const physics::World& sequential = run.worlds[1];
    QCOMPARE(soft.def().solver, physics::SolverKind::SoftStep);
    QCOMPARE(sequential.def().solver, physics::SolverKind::SequentialImpulse);
    // The soft step runs only where the step integrates directly (the text says so).
    QCOMPARE(soft.def().integrator, physics::IntegratorKind::SymplecticEuler);

    verifySoftStepFigures(step, soft);
    if (QTest::currentTestFailed())
        return;

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
    // Standing: no box moved more than 0.5 m sideways or turned more than 0.2 rad.
    for (std::size_t b = 0; b < start.size(); ++b) {
        RL_VERIFY_NEAR(soft.bodies()[b].position.x(), start[b].position.x(), 0.5, 0);
        RL_VERIFY_NEAR(soft.bodies()[b].angle, start[b].angle, 0.2, 0);
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
