// SPDX-License-Identifier: GPL-3.0-or-later
// Does the fit's 95 % interval mean what it says? Measurements made by an exact model written
// here, not by the lab (a ball dropped from rest bounces with e; its bounce times and flights
// in closed form, looked up flight by flight), filmed at 60, 120 and 240 frames a second from
// a random first frame, with Gaussian height noise: in 50 seeded trials per frame rate the
// interval must hold the true e at least 45 times. And the data that cannot give e (a ball at
// rest, no bounce yet, noise larger than the bounces, frames read as bounce times, a
// measurement starting long after the scene) are refused in one line, with no number.

#include "build_paths.h"
#include "test_main.h"

#include "format/scene_loader.h"
#include "measure/fit.h"
#include "physics/physics_test_util.h"

#include <QDir>
#include <QElapsedTimer>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <random>

using namespace rigidlab;

namespace {

const QString kSamples = rigidlab::test::sourcePath(u"/lessons/measure/samples");

constexpr double kG = 9.81;        ///< ball_floor.json's gravity [m/s²]
constexpr double kRadius = 0.05;   ///< its ball [m]
constexpr double kDropFrom = 1.05; ///< the ball's centre at rest at t = 0 [m]
constexpr double kNoise = 0.002;   ///< height noise, one standard deviation [m]

lessons::Scene ballFloor()
{
    const auto loaded = lessons::loadSceneFile(QDir(kSamples).filePath("ball_floor.json"));
    if (!loaded.ok)
        qFatal("%s", qPrintable(loaded.error));
    return loaded.scene;
}

/// The ball's centre height at time t, dropped from rest at kDropFrom onto a floor at 0:
/// bounce k at T_k, leaving at speed u e^k; found by walking the bounce list.
class DroppedBall {
public:
    explicit DroppedBall(double e)
    {
        const double fall = std::sqrt(2 * (kDropFrom - kRadius) / kG);
        double up = e * kG * fall; // speed after the first bounce
        m_bounces.push_back(fall);
        m_speeds.push_back(up);
        while (up > 1e-3 && m_bounces.size() < 200) {
            m_bounces.push_back(m_bounces.back() + 2 * up / kG);
            up *= e;
            m_speeds.push_back(up);
        }
    }
    double height(double t) const
    {
        if (t < m_bounces.front())
            return kDropFrom - 0.5 * kG * t * t;
        const auto k = static_cast<std::size_t>(
            std::upper_bound(m_bounces.begin(), m_bounces.end(), t) - m_bounces.begin() - 1);
        if (k + 1 == m_bounces.size() && t > m_bounces.back() + 2 * m_speeds[k] / kG)
            return kRadius; // at rest
        const double tau = t - m_bounces[k];
        return kRadius + m_speeds[k] * tau - 0.5 * kG * tau * tau;
    }

private:
    std::vector<double> m_bounces; ///< [s]
    std::vector<double> m_speeds;  ///< leaving each bounce [m/s]
};

/// Heights of the ball filmed at `fps` over [from, to] from a random first frame, with noise.
measure::Series filmed(const DroppedBall& ball, double fps, double from, double to, double noise,
                       std::mt19937& rng)
{
    std::uniform_real_distribution<double> phase(0.0, 1.0 / fps);
    std::normal_distribution<double> error(0.0, noise);
    measure::Series s;
    s.quantity = measure::Quantity::Y;
    for (double t = from + phase(rng); t <= to; t += 1.0 / fps) {
        s.t.push_back(t);
        s.value.push_back(ball.height(t) + error(rng));
    }
    return s;
}

measure::Parameter restitution(const lessons::Scene& scene)
{
    QString error;
    const auto p = measure::parseParameter(QStringLiteral("restitution:ball"), scene, error);
    if (!p)
        qFatal("%s", qPrintable(error));
    return *p;
}

measure::Target height(const lessons::Scene& scene)
{
    QString error;
    const auto t = measure::parseTarget(QStringLiteral("y:ball"), scene, error);
    if (!t)
        qFatal("%s", qPrintable(error));
    return *t;
}

/// A refusal says so in one line and gives no value.
bool refusedWithoutNumber(const measure::FitResult& fit)
{
    return !fit.ok && fit.values.empty() && !fit.error.isEmpty() && !fit.error.contains(u'\n') &&
           (fit.error.contains(QStringLiteral("cannot be determined")) ||
            fit.error.contains(QStringLiteral("cannot be fitted")));
}

} // namespace

class TestFitCoverage : public QObject {
    Q_OBJECT

private slots:
    void intervalCoversTheTruth_data()
    {
        QTest::addColumn<double>("fps");
        QTest::newRow("60 fps") << 60.0;
        QTest::newRow("120 fps") << 120.0;
        QTest::newRow("240 fps") << 240.0;
    }
    void intervalCoversTheTruth()
    {
        QFETCH(double, fps);
        const lessons::Scene scene = ballFloor();
        const measure::Parameter e = restitution(scene);
        const measure::Target y = height(scene);
        int covered = 0;
        double worst = 0;
        for (unsigned seed = 1; seed <= 50; ++seed) {
            std::mt19937 rng(seed);
            const double truth = std::uniform_real_distribution<double>(0.55, 0.9)(rng);
            const measure::Series s = filmed(DroppedBall(truth), fps, 0.0, 2.0, kNoise, rng);
            const measure::FitResult fit = measure::fitScene(scene, {e}, y, s);
            QVERIFY2(fit.ok, qPrintable(fit.error));
            QVERIFY(fit.exact);
            const double miss = std::abs(fit.values[0].value - truth);
            worst = std::max(worst, miss / fit.values[0].halfWidth95);
            covered += miss <= fit.values[0].halfWidth95 ? 1 : 0;
        }
        qInfo("%g fps: the 95 %% interval held the true e in %d of 50 (worst miss %.2f "
              "half-widths)",
              fps, covered, worst);
        QVERIFY2(covered >= 45, qPrintable(QStringLiteral("covered %1 of 50").arg(covered)));
    }

