// SPDX-License-Identifier: GPL-3.0-or-later
// The stress suite (see stress.h): every case builds its worlds in code, runs them, and
// judges them by what happened, against the verdict it is documented to have.

#include "numerics/stress.h"

#include "format/divergence_message.h"

#include "rigidlab/physics/shape.h"
#include "rigidlab/physics/world.h"

#include <Eigen/Eigenvalues>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>

namespace rigidlab::lessons {

using physics::BodyDef;
using physics::BodyType;
using physics::IntegratorKind;
using physics::Vec2;
using physics::World;
using physics::WorldDef;

namespace {

/// Stress runs count as diverged when the energy grows to this many times its scale.
constexpr double kEnergyGrowthBound = 10.0;
constexpr double kPenetrationLimit = 0.01; ///< [m], twice the allowed slop
constexpr double kJitterSpeed = 0.05;      ///< [m/s]

QString name(IntegratorKind k)
{
    const std::string_view n = physics::integratorName(k);
    return QString::fromUtf8(n.data(), static_cast<qsizetype>(n.size()));
}

/// "m1", "b12": ids of numbered bodies.
std::string numbered(char prefix, int i)
{
    std::string id(1, prefix);
    id += std::to_string(i);
    return id;
}

QString seconds(double s)
{
    return QString::number(s, 'g', 3) + QStringLiteral(" s");
}

struct Outcome {
    std::optional<physics::Divergence> divergence;
    double growth = 1;
    double penetration = 0;
    double finalSpeed = 0; ///< fastest dynamic body at the end [m/s]
};

Outcome simulate(World& w, double tEnd)
{
    w.divergenceSettings().energyGrowth = kEnergyGrowthBound;
    w.updateDiagnostics();
    const physics::Diagnostics& d0 = w.diagnostics();
    const double e0 = d0.total;
    double scale = physics::energyParts(d0);
    if (!(scale > 0))
        scale = 1.0;
    Outcome out;
    const long long steps = std::max(1LL, std::llround(tEnd / w.def().dt));
    for (long long i = 0; i < steps; ++i) {
        w.step();
        if (w.divergence()) {
            out.divergence = w.divergence();
            break;
        }
        out.growth = std::max(out.growth, 1.0 + (w.diagnostics().total - e0) / scale);
        for (const physics::Contact& c : w.contacts())
            for (int k = 0; k < c.manifold.pointCount; ++k)
                out.penetration = std::max(out.penetration,
                                           -c.manifold.points[static_cast<size_t>(k)].separation);
    }
    for (const physics::Body& b : w.bodies())
        if (b.isDynamic())
            out.finalSpeed = std::max(out.finalSpeed, b.velocity.norm());
    return out;
}

struct Judge {
    std::function<bool(const World&)> tunnelled; ///< optional
    bool restExpected = false;                   ///< check for jitter at the end
    double penetrationLimit = kPenetrationLimit;
};

void judge(StressRow& row, const World& w, const Outcome& o, const Judge& j)
{
    row.energyGrowth = o.growth;
    row.penetration = o.penetration;
    if (o.divergence) {
        row.verdict = QStringLiteral("diverged at t = ") + seconds(o.divergence->time);
        row.diagnosis = divergenceMessage(*o.divergence);
    } else if (j.tunnelled && j.tunnelled(w)) {
        row.verdict = QStringLiteral("tunnelled");
    } else if (o.penetration > j.penetrationLimit) {
        row.verdict = QStringLiteral("penetrating");
    } else if (j.restExpected && o.finalSpeed > kJitterSpeed) {
        row.verdict = QStringLiteral("jittering");
    } else {
        row.verdict = QStringLiteral("stable");
    }
}

WorldDef def(IntegratorKind k, double dt, bool gravity = true)
{
    WorldDef d;
    d.integrator = k;
    d.dt = dt;
    if (!gravity)
        d.gravity = Vec2::Zero();
    return d;
}

BodyDef box(const std::string& id, double w, double h, const Vec2& at, double mass = 0,
            BodyType type = BodyType::Dynamic)
{
    BodyDef b;
    b.name = id;
    b.shape = physics::makePolygonShape(physics::makeBox(w, h));
    b.position = at;
    b.mass = mass;
    b.type = type;
    return b;
}

BodyDef ball(const std::string& id, double r, const Vec2& at, double mass = 0)
{
    BodyDef b;
    b.name = id;
    b.shape = physics::makeCircleShape(r);
    b.position = at;
    b.mass = mass;
    return b;
}

/// The ground: a static 40 m x 1 m box whose top is at y = top.
void addGround(World& w, double top = 0.0, double x = 0.0)
{
    w.addBody(box("ground", 40.0, 1.0, Vec2(x, top - 0.5), 0, BodyType::Static));
}

// ---------------------------------------------------------------------------------------------
// stiff-spring: m = 1 kg on a spring of k = 1, 1e4, 1e7 N/m, dt = 1 ms, for 20 periods.

World oscillator(IntegratorKind k, double dt, double stiffness)
{
    World w(def(k, dt, false));
    BodyDef b = ball("mass", 0.05, Vec2(0.01, 0.0), 1.0);
    b.collide = false;
    const auto id = w.addBody(b);
    physics::SpringDef s;
    s.a = id;
    s.anchorB = Vec2(-2.0, 0.0);
    s.stiffness = stiffness;
    s.restLength = 2.0;
    w.addSpring(s);
    return w;
}

/// The theoretical limit of w dt for a method on an undamped oscillator, 0 for none (the
/// integrator's own, physics::IntegratorInfo).
double stabilityBound(IntegratorKind k)
{
    return physics::integratorInfo(k).stabilityBound;
}

QString limitText(IntegratorKind k, double omega)
{
    switch (physics::integratorInfo(k).stability) {
    case physics::Stability::Unstable:
        return QStringLiteral("none: energy x (1 + (w dt)^2) per step");
    case physics::Stability::Adaptive:
        return QStringLiteral("adaptive: substeps as needed");
    case physics::Stability::AStable:
        return QStringLiteral("none: A-stable");
    case physics::Stability::Bounded:
        break;
    }
    return QStringLiteral("w dt < %1: dt < %2")
        .arg(QString::number(stabilityBound(k), 'g', 3), seconds(stabilityBound(k) / omega));
}

/// Scans dt downwards from 0.5 s (60 steps per decade... 1.25x apart) for the largest dt
/// at which 20 periods (at least 200 steps) stay stable.
QString largestStable(const std::function<World(double)>& make, double period)
{
    constexpr int kPoints = 60;
    for (int i = 0; i < kPoints; ++i) {
        const double dt = 0.5 * std::pow(1e-6 / 0.5, static_cast<double>(i) / (kPoints - 1));
        World w = make(dt);
        const double tEnd = std::max(20 * period, 200 * dt);
        if (tEnd / dt > 1e6)
            return QStringLiteral("none down to %1").arg(seconds(dt));
        if (!simulate(w, tEnd).divergence)
            return seconds(dt);
    }
    return QStringLiteral("none down to 1e-06 s");
}

void stiffSpring(std::vector<StressRow>& rows)
{
    for (double k : {1.0, 1e4, 1e7}) {
        const double omega = std::sqrt(k);
        const double period = 2 * std::numbers::pi / omega;
        for (IntegratorKind kind : physics::kAllIntegrators) {
            StressRow row;
            row.caseName = QStringLiteral("stiff-spring");
            row.setup = QStringLiteral("k = %1 N/m, dt = 1 ms").arg(k, 0, 'g', 3);
            row.integrator = name(kind);
            World w = oscillator(kind, 1e-3, k);
            judge(row, w, simulate(w, 20 * period), {});
            // Euler grows at k = 1e4 and 1e7; every explicit method past w dt = its bound at 1e7.
            const bool grows = kind == IntegratorKind::Euler && k >= 1e4;
            const double bound = stabilityBound(kind);
            const bool pastLimit = bound > 0 && omega * 1e-3 > bound;
            row.expected =
                grows || pastLimit ? QStringLiteral("diverged") : QStringLiteral("stable");
            row.limit = limitText(kind, omega);
            if (k == 1e7 && kind != IntegratorKind::DormandPrince)
                row.largestStable =
                    largestStable([&](double dt) { return oscillator(kind, dt, k); }, period);
            rows.push_back(row);
        }
    }
}

// spring-chain: four 1 kg bodies in a line, springs of 1e4 and 1 N/m alternating (a stiffness
// ratio of 1e4), one end held; dt = 10 ms for 10 s. The limit is from the largest eigenvalue
// of M^-1 K.
void springChain(std::vector<StressRow>& rows)
{
    const std::array<double, 4> k{1e4, 1.0, 1e4, 1.0};
    auto make = [&](IntegratorKind kind, double dt) {
        World w(def(kind, dt, false));
        for (int i = 0; i < 4; ++i) {
            BodyDef b =
                ball(numbered('m', i + 1), 0.05, Vec2(i + 1.0 + (i == 3 ? 0.05 : 0.0), 0.0), 1.0);
            b.collide = false;
            w.addBody(b);
        }
        for (int i = 0; i < 4; ++i) {
            physics::SpringDef s;
            s.a = i == 0 ? physics::kWorld : i - 1;
            s.anchorA = Vec2::Zero();
            s.b = i;
            s.stiffness = k[static_cast<size_t>(i)];
            s.restLength = 1.0;
            w.addSpring(s);
        }
        return w;
    };
    // Stiffness matrix of the chain along x: spring i joins body i-1 (or the wall) and body i.
    Eigen::Matrix4d K = Eigen::Matrix4d::Zero();
    for (int i = 0; i < 4; ++i) {
        K(i, i) += k[static_cast<size_t>(i)];
        if (i > 0) {
            K(i - 1, i - 1) += k[static_cast<size_t>(i)];
            K(i - 1, i) -= k[static_cast<size_t>(i)];
            K(i, i - 1) -= k[static_cast<size_t>(i)];
        }
    }
    const double omega =
        std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(K).eigenvalues().maxCoeff());
    for (IntegratorKind kind : physics::kAllIntegrators) {
        StressRow row;
        row.caseName = QStringLiteral("spring-chain");
        row.setup = QStringLiteral("k 1e4 : 1, dt = 10 ms");
        row.integrator = name(kind);
        World w = make(kind, 0.01);
        judge(row, w, simulate(w, 10.0), {});
        row.expected =
            kind == IntegratorKind::Euler ? QStringLiteral("diverged") : QStringLiteral("stable");
        row.limit = limitText(kind, omega);
        if (kind != IntegratorKind::DormandPrince)
            row.largestStable = largestStable([&](double dt) { return make(kind, dt); },
                                              2 * std::numbers::pi / omega);
        rows.push_back(row);
    }
}

// mass-ratio: a heavy 0.5 m box on a light one on the ground, 1:100 and 1:1000, defaults
// (symplectic Euler, sequential impulses, 10 iterations, dt = 1 ms), 2 s.
void massRatio(std::vector<StressRow>& rows)
{
    for (double ratio : {100.0, 1000.0}) {
        World w(def(IntegratorKind::SymplecticEuler, 1e-3));
        addGround(w);
        w.addBody(box("light", 0.5, 0.5, Vec2(0, 0.25), 1.0));
        w.addBody(box("heavy", 0.5, 0.5, Vec2(0, 0.75), ratio));
        StressRow row;
        row.caseName = QStringLiteral("mass-ratio");
        row.setup = QStringLiteral("1:%1 stack").arg(ratio);
        row.integrator = name(IntegratorKind::SymplecticEuler);
        judge(row, w, simulate(w, 2.0), {{}, true});
        row.expected = QStringLiteral("stable");
        rows.push_back(row);
    }
}

// heavy-pendulum: a 100 kg bob hanging on a 1 kg bob, both on 1 m pins, from horizontal.
void heavyPendulum(std::vector<StressRow>& rows)
{
    for (IntegratorKind kind :
         {IntegratorKind::SymplecticEuler, IntegratorKind::Verlet, IntegratorKind::RK4}) {
        World w(def(kind, 1e-3));
        BodyDef light = ball("light", 0.05, Vec2(1, 0), 1.0);
        BodyDef heavy = ball("heavy", 0.1, Vec2(2, 0), 100.0);
        light.collide = heavy.collide = false;
        const auto a = w.addBody(light);
        const auto b = w.addBody(heavy);
        w.addPinJoint({a, Vec2(-1, 0), physics::kWorld, Vec2::Zero()});
        w.addPinJoint({b, Vec2(-1, 0), a, Vec2::Zero()});
        StressRow row;
        row.caseName = QStringLiteral("heavy-pendulum");
        row.setup = QStringLiteral("100 kg on 1 kg, dt = 1 ms");
        row.integrator = name(kind);
        judge(row, w, simulate(w, 10.0), {});
        row.expected = QStringLiteral("stable");
        rows.push_back(row);
    }
}

// bullet: a 5 cm ball at 300 m/s towards a 10 cm wall, dt = 5 ms (1.5 m per step).
void bullet(std::vector<StressRow>& rows)
{
    for (bool continuous : {true, false}) {
        WorldDef d = def(IntegratorKind::SymplecticEuler, 0.005, false);
        d.continuous = continuous;
        World w(d);
        w.addBody(box("wall", 0.1, 2.0, Vec2(1.0, 0.0), 0, BodyType::Static));
        BodyDef b = ball("bullet", 0.025, Vec2(0, 0), 0);
        b.density = 7800;
        b.velocity = Vec2(300, 0);
        w.addBody(b);
        StressRow row;
        row.caseName = QStringLiteral("bullet");
        row.setup = continuous ? QStringLiteral("continuous on") : QStringLiteral("continuous off");
        row.integrator = name(IntegratorKind::SymplecticEuler);
        judge(row, w, simulate(w, 0.05),
              {[](const World& w) { return w.body(1).position.x() > 1.05; }, false});
        row.expected = continuous ? QStringLiteral("stable") : QStringLiteral("tunnelled");
        rows.push_back(row);
    }
}

/// A ball of radius r dropped from 1 m onto the ground (restitution 0.5), judged for falling
/// through the ground and for sinking into it.
void dropRow(std::vector<StressRow>& rows, const QString& caseName, const QString& setup, double dt,
             double tEnd, double r, const Vec2& origin, const QString& expected,
             bool boxShape = false, double spin = 0)
{
    World w(def(IntegratorKind::SymplecticEuler, dt));
    addGround(w, origin.y(), origin.x());
    BodyDef b = boxShape ? box("body", 2 * r, 2 * r, origin + Vec2(0, 1.0))
                         : ball("body", r, origin + Vec2(0, 1.0));
    b.angularVelocity = spin;
    w.addBody(b);
    StressRow row;
    row.caseName = caseName;
    row.setup = setup;
    row.integrator = name(IntegratorKind::SymplecticEuler);
    const double floor = origin.y();
    judge(row, w, simulate(w, tEnd),
          {[floor](const World& w) { return w.body(1).position.y() < floor; }, spin == 0,
           std::min(kPenetrationLimit, r)});
    row.expected = expected;
    rows.push_back(row);
}

void dtRange(std::vector<StressRow>& rows)
{
    // Past 1e-4 s a 10 cm ball falling at 4.4 m/s moves a sizeable part of itself per step.
    // With the soft step (the default) its contact is found before it overlaps once it moves
    // more than the margin in a step, and its impact is solved at its moment, so at 0.01 s it
    // no longer sinks (with sequential impulses: 3 cm, before the position pass catches up).
    // At 0.1 s gravity adds 0.98 m/s a step, and a new contact bounces only from a faster
    // approach (restitutionThreshold, settings.h), so the ball comes to rest (before, with the
    // 0.5 m/s threshold alone, it bounced a little every step); so it does at 0.5 s (2.45 m per
    // step), where the soft step's sweep stops it at the ground's face (with sequential
    // impulses it ended below the ground).
    const std::pair<double, const char*> runs[] = {
        {1e-6, "stable"}, {1e-4, "stable"}, {1e-2, "stable"}, {0.1, "stable"}, {0.5, "stable"}};
    for (const auto& [dt, expected] : runs)
        dropRow(rows, QStringLiteral("dt-range"), QStringLiteral("ball drop, dt = %1 s").arg(dt),
                dt, 2.0, 0.1, Vec2::Zero(), QLatin1String(expected));
}

void tinyBody(std::vector<StressRow>& rows)
{
    dropRow(rows, QStringLiteral("tiny-body"), QStringLiteral("1 mm box, dt = 1 ms"), 1e-3, 2.0,
            0.0005, Vec2::Zero(), QStringLiteral("stable"), true);
}

void farAway(std::vector<StressRow>& rows)
{
    dropRow(rows, QStringLiteral("far-away"), QStringLiteral("ball drop at 1e6 m"), 1e-3, 2.0, 0.1,
            Vec2(1e6, 1e6), QStringLiteral("stable"));
}

void fastSpin(std::vector<StressRow>& rows)
{
    dropRow(rows, QStringLiteral("fast-spin"), QStringLiteral("box at 1e4 rad/s, dt = 1 ms"), 1e-3,
            2.0, 0.1, Vec2::Zero(), QStringLiteral("stable"), true, 1e4);
}

// thousand-bodies: 1000 balls of 5 cm radius dropped into a 4 m wide box, dt = 1/60 s, 5 s.
void thousandBodies(std::vector<StressRow>& rows)
{
    World w(def(IntegratorKind::SymplecticEuler, 1.0 / 60));
    addGround(w);
    w.addBody(box("left", 0.2, 6.0, Vec2(-2.1, 3.0), 0, BodyType::Static));
    w.addBody(box("right", 0.2, 6.0, Vec2(2.1, 3.0), 0, BodyType::Static));
    for (int i = 0; i < 1000; ++i)
        w.addBody(
            ball(numbered('b', i), 0.05,
                 Vec2(-1.9 + 0.12 * (i % 32) + 0.01 * ((i / 32) % 2), 0.3 + 0.12 * (i / 32))));
    StressRow row;
    row.caseName = QStringLiteral("thousand-bodies");
    row.setup = QStringLiteral("1000 balls into a box, dt = 1/60 s");
    row.integrator = name(IntegratorKind::SymplecticEuler);
    judge(row, w, simulate(w, 5.0),
          {[](const World& w) {
               for (const physics::Body& b : w.bodies())
                   if (b.isDynamic() && (std::abs(b.position.x()) > 2.0 || b.position.y() < 0))
                       return true;
               return false;
           },
           true});
    // Ten velocity iterations at 1/60 s do not hold a pile 30 balls deep: the bottom layers
    // overlap by centimetres.
    row.expected = QStringLiteral("penetrating");
    rows.push_back(row);
}

struct Case {
    const char* name;
    void (*run)(std::vector<StressRow>&);
};
constexpr Case kCases[] = {
    {"stiff-spring", &stiffSpring},
    {"spring-chain", &springChain},
    {"mass-ratio", &massRatio},
    {"heavy-pendulum", &heavyPendulum},
    {"bullet", &bullet},
    {"dt-range", &dtRange},
    {"tiny-body", &tinyBody},
    {"far-away", &farAway},
    {"fast-spin", &fastSpin},
    {"thousand-bodies", &thousandBodies},
};

} // namespace

