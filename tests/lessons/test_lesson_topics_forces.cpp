// SPDX-License-Identifier: GPL-3.0-or-later
// The lessons "Rotation and moment of inertia" and "Force and torque accumulators": what their
// texts and questions claim, against α = τ / I and a = F / m with the forces summed here.

#include "test_lesson_topics.h"

#include "test_main.h"

#include "rigidlab/physics/force_breakdown.h"

#include <cmath>

using namespace rigidlab;
using namespace rigidlab::test;

namespace {

/// The force and torque (about the centre of mass) the springs of `w` put on body `id` now,
/// summed here from Hooke's law, independently of the engine's accumulators.
std::pair<physics::Vec2, double> springLoad(const physics::World& w, physics::BodyId id)
{
    physics::Vec2 force = physics::Vec2::Zero();
    double torque = 0;
    const physics::Body& b = w.body(id);
    for (const physics::SpringDef& s : w.springs()) {
        if (s.a != id && s.b != id)
            continue;
        const bool onA = s.a == id;
        const physics::Vec2 here = b.transform().apply(onA ? s.anchorA : s.anchorB);
        const physics::BodyId other = onA ? s.b : s.a;
        const physics::Vec2 otherLocal = onA ? s.anchorB : s.anchorA;
        const physics::Vec2 there =
            other == physics::kWorld ? otherLocal : w.body(other).transform().apply(otherLocal);
        const physics::Vec2 d = there - here;
        const physics::Vec2 f = s.stiffness * (d.norm() - s.restLength) * d.normalized();
        force += f;
        torque += crossZ(here - b.position, f);
    }
    return {force, torque};
}

double boxInertia(double m, double w, double h)
{
    return m * (w * w + h * h) / 12.0;
}

} // namespace

void TestLessonTopics::rotationInertiaFromFormulas()
{
    // The table of the first step: I from the formulas equals the inspector's (the world's).
    ShippedStep bodies("rotation_inertia", 0);
    const lessons::LessonStep& step = bodies.step;
    const physics::World& w = bodies.run.worlds[0];
    const auto inertia = [&](const char* id) { return w.body(bodyId(step.scene, id)).inertia; };
    RL_VERIFY_NEAR(inertia("disc"), 0.5 * 1.0 * 0.25 * 0.25, 0, 1e-12);
    RL_VERIFY_NEAR(inertia("square"), boxInertia(1, 0.5, 0.5), 0, 1e-12);
    RL_VERIFY_NEAR(inertia("long"), boxInertia(1, 1, 0.1), 0, 1e-12);
    RL_VERIFY_NEAR(inertia("hub"), 0.5 * 0.2 * 0.25 * 0.25, 0, 1e-12);
    // Every body has 1 kg: the ring's hub and beads together too.
    double ring = w.body(bodyId(step.scene, "hub")).mass;
    for (const char* bead : {"bead1", "bead2", "bead3", "bead4"})
        ring += w.body(bodyId(step.scene, bead)).mass;
    RL_VERIFY_NEAR(ring, 1.0, 0, 1e-12);
    for (const char* id : {"disc", "square", "long"})
        RL_VERIFY_NEAR(w.body(bodyId(step.scene, id)).mass, 1.0, 0, 1e-12);
}

void TestLessonTopics::rotationAlphaIsTorqueOverInertia()
{
    // The same torque on each body, and after one step ω = (τ / I) dt: exactly Newton's law
    // for rotation, with the ring's I = I_hub + 4 m r² (its beads pinned at their centres turn
    // the hub's pins, not themselves).
    ShippedStep turned("rotation_inertia", 0);
    const lessons::LessonStep& step = turned.step;
    physics::World& w = turned.run.worlds[0];
    const double dt = w.def().dt;
    const physics::BodyId hub = bodyId(step.scene, "hub");
    double ringInertia = w.body(hub).inertia;
    for (const char* bead : {"bead1", "bead2", "bead3", "bead4"}) {
        const physics::Body& b = w.body(bodyId(step.scene, bead));
        ringInertia += b.mass * (b.position - w.body(hub).position).squaredNorm();
    }
    RL_VERIFY_NEAR(ringInertia, 0.5 * 0.2 * 0.0625 + 4 * 0.2 * 0.0625, 0, 1e-12);
    std::vector<std::pair<const char*, double>> bodies;
    for (const char* id : {"disc", "hub", "square", "long"}) {
        const physics::BodyId b = bodyId(step.scene, id);
        const double tau = springLoad(w, b).second;
        RL_VERIFY_NEAR(tau, 0.5, 0, 1e-12); // the text's τ = 0.25 m × 2 N
        bodies.emplace_back(id, tau / (b == hub ? ringInertia : w.body(b).inertia));
    }
    w.step();
    for (const auto& [id, alpha] : bodies)
        RL_VERIFY_NEAR(w.body(bodyId(step.scene, id)).angularVelocity, alpha * dt, 0, 1e-9);
}

