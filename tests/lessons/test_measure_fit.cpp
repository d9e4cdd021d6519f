// SPDX-License-Identifier: GPL-3.0-or-later
// The minimisers, and fits on synthetic measurements: the lab runs a scene with known
// parameters, Gaussian noise of a stated σ is added, and the fit must find the parameters
// again, with a 95 % interval that holds the true value in at least 90 % of seeded trials.
// (The fit's coverage against an exact model, not the lab, is test_fit_coverage.cpp.)
#include "test_main.h"
#include "test_measure.h"

#include "format/scene_loader.h"
#include "measure/fit.h"
#include "measure/minimise.h"
#include "physics/physics_test_util.h"

#include <QDir>
#include <QTest>

#include <cmath>
#include <random>

using namespace rigidlab;
using measure::Quantity;

namespace {

lessons::Scene sampleScene(const char* name)
{
    const auto loaded = lessons::loadSceneFile(
        QDir(test::kMeasureSamples).filePath(QLatin1StringView(name) + QStringLiteral(".json")));
    if (!loaded.ok)
        qFatal("%s", qPrintable(loaded.error));
    return loaded.scene;
}

measure::Parameter parameter(const char* text, const lessons::Scene& scene)
{
    QString error;
    const auto p = measure::parseParameter(QLatin1StringView(text), scene, error);
    if (!p)
        qFatal("%s", qPrintable(error));
    return *p;
}

measure::Target target(const char* text, const lessons::Scene& scene)
{
    QString error;
    const auto t = measure::parseTarget(QLatin1StringView(text), scene, error);
    if (!t)
        qFatal("%s", qPrintable(error));
    return *t;
}

/// The lab's own run at `frames` frames a second for `seconds`, plus noise of σ.
measure::Series synthetic(const lessons::Scene& scene, const measure::Target& t, double seconds,
                          double frames, double sigma, unsigned seed)
{
    measure::Series s;
    s.quantity = t.quantity;
    for (int i = 0; i / frames <= seconds + 1e-9; ++i)
        s.t.push_back(i / frames);
    const measure::Simulated sim = measure::simulateAt(scene, t, s.t);
    if (!sim.ok)
        qFatal("%s", qPrintable(sim.error));
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, sigma);
    for (double v : sim.values)
        s.value.push_back(v + noise(rng));
    return s;
}

struct Trials {
    int covered = 0;
    double worst = 0; ///< largest |fitted − true|
};

/// Seeded trials of a one-parameter fit. The measurement is the lab's run at a step of
/// `dataStep`, small enough that its own step error is far below the noise: the fit's model is
/// the continuous one (it halves the scene's step until that no longer matters), so data made
/// at the scene's own step would carry that step's error as a bias.
Trials runTrials(const lessons::Scene& scene, const measure::Parameter& p, const measure::Target& t,
                 double truth, double seconds, double sigma, double dataStep, unsigned count)
{
    lessons::Scene truthScene = scene;
    measure::setParameter(truthScene, p, truth);
    truthScene.world.dt = dataStep;
    const measure::Series clean = synthetic(truthScene, t, seconds, 60.0, 0.0, 0);
    Trials trials;
    for (unsigned seed = 1; seed <= count; ++seed) {
        measure::Series s = clean;
        std::mt19937 rng(seed);
        std::normal_distribution<double> noise(0.0, sigma);
        for (double& v : s.value)
            v += noise(rng);
        const measure::FitResult fit = measure::fitScene(scene, {p}, t, s);
        if (!fit.ok)
            qFatal("%s", qPrintable(fit.error));
        const double error = std::abs(fit.values[0].value - truth);
        trials.worst = std::max(trials.worst, error);
        trials.covered += error <= fit.values[0].halfWidth95 ? 1 : 0;
        // The residuals are the noise: their RMS is σ within a third.
        if (std::abs(fit.rms - sigma) > sigma / 3)
            qFatal("seed %u: residual RMS %g, noise %g", seed, fit.rms, sigma);
    }
    return trials;
}

/// Bounce times of a ball dropped from height h onto a floor with restitution e [s].
std::vector<double> bounceTimes(double h, double e, int count)
{
    const double g = 9.81;
    std::vector<double> t{std::sqrt(2 * h / g)};
    double v = e * std::sqrt(2 * g * h);
    while (static_cast<int>(t.size()) < count) {
        t.push_back(t.back() + 2 * v / g);
        v *= e;
    }
    return t;
}

} // namespace

