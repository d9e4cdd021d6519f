// SPDX-License-Identifier: GPL-3.0-or-later
// The soft step's contacts laid out for the SIMD kernel (fast/soft_kernel.h): coloured so that
// no two contacts of one colour share a moving body, then packed colour by colour into blocks
// of lanes. A pile at rest keeps its contacts step after step: then the colouring of the step
// before is kept and only the lanes are filled again (sameColouring). The plain path
// (SoftSolver::begin with plain) colours anew every step and puts one contact in each block.

#include "soft_solver.h"

#include <bit>

namespace rigidlab::physics {

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
        // The precision chosen once, not per lane.
        const auto refill = [&](auto& blocks) {
            for (Slot& slot : m_slots) {
                const Contact& ct = contacts[static_cast<size_t>(slot.contact)];
                slot.points = ct.manifold.pointCount;
                fillLaneOf(ct, blocks[static_cast<size_t>(slot.block)], slot.lane);
            }
        };
        if (m_single)
            refill(m_singleBlocks);
        else
            refill(m_blocks);
        return;
    }

    // Greedy colouring in the contacts' order (deterministic): each contact takes the lowest
    // colour that neither of its moving bodies has yet. A body that does not move (static,
    // kinematic, asleep) is only read, so any number of contacts of one colour may share it.
    // The arrays at their largest, cut to their counts after the loop, and written through
    // local pointers (the compiler loaded each vector's pointers again after every store).
    m_keyBodies = bodies.size();
    m_keyWidth = m_width;
    m_keySingle = m_single;
    m_colourMask.assign(bodies.size(), 0);
    m_colourSize.assign(kMaxColours, 0);
    m_keys.resize(contacts.size());
    m_candidates.resize(contacts.size());
    m_colourOf.resize(contacts.size());
    ColourKey* const keys = m_keys.data();
    int* const candidates = m_candidates.data();
    int* const colourOf = m_colourOf.data();
    std::uint64_t* const mask = m_colourMask.data();
    int* const colourSize = m_colourSize.data();
    size_t count = 0;
    int overflow = 0;
    for (size_t ci = 0; ci < contacts.size(); ++ci) {
        const Contact& ct = contacts[ci];
        const ColourKey key = colourKey(ct);
        keys[ci] = key;
        if (!key.movesA && !key.movesB)
            continue;
        std::uint64_t used = 0;
        if (key.movesA)
            used |= mask[static_cast<size_t>(ct.a)];
        if (key.movesB)
            used |= mask[static_cast<size_t>(ct.b)];
        int colour = -1;
        if (~used != 0) {
            colour = std::countr_zero(~used);
            const std::uint64_t bit = std::uint64_t{1} << colour;
            if (key.movesA)
                mask[static_cast<size_t>(ct.a)] |= bit;
            if (key.movesB)
                mask[static_cast<size_t>(ct.b)] |= bit;
            ++colourSize[static_cast<size_t>(colour)];
        } else {
            ++overflow;
        }
        candidates[count] = static_cast<int>(ci);
        colourOf[count] = colour;
        ++count;
    }
    m_candidates.resize(count);
    m_colourOf.resize(count);
    m_overflow = overflow;
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
    resetBlocks(blocks);
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
        slot.points = contacts[static_cast<size_t>(ci)].manifold.pointCount;
        m_slots.push_back(slot);
    }
    // The lanes filled in the slots' order, the contacts' (the precision chosen once).
    const auto fill = [&](auto& blocks) {
        for (const Slot& slot : m_slots)
            fillLaneOf(contacts[static_cast<size_t>(slot.contact)],
                       blocks[static_cast<size_t>(slot.block)], slot.lane);
    };
    if (m_single)
        fill(m_singleBlocks);
    else
        fill(m_blocks);
    // The lanes no contact took, emptied: past the last contact of each colour's last block,
    // past the kernel's width in the others (the plain path's one lane), past the first lane in
    // the overflow's blocks.
    const int spare = static_cast<int>(bodies.size());
    for (int c = 0; c < m_colourCount; ++c) {
        const int first = m_ranges[static_cast<size_t>(c)];
        const int last = next[static_cast<size_t>(c)]; // the block after the colour's last full one
        for (int k = first; k < last; ++k)
            emptyLanes(k, width, spare);
        if (lane[static_cast<size_t>(c)] > 0)
            emptyLanes(last, lane[static_cast<size_t>(c)], spare);
    }
    for (int k = start; k < overflowBlock; ++k)
        emptyLanes(k, 1, spare);
}

} // namespace rigidlab::physics