    void labRunHasNegligibleStepError()
    {
        // The same measurement fitted with the lab's run instead of the exact flights: the
        // fit halves the step until that no longer matters (or adds what it still moves), and
        // its interval holds the truth the exact model made.
        const lessons::Scene scene = ballFloor();
        std::mt19937 rng(11);
        const double truth = 0.8;
        const measure::Series s = filmed(DroppedBall(truth), 240.0, 0.0, 1.3, kNoise, rng);
        measure::FitOptions options;
        options.exactWherePossible = false;
        const measure::FitResult fit =
            measure::fitScene(scene, {restitution(scene)}, height(scene), s, options);
        QVERIFY2(fit.ok, qPrintable(fit.error));
        QVERIFY(!fit.exact);
        QVERIFY2(fit.step < scene.world.dt, qPrintable(QString::number(fit.step)));
        const double miss = std::abs(fit.values[0].value - truth);
        QVERIFY2(miss <= fit.values[0].halfWidth95,
                 qPrintable(QStringLiteral("e = %1 ± %2, truth %3; %4")
                                .arg(fit.values[0].value)
                                .arg(fit.values[0].halfWidth95)
                                .arg(truth)
                                .arg(measure::describeModel(fit, {restitution(scene)}))));
        QVERIFY(fit.stepErrorAdded ||
                std::abs(fit.stepChange[0]) <= fit.values[0].standardError / 3);
    }

    void undeterminedIsRefused_data()
    {
        QTest::addColumn<double>("from");
        QTest::addColumn<double>("to");
        QTest::addColumn<double>("noise");
        // The ball lies still from about 3 s for every e up to 0.9.
        QTest::newRow("ball at rest") << 20.0 << 22.0 << kNoise;
        // The first bounce comes at 0.45 s.
        QTest::newRow("no bounce yet") << 0.0 << 0.4 << kNoise;
        // One bounce, lost in noise of half a metre.
        QTest::newRow("noise larger than the bounce") << 0.0 << 0.6 << 0.5;
        // Long after the scene starts (a forgotten time zero): at rest, and fast.
        QTest::newRow("long offset") << 3000.0 << 3002.0 << kNoise;
    }
    void undeterminedIsRefused()
    {
        QFETCH(double, from);
        QFETCH(double, to);
        QFETCH(double, noise);
        const lessons::Scene scene = ballFloor();
        std::mt19937 rng(5);
        const measure::Series s = filmed(DroppedBall(0.7), 60.0, from, to, noise, rng);
        QElapsedTimer clock;
        clock.start();
        const measure::FitResult fit =
            measure::fitScene(scene, {restitution(scene)}, height(scene), s);
        QVERIFY2(refusedWithoutNumber(fit),
                 qPrintable(fit.ok ? QStringLiteral("fitted") : fit.error));
        QVERIFY(fit.error.contains(QStringLiteral("restitution:ball")));
        RL_VERIFY_AT_MOST(clock.elapsed(), 2000);
    }

    void longOffsetWithTheLabIsRefusedAtOnce()
    {
        // With the lab's run the same measurement would take minutes of steps: refused before
        // the first, with the way out.
        const lessons::Scene scene = ballFloor();
        std::mt19937 rng(5);
        const measure::Series s = filmed(DroppedBall(0.7), 60.0, 3000.0, 3002.0, kNoise, rng);
        measure::FitOptions options;
        options.exactWherePossible = false;
        QElapsedTimer clock;
        clock.start();
        const measure::FitResult fit =
            measure::fitScene(scene, {restitution(scene)}, height(scene), s, options);
        QVERIFY(!fit.ok);
        QVERIFY2(fit.error.contains(QStringLiteral("--time-zero")), qPrintable(fit.error));
        RL_VERIFY_AT_MOST(clock.elapsed(), 100);
    }

    void framesAreNotBounceTimes()
    {
        // A column of frame times read as bounce times: evenly spaced, and too many.
        std::vector<double> frames;
        for (int i = 0; i < 30; ++i)
            frames.push_back(i / 240.0);
        const measure::BounceFit few = measure::fitBounceTimes(frames);
        QVERIFY(!few.ok);
        QVERIFY2(few.error.contains(QStringLiteral("do not get shorter")), qPrintable(few.error));
        for (int i = 30; i < 1000; ++i)
            frames.push_back(i / 240.0);
        const measure::BounceFit many = measure::fitBounceTimes(frames);
        QVERIFY(!many.ok);
        QVERIFY2(many.error.startsWith(QStringLiteral("1000 bounce times: more than a ball")),
                 qPrintable(many.error));
    }
};

RIGIDLAB_TEST_GUILESS_MAIN(TestFitCoverage)
#include "test_fit_coverage.moc"
