// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private: the fast narrow phase (fast/kept_faces.cpp) writes this step's contacts over last
// step's, in the same arrays (the world's contacts and their anchors), instead of copying
// every contact it keeps or recycles into a second pair of arrays: a contact kept where it
// stands is not written at all, and a recycled one only in the fields that change.

#include "rigidlab/physics/contact.h"

#include "../stages/narrow_phase.h"

#include <algorithm>
#include <cassert>
#include <utility>
#include <vector>

namespace rigidlab::physics {

/// This step's contacts (sorted by pair) written from last step's (sorted by pair), walked
/// with one read cursor r and written with one write cursor w: each of this step's contacts
/// replaces last step's of the same pair, if any, and last step's contacts of pairs passed
/// over are dropped.
///
/// In place (the fast path's usual case) the two are the same arrays. While no contact is new,
/// w stays at or behind r, so a write never reaches a record still to be read, and a contact
/// kept where it stands is not copied. A new contact written where the next unread record
/// stands moves that record to the spill first (a ring whose room NarrowPhaseCache keeps); the
/// unread records are then the spill's, in order, followed by those from r on. Apart: last step's
/// contacts stay where they are (StepScratch::previous, for the readers after the narrow phase) and
/// this step's are appended to empty arrays.
class ContactRewrite {
public:
    /// In place: `contacts` and `anchors` hold last step's contacts, and will hold this step's.
    ContactRewrite(std::vector<Contact>& contacts, std::vector<ContactAnchors>& anchors,
                   NarrowPhaseCache& cache)
        : ContactRewrite(contacts, anchors, contacts, anchors, cache)
    {
    }
    /// Apart: from `previous` and `previousAnchors` into `contacts` and `anchors` (emptied).
    ContactRewrite(const std::vector<Contact>& previous,
                   const std::vector<ContactAnchors>& previousAnchors,
                   std::vector<Contact>& contacts, std::vector<ContactAnchors>& anchors,
                   NarrowPhaseCache& cache)
        : m_src(previous), m_srcAnchors(previousAnchors), m_out(contacts), m_outAnchors(anchors),
          m_spill(cache.spill), m_spillAnchors(cache.spillAnchors),
          m_inPlace(&previous == &contacts), m_end(previous.size())
    {
        assert(previousAnchors.size() == previous.size());
        assert(m_inPlace == (&previousAnchors == &anchors));
        if (!m_inPlace) {
            m_out.clear();
            m_outAnchors.clear();
        }
    }
    ContactRewrite(const ContactRewrite&) = delete;
    ContactRewrite& operator=(const ContactRewrite&) = delete;

    /// Last step's contact of the pair (a, b), or null; those of the pairs before it are
    /// dropped. Calls come in increasing (a, b). Valid until the next call of this class.
    const Contact* find(int a, int b)
    {
        while (const Contact* c = next()) {
            if (std::pair(c->a, c->b) >= std::pair(a, b))
                return c->a == a && c->b == b ? c : nullptr;
            consume();
        }
        return nullptr;
    }
    /// The anchors of the contact find() just returned.
    const ContactAnchors& anchorsOfFound() const
    {
        return m_spilt > 0 ? m_spillAnchors[m_head] : m_srcAnchors[m_read];
    }

    /// The contact find() just returned kept as this step's, with its anchors; returned for
    /// changes. Not copied when it stands where it is to be written.
    Contact& keepFound()
    {
        if (m_spilt > 0) {
            const Contact c = m_spill[m_head];
            const ContactAnchors k = m_spillAnchors[m_head];
            consume();
            return write(c, k);
        }
        if (m_inPlace && m_read == m_write) {
            ++m_read;
            return m_out[m_write++];
        }
        const size_t r = m_read++; // in place, behind w: no write reaches it
        return write(m_src[r], m_srcAnchors[r]);
    }

    /// A contact made this step, with its anchors: replaces last step's of its pair, if
    /// find() returned one.
    void put(const Contact& c, const ContactAnchors& k)
    {
        if (const Contact* last = next(); last && last->a == c.a && last->b == c.b)
            consume();
        write(c, k);
    }

    /// Drops the unread rest of last step's contacts: the arrays hold this step's.
    void finish()
    {
        m_out.resize(m_write);
        m_outAnchors.resize(m_write);
    }

private:
    /// The next unread record of last step, or null.
    const Contact* next() const
    {
        if (m_spilt > 0)
            return &m_spill[m_head];
        return m_read < m_end ? &m_src[m_read] : nullptr;
    }
    void consume()
    {
        if (m_spilt == 0) {
            ++m_read;
        } else {
            m_head = (m_head + 1) & (m_spill.size() - 1);
            --m_spilt;
        }
    }
    /// Adds the unread record at r to the spill's end.
    void spill()
    {
        if (m_spilt == m_spill.size()) { // full: twice the room, in order from the head
            std::vector<Contact> contacts(std::max<size_t>(16, 2 * m_spill.size()));
            std::vector<ContactAnchors> anchors(contacts.size());
            for (size_t i = 0; i < m_spilt; ++i) {
                contacts[i] = m_spill[(m_head + i) & (m_spill.size() - 1)];
                anchors[i] = m_spillAnchors[(m_head + i) & (m_spill.size() - 1)];
            }
            m_spill.swap(contacts);
            m_spillAnchors.swap(anchors);
            m_head = 0;
        }
        const size_t end = (m_head + m_spilt) & (m_spill.size() - 1);
        m_spill[end] = m_out[m_read];
        m_spillAnchors[end] = m_outAnchors[m_read];
        ++m_spilt;
        ++m_read;
    }
    /// Writes at w; in place, an unread record there goes to the spill first.
    Contact& write(const Contact& c, const ContactAnchors& k)
    {
        if (!m_inPlace || m_write >= m_end) { // in place: every unread record is spilt
            m_out.push_back(c);
            m_outAnchors.push_back(k);
            return m_out[m_write++];
        }
        if (m_write == m_read)
            spill();
        m_out[m_write] = c;
        m_outAnchors[m_write] = k;
        return m_out[m_write++];
    }

    const std::vector<Contact>& m_src;
    const std::vector<ContactAnchors>& m_srcAnchors;
    std::vector<Contact>& m_out;
    std::vector<ContactAnchors>& m_outAnchors;
    std::vector<Contact>& m_spill;
    std::vector<ContactAnchors>& m_spillAnchors;
    bool m_inPlace;
    size_t m_end;       ///< last step's count
    size_t m_read = 0;  ///< r: last step's next unread record in m_src (when none is spilt)
    size_t m_write = 0; ///< w: where this step's next contact goes
    /// The spill: a ring of unread records (its size a power of two, or 0), the first at
    /// m_head, m_spilt of them.
    size_t m_head = 0;
    size_t m_spilt = 0;
};

} // namespace rigidlab::physics
