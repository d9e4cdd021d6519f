// The world and its step. Each stage lives in a file of its own:
//   forces.cpp, joints.cpp  applied forces and exact pin-joint forces (inside integration)
//   integrators.cpp         explicit Euler, symplectic Euler, velocity Verlet, RK4
//   world_step.cpp          what a step needs; symplectic Euler straight on the bodies
//   broad_phase.cpp         a dynamic tree of bounding boxes, pairs kept from step to step
//   sat.cpp                 SAT for polygons, circles, contact manifolds
//   contact_solver.cpp      the seed's impulse, or sequential impulses; position correction
//   dissipation.cpp         the energy that contacts, drag and spring dampers take
//   diagnostics.cpp         energies and momenta
//   continuous.cpp          speculative contacts over a fast body's motion
//   divergence.cpp          a non-finite state or runaway energy stops the world
//   islands.cpp             islands of touching bodies, sleeping and waking

#include "rigidlab/physics/world.h"

#include "cpu_state.h"
#include "diagnostics_compute.h"
#include "dynamics.h"
#include "narrow_phase.h"
#include "world_scratch.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace rigidlab::physics {

World::World(const WorldDef& def)
    : m_def(def), m_integrator(makeIntegrator(def.integrator, def.tolerances)),
      m_scratch(std::make_unique<Scratch>())
{
}

World::~World() = default;

World::World(const World& o)
    : m_def(o.m_def), m_contactSettings(o.m_contactSettings), m_bodies(o.m_bodies),
      m_springs(o.m_springs), m_joints(o.m_joints), m_contacts(o.m_contacts),
      m_integrator(makeIntegrator(o.m_def.integrator, o.m_def.tolerances)), m_moving(o.m_moving),
      m_slot(o.m_slot), m_jointPairs(o.m_jointPairs), m_scratch(std::make_unique<Scratch>()),
      m_time(o.m_time), m_steps(o.m_steps), m_evaluations(o.m_evaluations),
      m_collisionLoss(o.m_collisionLoss), m_dragLoss(o.m_dragLoss), m_dampingLoss(o.m_dampingLoss),
      m_diagnostics(o.m_diagnostics), m_divergenceSettings(o.m_divergenceSettings),
      m_divergence(o.m_divergence), m_energyStart(o.m_energyStart), m_energyScale(o.m_energyScale)
{
}

World& World::operator=(const World& o)
{
    if (this != &o)
        *this = World(o);
    return *this;
}

World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

BodyId World::addBody(const BodyDef& def)
{
    Body b;
    b.name = def.name;
    b.type = def.type;
    b.shape = def.shape;
    b.collide = def.collide;
    b.restitution = def.restitution >= 0 ? def.restitution : m_def.restitution;
    b.friction = def.friction >= 0 ? def.friction : m_def.friction;

    const MassProperties mp = computeMass(def.shape, def.mass > 0 ? 1.0 : def.density);
    b.localCenter = mp.centroid;
    if (def.type == BodyType::Dynamic) {
        // A given mass keeps the shape's distribution: inertia scales with it.
        const double scale = def.mass > 0 ? def.mass / mp.mass : 1.0;
        b.mass = mp.mass * scale;
        b.inertia = mp.inertia * scale;
        b.invMass = b.mass > 0 ? 1.0 / b.mass : 0.0;
        b.invInertia = b.inertia > 0 ? 1.0 / b.inertia : 0.0;
    }
    const BodyId id = static_cast<BodyId>(m_bodies.size());
    m_bodies.push_back(std::move(b));
    setBodyOrigin(id, def.position, def.angle);
    setBodyVelocity(id, def.velocity, def.angularVelocity);

    m_slot.push_back(-1);
    if (def.type != BodyType::Static) {
        m_slot.back() = static_cast<int>(m_moving.size());
        m_moving.push_back(id);
    }
    return id;
}

void World::addSpring(const SpringDef& spring)
{
    m_springs.push_back(spring);
}

void World::addPinJoint(const PinJointDef& joint)
{
    m_joints.push_back(joint);
    if (joint.a != kWorld && joint.b != kWorld) {
        m_jointPairs.push_back(std::minmax(joint.a, joint.b));
        std::sort(m_jointPairs.begin(), m_jointPairs.end());
    }
}

