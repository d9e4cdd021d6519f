// SPDX-License-Identifier: GPL-3.0-or-later
// The reference problems and their exact solutions (see reference_problems.h).

#include "numerics/reference_problems.h"

#include "rigidlab/physics/shape.h"

#include <cmath>
#include <memory>
#include <numbers>

namespace rigidlab::lessons {

using physics::BodyDef;
using physics::Vec2;
using physics::World;
using physics::WorldDef;

namespace {

constexpr double kPi = std::numbers::pi;

WorldDef quietDef()
{
    WorldDef def;
    def.gravity = Vec2::Zero();
    def.restitution = 0.0;
    def.continuous = false;
    return def;
}

BodyDef circle(const std::string& name, double radius, double mass, const Vec2& position,
               const Vec2& velocity = Vec2::Zero())
{
    BodyDef b;
    b.name = name;
    b.shape = physics::makeCircleShape(radius);
    b.mass = mass;
    b.position = position;
    b.velocity = velocity;
    b.collide = false;
    return b;
}

// --- oscillator: m = 1 kg on k = 4 N/m (w = 2 rad/s), from x0 = 0.5 m at rest.
//     The spring's far end sits 2 m away on the x axis, so the force is -k x along x.
constexpr double kOscMass = 1.0, kOscStiffness = 4.0, kOscX0 = 0.5, kOscRest = 2.0;

ReferenceProblem oscillator()
{
    ReferenceProblem p;
    p.name = "oscillator";
    p.description = "mass on a spring, x = x0 cos(w t) (w = 2 rad/s)";
    p.tEnd = 10.0;
    p.dtFrom = 0.1;
    p.dtTo = 0.001;
    p.build = [] {
        World w(quietDef());
        const auto id = w.addBody(circle("mass", 0.1, kOscMass, Vec2(kOscX0, 0.0)));
        physics::SpringDef s;
        s.a = id;
        s.b = physics::kWorld;
        s.anchorB = Vec2(-kOscRest, 0.0);
        s.stiffness = kOscStiffness;
        s.restLength = kOscRest;
        w.addSpring(s);
        return w;
    };
    p.reference = [](double t) {
        const double omega = std::sqrt(kOscStiffness / kOscMass);
        Eigen::VectorXd q(3);
        q << kOscX0 * std::cos(omega * t), 0.0, 0.0;
        return q;
    };
    return p;
}

// --- pendulum: a bob of radius r on a massless rod of length L, pinned at the origin, let go
//     at theta0 from straight down. A physical pendulum: I_pivot = m r^2 / 2 + m L^2 and
//     theta'' = -w0^2 sin(theta), w0^2 = m g L / I_pivot. From rest at theta0, with
//     k = sin(theta0 / 2):  sin(theta / 2) = k sn(K(k^2) - w0 t | k^2)  (Lawden, "Elliptic
//     Functions and Applications", 5.1).
constexpr double kPendL = 1.0, kPendR = 0.05, kPendMass = 1.0, kPendTheta0 = 2.5, kG = 9.81;

ReferenceProblem pendulum()
{
    ReferenceProblem p;
    p.name = "pendulum";
    p.description = "pendulum from 2.5 rad, exact by the Jacobi elliptic function sn";
    p.tEnd = 10.0;
    p.dtFrom = 0.05;
    p.dtTo = 0.0005;
    p.armLength = kPendL;
    p.build = [] {
        WorldDef def = quietDef();
        def.gravity = Vec2(0.0, -kG);
        World w(def);
        BodyDef bob = circle("bob", kPendR, kPendMass,
                             Vec2(kPendL * std::sin(kPendTheta0), -kPendL * std::cos(kPendTheta0)));
        bob.angle = kPendTheta0;
        const auto id = w.addBody(bob);
        physics::PinJointDef pin;
        pin.a = id;
        pin.anchorA = Vec2(0.0, kPendL); // the bob-local point at the pivot
        pin.b = physics::kWorld;
        pin.anchorB = Vec2::Zero();
        w.addPinJoint(pin);
        return w;
    };
    p.reference = [](double t) {
        const double inertia = kPendMass * (0.5 * kPendR * kPendR + kPendL * kPendL);
        const double w0 = std::sqrt(kPendMass * kG * kPendL / inertia);
        const double k = std::sin(0.5 * kPendTheta0);
        const double m = k * k;
        const JacobiElliptic f = jacobiElliptic(ellipticK(m) - w0 * t, m);
        const double theta = 2.0 * std::asin(std::clamp(k * f.sn, -1.0, 1.0));
        Eigen::VectorXd q(3);
        q << kPendL * std::sin(theta), -kPendL * std::cos(theta), theta;
        return q;
    };
    return p;
}

// --- kepler: G = 1, masses 1 and 0.1, relative orbit a = 1, e = 0.5, starting at periapsis on
//     +x, centre of mass at rest at the origin. With mu = G (m1 + m2), n = sqrt(mu / a^3), the
//     relative position at t is a (cos E - e, sqrt(1 - e^2) sin E), E - e sin E = n t.
constexpr double kKepM1 = 1.0, kKepM2 = 0.1, kKepA = 1.0, kKepE = 0.5;

ReferenceProblem kepler()
{
    ReferenceProblem p;
    p.name = "kepler";
    p.description = "two bodies, orbit of eccentricity 0.5, exact by Kepler's equation";
    p.tEnd = 12.0; // two periods are 11.98 s
    p.dtFrom = 0.05;
    p.dtTo = 0.0005;
    p.build = [] {
        WorldDef def = quietDef();
        def.gravitation = 1.0;
        World w(def);
        const double total = kKepM1 + kKepM2;
        const double mu = def.gravitation * total;
        const double r0 = kKepA * (1.0 - kKepE);
        const double v0 = std::sqrt(mu * (1.0 + kKepE) / r0);
        w.addBody(circle("sun", 0.02, kKepM1, Vec2(-kKepM2 / total * r0, 0.0),
                         Vec2(0.0, -kKepM2 / total * v0)));
        w.addBody(circle("planet", 0.01, kKepM2, Vec2(kKepM1 / total * r0, 0.0),
                         Vec2(0.0, kKepM1 / total * v0)));
        return w;
    };
    p.reference = [](double t) {
        const double total = kKepM1 + kKepM2;
        const double n = std::sqrt(total / (kKepA * kKepA * kKepA));
        const double e = solveKepler(n * t, kKepE);
        const Vec2 r(kKepA * (std::cos(e) - kKepE),
                     kKepA * std::sqrt(1.0 - kKepE * kKepE) * std::sin(e));
        const Vec2 x1 = -kKepM2 / total * r, x2 = kKepM1 / total * r;
        Eigen::VectorXd q(6);
        q << x1.x(), x1.y(), 0.0, x2.x(), x2.y(), 0.0;
        return q;
    };
    return p;
}

// --- spinning-body: a 0.4 x 0.2 m box thrown at (3, 5) m/s spinning at 10 rad/s, under
//     gravity g and linear drag c (F = -c m v, M = -c I w). Then
//       v(t) = (v0 - g/c) e^(-c t) + g/c,   x(t) = x0 + g t / c + (v0 - g/c)(1 - e^(-c t)) / c,
//       w(t) = w0 e^(-c t),                 angle(t) = w0 (1 - e^(-c t)) / c,
//     g the gravity vector (0, -9.81).
constexpr double kSpinDrag = 0.5, kSpinW0 = 10.0;

ReferenceProblem spinningBody()
{
    ReferenceProblem p;
    p.name = "spinning-body";
    p.description = "a spinning box thrown under gravity and linear drag, exact";
    p.tEnd = 3.0;
    p.dtFrom = 0.05;
    p.dtTo = 0.0005;
    p.build = [] {
        WorldDef def = quietDef();
        def.gravity = Vec2(0.0, -kG);
        def.drag = kSpinDrag;
        World w(def);
        BodyDef box;
        box.name = "box";
        box.shape = physics::makePolygonShape(physics::makeBox(0.4, 0.2));
        box.mass = 2.0;
        box.velocity = Vec2(3.0, 5.0);
        box.angularVelocity = kSpinW0;
        box.collide = false;
        w.addBody(box);
        return w;
    };
    p.reference = [](double t) {
        const double c = kSpinDrag;
        const Vec2 g(0.0, -kG), v0(3.0, 5.0);
        const double decay = 1.0 - std::exp(-c * t);
        const Vec2 x = g * t / c + (v0 - g / c) * decay / c;
        Eigen::VectorXd q(3);
        q << x.x(), x.y(), kSpinW0 * decay / c;
        return q;
    };
    return p;
}

// --- double-pendulum: two 1 kg bobs, 1 m apart on pins, let go from horizontal. No closed
//     form: the reference is the same equations integrated by Dormand-Prince 5(4) at absolute
//     and relative tolerances of 1e-13, advanced lazily to each time asked for.
ReferenceProblem doublePendulum()
{
    ReferenceProblem p;
    p.name = "double-pendulum";
    p.description = "two bobs on pins from horizontal; reference: dopri5 at 1e-13 (not exact)";
    p.exact = false;
    p.armLength = 1.0;
    p.tEnd = 3.0;
    p.dtFrom = 0.02;
    p.dtTo = 0.0002;
    p.build = [] {
        WorldDef def = quietDef();
        def.gravity = Vec2(0.0, -kG);
        World w(def);
        const auto a = w.addBody(circle("upper", 0.05, 1.0, Vec2(1.0, 0.0)));
        const auto b = w.addBody(circle("lower", 0.05, 1.0, Vec2(2.0, 0.0)));
        physics::PinJointDef top;
        top.a = a;
        top.anchorA = Vec2(-1.0, 0.0);
        top.b = physics::kWorld;
        top.anchorB = Vec2::Zero();
        w.addPinJoint(top);
        physics::PinJointDef middle;
        middle.a = b;
        middle.anchorA = Vec2(-1.0, 0.0);
        middle.b = a;
        middle.anchorB = Vec2::Zero();
        w.addPinJoint(middle);
        return w;
    };
    // The fine run: its world, equations, integrator and state, shared by the copies of the
    // closure.
    struct Fine {
        World world;
        std::unique_ptr<physics::OdeSystem> equations;
        std::unique_ptr<physics::Integrator> integrator;
        Eigen::VectorXd q, v;
        double t = 0;
        void restart()
        {
            world.getState(q, v);
            integrator =
                physics::makeIntegrator(physics::IntegratorKind::DormandPrince, {1e-13, 1e-13});
            t = 0;
        }
    };
    auto fine = std::make_shared<Fine>();
    fine->world = p.build();
    fine->equations = fine->world.equations();
    fine->restart();
    p.reference = [fine](double t) {
        if (t < fine->t)
            fine->restart();
        if (t > fine->t) {
            fine->integrator->step(*fine->equations, fine->t, t - fine->t, fine->q, fine->v);
            fine->t = t;
        }
        return fine->q;
    };
    return p;
}

} // namespace

std::vector<ReferenceProblem> referenceProblems()
{
    return {oscillator(), pendulum(), kepler(), spinningBody(), doublePendulum()};
}

double positionError(const World& world, const Eigen::VectorXd& q, const Eigen::VectorXd& qr)
{
    double sum = 0;
    Eigen::Index i = 0;
    for (const physics::Body& b : world.bodies()) {
        if (!b.moves())
            continue;
        const double rho = b.mass > 0 ? std::sqrt(b.inertia / b.mass) : 0.0;
        const double dx = q[i] - qr[i], dy = q[i + 1] - qr[i + 1], da = q[i + 2] - qr[i + 2];
        sum += dx * dx + dy * dy + rho * rho * da * da;
        i += 3;
    }
    return std::sqrt(sum);
}

double problemError(const ReferenceProblem& problem, const World& world, const Eigen::VectorXd& q,
                    const Eigen::VectorXd& qr)
{
    if (problem.armLength <= 0)
        return positionError(world, q, qr);
    double sum = 0;
    for (Eigen::Index i = 2; i < q.size(); i += 3) {
        const double arc = problem.armLength * (q[i] - qr[i]);
        sum += arc * arc;
    }
    return std::sqrt(sum);
}

double ellipticK(double m)
{
    double a = 1.0, b = std::sqrt(1.0 - m);
    for (int i = 0; i < 64 && std::abs(a - b) > 1e-16 * a; ++i) {
        const double next = 0.5 * (a + b);
        b = std::sqrt(a * b);
        a = next;
    }
    return kPi / (a + b);
}

JacobiElliptic jacobiElliptic(double u, double m)
{
    // A&S 16.4.2-3: a_0 = 1, b_0 = sqrt(1 - m), c_0 = sqrt(m); a_{n+1} = (a_n + b_n) / 2,
    // b_{n+1} = sqrt(a_n b_n), c_{n+1} = (a_n - b_n) / 2 until c_N is negligible. Then
    // phi_N = 2^N a_N u and, going down, phi_{n-1} = (phi_n + asin(c_n sin(phi_n) / a_n)) / 2.
    // sn = sin(phi_0), cn = cos(phi_0).
    JacobiElliptic r;
    if (m <= 0.0) {
        r.sn = std::sin(u);
        r.cn = std::cos(u);
        return r;
    }
    constexpr int kMax = 16;
    double a[kMax + 1], c[kMax + 1];
    a[0] = 1.0;
    double b = std::sqrt(1.0 - m);
    c[0] = std::sqrt(m);
    int n = 0;
    while (n < kMax && std::abs(c[n]) > 1e-17) {
        a[n + 1] = 0.5 * (a[n] + b);
        c[n + 1] = 0.5 * (a[n] - b);
        b = std::sqrt(a[n] * b);
        ++n;
    }
    double phi = std::ldexp(a[n] * u, n);
    for (int i = n; i > 0; --i) {
        phi = 0.5 * (phi + std::asin(c[i] * std::sin(phi) / a[i]));
    }
    r.sn = std::sin(phi);
    r.cn = std::cos(phi);
    r.dn = std::sqrt(1.0 - m * r.sn * r.sn); // positive for real u and m < 1
    return r;
}

double solveKepler(double meanAnomaly, double eccentricity)
{
    // Reduce M to [-pi, pi), solve there (Newton from E = M converges for e < 1 from this
    // start; Danby's start M + 0.85 e sign(sin M) is safer for e near 1), add the turns back.
    const double turns = std::floor((meanAnomaly + kPi) / (2.0 * kPi));
    const double m = meanAnomaly - 2.0 * kPi * turns;
    double e = m + 0.85 * eccentricity * (std::sin(m) >= 0 ? 1.0 : -1.0);
    for (int i = 0; i < 50; ++i) {
        const double f = e - eccentricity * std::sin(e) - m;
        const double step = f / (1.0 - eccentricity * std::cos(e));
        e -= step;
        if (std::abs(step) <= 1e-15 * std::max(1.0, std::abs(e)))
            break;
    }
    return e + 2.0 * kPi * turns;
}

} // namespace rigidlab::lessons
