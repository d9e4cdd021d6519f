// Stage 3 of a step: the broad phase.

#include "broad_phase.h"

#include <algorithm>

namespace rigidlab::physics {

Aabb computeAabb(const Shape& shape, const Transform& xf, double margin)
{
    Aabb box;
    if (shape.type == ShapeType::Circle) {
        const Vec2 c = xf.apply(shape.circle.center);
        const Vec2 r = Vec2::Constant(shape.circle.radius + margin);
        box.lo = c - r;
        box.hi = c + r;
        return box;
    }
    const std::vector<Vec2>& v = shape.polygon.vertices;
    box.lo = box.hi = xf.apply(v[0]);
    for (size_t i = 1; i < v.size(); ++i) {
        const Vec2 p = xf.apply(v[i]);
        box.lo = box.lo.cwiseMin(p);
        box.hi = box.hi.cwiseMax(p);
    }
    box.lo.array() -= margin;
    box.hi.array() += margin;
    return box;
}

void BroadPhase::findPairs(const std::vector<Body>& bodies, double margin,
                           const std::vector<std::pair<int, int>>& excluded,
                           std::vector<std::pair<int, int>>& pairs)
{
    pairs.clear();
    m_entries.clear();
    for (size_t i = 0; i < bodies.size(); ++i) {
        const Body& b = bodies[i];
        if (!b.collide)
            continue;
        m_entries.push_back({computeAabb(b.shape, b.transform(), margin), static_cast<int>(i)});
    }
    std::sort(m_entries.begin(), m_entries.end(), [](const Entry& a, const Entry& b) {
        return a.box.lo.x() < b.box.lo.x() || (a.box.lo.x() == b.box.lo.x() && a.id < b.id);
    });
    for (size_t i = 0; i < m_entries.size(); ++i) {
        const Entry& e = m_entries[i];
        const bool eDynamic = bodies[static_cast<size_t>(e.id)].isDynamic();
        for (size_t j = i + 1; j < m_entries.size(); ++j) {
            const Entry& f = m_entries[j];
            if (f.box.lo.x() > e.box.hi.x())
                break; // sorted by lo.x: no later box can overlap e in x
            if (!eDynamic && !bodies[static_cast<size_t>(f.id)].isDynamic())
                continue; // static and kinematic bodies do not push each other
            if (!e.box.overlaps(f.box))
                continue;
            std::pair<int, int> p = std::minmax(e.id, f.id);
            if (std::binary_search(excluded.begin(), excluded.end(), p))
                continue;
            pairs.push_back(p);
        }
    }
    std::sort(pairs.begin(), pairs.end());
}

} // namespace rigidlab::physics