void World::setDt(double dt)
{
    m_def.dt = dt;
}

void World::setIntegrator(IntegratorKind kind)
{
    m_def.integrator = kind;
    m_integrator = makeIntegrator(kind, m_def.tolerances);
}

void World::setTolerances(const Tolerances& tolerances)
{
    m_def.tolerances = tolerances;
    m_integrator->setTolerances(tolerances);
}

void World::setRestitution(double e)
{
    m_def.restitution = e;
    for (Body& b : m_bodies)
        b.restitution = e;
    wakeAll();
}

void World::setFriction(double mu)
{
    m_def.friction = mu;
    for (Body& b : m_bodies)
        b.friction = mu;
    wakeAll();
}

void World::setBodyOrigin(BodyId id, const Vec2& origin, double angle)
{
    Body& b = body(id);
    b.angle = angle;
    b.position = origin + Rotation(angle).apply(b.localCenter);
    wakeBody(id);
}

void World::setBodyVelocity(BodyId id, const Vec2& originVelocity, double angularVelocity)
{
    Body& b = body(id);
    b.angularVelocity = angularVelocity;
    b.velocity = originVelocity + cross(angularVelocity, Vec2(b.position - b.origin()));
    wakeBody(id);
}

bool World::setBodyMass(BodyId id, double mass)
{
    if (id < 0 || id >= static_cast<BodyId>(m_bodies.size()) || !(mass > 0) || !std::isfinite(mass))
        return false;
    Body& b = body(id);
    if (!b.isDynamic() || !(b.mass > 0))
        return false;
    // I = m k² for a fixed shape: the radius of gyration k does not depend on the mass.
    const double scale = mass / b.mass;
    b.mass = mass;
    b.invMass = 1.0 / mass;
    b.inertia *= scale;
    b.invInertia = b.inertia > 0 ? 1.0 / b.inertia : 0.0;
    // The energy changed by hand, not by the integrator: the divergence check measures growth
    // from the energy the next step starts with.
    m_energyStart.reset();
    wakeBody(id);
    return true;
}

Vec2 World::originVelocity(BodyId id) const
{
    const Body& b = body(id);
    return b.pointVelocity(b.origin());
}

void World::step()
{
    assert(m_integrator);
    if (m_divergence)
        return; // stopped with a diagnosis; see divergence()
    if (!m_energyStart)
        rememberStartEnergy();
    clearUpperVectorState();
    const auto start = StageTimer::Clock::now();
    m_profile = StepProfile{};
    // What this step needs (world_step.cpp): contacts only if some two bodies can collide,
    // the direct integration when only contacts couple the bodies, islands when sleeping.
    m_plan = planStep();
    if (!m_plan.sleep)
        m_profile.awake = m_plan.dynamic;
    if (m_plan.collide) {
        // Velocities at the start of the step, to time bounces within it.
        Scratch& s = *m_scratch;
        s.velocityAtStart.resize(m_bodies.size());
        s.angularVelocityAtStart.resize(m_bodies.size());
        for (size_t i = 0; i < m_bodies.size(); ++i) {
            s.velocityAtStart[i] = m_bodies[i].velocity;
            s.angularVelocityAtStart[i] = m_bodies[i].angularVelocity;
        }
        // Contacts between the shapes where they stand now: broad phase, then SAT /
        // manifolds.
        findContacts();
    } else {
        m_contacts.clear();
    }
    // Islands: a body touched by an awake one wakes, with everything touching it.
    if (m_plan.sleep)
        wakeIslands();
    // Forces and integration: the chosen integrator, forces evaluated at every stage, pin
    // joints as exact constraint forces.
    integrate();
    // Collision response: impulses on the new velocities, then position correction.
    if (!m_contacts.empty() && m_plan.anyAwake)
        solveContacts();
    // Islands that have rested long enough go to sleep.
    if (m_plan.sleep)
        sleepIslands();

    for (Body& b : m_bodies) {
        b.force = Vec2::Zero();
        b.torque = 0.0;
    }
    m_time += m_def.dt;
    ++m_steps;
    {
        StageTimer timer(m_profile, Stage::Diagnostics);
        updateDiagnostics();
    }
    // A non-finite state or runaway energy stops the world with a diagnosis.
    checkDivergence();
    m_profile.total =
        std::chrono::duration<double, std::milli>(StageTimer::Clock::now() - start).count();
}

