// SPDX-License-Identifier: GPL-3.0-or-later
// Box2D v3's side of the benchmarks: the same bodies in a b2World of the C API, on one thread.
// Built only when ./lab bench is given a Box2D v3 source tree (BOX2D_V3_DIR, CMakeLists.txt):
// this is the one translation unit that includes v3's <box2d/box2d.h>, which has the same name
// as 2.4's (bench_box2d.cpp). It is compiled twice, once for each build of Box2D v3 (SSE2, its
// default, and AVX2), each copy into a shared library of its own with a factory of its own
// (RIGIDLAB_BENCH_BOX2D_V3_FACTORY) and a name with the build (RIGIDLAB_BENCH_BOX2D_V3_LABEL).

#include "bench_peers.h"

#include <box2d/box2d.h>

#include <vector>

namespace rigidlab::bench {

namespace {

using bench::BenchShapeKind;

/// Box2D v3 solves each step in 4 substeps of soft contacts with relaxation (its default).
constexpr int kSubSteps = 4;

class Box2dV3Engine final : public bench::BenchEngine {
public:
    ~Box2dV3Engine() override { destroy(); }

    std::string name() const override { return "Box2D v3 " RIGIDLAB_BENCH_BOX2D_V3_LABEL; }
    std::string settings() const override
    {
        const b2Version v = b2GetVersion();
        return std::to_string(v.major) + "." + std::to_string(v.minor) + "." +
               std::to_string(v.revision) + " built with " RIGIDLAB_BENCH_BOX2D_V3_LABEL ", " +
               std::to_string(kSubSteps) +
               " substeps, single precision, one thread (workerCount 1, no task system), "
               "sleeping off";
    }

    void build(const bench::BenchScene& scene) override
    {
        destroy();
        b2WorldDef wd = b2DefaultWorldDef();
        wd.gravity = {static_cast<float>(scene.gravity.x()), static_cast<float>(scene.gravity.y())};
        wd.enableSleep = false;
        wd.workerCount = 1;
        wd.enqueueTask = nullptr;
        wd.finishTask = nullptr;
        m_world = b2CreateWorld(&wd);
        m_dt = static_cast<float>(scene.dt);
        for (const bench::BenchBody& b : scene.bodies) {
            b2BodyDef bd = b2DefaultBodyDef();
            bd.type = b.isStatic ? b2_staticBody : b2_dynamicBody;
            bd.position = {static_cast<float>(b.position.x()), static_cast<float>(b.position.y())};
            bd.rotation = b2MakeRot(static_cast<float>(b.angle));
            bd.enableSleep = false;
            const b2BodyId body = b2CreateBody(m_world, &bd);
            b2ShapeDef sd = b2DefaultShapeDef();
            sd.density = static_cast<float>(b.density);
            sd.material.friction = static_cast<float>(b.friction);
            sd.material.restitution = 0.0f;
            switch (b.shape.kind) {
            case BenchShapeKind::Box: {
                const b2Polygon box = b2MakeBox(static_cast<float>(0.5 * b.shape.width),
                                                static_cast<float>(0.5 * b.shape.height));
                b2CreatePolygonShape(body, &sd, &box);
                break;
            }
            case BenchShapeKind::Circle: {
                const b2Circle circle{{0.0f, 0.0f}, static_cast<float>(b.shape.radius)};
                b2CreateCircleShape(body, &sd, &circle);
                break;
            }
            case BenchShapeKind::Polygon: {
                std::vector<b2Vec2> v;
                for (const auto& p : b.shape.vertices)
                    v.push_back({static_cast<float>(p.x()), static_cast<float>(p.y())});
                const b2Hull hull = b2ComputeHull(v.data(), static_cast<int>(v.size()));
                const b2Polygon polygon = b2MakePolygon(&hull, 0.0f);
                b2CreatePolygonShape(body, &sd, &polygon);
                break;
            }
            }
            m_bodies.push_back(body);
        }
    }

    void step() override { b2World_Step(m_world, m_dt, kSubSteps); }

    void poses(std::vector<bench::BenchPose>& out) const override
    {
        out.clear();
        for (const b2BodyId b : m_bodies) {
            const b2Pos p = b2Body_GetPosition(b);
            out.push_back({physics::Vec2(p.x, p.y), b2Rot_GetAngle(b2Body_GetRotation(b))});
        }
    }

private:
    void destroy()
    {
        if (b2World_IsValid(m_world))
            b2DestroyWorld(m_world);
        m_world = b2_nullWorldId;
        m_bodies.clear();
    }

    b2WorldId m_world = b2_nullWorldId;
    std::vector<b2BodyId> m_bodies; // owned by m_world; in the scene's order
    float m_dt = 1.0f / 60.0f;
};

} // namespace

[[gnu::visibility("default")]] std::unique_ptr<bench::BenchEngine> RIGIDLAB_BENCH_BOX2D_V3_FACTORY()
{
    return std::make_unique<Box2dV3Engine>();
}

} // namespace rigidlab::bench