void TestMeasure::brentFindsMinimum()
{
    const auto m = measure::minimiseBrent([](double x) { return std::pow(x - 0.3, 2) + 1; }, 0, 1);
    RL_VERIFY_NEAR(m.x[0], 0.3, 1e-6, 0);
    RL_VERIFY_NEAR(m.value, 1.0, 1e-12, 0);
    QVERIFY(m.evaluations > 2 && m.evaluations < 60);
    // A minimum on the bound.
    const auto edge = measure::minimiseBrent([](double x) { return x; }, 0.2, 1);
    RL_VERIFY_NEAR(edge.x[0], 0.2, 1e-6, 0);
}

void TestMeasure::nelderMeadFindsMinimum()
{
    const auto rosenbrock = [](const std::vector<double>& x) {
        return 100 * std::pow(x[1] - x[0] * x[0], 2) + std::pow(1 - x[0], 2);
    };
    const auto m = measure::minimiseNelderMead(rosenbrock, {-1.2, 1.0}, {0.1, 0.1}, {-2, -2},
                                               {2, 2}, 1e-14, 2000);
    RL_VERIFY_NEAR(m.x[0], 1.0, 1e-4, 0);
    RL_VERIFY_NEAR(m.x[1], 1.0, 1e-4, 0);
    // Bounds hold: the unbounded minimum (3, -1) lies outside [0, 2] × [0, 2].
    const auto bowl = [](const std::vector<double>& x) {
        return std::pow(x[0] - 3, 2) + std::pow(x[1] + 1, 2);
    };
    const auto b = measure::minimiseNelderMead(bowl, {1, 1}, {0.2, 0.2}, {0, 0}, {2, 2});
    RL_VERIFY_NEAR(b.x[0], 2.0, 1e-6, 0);
    RL_VERIFY_NEAR(b.x[1], 0.0, 1e-6, 0);
}

void TestMeasure::gridFindsDeeperDip()
{
    // Two dips: a shallow one at 0.2 and the deepest at 0.8; Brent alone from the middle
    // of [0, 1] may end in either.
    const auto f = [](const std::vector<double>& x) {
        return -0.5 * std::exp(-std::pow((x[0] - 0.2) / 0.05, 2)) -
               std::exp(-std::pow((x[0] - 0.8) / 0.05, 2));
    };
    const auto m = measure::minimiseInBounds(f, {0}, {1}, 21);
    RL_VERIFY_NEAR(m.x[0], 0.8, 1e-5, 0);
    const auto f2 = [&](const std::vector<double>& x) {
        return f({x[0]}) + std::pow(x[1] - 0.5, 2);
    };
    const auto m2 = measure::minimiseInBounds(f2, {0, 0}, {1, 1}, 11);
    RL_VERIFY_NEAR(m2.x[0], 0.8, 1e-4, 0);
    RL_VERIFY_NEAR(m2.x[1], 0.5, 1e-4, 0);
}

void TestMeasure::parsesParametersAndTargets_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("isTarget");
    QTest::addColumn<QString>("error");
    QTest::newRow("restitution-all") << "restitution" << false << "";
    QTest::newRow("restitution-body") << "restitution:ball" << false << "";
    QTest::newRow("friction-pair") << "friction:ball,floor" << false << "";
    QTest::newRow("vx") << "vx:ball" << false << "";
    QTest::newRow("unknown-param") << "drag:ball" << false
                                   << "unknown parameter \"drag\" (expected restitution, friction, "
                                      "vx or vy)";
    QTest::newRow("unknown-body") << "restitution:nope" << false
                                  << "unknown body \"nope\" (the scene has: floor, ball)";
    QTest::newRow("vx-without-body") << "vx" << false << "vx: name one body, as in vx:ball";
    QTest::newRow("target") << "y:ball" << true << "";
    QTest::newRow("target-speed") << "v:ball" << true << "";
    QTest::newRow("target-no-body") << "y" << true
                                    << "\"y\": expected QUANTITY:BODY with QUANTITY x, y, vx, vy "
                                       "or v, as in y:ball";
    QTest::newRow("target-time") << "t:ball" << true
                                 << "\"t:ball\": expected QUANTITY:BODY with QUANTITY x, y, vx, "
                                    "vy or v, as in y:ball";
    QTest::newRow("target-unknown-body")
        << "y:wall" << true << "unknown body \"wall\" (the scene has: floor, ball)";
    QTest::newRow("target-static-body")
        << "y:floor" << true
        << "\"y:floor\": floor does not move by itself (it is not a dynamic body): measure one "
           "that does";
}

