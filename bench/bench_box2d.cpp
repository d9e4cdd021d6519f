// SPDX-License-Identifier: GPL-3.0-or-later
// Box2D 2.4's side of the benchmarks: the same bodies in a b2World.

#include "bench_peers.h"

#include <box2d/box2d.h>

namespace rigidlab::bench {

namespace {

using bench::BenchShapeKind;

class Box2dEngine final : public bench::BenchEngine {
public:
    std::string name() const override { return "Box2D 2.4"; }
    std::string settings() const override
    {
        return "2.4.1, 8 velocity / 3 position iterations, single precision, sleeping off";
    }

    void build(const bench::BenchScene& scene) override
    {
        m_bodies.clear();
        m_world = std::make_unique<b2World>(
            b2Vec2(static_cast<float>(scene.gravity.x()), static_cast<float>(scene.gravity.y())));
        m_world->SetAllowSleeping(false);
        m_dt = static_cast<float>(scene.dt);
        for (const bench::BenchBody& b : scene.bodies) {
            b2BodyDef bd;
            bd.type = b.isStatic ? b2_staticBody : b2_dynamicBody;
            bd.position.Set(static_cast<float>(b.position.x()), static_cast<float>(b.position.y()));
            bd.angle = static_cast<float>(b.angle);
            b2Body* body = m_world->CreateBody(&bd);
            b2PolygonShape polygon;
            b2CircleShape circle;
            b2FixtureDef fd;
            switch (b.shape.kind) {
            case BenchShapeKind::Box:
                polygon.SetAsBox(static_cast<float>(0.5 * b.shape.width),
                                 static_cast<float>(0.5 * b.shape.height));
                fd.shape = &polygon;
                break;
            case BenchShapeKind::Circle:
                circle.m_radius = static_cast<float>(b.shape.radius);
                fd.shape = &circle;
                break;
            case BenchShapeKind::Polygon: {
                std::vector<b2Vec2> v;
                for (const auto& p : b.shape.vertices)
                    v.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
                polygon.Set(v.data(), static_cast<int32>(v.size()));
                fd.shape = &polygon;
                break;
            }
            }
            fd.density = static_cast<float>(b.density);
            fd.friction = static_cast<float>(b.friction);
            fd.restitution = 0.0f;
            body->CreateFixture(&fd);
            m_bodies.push_back(body);
        }
    }

    void step() override { m_world->Step(m_dt, 8, 3); }

    void poses(std::vector<bench::BenchPose>& out) const override
    {
        out.clear();
        for (const b2Body* b : m_bodies)
            out.push_back({physics::Vec2(b->GetPosition().x, b->GetPosition().y), b->GetAngle()});
    }

private:
    std::unique_ptr<b2World> m_world;
    std::vector<b2Body*> m_bodies; // owned by m_world; in the scene's order
    float m_dt = 1.0f / 60.0f;
};

} // namespace

std::unique_ptr<bench::BenchEngine> makeBox2dEngine()
{
    return std::make_unique<Box2dEngine>();
}

} // namespace rigidlab::bench
