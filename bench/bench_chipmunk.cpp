// SPDX-License-Identifier: GPL-3.0-or-later
// Chipmunk 7's side of the benchmarks: the same bodies in a cpSpace.

#include "bench_peers.h"

#include <chipmunk/chipmunk.h>

namespace rigidlab::bench {

namespace {

using bench::BenchShapeKind;

/// Chipmunk's default collision slop (0.1) is meant for pixel units; in metres the scenes use
/// Box2D's 0.005 m, so that both engines allow the same overlap.
constexpr double kCollisionSlop = 0.005;

class ChipmunkEngine final : public bench::BenchEngine {
public:
    ~ChipmunkEngine() override { clear(); }

    std::string name() const override { return "Chipmunk"; }
    std::string settings() const override
    {
        return "7.0.3, 10 iterations, collision slop 0.005 m, double precision, sleeping off";
    }

    void build(const bench::BenchScene& scene) override
    {
        clear();
        m_space = cpSpaceNew();
        cpSpaceSetIterations(m_space, 10);
        cpSpaceSetGravity(m_space, cpv(scene.gravity.x(), scene.gravity.y()));
        cpSpaceSetCollisionSlop(m_space, kCollisionSlop);
        m_dt = scene.dt;
        for (const bench::BenchBody& b : scene.bodies) {
            cpBody* body = nullptr;
            cpShape* shape = nullptr;
            std::vector<cpVect> v;
            double area = 0.0;
            switch (b.shape.kind) {
            case BenchShapeKind::Box:
                area = b.shape.width * b.shape.height;
                break;
            case BenchShapeKind::Circle:
                area = cpAreaForCircle(0.0, b.shape.radius);
                break;
            case BenchShapeKind::Polygon:
                for (const auto& p : b.shape.vertices)
                    v.push_back(cpv(p.x(), p.y()));
                area = cpAreaForPoly(static_cast<int>(v.size()), v.data(), 0.0);
                break;
            }
            const double mass = b.density * area;
            if (b.isStatic) {
                body = cpBodyNewStatic();
            } else {
                double moment = 0.0;
                switch (b.shape.kind) {
                case BenchShapeKind::Box:
                    moment = cpMomentForBox(mass, b.shape.width, b.shape.height);
                    break;
                case BenchShapeKind::Circle:
                    moment = cpMomentForCircle(mass, 0.0, b.shape.radius, cpvzero);
                    break;
                case BenchShapeKind::Polygon:
                    moment =
                        cpMomentForPoly(mass, static_cast<int>(v.size()), v.data(), cpvzero, 0.0);
                    break;
                }
                body = cpBodyNew(mass, moment);
            }
            cpSpaceAddBody(m_space, body);
            cpBodySetPosition(body, cpv(b.position.x(), b.position.y()));
            cpBodySetAngle(body, b.angle);
            switch (b.shape.kind) {
            case BenchShapeKind::Box:
                shape = cpBoxShapeNew(body, b.shape.width, b.shape.height, 0.0);
                break;
            case BenchShapeKind::Circle:
                shape = cpCircleShapeNew(body, b.shape.radius, cpvzero);
                break;
            case BenchShapeKind::Polygon:
                shape = cpPolyShapeNew(body, static_cast<int>(v.size()), v.data(),
                                       cpTransformIdentity, 0.0);
                break;
            }
            cpShapeSetFriction(shape, b.friction);
            cpShapeSetElasticity(shape, 0.0);
            cpSpaceAddShape(m_space, shape);
            m_bodies.push_back(body);
            m_shapes.push_back(shape);
        }
        // Static shapes placed after their bodies moved: tell the spatial index.
        cpSpaceReindexStatic(m_space);
    }

    void step() override { cpSpaceStep(m_space, m_dt); }

    void poses(std::vector<bench::BenchPose>& out) const override
    {
        out.clear();
        for (cpBody* b : m_bodies) {
            const cpVect p = cpBodyGetPosition(b);
            out.push_back({physics::Vec2(p.x, p.y), cpBodyGetAngle(b)});
        }
    }

private:
    void clear()
    {
        if (!m_space)
            return;
        for (cpShape* s : m_shapes) {
            cpSpaceRemoveShape(m_space, s);
            cpShapeFree(s);
        }
        for (cpBody* b : m_bodies) {
            cpSpaceRemoveBody(m_space, b);
            cpBodyFree(b);
        }
        m_shapes.clear();
        m_bodies.clear();
        cpSpaceFree(m_space);
        m_space = nullptr;
    }

    cpSpace* m_space = nullptr;
    std::vector<cpBody*> m_bodies; // in the scene's order
    std::vector<cpShape*> m_shapes;
    double m_dt = 1.0 / 60.0;
};

} // namespace

std::unique_ptr<bench::BenchEngine> makeChipmunkEngine()
{
    return std::make_unique<ChipmunkEngine>();
}

} // namespace rigidlab::bench
