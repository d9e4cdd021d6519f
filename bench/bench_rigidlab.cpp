// SPDX-License-Identifier: GPL-3.0-or-later
// RigidLab's side of the benchmarks: the engine-neutral scene as a physics::World.

#include "bench.h"

#include "rigidlab/physics/shape.h"

#include <algorithm>
#include <cassert>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <iterator>

namespace rigidlab::bench {

namespace {

physics::Shape toShape(const BenchShape& s)
{
    switch (s.kind) {
    case BenchShapeKind::Box:
        return physics::makePolygonShape(physics::makeBox(s.width, s.height));
    case BenchShapeKind::Circle:
        return physics::makeCircleShape(s.radius);
    case BenchShapeKind::Polygon: {
        const auto built = physics::makePolygon(s.vertices);
        assert(built.ok() && built.value().warning.empty());
        return physics::makePolygonShape(built.value().polygon);
    }
    }
    return {};
}

class RigidLabBench final : public BenchEngine {
public:
    explicit RigidLabBench(const RigidLabBenchSettings& settings) : m_settings(settings) {}

    std::string name() const override
    {
        if (m_settings.solver != physics::SolverKind::SoftStep)
            return "RigidLab";
        return m_settings.singlePrecision ? "RigidLab SS f32" : "RigidLab SS";
    }
    std::string settings() const override
    {
        if (m_settings.solver == physics::SolverKind::SoftStep)
            return std::string(physics::solverName(m_settings.solver)) + ", " +
                   std::to_string(m_settings.substeps) + " substeps, symplectic Euler, " +
                   (m_settings.singlePrecision
                        ? "contact passes in single precision (the rest double), "
                        : "double precision, ") +
                   "sleeping " + (m_settings.sleep ? "on" : "off");
        return std::string(physics::solverName(m_settings.solver)) + ", " +
               std::to_string(m_settings.iterations) + " velocity / " +
               std::to_string(m_settings.positionIterations) +
               " position iterations, symplectic Euler, double precision, sleeping " +
               (m_settings.sleep ? "on" : "off");
    }
    void build(const BenchScene& scene) override { m_world = buildBenchWorld(scene, m_settings); }
    void step() override { m_world.step(); }
    void poses(std::vector<BenchPose>& out) const override
    {
        out.clear();
        for (const physics::Body& b : m_world.bodies())
            out.push_back({b.position, b.angle});
    }
    std::optional<std::uint64_t> stateHash() const override { return bench::stateHash(m_world); }

private:
    RigidLabBenchSettings m_settings;
    physics::World m_world;
};

} // namespace

std::uint64_t fnv1a(const double* values, size_t count, std::uint64_t hash)
{
    for (size_t i = 0; i < count; ++i) {
        unsigned char bytes[sizeof(double)];
        std::memcpy(bytes, &values[i], sizeof bytes);
        for (const unsigned char byte : bytes) {
            hash ^= byte;
            hash *= 0x100000001b3ull;
        }
    }
    return hash;
}

std::uint64_t stateHash(const physics::World& world)
{
    std::uint64_t hash = fnv1a(nullptr, 0);
    for (const physics::Body& b : world.bodies()) {
        const double state[] = {b.position.x(), b.position.y(), b.angle,
                                b.velocity.x(), b.velocity.y(), b.angularVelocity};
        hash = fnv1a(state, std::size(state), hash);
    }
    return hash;
}

physics::World buildBenchWorld(const BenchScene& scene, const RigidLabBenchSettings& settings)
{
    physics::WorldDef def;
    def.gravity = scene.gravity;
    def.dt = scene.dt;
    def.integrator = physics::IntegratorKind::SymplecticEuler;
    def.solver = settings.solver;
    def.iterations = settings.iterations;
    def.restitution = 0.0;
    def.friction = 0.6;
    def.sleep = settings.sleep;
    physics::World world(def);
    world.contactSettings().positionIterations = settings.positionIterations;
    world.contactSettings().soft.singlePrecision = settings.singlePrecision;
    world.contactSettings().soft.substeps = settings.substeps;
    for (const BenchBody& b : scene.bodies) {
        physics::BodyDef d;
        d.type = b.isStatic ? physics::BodyType::Static : physics::BodyType::Dynamic;
        d.shape = toShape(b.shape);
        d.position = b.position;
        d.angle = b.angle;
        d.density = b.density;
        d.friction = b.friction;
        d.restitution = 0.0;
        world.addBody(d);
    }
    return world;
}

namespace {

std::string number(double v)
{
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, v);
    return std::string(text, end.ptr);
}

std::string point(const physics::Vec2& p)
{
    std::string out(1, '[');
    out += number(p.x());
    out += ", ";
    out += number(p.y());
    out += ']';
    return out;
}

} // namespace

