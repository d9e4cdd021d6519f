// SPDX-License-Identifier: GPL-3.0-or-later
#include "run/swept_bounds.h"

#include "run/off_stage.h"

#include "rigidlab/physics/overloaded.h"

#include <algorithm>

namespace rigidlab::lessons {

QRectF bodyBounds(const physics::Body& body)
{
    const physics::Transform t = body.transform();
    return body.shape.visit(physics::Overloaded{
        [&](const physics::Circle& c) {
            const physics::Vec2 p = t.apply(c.center);
            return QRectF(p.x() - c.radius, p.y() - c.radius, 2 * c.radius, 2 * c.radius);
        },
        [&](const physics::Polygon& poly) {
            physics::Vec2 lo = t.apply(poly.vertices.front()), hi = lo;
            for (const physics::Vec2& v : poly.vertices) {
                const physics::Vec2 p = t.apply(v);
                lo = lo.cwiseMin(p);
                hi = hi.cwiseMax(p);
            }
            return QRectF(QPointF(lo.x(), lo.y()), QPointF(hi.x(), hi.y()));
        }});
}

namespace {

QRectF movingBodiesBox(const physics::World& world)
{
    QRectF box;
    for (const physics::Body& b : world.bodies())
        if (b.moves())
            box |= bodyBounds(b);
    return box;
}

} // namespace

QRectF sweptBounds(const physics::World& world, double until)
{
    QRectF box = movingBodiesBox(world);
    const auto moving = std::count_if(world.bodies().begin(), world.bodies().end(),
                                      [](const physics::Body& b) { return b.moves(); });
    if (moving == 0 || world.divergence())
        return box;
    const double dt = world.def().dt;
    const double maxSteps = kSweepBodyStepBudget / static_cast<double>(moving);
    const StageFloor floor = stageFloor(world);
    physics::World copy(world);
    for (long long k = 0; copy.time() < until - 0.5 * dt && k < maxSteps; ++k) {
        copy.step();
        if (copy.divergence() || offStage(copy, floor))
            break;
        box |= movingBodiesBox(copy);
    }
    return box;
}

} // namespace rigidlab::lessons
