// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/scene_overlaps.h"

#include "format/json_reader.h"

#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/sat.h"
#include "rigidlab/physics/settings.h"
#include "rigidlab/physics/work_budget.h"

#include <algorithm>

namespace rigidlab::lessons {

namespace {

using physics::BodyDef;

using physics::Vec2;

struct Box {
    Vec2 lo = Vec2::Zero(), hi = Vec2::Zero(); ///< corners in the world [m]
};

Box boxOf(const BodyDef& def)
{
    const physics::Transform xf(def.position, def.angle);
    return def.shape.visit(physics::Overloaded{
        [&](const physics::Circle& c) {
            const Vec2 p = xf.apply(c.center);
            const Vec2 r(c.radius, c.radius);
            return Box{p - r, p + r};
        },
        [&](const physics::Polygon& poly) {
            Box b{xf.apply(poly.vertices.front()), xf.apply(poly.vertices.front())};
            for (const Vec2& v : poly.vertices) {
                const Vec2 p = xf.apply(v);
                b.lo = b.lo.cwiseMin(p);
                b.hi = b.hi.cwiseMax(p);
            }
            return b;
        }});
}

bool overlapping(const BodyDef& a, const BodyDef& b, double allowed)
{
    const physics::Manifold m =
        physics::collideShapes(a.shape, physics::Transform(a.position, a.angle), b.shape,
                               physics::Transform(b.position, b.angle), 0.0);
    for (int k = 0; k < m.pointCount; ++k)
        if (m.points[static_cast<std::size_t>(k)].separation < -allowed)
            return true;
    return false;
}

} // namespace

OverlapSurvey surveyOverlaps(const Scene& scene, std::size_t most)
{
    // Penetration the engine itself allows at rest (its linear slop) is not an overlap: a box
    // snapped onto the ground touches it.
    const double allowed = physics::ContactSettings{}.linearSlop;
    const std::vector<BodyDef>& bodies = scene.bodies;
    std::vector<Box> boxes;
    std::vector<std::size_t> order;
    boxes.reserve(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        boxes.push_back(boxOf(bodies[i]));
        if (bodies[i].collide)
            order.push_back(i);
    }
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return boxes[a].lo.x() < boxes[b].lo.x() || (boxes[a].lo.x() == boxes[b].lo.x() && a < b);
    });
    const std::size_t budget = boxPairBudget(scene);
    OverlapSurvey survey;
    for (std::size_t s = 0; s < order.size(); ++s) {
        const std::size_t i = order[s];
        for (std::size_t t = s + 1; t < order.size(); ++t) {
            const std::size_t j = order[t];
            if (boxes[j].lo.x() > boxes[i].hi.x())
                break; // sorted by left edge: no later box reaches back to i
            const BodyDef& a = bodies[i];
            const BodyDef& b = bodies[j];
            if (a.type != physics::BodyType::Dynamic && b.type != physics::BodyType::Dynamic)
                continue;
            if ((boxes[i].hi.array() < boxes[j].lo.array()).any() ||
                (boxes[j].hi.array() < boxes[i].lo.array()).any())
                continue;
            if (++survey.boxPairs > budget) {
                survey.crowded = true;
                survey.crowdedAt = static_cast<physics::BodyId>(i);
                return survey;
            }
            if (!overlapping(a, b, allowed))
                continue;
            if (survey.pairs.size() == most) {
                survey.more = true;
                continue;
            }
            survey.pairs.emplace_back(static_cast<physics::BodyId>(std::min(i, j)),
                                      static_cast<physics::BodyId>(std::max(i, j)));
        }
    }
    return survey;
}

std::size_t boxPairBudget(const Scene& scene)
{
    return physics::pairBudget(scene.bodies.size());
}

QString checkCrowding(const Scene& scene, const QString& source, QStringList& warnings)
{
    using detail::FileMessages;
    const OverlapSurvey survey = surveyOverlaps(scene, kManyOverlaps);
    const auto name = [&scene](physics::BodyId i) {
        return QString::fromStdString(scene.bodies[static_cast<std::size_t>(i)].name);
    };
    if (survey.crowded) {
        const Vec2 at = scene.bodies[static_cast<std::size_t>(survey.crowdedAt)].position;
        return source + FileMessages::tr(": bodies: more than %1 pairs of bodies overlap or "
                                         "nearly touch (around \"%2\" at %3, %4 m): so crowded "
                                         "a start needs memory and time growing with the square "
                                         "of the bodies; spread them out")
                            .arg(boxPairBudget(scene))
                            .arg(name(survey.crowdedAt))
                            .arg(at.x())
                            .arg(at.y());
    }
    if (survey.pairs.size() >= kManyOverlaps) {
        const auto [a, b] = survey.pairs.front();
        warnings << source + FileMessages::tr(": bodies: %1 or more pairs of bodies start "
                                              "overlapping (\"%2\" and \"%3\" among them): "
                                              "the contacts push them apart at once")
                                 .arg(survey.pairs.size())
                                 .arg(name(a), name(b));
    }
    return {};
}

} // namespace rigidlab::lessons
