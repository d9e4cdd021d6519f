// SPDX-License-Identifier: GPL-3.0-or-later
// Worlds that stop where a lesson's text says (stiff springs, the pendulum with Euler), explicit
// Euler's energy growth against theory, and the command line's words for a divergence.

#include "physics/physics_test_util.h"
#include "test_lesson.h"
#include "test_lesson_physics.h"

#include "format/divergence_message.h"

#include <QRegularExpression>

#include <cmath>

using namespace rigidlab;
using namespace rigidlab::test;

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
    QTest::newRow("stiff-euler") << "stiff_springs" << 0 << "at about 30\u00a0s" << QList<int>{0}
                                 << 1.0;
    QTest::newRow("stiff-verlet") << "stiff_springs" << 2 << "Verlet after about 0.05\u00a0s"
                                  << QList<int>{2} << 0.005;
    QTest::newRow("stiff-symplectic-euler")
        << "stiff_springs" << 2 << "symplectic Euler after about 0.24\u00a0s" << QList<int>{1}
        << 0.005;
    QTest::newRow("stiff-rk4") << "stiff_springs" << 3 << "stops it after about 0.28\u00a0s"
                               << QList<int>{3} << 0.005;
    QTest::newRow("stiff-four-steps")
        << "stiff_springs" << 3 << "after four steps, 0.02\u00a0s" << QList<int>{1, 2} << 1e-9;
    QTest::newRow("pendulum-euler")
        << "energy_drift" << 2 << "at about 16\u00a0s" << QList<int>{0} << 0.5;
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
        QRegularExpression(QStringLiteral("(\\d+(\\.\\d+)?)\\x{00A0}s")).match(phrase);
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
    QVERIFY(s.text.contains(QStringLiteral("after about 4.6\u00a0s its energy is ten times")));
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
