// SPDX-License-Identifier: GPL-3.0-or-later
// The broad phase's dynamic tree of boxes (see aabb_tree.h).

#include "aabb_tree.h"

#include <algorithm>
#include <cassert>

namespace rigidlab::physics {

int AabbTree::allocate()
{
    if (m_free == kNull) {
        m_nodes.emplace_back();
        return static_cast<int>(m_nodes.size()) - 1;
    }
    const int node = m_free;
    m_free = m_nodes[static_cast<size_t>(node)].parent;
    m_nodes[static_cast<size_t>(node)] = Node{};
    return node;
}

void AabbTree::release(int node)
{
    Node& n = m_nodes[static_cast<size_t>(node)];
    n.parent = m_free;
    n.child1 = n.child2 = kNull;
    n.height = -1;
    m_free = node;
}

int AabbTree::insert(const Aabb& box, int value)
{
    const int leaf = allocate();
    Node& n = m_nodes[static_cast<size_t>(leaf)];
    n.box = box;
    n.value = value;
    n.height = 0;
    insertLeaf(leaf);
    return leaf;
}

void AabbTree::remove(int leaf)
{
    assert(m_nodes[static_cast<size_t>(leaf)].isLeaf());
    removeLeaf(leaf);
    release(leaf);
}

void AabbTree::insertLeaf(int leaf)
{
    if (m_root == kNull) {
        m_root = leaf;
        m_nodes[static_cast<size_t>(leaf)].parent = kNull;
        return;
    }
    // Walk down to the best sibling. At an inner node, pairing the leaf with the whole node
    // costs the perimeter of their union (a new parent), counted twice as in the surface-area
    // heuristic; going down into a child costs the growth of every box on the way plus that
    // child's own growth (or, for a leaf child, the new parent's perimeter).
    const Aabb box = m_nodes[static_cast<size_t>(leaf)].box;
    int index = m_root;
    while (!m_nodes[static_cast<size_t>(index)].isLeaf()) {
        const Node& n = m_nodes[static_cast<size_t>(index)];
        const double perimeter = n.box.perimeter();
        const double combined = n.box.merged(box).perimeter();
        const double here = 2.0 * combined;
        const double inherited = 2.0 * (combined - perimeter);
        auto descend = [&](int child) {
            const Node& c = m_nodes[static_cast<size_t>(child)];
            const double grown = c.box.merged(box).perimeter();
            return (c.isLeaf() ? grown : grown - c.box.perimeter()) + inherited;
        };
        const double cost1 = descend(n.child1), cost2 = descend(n.child2);
        if (here < cost1 && here < cost2)
            break;
        index = cost1 <= cost2 ? n.child1 : n.child2;
    }

    const int sibling = index;
    const int oldParent = m_nodes[static_cast<size_t>(sibling)].parent;
    const int parent = allocate(); // may grow m_nodes: take references only after this
    Node& p = m_nodes[static_cast<size_t>(parent)];
    p.parent = oldParent;
    p.box = box.merged(m_nodes[static_cast<size_t>(sibling)].box);
    p.height = m_nodes[static_cast<size_t>(sibling)].height + 1;
    p.child1 = sibling;
    p.child2 = leaf;
    m_nodes[static_cast<size_t>(sibling)].parent = parent;
    m_nodes[static_cast<size_t>(leaf)].parent = parent;
    if (oldParent == kNull) {
        m_root = parent;
    } else {
        Node& op = m_nodes[static_cast<size_t>(oldParent)];
        (op.child1 == sibling ? op.child1 : op.child2) = parent;
    }
    fixUpwards(m_nodes[static_cast<size_t>(leaf)].parent);
}

void AabbTree::removeLeaf(int leaf)
{
    if (leaf == m_root) {
        m_root = kNull;
        return;
    }
    const int parent = m_nodes[static_cast<size_t>(leaf)].parent;
    const Node& p = m_nodes[static_cast<size_t>(parent)];
    const int grand = p.parent;
    const int sibling = p.child1 == leaf ? p.child2 : p.child1;
    m_nodes[static_cast<size_t>(sibling)].parent = grand;
    if (grand == kNull) {
        m_root = sibling;
        release(parent);
        return;
    }
    Node& g = m_nodes[static_cast<size_t>(grand)];
    (g.child1 == parent ? g.child1 : g.child2) = sibling;
    release(parent);
    fixUpwards(grand);
}

void AabbTree::fixUpwards(int node)
{
    while (node != kNull) {
        node = balance(node);
        Node& n = m_nodes[static_cast<size_t>(node)];
        const Node& c1 = m_nodes[static_cast<size_t>(n.child1)];
        const Node& c2 = m_nodes[static_cast<size_t>(n.child2)];
        n.height = 1 + std::max(c1.height, c2.height);
        n.box = c1.box.merged(c2.box);
        node = n.parent;
    }
}

int AabbTree::balance(int a)
{
    Node& A = m_nodes[static_cast<size_t>(a)];
    if (A.isLeaf() || A.height < 2)
        return a;
    const int b = A.child1, c = A.child2;
    const int lean =
        m_nodes[static_cast<size_t>(c)].height - m_nodes[static_cast<size_t>(b)].height;
    if (lean >= -1 && lean <= 1)
        return a;

    // The taller child t rises to a's place; a keeps its other child and takes t's shorter
    // child, t keeps its taller one.
    //
    //        a                t
    //       / \              / \   .
    //      s   t     ->     a   tall
    //         / \          / \   .
    //     tall   short    s   short
    const int t = lean > 1 ? c : b;
    const int s = lean > 1 ? b : c;
    Node& T = m_nodes[static_cast<size_t>(t)];
    const int f = T.child1, g = T.child2;
    const bool fTaller =
        m_nodes[static_cast<size_t>(f)].height > m_nodes[static_cast<size_t>(g)].height;
    const int tall = fTaller ? f : g, shorter = fTaller ? g : f;

    T.parent = A.parent;
    A.parent = t;
    if (T.parent == kNull) {
        m_root = t;
    } else {
        Node& P = m_nodes[static_cast<size_t>(T.parent)];
        (P.child1 == a ? P.child1 : P.child2) = t;
    }
    T.child1 = a;
    T.child2 = tall;
    A.child1 = s;
    A.child2 = shorter;
    m_nodes[static_cast<size_t>(shorter)].parent = a;

    const Node& S = m_nodes[static_cast<size_t>(s)];
    const Node& Sh = m_nodes[static_cast<size_t>(shorter)];
    const Node& Tall = m_nodes[static_cast<size_t>(tall)];
    A.box = S.box.merged(Sh.box);
    A.height = 1 + std::max(S.height, Sh.height);
    T.box = A.box.merged(Tall.box);
    T.height = 1 + std::max(A.height, Tall.height);
    return t;
}

} // namespace rigidlab::physics