std::string benchSceneJson(const BenchScene& scene, const RigidLabBenchSettings& settings)
{
    std::string out = "{\n  \"rigidlab\": 1,\n  \"title\": \"Benchmark: " + scene.name +
                      "\",\n  \"description\": \"" + scene.description +
                      " (rigidlab-cli bench --scene " + scene.name + ")\",\n";
    out += "  \"world\": {\"gravity\": " + point(scene.gravity) + ", \"dt\": " + number(scene.dt) +
           ", \"integrator\": \"symplectic-euler\", \"solver\": \"" +
           std::string(physics::solverName(settings.solver)) +
           "\", \"iterations\": " + std::to_string(settings.iterations) +
           ", \"restitution\": 0, \"friction\": 0.6, \"sleep\": " +
           (settings.sleep ? "true" : "false") + "},\n  \"bodies\": [\n";
    for (size_t i = 0; i < scene.bodies.size(); ++i) {
        const BenchBody& b = scene.bodies[i];
        out += "    {\"id\": \"b" + std::to_string(i) + "\"";
        if (b.isStatic)
            out += ", \"type\": \"static\"";
        switch (b.shape.kind) {
        case BenchShapeKind::Box:
            out += ", \"shape\": {\"type\": \"box\", \"width\": " + number(b.shape.width) +
                   ", \"height\": " + number(b.shape.height) + "}";
            break;
        case BenchShapeKind::Circle:
            out +=
                ", \"shape\": {\"type\": \"circle\", \"radius\": " + number(b.shape.radius) + "}";
            break;
        case BenchShapeKind::Polygon:
            out += ", \"shape\": {\"type\": \"polygon\", \"vertices\": [";
            for (size_t k = 0; k < b.shape.vertices.size(); ++k)
                out += (k ? ", " : "") + point(b.shape.vertices[k]);
            out += "]}";
            break;
        }
        out += ", \"position\": " + point(b.position);
        if (b.angle != 0.0)
            out += ", \"angle\": " + number(b.angle);
        if (b.density != 1.0)
            out += ", \"density\": " + number(b.density);
        out += i + 1 < scene.bodies.size() ? "},\n" : "}\n";
    }
    out += "  ]\n}\n";
    return out;
}

std::string rigidLabProfile(const BenchScene& scene, const BenchOptions& options,
                            const RigidLabBenchSettings& settings)
{
    physics::World world = buildBenchWorld(scene, settings);
    world.step(); // sets up the contacts: not counted, as in runBench
    double ms[physics::kStageCount] = {};
    bool ran[physics::kStageCount] = {};
    double total = 0, pairs = 0, contacts = 0;
    const int counted = std::max(1, options.steps - 1);
    for (int i = 0; i < counted; ++i) {
        world.step();
        const physics::StepProfile& p = world.profile();
        for (int s = 0; s < physics::kStageCount; ++s) {
            ms[s] += p.ms[s];
            ran[s] = ran[s] || p.ran[s];
        }
        total += p.total;
        pairs += p.pairs;
        contacts += p.contacts;
    }
    char text[96];
    std::snprintf(text, sizeof text, "%-12s %.3f ms/step:", scene.name.c_str(), total / counted);
    std::string out = text;
    for (int s = 0; s < physics::kStageCount; ++s) {
        if (!ran[s])
            continue;
        std::snprintf(text, sizeof text, " %s %.3f (%.0f %%),",
                      physics::stageName(static_cast<physics::Stage>(s)), ms[s] / counted,
                      total > 0 ? 100.0 * ms[s] / total : 0.0);
        out += text;
    }
    std::snprintf(text, sizeof text, " %.0f pairs, %.0f contacts", pairs / counted,
                  contacts / counted);
    return out + text;
}

std::unique_ptr<BenchEngine> makeRigidLabBenchEngine(const RigidLabBenchSettings& settings)
{
    return std::make_unique<RigidLabBench>(settings);
}

} // namespace rigidlab::bench
