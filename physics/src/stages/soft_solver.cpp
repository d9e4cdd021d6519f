// SPDX-License-Identifier: GPL-3.0-or-later
// Stage::ContactSolve of the soft step (SolverKind::SoftStep): soft contact constraints over
// substeps, after Catto's "Soft Step" (Solver2D, 2024; Box2D v3's solver).
//
// A contact is a spring and damper on its penetration, of frequency f and damping ratio z,
// solved implicitly over the substep h (Catto, "Soft Constraints", GDC 2011):
//     w = 2 pi f,  a1 = 2 z + h w,  a2 = h w a1,  a3 = 1 / (1 + a2)
//     bias rate = w / a1,  mass scale = a2 a3,  impulse scale = a3.
// The frequency follows the substep (a quarter of the substep rate by default), so a stack
// sinks by the same small amount whatever dt; a contact with a body that does not move gets
// twice the frequency, since only one side gives way. Each substep integrates the velocities,
// warm starts, solves with the soft bias, integrates the positions and relaxes (the same pass,
// rigid and without bias): the relax pass takes out the velocity the push gave, so stacks
// stay still and pushes do not become bounces. Friction is solved in the relax pass (and in
// the biased pass too with SoftStepSettings::frictionWithBias): there the normal impulses
// carry the weight without the push, and a base-100 pyramid stands (with friction in both,
// its middle rows slid metres apart in 10 s). Bounces are not solved here: the collision phase
// gives them before the substeps (soft_step.cpp), from each contact's approach at its impact.
//
// Speed (fast/soft_kernel.h, fast/soft_colouring.cpp): the contacts are coloured so that no
// two of one colour share a moving body, and the kernel solves one colour's contacts side by
// side in SIMD lanes.

#include "soft_solver.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numbers>
#include <type_traits>