void TestLessonTopics::rotationQuestionsHaveTheirAnswers()
{
    // ω = α t at 0.1 s, with α = τ / I, is judged right; the bodies turn in the order of
    // their I (the disc fastest); and L about the origin grows at the total torque, 2 N m.
    ShippedStep turned("rotation_inertia", 0);
    const lessons::LessonStep& step = turned.step;
    StepRun& run = turned.run;
    const double l0 = run.worlds[0].diagnostics().angularMomentum;
    run.run(0.01);
    RL_VERIFY_NEAR((run.worlds[0].diagnostics().angularMomentum - l0) / 0.01, 2.0, 0, 0.01);
    run.run(0.1 - 0.01);
    const physics::World& w = run.worlds[0];
    const double tau = 0.5, t = 0.1;
    QString message;
    QVERIFY2(
        judgedRight(step, 0, tau / (0.5 * 1.0 * 0.25 * 0.25) * t, run.measurements[0], &message),
        qPrintable(message));
    QVERIFY2(judgedRight(step, 1, tau / boxInertia(1, 1, 0.1) * t, run.measurements[0], &message),
             qPrintable(message));
    // The answers of a student who forgot that I differs (the disc's for all) are wrong.
    QVERIFY(!judgedRight(step, 1, tau / (0.5 * 0.0625) * t, run.measurements[0], &message));
    const auto omega = [&](const char* id) {
        return w.body(bodyId(step.scene, id)).angularVelocity;
    };
    QVERIFY(omega("disc") > omega("square"));
    QVERIFY(omega("square") > omega("hub"));
    QVERIFY(omega("hub") > omega("long"));
}

void TestLessonTopics::rotationOffCentrePullMovesAndTurns()
{
    // Pulled at the centre or at the end with the same 2 N, both centres get a = F / m; only
    // the end-pulled rod turns, with α = r × F / I. One step exactly, then the questions.
    ShippedStep pulled("rotation_inertia", 1);
    const lessons::LessonStep& step = pulled.step;
    StepRun& run = pulled.run;
    physics::World& w = run.worlds[0];
    const double dt = w.def().dt;
    const physics::BodyId centre = bodyId(step.scene, "centre");
    const physics::BodyId end = bodyId(step.scene, "end");
    const auto [fc, tc] = springLoad(w, centre);
    const auto [fe, te] = springLoad(w, end);
    RL_VERIFY_NEAR(fc.y(), 2.0, 0, 1e-12);
    RL_VERIFY_NEAR(fe.y(), 2.0, 0, 1e-12);
    RL_VERIFY_NEAR(tc, 0.0, 1e-15, 0);
    RL_VERIFY_NEAR(te, 1.0, 0, 1e-12); // the text's 0.5 m × 2 N
    const double iEnd = w.body(end).inertia;
    run.run(dt);
    RL_VERIFY_NEAR(w.body(centre).velocity.y(), fc.y() / w.body(centre).mass * dt, 0, 1e-9);
    RL_VERIFY_NEAR(w.body(end).velocity.y(), fe.y() / w.body(end).mass * dt, 0, 1e-9);
    RL_VERIFY_NEAR(w.body(end).angularVelocity, te / iEnd * dt, 0, 1e-9);
    RL_VERIFY_NEAR(w.body(centre).angularVelocity, 0.0, 1e-15, 0);
    run.run(0.1 - dt);
    QString message;
    QVERIFY2(judgedRight(step, 0, 2.0 * 0.1, run.measurements[0], &message), qPrintable(message));
    QVERIFY2(judgedRight(step, 1, 0.5 * 2.0 / boxInertia(1, 1, 0.1) * 0.1, run.measurements[0],
                         &message),
             qPrintable(message));
    // Momentum: p_y grows at the two cords' 4 N whatever the rods do.
    RL_VERIFY_NEAR(w.diagnostics().momentum.y() / 0.1, 4.0, 0, 0.01);
}

