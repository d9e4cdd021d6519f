#pragma once
// Private: the broad phase finds the pairs of bodies whose bounding boxes overlap.

#include "rigidlab/physics/body.h"

#include <utility>
#include <vector>

namespace rigidlab::physics {

struct Aabb {
    Vec2 lo = Vec2::Zero(); ///< [m]
    Vec2 hi = Vec2::Zero(); ///< [m]
    bool overlaps(const Aabb& o) const
    {
        return lo.x() <= o.hi.x() && o.lo.x() <= hi.x() && lo.y() <= o.hi.y() && o.lo.y() <= hi.y();
    }
};

/// The shape's bounding box in the world, grown by margin on every side.
Aabb computeAabb(const Shape& shape, const Transform& xf, double margin);

/// Sort and sweep along x: O(n log n) to sort, then only boxes that overlap in x are tested.
/// Pairs (a, b) come out with a < b, sorted, so that the contact order is deterministic.
class BroadPhase {
public:
    /// `excluded` holds pairs (a < b) that never collide (bodies joined by a pin).
    void findPairs(const std::vector<Body>& bodies, double margin,
                   const std::vector<std::pair<int, int>>& excluded,
                   std::vector<std::pair<int, int>>& pairs);

private:
    struct Entry {
        Aabb box;
        int id = 0;
    };
    std::vector<Entry> m_entries;
};

} // namespace rigidlab::physics
