// SPDX-License-Identifier: GPL-3.0-or-later
// Bodies that overlap as the editor placed them: the scene runs, but the contacts push them
// apart at once, which a teacher should know before the class sees it.

#include "edit/edit_support.h"

#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/sat.h"
#include "rigidlab/physics/world.h"

#include <QStringList>

namespace rigidlab::lessons::edit {

using namespace support;
using physics::BodyDef;
using physics::BodyId;
using physics::Vec2;

namespace {

/// The body's bounding box in the world [m]: min and max corners.
std::pair<Vec2, Vec2> bounds(const BodyDef& def)
{
    const physics::Transform xf(def.position, def.angle);
    return def.shape.visit(physics::Overloaded{[&](const physics::Circle& c) {
                                                   const Vec2 p = xf.apply(c.center);
                                                   const Vec2 r(c.radius, c.radius);
                                                   return std::pair<Vec2, Vec2>(p - r, p + r);
                                               },
                                               [&](const physics::Polygon& poly) {
                                                   Vec2 lo = xf.apply(poly.vertices.front());
                                                   Vec2 hi = lo;
                                                   for (const Vec2& v : poly.vertices) {
                                                       const Vec2 p = xf.apply(v);
                                                       lo = lo.cwiseMin(p);
                                                       hi = hi.cwiseMax(p);
                                                   }
                                                   return std::pair<Vec2, Vec2>(lo, hi);
                                               }});
}

} // namespace

std::vector<std::pair<BodyId, BodyId>> overlappingPairs(const Scene& scene)
{
    // Penetration the engine itself allows at rest (its linear slop) is not an overlap: a box
    // snapped onto the ground touches it.
    const double allowed = physics::ContactSettings{}.linearSlop;
    std::vector<std::pair<Vec2, Vec2>> boxes;
    boxes.reserve(scene.bodies.size());
    for (const BodyDef& def : scene.bodies) {
        boxes.push_back(bounds(def));
    }
    std::vector<std::pair<BodyId, BodyId>> pairs;
    for (size_t i = 0; i < scene.bodies.size(); ++i) {
        const BodyDef& a = scene.bodies[i];
        for (size_t j = i + 1; j < scene.bodies.size(); ++j) {
            const BodyDef& b = scene.bodies[j];
            if (!a.collide || !b.collide ||
                (a.type != physics::BodyType::Dynamic && b.type != physics::BodyType::Dynamic)) {
                continue;
            }
            if ((boxes[i].second.array() < boxes[j].first.array()).any() ||
                (boxes[j].second.array() < boxes[i].first.array()).any()) {
                continue;
            }
            const physics::Manifold m =
                physics::collideShapes(a.shape, physics::Transform(a.position, a.angle), b.shape,
                                       physics::Transform(b.position, b.angle), 0.0);
            for (int k = 0; k < m.pointCount; ++k) {
                if (m.points[static_cast<size_t>(k)].separation < -allowed) {
                    pairs.emplace_back(static_cast<BodyId>(i), static_cast<BodyId>(j));
                    break;
                }
            }
        }
    }
    return pairs;
}

QString overlapMessage(const Scene& scene)
{
    const auto pairs = overlappingPairs(scene);
    if (pairs.empty()) {
        return {};
    }
    QStringList names;
    for (const auto& [a, b] : pairs) {
        names << EditMessages::tr("%1 overlaps %2")
                     .arg(bodyId(scene.bodies[static_cast<size_t>(a)]),
                          bodyId(scene.bodies[static_cast<size_t>(b)]));
    }
    return EditMessages::tr("%1; overlapping bodies are pushed apart when the scene runs")
        .arg(names.join(QStringLiteral(", ")));
}

} // namespace rigidlab::lessons::edit