void TestMeasure::parsesParametersAndTargets()
{
    QFETCH(QString, text);
    QFETCH(bool, isTarget);
    QFETCH(QString, error);
    const lessons::Scene scene = sampleScene("ball_floor");
    QString got;
    const bool ok = isTarget ? measure::parseTarget(text, scene, got).has_value()
                             : measure::parseParameter(text, scene, got).has_value();
    QCOMPARE(ok, error.isEmpty());
    QCOMPARE(got, error);
}

void TestMeasure::simulatedSamplesInterpolate()
{
    // Free fall from rest. Symplectic Euler's steps land on y0 − g t²/2 − g t dt/2 exactly
    // (v first, then x); between steps the line between them is within g dt²/8 of that.
    lessons::Scene scene = sampleScene("ball_floor");
    const measure::Target t = target("y:ball", scene);
    const std::vector<double> times{0.0, 0.1, 0.1234, 0.3};
    const measure::Simulated s = measure::simulateAt(scene, t, times);
    QVERIFY2(s.ok, qPrintable(s.error));
    for (std::size_t i = 0; i < times.size(); ++i)
        RL_VERIFY_NEAR(s.values[i],
                       1.05 - 0.5 * 9.81 * times[i] * times[i] - 0.5 * 9.81 * times[i] * 0.002,
                       9.81 * 0.002 * 0.002 / 8 + 1e-12, 0);
    // The parameter reaches the simulation through the scene definition.
    const measure::Parameter e = parameter("restitution:ball", scene);
    QCOMPARE(measure::parameterValue(scene, e), 0.8);
    measure::setParameter(scene, e, 0.4);
    QCOMPARE(measure::parameterValue(scene, e), 0.4);
    QCOMPARE(lessons::buildWorld(scene).body(1).restitution, 0.4);
}

void TestMeasure::exactFlightsAreTheLabsLimit()
{
    // The fit models a ball on a floor by its exact flights (exact_flights.h), the limit of
    // the lab's own run as the step goes to zero: the lab at 10 µs, filmed at 60 frames a
    // second for 1.6 s (three bounces) without noise, gives back its e = 0.72 to a part in a
    // thousand, and the flights follow it to a fraction of a millimetre.
    lessons::Scene scene = sampleScene("ball_floor");
    const measure::Parameter e = parameter("restitution:ball", scene);
    const measure::Target y = target("y:ball", scene);
    lessons::Scene fine = scene;
    measure::setParameter(fine, e, 0.72);
    fine.world.dt = 1e-5;
    const measure::Series s = synthetic(fine, y, 1.6, 60.0, 0.0, 1);
    const measure::FitResult fit = measure::fitScene(scene, {e}, y, s);
    QVERIFY2(fit.ok, qPrintable(fit.error));
    QVERIFY(fit.exact);
    RL_VERIFY_NEAR(fit.values[0].value, 0.72, 1e-3, 0);
    RL_VERIFY_AT_MOST(fit.rms, 5e-4);
}

void TestMeasure::fitsFriction()
{
    // A box pushed off at 3 m/s slides to a stop, filmed at 60 frames a second for 1 s;
    // position noise σ = 3 mm. The pair's μ: both bodies get the value. The lab's run, in the
    // loop, at the step the fit chooses; 20 trials (each fit halves the step a few times).
    const lessons::Scene scene = sampleScene("box_slide");
    const Trials trials = runTrials(scene, parameter("friction:box,floor", scene),
                                    target("x:box", scene), 0.33, 1.0, 0.003, 2e-5, 20);
    RL_VERIFY_AT_MOST(trials.worst, 0.02);
    QVERIFY2(trials.covered >= 17,
             qPrintable(QStringLiteral("covered %1 of 20").arg(trials.covered)));
}

