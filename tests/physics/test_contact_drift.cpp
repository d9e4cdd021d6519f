// SPDX-License-Identifier: GPL-3.0-or-later
// Energy drift where bodies rest in contact, with every integrator: the shipped ball drop (three
// balls bouncing to rest) and box stack, a minute each, measured as the lab's drift plot
// measures it, (E + dissipated - E0) / |E0|, with what the contacts took added back.
//
// What the integrator alone would do is known exactly here: under gravity alone, Verlet, RK4,
// dopri5 and the implicit midpoint rule are exact, symplectic Euler's error stays below
// m g^2 dt^2 / 2 and does not grow, and explicit Euler gains exactly m g^2 dt^2 / 2 in every step
// a body flies freely (q1 = q0 + h v0 leaves out the h^2 g / 2 of the fall while v grows by
// h g). That gain, counted over the steps each body spends touching nothing, is what the drift
// may be; the contacts may add at most 1 % of E0 on top. (Symplectic Euler, the lab's default,
// drifts 0.24 % on the ball drop, from bounces timed within a step; before the contacts and
// the integrators were composed consistently, Verlet and RK4 drifted 12.6 % and 14.7 % on these
// scenes, explicit Euler 20 % and 29 %.)

#include "build_paths.h"
#include "physics_test_util.h"

#include "format/scene.h"
#include "format/scene_loader.h"

#include <QDir>

using namespace rigidlab;
using namespace rigidlab::test;
using physics::IntegratorKind;

namespace {

constexpr double kSeconds = 60.0;      // simulated time of each run [s]
constexpr double kContactShare = 0.01; // what the contacts may add to the drift [1]

/// A constant acceleration, the same at every stage: what a resting contact's push is.
class ConstantPush final : public physics::OdeSystem {
public:
    explicit ConstantPush(const Eigen::Vector3d& a) : m_a(a) {}
    void acceleration(double, const Eigen::VectorXd&, const Eigen::VectorXd&,
                      Eigen::VectorXd& a) override
    {
        a = m_a;
    }

private:
    Eigen::Vector3d m_a;
};

/// Explicit Euler's exact energy gain in a free step under gravity g [J]: q1 = q0 + h v0,
/// v1 = v0 + h g, so E1 - E0 = m (v0 h g + h^2 g^2 / 2) - m g h v0 = m g^2 h^2 / 2.
double freeStepGain(IntegratorKind kind, double mass, double g, double h)
{
    return kind == IntegratorKind::Euler ? 0.5 * mass * g * g * h * h : 0.0;
}

} // namespace

class TestContactDrift : public QObject {
    Q_OBJECT
private slots:
    void steadyPushIsTheIntegratorsOwn_data();
    void steadyPushIsTheIntegratorsOwn();
    void restingContactsKeepTheEnergy_data();
    void restingContactsKeepTheEnergy();
};

void TestContactDrift::steadyPushIsTheIntegratorsOwn_data()
{
    QTest::addColumn<int>("integrator");
    for (const physics::IntegratorInfo& info : physics::kIntegrators)
        QTest::addRow("%s", std::string(info.name).c_str()) << static_cast<int>(info.kind);
}

// The contact stage moves a resting body by IntegratorInfo::steadyPush dt times the contact's
// change of velocity. That row must be what the integrator itself does with a constant
// acceleration over one step from rest.
void TestContactDrift::steadyPushIsTheIntegratorsOwn()
{
    QFETCH(int, integrator);
    const auto kind = static_cast<IntegratorKind>(integrator);
    const Eigen::Vector3d a(1.5, -9.81, 0.25); // [m/s^2, m/s^2, rad/s^2]
    constexpr double h = 0.01;                 // [s]
    ConstantPush push(a);
    Eigen::VectorXd q = Eigen::VectorXd::Zero(3), v = Eigen::VectorXd::Zero(3);
    physics::makeIntegrator(kind)->step(push, 0.0, h, q, v);
    const double c = physics::integratorInfo(kind).steadyPush;
    for (int i = 0; i < 3; ++i)
        RL_VERIFY_NEAR(q[i], c * h * h * a[i], 1e-15, 1e-12);
}

void TestContactDrift::restingContactsKeepTheEnergy_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<int>("integrator");
    for (const char* scene : {"ball_drop", "box_stack"})
        for (const physics::IntegratorInfo& info : physics::kIntegrators)
            QTest::addRow("%s-%s", scene, std::string(info.name).c_str())
                << QString::fromLatin1(scene) << static_cast<int>(info.kind);
}

void TestContactDrift::restingContactsKeepTheEnergy()
{
    QFETCH(QString, scene);
    QFETCH(int, integrator);
    const auto kind = static_cast<IntegratorKind>(integrator);
    const lessons::SceneLoadResult loaded =
        lessons::loadSceneFile(QDir(rigidlab::test::sourcePath())
                                   .filePath(QStringLiteral("lessons/scenes/%1.json").arg(scene)));
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    physics::World world = lessons::buildWorld(loaded.scene);
    world.setIntegrator(kind);
    world.updateDiagnostics();
    const physics::Diagnostics& d = world.diagnostics();
    const double e0 = d.total - d.dissipated;
    QVERIFY(std::abs(e0) > 1.0); // both scenes start high above the floor: |E0| is the scale

    const double h = world.def().dt, g = world.def().gravity.norm();
    const long long steps = std::llround(kSeconds / h);
    double freeGain = 0.0; // what explicit Euler gains in free flight, summed [J]
    std::vector<char> touching(world.bodies().size());
    for (long long i = 0; i < steps; ++i) {
        std::fill(touching.begin(), touching.end(), 0);
        // Touching: a contact that pushed (one within the margin that pushes nothing leaves
        // the body to its integrator's free flight).
        for (const physics::Contact& c : world.contacts())
            if (c.normalImpulse[0] > 0 || c.normalImpulse[1] > 0)
                for (physics::BodyId id : {c.a, c.b})
                    if (id != physics::kWorld)
                        touching[static_cast<size_t>(id)] = 1;
        for (size_t b = 0; b < world.bodies().size(); ++b)
            if (world.bodies()[b].isDynamic() && !touching[b])
                freeGain += freeStepGain(kind, world.bodies()[b].mass, g, h);
        world.step();
    }
    QVERIFY(!world.divergence());
    const physics::Diagnostics& end = world.diagnostics();
    const double drift = (end.total + end.dissipated - e0) / std::abs(e0);
    const double expected = freeGain / std::abs(e0);
    qInfo("%s, %s: drift %.3g %%, explicit Euler's free flight %.3g %%", qPrintable(scene),
          std::string(physics::integratorName(kind)).c_str(), 100.0 * drift, 100.0 * expected);
    RL_VERIFY_AT_MOST(std::abs(drift - expected), kContactShare);
}

QTEST_GUILESS_MAIN(TestContactDrift)
#include "test_contact_drift.moc"
