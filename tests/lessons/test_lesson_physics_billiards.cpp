// SPDX-License-Identifier: GPL-3.0-or-later
// The billiards lesson's claims, checked on its own scenes: the break keeps the cue ball's
// momentum with either solver, the editor step is answered by the edit its text asks for, the
// balls reach the cushions when the text says.

#include "physics/physics_test_util.h"
#include "test_lesson.h"
#include "test_lesson_physics.h"

#include "edit/scene_edits.h"

#include <QRegularExpression>

#include <algorithm>
#include <cmath>

using namespace rigidlab;
using namespace rigidlab::test;

void TestLesson::billiardsBreakConservesMomentum()
{
    // Without cushions and cloth, with either solver: px and py stay what the cue ball brought.
    ShippedStep breakStep("billiards_momentum", 2);
    StepRun& run = breakStep.run;
    double lowestPx[2] = {1e9, 1e9}, highestPx[2] = {-1e9, -1e9};
    run.run(2.0, [&](std::size_t i) {
        const double px = run.worlds[i].diagnostics().momentum.x();
        lowestPx[i] = std::min(lowestPx[i], px);
        highestPx[i] = std::max(highestPx[i], px);
    });
    for (std::size_t i = 0; i < 2; ++i) {
        // The cue ball's 0.17 kg × (4, 0.01) m/s.
        QVERIFY(std::abs(lowestPx[i] - 0.68) < 1e-9 && std::abs(highestPx[i] - 0.68) < 1e-9);
        RL_VERIFY_NEAR(run.worlds[i].diagnostics().momentum.y(), 0.0017, 1e-9, 0);
        // Many collisions happened.
        QVERIFY(run.measurements[i].collisions().size() > 20);
    }
    // With e = 0.93 sequential impulses end the break below the cue ball's kinetic energy.
    // The paper's contact-by-contact impulse ends it elsewhere: which way depends on the
    // order round-off gives the simultaneous contacts (a Release and a sanitizer build
    // differ), and in some orders it still ends above the start, an open problem of the
    // paper's solver with many simultaneous contacts. What the lesson claims is only that the
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
    const lessons::Verdict right = judgedAtExport(built, q, answer);
    QVERIFY2(right.measured, qPrintable(right.message));
    QVERIFY2(right.right, qPrintable(right.message));

    // Unedited, the moving ball stops dead: the same answer is wrong.
    const lessons::Verdict wrong = judgedAtExport(step, q, answer);
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
        QRegularExpression(
            QStringLiteral("From about t = ([0-9.]+)\\x{00A0}s on, balls start to hit "
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
        if (const auto* measured = q.as<lessons::MeasuredQuestion>())
            lastQuestion = std::max(lastQuestion, measured->measure.time);
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
                 QStringLiteral("at about t = %1\u00a0s").arg(std::round(breakAt * 10) / 10)),
             qPrintable(QStringLiteral("the break at %1 s").arg(breakAt)));
}