QStringList stressCaseNames()
{
    QStringList names;
    for (const Case& c : kCases)
        names.append(QLatin1String(c.name));
    return names;
}

std::vector<StressRow> runStress(const QString& caseName)
{
    std::vector<StressRow> rows;
    for (const Case& c : kCases)
        if (caseName.isEmpty() || caseName == QLatin1String(c.name))
            c.run(rows);
    return rows;
}

QString stressTable(const std::vector<StressRow>& rows)
{
    const QStringList head{"case",        "setup",      "integrator",
                           "verdict",     "documented", "energy x",
                           "penetration", "limit",      "largest stable dt"};
    std::vector<QStringList> cells{head};
    for (const StressRow& r : rows)
        cells.push_back(
            {r.caseName, r.setup, r.integrator, r.verdict,
             r.asDocumented() ? QStringLiteral("yes") : QStringLiteral("NO: ") + r.expected,
             QString::number(r.energyGrowth, 'g', 3),
             QString::number(r.penetration * 1000, 'f', 2) + QStringLiteral(" mm"), r.limit,
             r.largestStable});
    std::vector<qsizetype> width(head.size(), 0);
    for (const QStringList& line : cells)
        for (qsizetype i = 0; i < line.size(); ++i)
            width[static_cast<size_t>(i)] = std::max(width[static_cast<size_t>(i)], line[i].size());
    QString out;
    for (const QStringList& line : cells) {
        for (qsizetype i = 0; i < line.size(); ++i)
            out += line[i].leftJustified(width[static_cast<size_t>(i)] + 2);
        out = out.trimmed() + u'\n';
    }
    return out;
}

QByteArray stressJson(const std::vector<StressRow>& rows)
{
    QJsonArray array;
    for (const StressRow& r : rows)
        array.append(QJsonObject{{"case", r.caseName},
                                 {"setup", r.setup},
                                 {"integrator", r.integrator},
                                 {"verdict", r.verdict},
                                 {"documented", r.expected},
                                 {"asDocumented", r.asDocumented()},
                                 {"energyGrowth", r.energyGrowth},
                                 {"penetration", r.penetration},
                                 {"limit", r.limit},
                                 {"largestStableDt", r.largestStable},
                                 {"diagnosis", r.diagnosis}});
    return QJsonDocument(array).toJson();
}

} // namespace rigidlab::lessons
