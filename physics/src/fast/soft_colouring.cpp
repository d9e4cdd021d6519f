// SPDX-License-Identifier: GPL-3.0-or-later
// The soft step's contacts laid out for the SIMD kernel (fast/soft_kernel.h): coloured so that
// no two contacts of one colour share a moving body, then packed colour by colour into blocks
// of lanes. A pile at rest keeps its contacts step after step: then the colouring of the step
// before is kept and only the lanes are filled again (sameColouring). The plain path
// (SoftSolver::begin with plain) colours anew every step and puts one contact in each block.

#include "soft_solver.h"

#include <bit>

namespace rigidlab::physics {

SoftSolver::ColourKey SoftSolver::colourKey(const Contact& ct) const
{
    return {ct.a, ct.b, m_active[static_cast<size_t>(ct.a)] != 0,
            m_active[static_cast<size_t>(ct.b)] != 0};
}

bool SoftSolver::sameColouring(const std::vector<Contact>& contacts,
                               const std::vector<Body>& bodies) const
{
    if (contacts.size() != m_keys.size() || bodies.size() != m_keyBodies || m_width != m_keyWidth ||
        m_single != m_keySingle)
        return false;
    for (size_t ci = 0; ci < contacts.size(); ++ci)
        if (!(colourKey(contacts[ci]) == m_keys[ci]))
            return false;
    return true;
}

void SoftSolver::buildBlocks(const std::vector<Contact>& contacts, const std::vector<Body>& bodies)
{
    if (!m_plain && sameColouring(contacts, bodies)) {
        // The same contacts between the same bodies: the same colours, blocks and lanes as
        // colouring them again would give; only what the lanes hold has changed.
        for (Slot& slot : m_slots) {
            const Contact& ct = contacts[static_cast<size_t>(slot.contact)];
            slot.points = ct.manifold.pointCount;
            fillLane(ct, slot.block, slot.lane);
        }
        return;
    }

    // Greedy colouring in the contacts' order (deterministic): each contact takes the lowest
    // colour that neither of its moving bodies has yet. A body that does not move (static,
    // kinematic, asleep) is only read, so any number of contacts of one colour may share it.
    m_keys.clear();
    m_keyBodies = bodies.size();
    m_keyWidth = m_width;
    m_keySingle = m_single;
    m_colourMask.assign(bodies.size(), 0);
    m_candidates.clear();
    m_colourOf.clear();
    m_colourSize.assign(kMaxColours, 0);
    m_overflow = 0;
    for (size_t ci = 0; ci < contacts.size(); ++ci) {
        const Contact& ct = contacts[ci];
        const ColourKey key = colourKey(ct);
        m_keys.push_back(key);
        if (!key.movesA && !key.movesB)
            continue;
        std::uint64_t used = 0;
        if (key.movesA)
            used |= m_colourMask[static_cast<size_t>(ct.a)];
        if (key.movesB)
            used |= m_colourMask[static_cast<size_t>(ct.b)];
        int colour = -1;
        if (~used != 0) {
            colour = std::countr_zero(~used);
            const std::uint64_t bit = std::uint64_t{1} << colour;
            if (key.movesA)
                m_colourMask[static_cast<size_t>(ct.a)] |= bit;
            if (key.movesB)
                m_colourMask[static_cast<size_t>(ct.b)] |= bit;
            ++m_colourSize[static_cast<size_t>(colour)];
        } else {
            ++m_overflow;
        }
        m_candidates.push_back(static_cast<int>(ci));
        m_colourOf.push_back(colour);
    }
    m_colourCount = 0;
    for (int c = 0; c < kMaxColours; ++c)
        if (m_colourSize[static_cast<size_t>(c)] > 0)
            m_colourCount = c + 1;

    layBlocks(contacts, bodies);
}

void SoftSolver::layBlocks(const std::vector<Contact>& contacts, const std::vector<Body>& bodies)
{
    // Blocks: colour by colour, m_width lanes each; the overflow last, one contact
    // per block (solved one after the other). Empty lanes point at the spare body (index n)
    // with zero masses, so they change nothing.
    const int width = m_width;
    int blocks = m_overflow;
    for (int c = 0; c < m_colourCount; ++c)
        blocks += (m_colourSize[static_cast<size_t>(c)] + width - 1) / width;
    resetBlocks(blocks, static_cast<int>(bodies.size()));
    // First block of each colour, then filled in the contacts' order.
    std::vector<int>& next = m_nextBlock;
    std::vector<int>& lane = m_nextLane;
    next.assign(static_cast<size_t>(m_colourCount) + 1, 0);
    lane.assign(static_cast<size_t>(m_colourCount) + 1, 0);
    int start = 0;
    for (int c = 0; c < m_colourCount; ++c) {
        next[static_cast<size_t>(c)] = start;
        start += (m_colourSize[static_cast<size_t>(c)] + width - 1) / width;
    }
    int overflowBlock = start;
    // The kernel's calls (KernelOf): each colour's blocks, then each overflow block alone.
    m_ranges.clear();
    for (int c = 0; c < m_colourCount; ++c)
        m_ranges.push_back(next[static_cast<size_t>(c)]);
    for (int k = 0; k <= m_overflow; ++k)
        m_ranges.push_back(start + k);
    m_slots.clear();
    m_slots.reserve(m_candidates.size());
    for (size_t k = 0; k < m_candidates.size(); ++k) {
        const int ci = m_candidates[k];
        const int colour = m_colourOf[k];
        Slot slot;
        slot.contact = ci;
        if (colour >= 0) {
            const auto c = static_cast<size_t>(colour);
            slot.block = next[c];
            slot.lane = lane[c];
            if (++lane[c] == width) {
                lane[c] = 0;
                ++next[c];
            }
        } else {
            slot.block = overflowBlock++;
            slot.lane = 0;
        }
        const Contact& ct = contacts[static_cast<size_t>(ci)];
        slot.points = ct.manifold.pointCount;
        fillLane(ct, slot.block, slot.lane);
        m_slots.push_back(slot);
    }
}

} // namespace rigidlab::physics