void TestLessonTopics::accumulatorsSumTheFourForces()
{
    // The table of the first step summed here: weight, cord, push and drag give F = (4, 0) N
    // and τ = 0.5 N m; after one step the lab's velocities changed by exactly F dt / m and
    // τ dt / I.
    ShippedStep pushed("force_accumulators", 0);
    const lessons::LessonStep& step = pushed.step;
    physics::World& w = pushed.run.worlds[0];
    const physics::BodyId crate = bodyId(step.scene, "crate");
    const physics::Body b0 = w.body(crate);
    const physics::Vec2 weight = b0.mass * w.def().gravity;
    const physics::Vec2 drag = -w.def().drag * b0.mass * b0.velocity;
    const double dragTorque = -w.def().drag * b0.inertia * b0.angularVelocity;
    const auto [springs, springTorque] = springLoad(w, crate);
    const physics::Vec2 net = weight + drag + springs;
    const double tau = springTorque + dragTorque;
    RL_VERIFY_NEAR(weight.y(), -20.0, 0, 1e-12);
    RL_VERIFY_NEAR(drag.x(), -1.0, 0, 1e-12);
    RL_VERIFY_NEAR(net.x(), 4.0, 0, 1e-12);
    RL_VERIFY_NEAR(net.y(), 0.0, 1e-12, 0);
    RL_VERIFY_NEAR(tau, 0.5, 0, 1e-12);
    RL_VERIFY_NEAR(b0.inertia, boxInertia(2, 0.4, 0.4), 0, 1e-12);
    // The inspector's forces (physics::forceBreakdown): the same four, the same sums.
    const physics::ForceBreakdown shown = physics::forceBreakdown(w, crate);
    QCOMPARE(shown.terms.size(), std::size_t{4});
    RL_VERIFY_NEAR(shown.terms[0].force.y(), weight.y(), 0, 1e-12);
    RL_VERIFY_NEAR(shown.terms[1].force.x(), drag.x(), 0, 1e-12);
    RL_VERIFY_NEAR(shown.force.x(), net.x(), 0, 1e-12);
    RL_VERIFY_NEAR(shown.force.y(), net.y(), 1e-12, 0);
    RL_VERIFY_NEAR(shown.torque, tau, 0, 1e-12);
    // Each spring acts at its anchor on the crate: the cord at the top's middle.
    RL_VERIFY_NEAR((shown.terms[2].point - b0.position).y(), 0.2, 0, 1e-12);
    RL_VERIFY_NEAR(shown.terms[3].torque, 0.5, 0, 1e-12);
    w.step();
    const physics::Body& b1 = w.body(crate);
    const double dt = w.def().dt;
    RL_VERIFY_NEAR((b1.velocity.x() - b0.velocity.x()) / dt * b0.mass, net.x(), 0, 1e-9);
    RL_VERIFY_NEAR((b1.velocity.y() - b0.velocity.y()) / dt * b0.mass, net.y(), 1e-9, 0);
    RL_VERIFY_NEAR((b1.angularVelocity - b0.angularVelocity) / dt * b0.inertia, tau, 0, 1e-9);
}

