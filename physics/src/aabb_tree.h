// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private: a dynamic tree of bounding boxes (a bounding volume hierarchy kept balanced as
// boxes come and go), for the broad phase.
//
// Leaves hold a box and a user value (a body id). An inner node's box encloses its two
// children's. A new leaf goes next to the node where it makes the tree's total perimeter
// grow least (the surface-area heuristic, in 2D the perimeter), and every inner node on the
// way back up is rotated when one child is more than one level taller than the other, as in
// an AVL tree, so that a query costs O(log n + answers). The idea is the one of Box2D's
// b2DynamicTree and Bullet's btDbvt; this code is written from the description.
//
//            root             each inner box = union of its children's boxes
//           /    \   .
//        inner   leaf c
//        /   \   .
//    leaf a  leaf b
//
// Nodes live in one vector and refer to each other by index; freed nodes are reused. Given
// the same sequence of calls the tree is the same, so that results stay deterministic.

#include "broad_phase.h"

#include <vector>

namespace rigidlab::physics {

class AabbTree {
public:
    static constexpr int kNull = -1;

    /// Adds a leaf; returns its node index (stable until the leaf is removed).
    int insert(const Aabb& box, int value);
    void remove(int leaf);
    const Aabb& box(int node) const { return m_nodes[static_cast<size_t>(node)].box; }
    int value(int leaf) const { return m_nodes[static_cast<size_t>(leaf)].value; }
    /// Height of the tree (0 when empty, 1 for a single leaf).
    int height() const
    {
        return m_root == kNull ? 0 : m_nodes[static_cast<size_t>(m_root)].height + 1;
    }

    /// Calls fn(value) for every leaf whose box overlaps `box`.
    template <typename Fn> void query(const Aabb& box, Fn&& fn) const
    {
        if (m_root == kNull)
            return;
        m_stack.clear();
        m_stack.push_back(m_root);
        while (!m_stack.empty()) {
            const Node& n = m_nodes[static_cast<size_t>(m_stack.back())];
            m_stack.pop_back();
            if (!n.box.overlaps(box))
                continue;
            if (n.isLeaf()) {
                fn(n.value);
            } else {
                m_stack.push_back(n.child1);
                m_stack.push_back(n.child2);
            }
        }
    }

private:
    struct Node {
        Aabb box;
        int parent = kNull; ///< or the next free node, while free
        int child1 = kNull, child2 = kNull;
        int height = 0; ///< 0 for a leaf, -1 for a free node
        int value = -1; ///< leaves: the body id
        bool isLeaf() const { return child1 == kNull; }
    };

    int allocate();
    void release(int node);
    void insertLeaf(int leaf);
    void removeLeaf(int leaf);
    /// Rotates node a up if it is unbalanced; returns the index now at a's place.
    int balance(int a);
    /// Refits boxes and heights from `node` up to the root, balancing on the way.
    void fixUpwards(int node);

    std::vector<Node> m_nodes;
    int m_root = kNull;
    int m_free = kNull;
    mutable std::vector<int> m_stack; ///< query scratch
};

} // namespace rigidlab::physics
