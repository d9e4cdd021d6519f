// SPDX-License-Identifier: GPL-3.0-or-later
// Stage::BroadPhase (profile.h): the broad phase (see broad_phase.h).

#include "broad_phase.h"

#include "aabb_tree.h"

#include "rigidlab/physics/work_budget.h"

#include <algorithm>

namespace rigidlab::physics {

namespace {

using Pairs = std::vector<std::pair<int, int>>;

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

/// Merges the kept pairs that are still alive with the new ones (both sorted) into `merged`,
/// and writes those of them whose boxes overlap, and are not excluded, to `pairs`: one pass,
/// both lists written in place (at most every kept pair and every new one).
template <typename Alive>
void mergePairs(const Pairs& kept, Alive&& alive, const Pairs& fresh,
                const std::vector<Aabb>& boxes, const Pairs& excluded, Pairs& merged, Pairs& pairs)
{
    const size_t most = kept.size() + fresh.size();
    merged.resize(most);
    pairs.resize(most);
    std::pair<int, int>* to = merged.data();
    std::pair<int, int>* out = pairs.data();
    const Aabb* box = boxes.data();
    const bool anyExcluded = !excluded.empty();
    auto keep = [&](const std::pair<int, int>& p) {
        *to++ = p;
        *out = p;
        out += box[p.first].overlaps(box[p.second]) &&
               (!anyExcluded || !std::binary_search(excluded.begin(), excluded.end(), p));
    };
    const std::pair<int, int>* found = fresh.data();
    const std::pair<int, int>* foundEnd = found + fresh.size();
    if (found == foundEnd) { // no body left its fat box: most steps of a pile
        for (const auto& p : kept)
            if (alive(p))
                keep(p);
    } else {
        for (const auto& p : kept) {
            if (!alive(p))
                continue;
            while (found != foundEnd && *found < p)
                keep(*found++);
            if (found != foundEnd && *found == p)
                ++found; // found again
            keep(p);
        }
        while (found != foundEnd)
            keep(*found++);
    }
    merged.resize(static_cast<size_t>(to - merged.data()));
    pairs.resize(static_cast<size_t>(out - pairs.data()));
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
                                      // xf.apply(v) for both coordinates at once: c vx - s vy
                                      // is c vx + (-s) vy, the same number, so the box is
                                      // the one of the vertices turned one at a time.
                                      using Pair = Eigen::Array2d;
                                      const Pair cs(xf.q.c, xf.q.s), sc(-xf.q.s, xf.q.c);
                                      const Pair p = xf.p.array();
                                      const std::vector<Vec2>& v = polygon.vertices;
                                      Pair lo = cs * v[0].x() + sc * v[0].y() + p;
                                      Pair hi = lo;
                                      for (size_t i = 1; i < v.size(); ++i) {
                                          const Pair q = cs * v[i].x() + sc * v[i].y() + p;
                                          lo = lo.min(q);
                                          hi = hi.max(q);
                                      }
                                      return Aabb{(lo - margin).matrix(), (hi + margin).matrix()};
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
    m_fat.resize(n);
    m_grow.resize(n, 0.0);
    m_state.assign(n, kStayed);
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
            m_state[i] = kOut;
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
        if (leaf != AabbTree::kNull && m_fat[i].contains(box))
            continue;
        if (leaf != AabbTree::kNull)
            m_tree->remove(leaf);
        m_fat[i] = fatten(box, b.velocity * dt);
        leaf = m_tree->insert(m_fat[i], static_cast<int>(i));
        m_state[i] = kMoved;
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
        queryTree(m_fat[static_cast<size_t>(i)], m_hits);
        for (int j : m_hits) {
            if (j == i || (m_state[static_cast<size_t>(j)] == kMoved && j < i))
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

    // Kept pairs (both still in the tree, fat boxes still overlapping) merged with the new, and
    // the answer: those whose boxes overlap now. Two bodies that both stayed in their fat boxes
    // kept those boxes, which overlapped when the pair was found or last kept: not looked at.
    auto alive = [&](const std::pair<int, int>& p) {
        const auto a = static_cast<size_t>(p.first);
        const auto b = static_cast<size_t>(p.second);
        if (b >= n)
            return false;
        const int state = m_state[a] | m_state[b];
        return state == kStayed || (state == kMoved && m_fat[a].overlaps(m_fat[b]));
    };
    mergePairs(m_pairs, alive, m_found, m_box, excluded, m_merged, pairs);
    std::swap(m_pairs, m_merged);
    if (pairs.size() > budget)
        stopCrowded({pairs[budget].first, pairs.size(), false}, pairs);
}

} // namespace rigidlab::physics
