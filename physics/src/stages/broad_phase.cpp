// SPDX-License-Identifier: GPL-3.0-or-later
// Stage::BroadPhase (profile.h): the broad phase (see broad_phase.h).

#include "broad_phase.h"

#include "aabb_tree.h"

#include "rigidlab/physics/work_budget.h"

#include <algorithm>

namespace rigidlab::physics {

namespace {

/// A fat box reaches this far beyond the body's box [m]: small motions stay inside it.
constexpr double kFatMargin = 0.1;
/// ... and this many steps ahead along the body's motion.
constexpr double kFatSteps = 2.0;

Aabb fatten(const Aabb& box, const Vec2& displacement)
{
    Aabb fat{box.lo.array() - kFatMargin, box.hi.array() + kFatMargin};
    const Vec2 d = kFatSteps * displacement;
    fat.lo += d.cwiseMin(Vec2::Zero());
    fat.hi += d.cwiseMax(Vec2::Zero());
    return fat;
}

} // namespace

Aabb computeAabb(const Shape& shape, const Transform& xf, double margin)
{
    return shape.visit(Overloaded{[&](const Circle& circle) {
                                      Aabb box;
                                      const Vec2 c = xf.apply(circle.center);
                                      const Vec2 r = Vec2::Constant(circle.radius + margin);
                                      box.lo = c - r;
                                      box.hi = c + r;
                                      return box;
                                  },
                                  [&](const Polygon& polygon) {
                                      Aabb box;
                                      const std::vector<Vec2>& v = polygon.vertices;
                                      box.lo = box.hi = xf.apply(v[0]);
                                      for (size_t i = 1; i < v.size(); ++i) {
                                          const Vec2 p = xf.apply(v[i]);
                                          box.lo = box.lo.cwiseMin(p);
                                          box.hi = box.hi.cwiseMax(p);
                                      }
                                      box.lo.array() -= margin;
                                      box.hi.array() += margin;
                                      return box;
                                  }});
}

BroadPhase::BroadPhase() : m_tree(std::make_unique<AabbTree>()) {}
BroadPhase::~BroadPhase() = default;

void BroadPhase::queryTree(const Aabb& box, std::vector<int>& out) const
{
    out.clear();
    m_tree->query(box, [&](int id) { out.push_back(id); });
}

void BroadPhase::updateBoxes(const std::vector<Body>& bodies, const std::vector<Transform>& xf,
                             double margin, const std::vector<double>& grow, double dt)
{
    const size_t n = bodies.size();
    m_leaf.resize(n, AabbTree::kNull);
    m_box.resize(n);
    m_grow.resize(n, 0.0);
    m_moved.assign(n, 0);
    m_movedList.clear();

    // Boxes: a body that left its fat box goes back into the tree with a new one.
    for (size_t i = 0; i < n; ++i) {
        const Body& b = bodies[i];
        int& leaf = m_leaf[i];
        if (!b.collide) {
            if (leaf != AabbTree::kNull) {
                m_tree->remove(leaf);
                leaf = AabbTree::kNull;
            }
            continue;
        }
        const double g = grow.empty() ? 0.0 : grow[i];
        if (leaf != AabbTree::kNull && b.isDynamic() && !b.awake && g == m_grow[i])
            continue; // asleep: where it was
        // A fast body's box reaches as far as its motion (continuous.cpp) and its fat box
        // holds that box: the pairs it needs are then among the tree's kept pairs, with no
        // query of its own every step, and only a body that outruns its fat box asks again.
        const Aabb box = computeAabb(b.shape, xf[i], margin + g);
        m_box[i] = box;
        m_grow[i] = g;
        if (leaf != AabbTree::kNull && m_tree->box(leaf).contains(box))
            continue;
        if (leaf != AabbTree::kNull)
            m_tree->remove(leaf);
        leaf = m_tree->insert(fatten(box, b.velocity * dt), static_cast<int>(i));
        m_moved[i] = 1;
        m_movedList.push_back(static_cast<int>(i));
    }
}

void BroadPhase::stopCrowded(const Crowding& crowding, std::vector<std::pair<int, int>>& pairs)
{
    m_crowding = crowding;
    pairs.clear();
    m_found.clear();
    m_merged.clear();
    m_pairs.clear();
    m_tree = std::make_unique<AabbTree>();
    m_leaf.assign(m_leaf.size(), AabbTree::kNull);
}

void BroadPhase::findPairs(const std::vector<Body>& bodies, const std::vector<Transform>& xf,
                           double margin, const std::vector<double>& grow, double dt,
                           const std::vector<std::pair<int, int>>& excluded, std::size_t budget,
                           std::vector<std::pair<int, int>>& pairs)
{
    const size_t n = bodies.size();
    m_crowding.reset();
    updateBoxes(bodies, xf, margin, grow, dt);

    // New neighbours of the bodies that moved. A pair of two moved bodies is taken when the
    // lower id asks. Counted as they come: a heap stops here after a few bodies' queries,
    // before its pairs fill the memory.
    m_found.clear();
    std::size_t close = 0; // new pairs whose boxes (not only their fat boxes) overlap
    const std::size_t fatCap = kFatPairsPerPair * budget;
    for (int i : m_movedList) {
        const bool iDynamic = bodies[static_cast<size_t>(i)].isDynamic();
        queryTree(m_tree->box(m_leaf[static_cast<size_t>(i)]), m_hits);
        for (int j : m_hits) {
            if (j == i || (m_moved[static_cast<size_t>(j)] && j < i))
                continue;
            if (!iDynamic && !bodies[static_cast<size_t>(j)].isDynamic())
                continue; // static and kinematic bodies do not push each other
            m_found.push_back(std::minmax(i, j));
            if (m_box[static_cast<size_t>(i)].overlaps(m_box[static_cast<size_t>(j)]))
                ++close;
            if (close > budget || m_found.size() > fatCap) {
                const bool fat = close <= budget;
                stopCrowded({i, fat ? m_found.size() : close, fat}, pairs);
                return;
            }
        }
    }
    std::sort(m_found.begin(), m_found.end());

    // Kept pairs (both still in the tree, fat boxes still overlapping) merged with the new.
    m_merged.clear();
    auto alive = [&](const std::pair<int, int>& p) {
        const int la = m_leaf[static_cast<size_t>(p.first)];
        const int lb = m_leaf[static_cast<size_t>(p.second)];
        return la != AabbTree::kNull && lb != AabbTree::kNull &&
               m_tree->box(la).overlaps(m_tree->box(lb));
    };
    size_t k = 0;
    for (const auto& p : m_pairs) {
        if (static_cast<size_t>(p.second) >= n || !alive(p))
            continue;
        while (k < m_found.size() && m_found[k] < p)
            m_merged.push_back(m_found[k++]);
        if (k < m_found.size() && m_found[k] == p)
            ++k; // found again
        m_merged.push_back(p);
    }
    m_merged.insert(m_merged.end(), m_found.begin() + static_cast<std::ptrdiff_t>(k),
                    m_found.end());
    std::swap(m_pairs, m_merged);

    // The answer: pairs whose boxes overlap now.
    pairs.clear();
    for (const auto& p : m_pairs) {
        if (!m_box[static_cast<size_t>(p.first)].overlaps(m_box[static_cast<size_t>(p.second)]))
            continue;
        if (!excluded.empty() && std::binary_search(excluded.begin(), excluded.end(), p))
            continue;
        pairs.push_back(p);
    }
    if (pairs.size() > budget)
        stopCrowded({pairs[budget].first, pairs.size(), false}, pairs);
}

} // namespace rigidlab::physics
