// SPDX-License-Identifier: GPL-3.0-or-later
// The conservation experiments (conservation.h).

#include "numerics/conservation.h"

#include "rigidlab/physics/shape.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>

namespace rigidlab::lessons {

namespace {

using physics::Rotation;
using physics::Vec2;

double kineticEnergy(const physics::World& world)
{
    double e = 0;
    for (const physics::Body& b : world.bodies())
        if (b.isDynamic())
            e += 0.5 * b.mass * b.velocity.squaredNorm() +
                 0.5 * b.inertia * b.angularVelocity * b.angularVelocity;
    return e;
}

physics::WorldDef elasticDef(physics::SolverKind solver, double dt)
{
    physics::WorldDef def;
    def.gravity = Vec2::Zero();
    def.dt = dt;
    def.integrator = physics::IntegratorKind::SymplecticEuler;
    def.solver = solver;
    def.drag = 0.0;
    def.gravitation = 0.0;
    def.restitution = 1.0;
    def.friction = 0.0;
    return def;
}

/// Columns and rows of the starting grid: about 3 columns to 2 rows.
int gasColumns(int balls)
{
    return std::max(1, static_cast<int>(std::ceil(std::sqrt(1.5 * balls))));
}

/// Half the inner width and height of the gas's box [m].
Vec2 gasHalfBox(const GasSpec& spec)
{
    const int columns = gasColumns(spec.balls);
    const int rows = (spec.balls + columns - 1) / columns;
    return {0.5 * columns * spec.spacing, 0.5 * rows * spec.spacing};
}

template <class Step>
ConservationResult run(physics::World& world, int steps, physics::SolverKind solver, Step after)
{
    ConservationResult r;
    r.solver = std::string(physics::solverName(solver));
    r.start = kineticEnergy(world);
    double previous = r.start;
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i) {
        world.step();
        const double e = kineticEnergy(world);
        r.worst = std::max(r.worst, std::abs(e - r.start) / r.start);
        if (previous > 0)
            r.worstGain = std::max(r.worstGain, (e - previous) / previous);
        previous = e;
        after(world);
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.end = kineticEnergy(world);
    return r;
}

} // namespace

physics::World makeElasticGas(const GasSpec& spec, physics::SolverKind solver)
{
    physics::World world(elasticDef(solver, spec.dt));
    const Vec2 half = gasHalfBox(spec);
    constexpr double kThick = 1.0; // wall thickness [m]
    const auto wall = [&](double x, double y, double w, double h) {
        physics::BodyDef d;
        d.type = physics::BodyType::Static;
        d.shape = physics::makePolygonShape(physics::makeBox(w, h));
        d.position = {x, y};
        world.addBody(d);
    };
    const double w = 2.0 * half.x() + 2.0 * kThick, h = 2.0 * half.y() + 2.0 * kThick;
    wall(0, -half.y() - 0.5 * kThick, w, kThick);
    wall(0, half.y() + 0.5 * kThick, w, kThick);
    wall(-half.x() - 0.5 * kThick, 0, kThick, h);
    wall(half.x() + 0.5 * kThick, 0, kThick, h);
    std::uint32_t seed = spec.seed;
    const auto random = [&seed] { // in [-1, 1)
        seed = seed * 1664525u + 1013904223u;
        return static_cast<double>(seed >> 8) / static_cast<double>(1u << 23) - 1.0;
    };
    const int columns = gasColumns(spec.balls);
    for (int i = 0; i < spec.balls; ++i) {
        physics::BodyDef d;
        d.shape = physics::makeCircleShape(spec.radius);
        d.position = {-half.x() + spec.spacing * (0.5 + i % columns),
                      -half.y() + spec.spacing * (0.5 + i / columns)};
        d.velocity = {spec.speed * random(), spec.speed * random()};
        world.addBody(d);
    }
    return world;
}

ConservationResult runElasticGas(const GasSpec& spec, physics::SolverKind solver)
{
    physics::World world = makeElasticGas(spec, solver);
    const Vec2 half = gasHalfBox(spec);
    const int steps = static_cast<int>(std::lround(spec.seconds / spec.dt));
    ConservationResult r = run(world, steps, solver, [](const physics::World&) {});
    for (const physics::Body& b : world.bodies())
        if (b.isDynamic() &&
            (std::abs(b.position.x()) > half.x() || std::abs(b.position.y()) > half.y()))
            ++r.escaped;
    return r;
}

physics::World makeCradleRow(const CradleSpec& spec, physics::SolverKind solver)
{
    physics::World world(elasticDef(solver, spec.dt));
    const double d = 2.0 * spec.radius;
    physics::BodyDef striker;
    striker.shape = physics::makeCircleShape(spec.radius);
    striker.position = {-d - spec.gap, 0.0};
    striker.velocity = {spec.speed, 0.0};
    world.addBody(striker);
    for (int i = 0; i < spec.balls; ++i) {
        physics::BodyDef ball;
        ball.shape = physics::makeCircleShape(spec.radius);
        ball.position = {d * i, 0.0};
        world.addBody(ball);
    }
    return world;
}

ConservationResult runCradleRow(const CradleSpec& spec, physics::SolverKind solver)
{
    physics::World world = makeCradleRow(spec, solver);
    return run(world, spec.steps, solver, [](const physics::World&) {});
}

ConservationResult runNewtonsCradle(physics::SolverKind solver, double seconds)
{
    physics::WorldDef def = elasticDef(solver, 5e-4);
    def.gravity = {0.0, -9.81};
    physics::World world(def);
    constexpr double kRadius = 0.05, kRod = 0.6, kPitch = 0.101, kMass = 0.2; // [m], [kg]
    const double pull = std::numbers::pi / 6.0;                               // [rad]
    for (int i = 0; i < 5; ++i) {
        const Vec2 pivot(kPitch * (i - 2), 1.0);
        physics::BodyDef ball;
        ball.shape = physics::makeCircleShape(kRadius);
        ball.mass = kMass;
        ball.angle = i == 0 ? -pull : 0.0;
        ball.position = pivot + Rotation(ball.angle).apply(Vec2(0.0, -kRod));
        const physics::BodyId id = world.addBody(ball);
        physics::PinJointDef pin;
        pin.a = id;
        pin.anchorA = Vec2(0.0, kRod);
        pin.b = physics::kWorld;
        pin.anchorB = pivot;
        world.addPinJoint(pin);
    }
    const double lowest = kMass * 9.81 * (1.0 - kRod); // the potential of a ball at rest
    const auto energy = [&] {
        double e = kineticEnergy(world);
        for (const physics::Body& b : world.bodies())
            e += b.mass * 9.81 * b.position.y();
        return e - 5.0 * lowest;
    };
    ConservationResult r;
    r.solver = std::string(physics::solverName(solver));
    r.start = energy();
    double previous = r.start;
    const int steps = static_cast<int>(std::lround(seconds / def.dt));
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i) {
        world.step();
        const double e = energy();
        r.worst = std::max(r.worst, std::abs(e - r.start) / r.start);
        if (world.diagnostics().contacts >= 2)
            r.worstGain = std::max(r.worstGain, (e - previous) / r.start);
        previous = e;
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.end = energy();
    return r;
}

std::string conservationTable(const std::vector<ConservationResult>& rows)
{
    std::string out;
    char line[256];
    std::snprintf(line, sizeof line, "%-20s %14s %14s %11s %11s %11s %8s %9s\n", "solver",
                  "E start [J]", "E end [J]", "drift", "worst", "worst gain", "escaped",
                  "time [s]");
    out += line;
    for (const ConservationResult& r : rows) {
        std::snprintf(line, sizeof line, "%-20s %14.6f %14.6f %+11.2e %11.2e %11.2e %8d %9.2f\n",
                      r.solver.c_str(), r.start, r.end, r.drift(), r.worst, r.worstGain, r.escaped,
                      r.seconds);
        out += line;
    }
    return out;
}

} // namespace rigidlab::lessons