template <typename Fn> void World::withState(Fn&& fn)
{
    Eigen::VectorXd& q = m_scratch->q;
    Eigen::VectorXd& v = m_scratch->v;
    const Eigen::Index n = 3 * static_cast<Eigen::Index>(m_moving.size());
    q.resize(n);
    v.resize(n);
    for (size_t s = 0; s < m_moving.size(); ++s) {
        const Body& b = m_bodies[static_cast<size_t>(m_moving[s])];
        const Eigen::Index i = 3 * static_cast<Eigen::Index>(s);
        q.segment<3>(i) << b.position.x(), b.position.y(), b.angle;
        v.segment<3>(i) << b.velocity.x(), b.velocity.y(), b.angularVelocity;
    }
    Dynamics dynamics(m_def, m_bodies, m_slot, m_springs, m_joints);
    fn(dynamics, q, v);
    m_evaluations += dynamics.evaluations;
    for (size_t s = 0; s < m_moving.size(); ++s) {
        Body& b = m_bodies[static_cast<size_t>(m_moving[s])];
        if (b.isDynamic() && !b.awake)
            continue; // asleep: it does not move, whatever the integrator made of it
        const Eigen::Index i = 3 * static_cast<Eigen::Index>(s);
        b.position = Vec2(q[i], q[i + 1]);
        b.angle = q[i + 2];
        b.velocity = Vec2(v[i], v[i + 1]);
        b.angularVelocity = v[i + 2];
    }
}

void World::integrate()
{
    if (m_moving.empty())
        return;
    if (m_plan.direct) {
        integrateDirect();
        return;
    }
    StageTimer timer(m_profile, Stage::Integration);
    const double t = m_time, h = m_def.dt;
    withState([&](Dynamics& dynamics, Eigen::VectorXd& q, Eigen::VectorXd& v) {
        Scratch& s = *m_scratch;
        const bool dissipates = dynamics.dissipates();
        if (dissipates) {
            s.q0 = q;
            s.v0 = v;
        }
        m_integrator->step(dynamics, t, h, q, v);
        // What drag and dampers took, before the joints move anything (dissipation.cpp).
        if (dissipates) {
            const Dissipation loss = stepDissipation(dynamics, m_def.integrator, h, s.q0, s.v0, q,
                                                     v, s.meanVelocity, s.midpoint);
            m_dragLoss += loss.drag;
            m_dampingLoss += loss.damping;
        }
        // The force evaluations inside count as the forces stage, not as integration.
        m_profile.ran[static_cast<int>(Stage::Forces)] = true;
        m_profile.ms[static_cast<int>(Stage::Forces)] += dynamics.forceMilliseconds;
        m_profile.ms[static_cast<int>(Stage::Integration)] -= dynamics.forceMilliseconds;
        // Back onto the joints. For symplectic Euler the SHAKE form: the position correction
        // dq is made by the velocity, v += dq / h, as if the joint's impulse had acted at the
        // start of the step (q1 = q0 + h v1 still holds), which keeps a pendulum's energy in a
        // bounded band. The projection uses the joint's direction at the end of the step, so
        // this holds while a step turns the bodies through a small angle; past that (a fast
        // spin) only the positions are corrected, which is stable but loses a little energy.
        // For the other integrators RATTLE's two projections: positions, then velocities.
        if (m_def.integrator == IntegratorKind::SymplecticEuler && !m_joints.empty()) {
            constexpr double kSmallTurn = 0.1; // [rad per step]
            double turn = 0.0;
            for (Eigen::Index i = 2; i < v.size(); i += 3)
                turn = std::max(turn, std::abs(v[i]) * h);
            m_scratch->shake = q;
            dynamics.projectJointPositions(q);
            if (turn < kSmallTurn)
                v += (q - m_scratch->shake) / h;
        } else {
            dynamics.projectJointPositions(q);
            dynamics.projectJointVelocities(q, v);
        }
    });
}