void TestMeasure::fitsTwoParameters()
{
    // μ and the push-off speed together, from the same sliding box (Nelder–Mead).
    const lessons::Scene scene = sampleScene("box_slide");
    const std::vector<measure::Parameter> params{parameter("friction:box,floor", scene),
                                                 parameter("vx:box", scene)};
    const measure::Target t = target("x:box", scene);
    lessons::Scene truth = scene;
    measure::setParameter(truth, params[0], 0.25);
    measure::setParameter(truth, params[1], 2.6);
    for (unsigned seed = 1; seed <= 3; ++seed) {
        const measure::Series s = synthetic(truth, t, 1.2, 60.0, 0.003, seed);
        const measure::FitResult fit = measure::fitScene(scene, params, t, s);
        QVERIFY2(fit.ok, qPrintable(fit.error));
        RL_VERIFY_NEAR(fit.values[0].value, 0.25, 0.02, 0);
        RL_VERIFY_NEAR(fit.values[1].value, 2.6, 0.05, 0);
        QVERIFY(fit.values[0].standardError > 0 && fit.values[1].standardError > 0);
        QCOMPARE(int(fit.residuals.size()), int(s.t.size()));
    }
}

void TestMeasure::bounceTimesGiveRestitution()
{
    // Exact bounce times of e = 0.8 from 1 m, timing noise σ = 1 ms: e within 0.005, the
    // 95 % interval holding it in 90 % of 50 trials.
    const std::vector<double> exact = bounceTimes(1.0, 0.8, 8);
    int covered = 0;
    for (unsigned seed = 1; seed <= 50; ++seed) {
        std::mt19937 rng(seed);
        std::normal_distribution<double> noise(0.0, 0.001);
        std::vector<double> times = exact;
        for (double& t : times)
            t += noise(rng);
        const measure::BounceFit fit = measure::fitBounceTimes(times);
        QVERIFY2(fit.ok, qPrintable(fit.error));
        RL_VERIFY_NEAR(fit.e.value, 0.8, 0.005, 0);
        covered += std::abs(fit.e.value - 0.8) <= fit.e.halfWidth95 ? 1 : 0;
    }
    QVERIFY2(covered >= 45, qPrintable(QStringLiteral("covered %1 of 50").arg(covered)));
    // Without noise the relation is exact.
    const measure::BounceFit exactFit = measure::fitBounceTimes(bounceTimes(0.5, 0.65, 6));
    RL_VERIFY_NEAR(exactFit.e.value, 0.65, 1e-12, 0);
    QCOMPARE(int(exactFit.flightTimes.size()), 5);
}

void TestMeasure::bounceTimesFromTheLab()
{
    // The lab's own bounces (the vertical velocity turns up) of e = 0.72 at dt = 0.5 ms, with
    // 1 ms of timing noise.
    lessons::Scene scene = sampleScene("ball_floor");
    measure::setParameter(scene, parameter("restitution:ball", scene), 0.72);
    scene.world.dt = 0.0005;
    physics::World world = lessons::buildWorld(scene);
    std::vector<double> bounces;
    double vy = 0;
    while (bounces.size() < 7 && world.time() < 5) {
        world.step();
        const double now = world.body(1).velocity.y();
        if (vy < 0 && now >= 0)
            bounces.push_back(world.time());
        vy = now;
    }
    QCOMPARE(int(bounces.size()), 7);
    std::mt19937 rng(7);
    std::normal_distribution<double> noise(0.0, 0.001);
    for (double& t : bounces)
        t += noise(rng);
    const measure::BounceFit fit = measure::fitBounceTimes(bounces);
    QVERIFY2(fit.ok, qPrintable(fit.error));
    RL_VERIFY_NEAR(fit.e.value, 0.72, 0.005, 0);
}

void TestMeasure::refusesUnfittable()
{
    // Friction does not move a ball dropped straight down: said, not a made-up value.
    const lessons::Scene scene = sampleScene("ball_floor");
    const measure::Target t = target("y:ball", scene);
    const measure::Series s = synthetic(scene, t, 0.5, 60.0, 0.001, 1);
    const measure::FitResult fit =
        measure::fitScene(scene, {parameter("friction:ball", scene)}, t, s);
    QVERIFY(!fit.ok);
    QCOMPARE(fit.error,
             QStringLiteral("the measurement does not depend on friction:ball: it cannot "
                            "be fitted from it"));
    // Too few points, too few bounces, flights that grow.
    measure::Series two = s;
    two.t.resize(1);
    two.value.resize(1);
    QCOMPARE(measure::fitScene(scene, {parameter("restitution:ball", scene)}, t, two).error,
             QStringLiteral("1 points cannot fit 1 parameters: measure more"));
    QCOMPARE(measure::fitBounceTimes({0.4, 1.0, 1.5}).error,
             QStringLiteral("3 bounce times: e needs at least 4 (three flights between them)"));
    QVERIFY(!measure::fitBounceTimes({0.4, 0.8, 1.3, 1.9}).ok);
}
