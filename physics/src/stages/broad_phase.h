// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private: the broad phase finds the pairs of bodies whose bounding boxes overlap.

#include "rigidlab/physics/body.h"

#include <cstddef>
#include <memory>
#include <optional>
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
    bool contains(const Aabb& o) const
    {
        return lo.x() <= o.lo.x() && lo.y() <= o.lo.y() && o.hi.x() <= hi.x() && o.hi.y() <= hi.y();
    }
    Aabb merged(const Aabb& o) const { return {lo.cwiseMin(o.lo), hi.cwiseMax(o.hi)}; }
    double perimeter() const { return 2.0 * ((hi.x() - lo.x()) + (hi.y() - lo.y())); }
};

/// The shape's bounding box in the world, grown by margin on every side.
Aabb computeAabb(const Shape& shape, const Transform& xf, double margin);

class AabbTree;

/// Where findPairs stopped: more pairs than its budget (work_budget.h).
struct Crowding {
    int body = 0;          ///< a body of the pair that crossed the budget
    std::size_t pairs = 0; ///< the pairs found when it stopped
    bool fat = false;      ///< the pairs of fat boxes crossed their cap, not the pairs themselves
};

/// A dynamic tree of "fat" boxes (each body's box grown by a few centimetres and by its
/// motion over a couple of steps), and the pairs whose fat boxes overlap, kept from step to
/// step. A body whose box stays inside its fat box costs nothing but that check; one that
/// leaves it is put back in the tree and asks the tree for its new neighbours, in
/// O(log n). A resting pile therefore costs O(n), not the O(n^1.5) of sweeping along x
/// (a pyramid's columns all overlap in x).
///
/// The answer depends only on where the bodies are, never on the tree's history: the
/// pairs whose boxes (grown by margin) overlap, (a, b) with a < b, sorted, so that the
/// contact order is deterministic and a copied world finds the same pairs.
class BroadPhase {
public:
    BroadPhase();
    ~BroadPhase();
    BroadPhase(const BroadPhase&) = delete;
    BroadPhase& operator=(const BroadPhase&) = delete;

    /// `xf`: each body's placement now; `dt`: the step [s], to grow a moving body's fat box
    /// along its motion. `grow`: per body, how much more than margin its box reaches [m] (a
    /// fast body's motion in the step, continuous.cpp), or empty for none. `excluded` holds
    /// pairs (a < b) that never collide (bodies joined by a pin). Bodies asleep keep the box
    /// they had. `budget`: the most pairs (pairBudget()); past it, or past kFatPairsPerPair
    /// times it of fat-box pairs, the search stops at once (its memory stays in proportion to
    /// the budget), `pairs` is empty, crowding() says where, and the tree starts afresh.
    void findPairs(const std::vector<Body>& bodies, const std::vector<Transform>& xf, double margin,
                   const std::vector<double>& grow, double dt,
                   const std::vector<std::pair<int, int>>& excluded, std::size_t budget,
                   std::vector<std::pair<int, int>>& pairs);
    /// Set when the last findPairs stopped at its budget.
    const std::optional<Crowding>& crowding() const { return m_crowding; }

    /// Calls fn(id) for every body whose fat box overlaps `box` (as of the last findPairs).
    template <typename Fn> void query(const Aabb& box, Fn&& fn) const;
    /// How many bodies the last findPairs put back in the tree (each one query of it).
    int refitted() const { return static_cast<int>(m_movedList.size()); }
    /// A body's box as of the last findPairs, grown by margin and its `grow` [m].
    const Aabb& box(int id) const { return m_box[static_cast<size_t>(id)]; }

private:
    void queryTree(const Aabb& box, std::vector<int>& out) const;
    /// Each body's box grown by margin and its grow; a body whose box left its fat box goes
    /// back into the tree with a new one, fattened by its motion over dt, and is listed as
    /// moved.
    void updateBoxes(const std::vector<Body>& bodies, const std::vector<Transform>& xf,
                     double margin, const std::vector<double>& grow, double dt);
    /// Stops a search at its budget: no pairs, and a tree to be built again from nothing.
    void stopCrowded(const Crowding& crowding, std::vector<std::pair<int, int>>& pairs);

    std::unique_ptr<AabbTree> m_tree;
    std::vector<int> m_leaf;    ///< per body: its leaf in the tree, -1 if none
    std::vector<Aabb> m_box;    ///< per body: its box grown by margin and its grow
    std::vector<Aabb> m_fat;    ///< per body: its fat box (its leaf's box), while it has a leaf
    std::vector<double> m_grow; ///< per body: the grow m_box was made with [m]
    /// Per body in the last findPairs: stayed in its fat box, moved out of it (a new leaf), or
    /// out of the tree (it does not collide). Bits, so that a pair's two can be or-ed.
    enum State : char { kStayed = 0, kMoved = 1, kOut = 2 };
    std::vector<char> m_state;
    std::vector<int> m_movedList;
    std::vector<std::pair<int, int>> m_pairs; ///< fat boxes overlapping, sorted
    std::vector<std::pair<int, int>> m_found, m_merged;
    mutable std::vector<int> m_hits;
    std::optional<Crowding> m_crowding;
};

template <typename Fn> void BroadPhase::query(const Aabb& box, Fn&& fn) const
{
    queryTree(box, m_hits);
    for (int id : m_hits)
        fn(id);
}

} // namespace rigidlab::physics