void World::findContacts()
{
    Scratch& s = *m_scratch;
    std::swap(s.previous, m_contacts);
    m_contacts.clear();
    const double margin = m_contactSettings.margin;
    StageTimer broad(m_profile, Stage::BroadPhase);
    updateTransforms();
    s.broadPhase.findPairs(m_bodies, s.xf, margin, m_def.dt, m_jointPairs, s.pairs);
    // Fast bodies: pairs and margins over their motion in this step (continuous collision).
    addSweptPairs(s.pairs);
    broad.stop();
    m_profile.pairs = static_cast<int>(s.pairs.size());

    StageTimer narrow(m_profile, Stage::NarrowPhase);
    narrowPhase(m_bodies, s.xf, s.pairs, margin, m_sweep, s.previous, m_contacts);
    m_profile.contacts = static_cast<int>(m_contacts.size());
}

double restitutionThreshold(const WorldDef& def, const ContactSettings& settings)
{
    constexpr double kFloor = 0.01; // [m/s]
    return std::min(settings.restitutionThreshold,
                    std::max(kFloor, 2.0 * def.gravity.norm() * def.dt));
}

void World::solveContacts()
{
    if (m_contacts.empty())
        return;
    StageTimer timer(m_profile, Stage::ContactSolve);
    Scratch& s = *m_scratch;
    const double h = m_def.dt;
    s.velocityBefore.resize(m_bodies.size());
    s.angularVelocityBefore.resize(m_bodies.size());
    for (size_t i = 0; i < m_bodies.size(); ++i) {
        s.velocityBefore[i] = m_bodies[i].velocity;
        s.angularVelocityBefore[i] = m_bodies[i].angularVelocity;
    }
    ContactSolver& solver = s.solver;
    solver.begin(m_contacts, m_bodies, m_contactSettings, h, s.xfPosition, s.velocityAtStart,
                 s.angularVelocityAtStart);
    if (m_def.solver == SolverKind::SeedImpulse)
        solver.solveSeed();
    else
        solver.solveSequential(m_def.iterations, true,
                               restitutionThreshold(m_def, m_contactSettings));

    // A resting contact's impulse changes the velocity for the whole step, so the position
    // moves by dt times the change (for symplectic Euler exactly Box2D's order: solve the
    // velocities, then integrate the positions). A bounce timed at the fraction f of the step
    // moves it by (1 - f) dt times the change.
    const std::vector<double>& impact = solver.impactFractions();
    for (size_t i = 0; i < m_bodies.size(); ++i) {
        Body& b = m_bodies[i];
        if (!b.isActive())
            continue;
        const double after = (1.0 - impact[i]) * h;
        b.position += after * (b.velocity - s.velocityBefore[i]);
        b.angle += after * (b.angularVelocity - s.angularVelocityBefore[i]);
    }
    // Impulses on jointed bodies may push along a joint: take that velocity out again.
    if (!m_joints.empty() && solver.appliedImpulse())
        withState([](Dynamics& d, Eigen::VectorXd& q, Eigen::VectorXd& v) {
            d.projectJointVelocities(q, v);
        });
    // What the contacts took (dissipation.cpp): friction and inelastic bounces.
    m_collisionLoss += contactLoss(m_bodies, s.velocityAtStart, s.angularVelocityAtStart,
                                   s.velocityBefore, s.angularVelocityBefore, impact);

    m_profile.solved = solver.constraintCount();
    m_profile.positionPasses = solver.solvePositions(m_contactSettings.positionIterations);
    if (!m_joints.empty())
        withState(
            [](Dynamics& d, Eigen::VectorXd& q, Eigen::VectorXd&) { d.projectJointPositions(q); });
}

void World::updateDiagnostics()
{
    m_diagnostics = computeDiagnostics(m_def, m_bodies, m_springs);
    m_diagnostics.collisionLoss = m_collisionLoss;
    m_diagnostics.dragLoss = m_dragLoss;
    m_diagnostics.dampingLoss = m_dampingLoss;
    m_diagnostics.dissipated = m_collisionLoss + m_dragLoss + m_dampingLoss;
    int count = 0;
    for (const Contact& c : m_contacts)
        for (int i = 0; i < c.manifold.pointCount; ++i)
            if (c.manifold.points[static_cast<size_t>(i)].separation <= 0 ||
                c.normalImpulse[static_cast<size_t>(i)] > 0)
                ++count;
    m_diagnostics.contacts = count;
}

} // namespace rigidlab::physics