void TestLessonTopics::accumulatorQuestionsHaveTheirAnswers()
{
    // The textbook answers v = v₀ + (F / m) t and ω = (τ / I) t, with the sums at the start,
    // are judged right; forgetting drag (F = 5 N) or the push's lever arm (τ = 0) is not.
    ShippedStep pushed("force_accumulators", 0);
    const lessons::LessonStep& step = pushed.step;
    const lessons::Measurements& measured = pushed.runToExport();
    QString message;
    const double m = 2, inertia = boxInertia(2, 0.4, 0.4);
    QVERIFY2(judgedRight(step, 0, 1.0 + 4.0 / m * 0.05, measured, &message), qPrintable(message));
    QVERIFY(!judgedRight(step, 0, 1.0 + 5.0 / m * 0.05, measured, &message));
    QVERIFY(!judgedRight(step, 0, 1.0, measured, &message));
    QVERIFY2(judgedRight(step, 1, 0.5 / inertia * 0.02, measured, &message), qPrintable(message));
    QVERIFY(!judgedRight(step, 1, 0.0, measured, &message));
}

void TestLessonTopics::dragAloneDecaysExponentially()
{
    // F = −k m v and M = −k I ω: the speed and the spin fall as exp(−k t); symplectic Euler
    // takes (1 − k dt) of them each step, which is what the lab must do exactly.
    ShippedStep dragged("force_accumulators", 1);
    const lessons::LessonStep& step = dragged.step;
    StepRun& run = dragged.run;
    const physics::World& w = run.worlds[0];
    const physics::BodyId crate = bodyId(step.scene, "crate");
    const double k = w.def().drag, dt = w.def().dt;
    const double v0 = w.body(crate).velocity.norm(), w0 = w.body(crate).angularVelocity;
    run.run(2.0);
    const double steps = std::round(2.0 / dt);
    RL_VERIFY_NEAR(w.body(crate).velocity.norm(), v0 * std::pow(1 - k * dt, steps), 0, 1e-9);
    RL_VERIFY_NEAR(w.body(crate).angularVelocity, w0 * std::pow(1 - k * dt, steps), 0, 1e-9);
    RL_VERIFY_NEAR(w.body(crate).velocity.norm(), v0 * std::exp(-k * 2.0), 0, 1e-3);
    QString message;
    QVERIFY2(judgedRight(step, 0, v0 * std::exp(-k * 2.0), run.measurements[0], &message),
             qPrintable(message));
    QVERIFY2(judgedRight(step, 1, w0 * std::exp(-k * 2.0), run.measurements[0], &message),
             qPrintable(message));
    // Linear (v₀ − k v₀ t) would be far off: the answer 0 is wrong.
    QVERIFY(!judgedRight(step, 0, v0 * (1 - k * 2.0), run.measurements[0], &message));
}

void TestLessonTopics::forceForOneStepIsAnImpulse()
{
    // The text's numbers: 5 N in the accumulator for one step (it is cleared after it) changes
    // the 2 kg crate's velocity by F dt / m = 0.0025 m/s; held every step for 1 s, by 2.5 m/s.
    // Without drag, so that nothing else changes the velocity.
    const lessons::Lesson lesson = shippedLesson("force_accumulators");
    lessons::LessonStep step = stepOf(lesson, 1);
    step.scene.world.drag = 0;
    const physics::BodyId crate = bodyId(step.scene, "crate");
    physics::World once = lessons::buildStepWorlds(step).front();
    physics::World held = once;
    const double dt = once.def().dt, m = once.body(crate).mass;
    const double v0 = once.body(crate).velocity.x();
    const physics::Vec2 push(5, 0);
    once.applyForce(crate, push, 0);
    once.step();
    RL_VERIFY_NEAR(once.body(crate).velocity.x() - v0, 0.0025, 0, 1e-9);
    RL_VERIFY_NEAR(once.body(crate).velocity.x() - v0, push.x() * dt / m, 0, 1e-9);
    // Cleared: the next step without a new push leaves the velocity as it is.
    const double after = once.body(crate).velocity.x();
    once.step();
    RL_VERIFY_NEAR(once.body(crate).velocity.x(), after, 1e-15, 0);
    const auto steps = static_cast<int>(std::round(1.0 / dt));
    for (int i = 0; i < steps; ++i) {
        held.applyForce(crate, push, 0);
        held.step();
    }
    RL_VERIFY_NEAR(held.body(crate).velocity.x() - v0, 2.5, 0, 1e-9);
}

RIGIDLAB_TEST_GUILESS_MAIN(TestLessonTopics)