namespace rigidlab::physics {

namespace {

Softness softness(double hertz, double dampingRatio, double h)
{
    if (hertz <= 0)
        return {};
    const double omega = 2.0 * std::numbers::pi * hertz;
    const double a1 = 2.0 * dampingRatio + h * omega;
    const double a2 = h * omega * a1;
    const double a3 = 1.0 / (1.0 + a2);
    return {omega / a1, a2 * a3, a3};
}

} // namespace

namespace soft {
bool haveAvx2()
{
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}
} // namespace soft

void softContactCoefficients(const SoftStepSettings& settings, double h, Softness (&out)[2])
{
    // The two softnesses a contact can have (fillLaneOf): between moving bodies, and twice the
    // frequency against a body that does not move.
    const double hertz = settings.contactFrequency / h;
    out[0] = softness(hertz, settings.dampingRatio, h);
    out[1] = softness(2.0 * hertz, settings.dampingRatio, h);
}

void SoftSolver::takeBodies(const std::vector<Body>& bodies, const std::vector<Vec2>& acceleration,
                            const std::vector<double>& angularAcceleration)
{
    const size_t n = bodies.size();
    // Each body's state written whole in the loop below, the spare one here.
    m_state.resize(n + 1);
    m_state[n] = soft::BodyState{};
    m_position.resize(n);
    m_angle.resize(n);
    m_kinematic.clear();
    m_drift.clear();
    m_angularDrift.clear();
    m_pins.clear();
    m_invInertia.resize(n);
    m_turns.resize(n);
    m_active.resize(n);
    // The moving bodies' arrays at their largest, cut to the count at the end (their elements
    // need no destruction); written through local pointers, which the compiler otherwise
    // loaded again after every store.
    m_moving.resize(n);
    m_acceleration.resize(n);
    m_angularAcceleration.resize(n);
    m_mass.resize(n);
    m_inertia.resize(n);
    soft::BodyState* const state = m_state.data();
    Vec2* const position = m_position.data();
    double* const angle = m_angle.data();
    double* const invInertia = m_invInertia.data();
    char* const turns = m_turns.data();
    char* const active = m_active.data();
    int* const moving = m_moving.data();
    Vec2* const movingAcceleration = m_acceleration.data();
    double* const movingAngularAcceleration = m_angularAcceleration.data();
    double* const mass = m_mass.data();
    double* const inertia = m_inertia.data();
    size_t count = 0;
    for (size_t i = 0; i < n; ++i) {
        const Body& b = bodies[i];
        const bool isActive = b.isActive();
        active[i] = isActive;
        const Circle* circle = b.shape.asCircle();
        turns[i] = !circle || circle->center != b.localCenter;
        soft::BodyState& s = state[i];
        s = soft::BodyState{};
        s.vx = b.velocity.x();
        s.vy = b.velocity.y();
        s.w = b.angularVelocity;
        s.invMass = isActive ? b.invMass : 0.0;
        invInertia[i] = isActive ? b.invInertia : 0.0;
        position[i] = b.position;
        angle[i] = b.angle;
        if (isActive) {
            moving[count] = static_cast<int>(i);
            movingAcceleration[count] = acceleration[i];
            movingAngularAcceleration[count] = angularAcceleration[i];
            mass[count] = b.mass;
            inertia[count] = b.inertia;
            ++count;
        } else if (b.type == BodyType::Kinematic) {
            m_kinematic.push_back(static_cast<int>(i));
        }
    }
    m_moving.resize(count);
    m_acceleration.resize(count);
    m_angularAcceleration.resize(count);
    m_mass.resize(count);
    m_inertia.resize(count);
}

void SoftSolver::begin(std::vector<Contact>& contacts, const std::vector<Body>& bodies,
                       const std::vector<Vec2>& acceleration,
                       const std::vector<double>& angularAcceleration, const Substeps& substeps,
                       const Softness (&softness)[2], const SoftStepSettings& settings, bool plain)
{
    m_contacts = &contacts;
    m_settings = settings;
    m_energyValid = false;
    m_substeps = substeps;
    // The plain path solves one contact per block (the second lane of the two-lane kernel
    // empty), in the colours' order: the order the wide kernels solve them in, so the same
    // bits. The fast path fills every lane, four where the processor has AVX2.
    static const bool wide = soft::haveAvx2() && soft::kernel4Avx2().solve != nullptr;
    static const bool wideSingle = soft::haveAvx2() && soft::singleKernel8Avx2().solve != nullptr;
    m_kernel = wide && settings.wideKernel && !plain ? soft::kernel4Avx2() : soft::kernel2();
    m_singleKernel = wideSingle && settings.wideKernel && !plain ? soft::singleKernel8Avx2()
                                                                 : soft::singleKernel4();
    m_single = settings.singlePrecision;
    m_width = plain ? 1 : m_single ? m_singleKernel.width : m_kernel.width;
    m_plain = plain;
    m_pass.maxPushSpeed = settings.maxPushSpeed;
    m_pass.softness[0] = softness[0];
    m_pass.softness[1] = softness[1];
    takeBodies(bodies, acceleration, angularAcceleration);
    const size_t n = bodies.size();
    if (m_single) {
        // The float copy starts with no change of velocity and no rotation (qc - 1 = 0).
        m_singleState.resize(n + 1);
        m_singleBase.resize(n + 1);
        m_singleOrigin.resize(n + 1);
        m_singleWarm.assign(n + 1, {0.0, 0.0, 0.0}); // summed by fillLaneOf()
        for (size_t i = 0; i <= n; ++i) {
            const soft::BodyState& d = m_state[i];
            m_singleOrigin[i] = {d.vx, d.vy, d.w};
            m_singleState[i] = {0.0f, 0.0f, 0.0f, static_cast<float>(d.invMass),
                                0.0f, 0.0f, 0.0f, 0.0f};
        }
    }
    buildBlocks(contacts, bodies);
}

void SoftSolver::integrateVelocities(bool sumBefore)
{
    if (sumBefore)
        integrateVelocitiesOf<true>(m_state);
    else
        integrateVelocitiesOf<false>(m_state);
}

template <typename State>
void SoftSolver::addEnergy(size_t k, const State& s, double& energy, double& power) const
{
    // Twice the kinetic energy, and the loads' power, of moving body k.
    energy += m_mass[k] * (s.vx * s.vx + s.vy * s.vy) + m_inertia[k] * s.w * s.w;
    power += m_mass[k] * (m_acceleration[k].x() * s.vx + m_acceleration[k].y() * s.vy) +
             m_inertia[k] * m_angularAcceleration[k] * s.w;
}

template <bool SumBefore, typename State>
void SoftSolver::integrateVelocitiesOf(std::vector<State>& state)
{
    // The energy sums of the new velocities in the same pass (the same arithmetic, in the
    // same order, as sumEnergy()): soft_step.cpp asks for them next. SumBefore: those of the
    // velocities before too (energyBefore()), which soft_step.cpp asked for after the relax
    // pass of the substep before in a pass of their own. The arrays through local pointers,
    // as in integratePositionsOf().
    const double h = m_substeps.h;
    double e = 0.0, p = 0.0, e0 = 0.0, p0 = 0.0;
    State* const states = state.data();
    const int* const moving = m_moving.data();
    const size_t count = m_moving.size();
    const Vec2* const acceleration = m_acceleration.data();
    const double* const angularAcceleration = m_angularAcceleration.data();
    for (size_t k = 0; k < count; ++k) {
        State& s = states[static_cast<size_t>(moving[k])];
        if constexpr (SumBefore)
            addEnergy(k, s, e0, p0);
        s.vx += h * acceleration[k].x();
        s.vy += h * acceleration[k].y();
        s.w += h * angularAcceleration[k];
        addEnergy(k, s, e, p);
    }
    if constexpr (SumBefore) {
        m_energyBefore = 0.5 * e0;
        m_powerBefore = p0;
    }
    m_energy = 0.5 * e;
    m_power = p;
    m_energyValid = true;
}

void SoftSolver::setDrift(const std::vector<Vec2>& drift, const std::vector<double>& angularDrift)
{
    m_drift = drift;
    m_angularDrift = angularDrift;
}

void SoftSolver::warmStart()
{
    m_energyValid = false;
    if (m_single) {
        // In double, body by body: the velocity all its contacts' impulses give it, which is
        // their impulses at the start of the step and each pass's change since (m_singleWarm).
        // Then the velocities to the float copy.
        for (int id : m_moving) {
            const auto i = static_cast<size_t>(id);
            soft::BodyState& d = m_state[i];
            const std::array<double, 3>& warm = m_singleWarm[i];
            d.vx += warm[0];
            d.vy += warm[1];
            d.w += warm[2];
        }
        toSingle(false);
        return; // no pins in single precision (soft_step.cpp)
    }
    forEachRange([&](int first, int count) {
        m_kernel.warmStart(m_blocks.data() + first, count, m_state.data());
    });
    if (!m_pins.empty())
        warmStartPins();
}

void SoftSolver::solve(bool useBias, bool lookAhead)
{
    m_energyValid = false;
    // A gap s may close at -s / t over the look-ahead time t (the kernel's bias s / t); without
    // look-ahead t is as good as 0, so that no gap asks anything of the velocities. 1e-200 s
    // keeps s / t finite for any gap and any mass.
    constexpr double kNoLookAhead = 1e200; // [1/s]
    m_pass.inverseSubstep = lookAhead ? m_substeps.invH : kNoLookAhead;
    m_pass.useBias = useBias;
    m_pass.friction = !useBias || m_settings.frictionWithBias;
    if (m_single && !useBias && !lookAhead) {
        // The step's last pass in double (fast/soft_kernel.cpp): the velocities the step ends
        // with are then as exact as double precision's, a ball put to rest at 0 m/s, not at a
        // float's grain of the step's change of velocity, up or down.
        m_singleKernel.relaxDouble(m_singleBlocks.data(), static_cast<int>(m_singleBlocks.size()),
                                   m_state.data(), m_pass);
        return; // no pins in single precision (soft_step.cpp)
    }
    forEachRange([&](int first, int count) {
        if (m_single)
            m_singleKernel.solve(m_singleBlocks.data() + first, count, m_singleState.data(),
                                 m_pass);
        else
            m_kernel.solve(m_blocks.data() + first, count, m_state.data(), m_pass);
    });
    if (m_single)
        fromSingle();
    if (!m_pins.empty())
        solvePins(useBias);
}

void SoftSolver::integratePositions()
{
    integratePositionsOf(m_state);
    if (m_single)
        toSingle(true);
}

template <typename State> void SoftSolver::integratePositionsOf(std::vector<State>& state)
{
    const double h = m_substeps.h;
    const bool drifts = !m_drift.empty();
    // The arrays through local pointers: a store into a body's state may alias a vector's
    // own pointers as far as the compiler knows, and it loaded each of them again per body.
    State* const states = state.data();
    Vec2* const position = m_position.data();
    double* const angle = m_angle.data();
    const char* const turns = m_turns.data();
    const Vec2* const drift = m_drift.data();
    const double* const angularDrift = m_angularDrift.data();
    auto move = [&](int id) {
        const auto i = static_cast<size_t>(id);
        State& s = states[i];
        double dx = h * s.vx, dy = h * s.vy, da = h * s.w;
        if (drifts) {
            dx += h * drift[i].x();
            dy += h * drift[i].y();
            da += h * angularDrift[i];
        }
        position[i] += Vec2(dx, dy);
        angle[i] += da;
        s.dpx += dx;
        s.dpy += dy;
        // A circle about its centre of mass touches where the normal meets it, however it
        // turns: its lever arm stays. Turned with a rolling disc, the arm lifted its touching
        // point by r (1 - cos) of the turn, a gap that was not there, and the disc rode up to
        // 2 mm low into the ground at dt = 1/60 s.
        if (!turns[i])
            return;
        // The rotation since the step began, turned by da to first order and normalised: it
        // only places the lever arms for the separation, so a sine and cosine are not needed.
        const double c = s.qc - da * s.qs, sn = s.qs + da * s.qc;
        const double inv = 1.0 / std::sqrt(c * c + sn * sn);
        s.qc = c * inv;
        s.qs = sn * inv;
    };
    double power = 0.0; // movePower(), in the same pass
    const int* const moving = m_moving.data();
    const size_t count = m_moving.size();
    const Vec2* const acceleration = m_acceleration.data();
    const double* const angularAcceleration = m_angularAcceleration.data();
    const double* const mass = m_mass.data();
    const double* const inertia = m_inertia.data();
    for (size_t k = 0; k < count; ++k) {
        const State& s = states[static_cast<size_t>(moving[k])];
        move(moving[k]);
        power += mass[k] * (acceleration[k].x() * s.vx + acceleration[k].y() * s.vy) +
                 inertia[k] * angularAcceleration[k] * s.w;
    }
    m_movePower = power;
    for (int id : m_kinematic)
        move(id);
}

void SoftSolver::sumEnergy() const
{
    sumEnergyOf(m_state);
}

template <typename State> void SoftSolver::sumEnergyOf(const std::vector<State>& state) const
{
    double e = 0.0, p = 0.0;
    for (size_t k = 0; k < m_moving.size(); ++k)
        addEnergy(k, state[static_cast<size_t>(m_moving[k])], e, p);
    m_energy = 0.5 * e;
    m_power = p;
    m_energyValid = true;
}

double SoftSolver::kineticEnergy() const
{
    if (!m_energyValid)
        sumEnergy();
    return m_energy;
}

double SoftSolver::loadPower() const
{
    if (!m_energyValid)
        sumEnergy();
    return m_power;
}

void SoftSolver::end(std::vector<Body>& bodies)
{
    if (m_single)
        endOf(bodies, m_state, m_singleBlocks);
    else
        endOf(bodies, m_state, m_blocks);
}

template <typename State, typename BlockType>
void SoftSolver::endOf(std::vector<Body>& bodies, const std::vector<State>& state,
                       const std::vector<BlockType>& blocks)
{
    // The arrays through local pointers, as in integratePositionsOf().
    Body* const out = bodies.data();
    const State* const states = state.data();
    const Vec2* const position = m_position.data();
    const double* const angle = m_angle.data();
    auto write = [&](int id) {
        const auto i = static_cast<size_t>(id);
        Body& b = out[i];
        const State& s = states[i];
        b.velocity = Vec2(s.vx, s.vy);
        b.angularVelocity = s.w;
        b.position = position[i];
        b.angle = angle[i];
    };
    for (int id : m_moving)
        write(id);
    for (int id : m_kinematic)
        write(id);
    const double substeps = m_substeps.count;
    Contact* const contacts = m_contacts->data();
    const BlockType* const block = blocks.data();
    for (const Slot& slot : m_slots) {
        Contact& ct = contacts[static_cast<size_t>(slot.contact)];
        const BlockType& k = block[static_cast<size_t>(slot.block)];
        const auto l = static_cast<size_t>(slot.lane);
        for (int i = 0; i < slot.points; ++i) {
            const auto& p = k.p[i];
            double& normal = ct.normalImpulse[static_cast<size_t>(i)];
            double& tangent = ct.tangentImpulse[static_cast<size_t>(i)];
            if constexpr (requires { p.single.normalChange; }) {
                // Single precision: the contact's impulse at the start of the step, which it
                // still holds, with the passes' change; 0 where the change took the rounded
                // start back to 0 (the clamp), not the rounding's remainder.
                normal = p.normalImpulse[l] + p.single.normalChange[l] == 0.0f
                             ? 0.0
                             : normal + substeps * static_cast<double>(p.single.normalChange[l]);
                tangent = p.tangentImpulse[l] + p.single.tangentChange[l] == 0.0f
                              ? 0.0
                              : tangent + substeps * static_cast<double>(p.single.tangentChange[l]);
            } else {
                normal = substeps * p.normalImpulse[l];
                tangent = substeps * p.tangentImpulse[l];
            }
        }
    }
}

} // namespace rigidlab::physics
