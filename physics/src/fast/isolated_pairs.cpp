// SPDX-License-Identifier: GPL-3.0-or-later
// The search for isolated impacts (stages/soft_impacts.cpp, findIsolatedImpacts) with the same
// result for less memory traffic. The plain search reads each contact's pair twice and each
// contact's two bodies' records to ask whether they move; in a pile of thousands of bodies the
// contacts (hundreds of bytes each) and the bodies no longer stay in the cache, and the search
// waited on memory for a pass that finds nothing. Here the pairs are copied out on the first
// pass, whether each body is alone is decided once per body, in the bodies' order, and only a
// contact whose two bodies are alone is read again.

#include "rigidlab/physics/world.h"

#include "stages.h"

namespace rigidlab::physics {

bool findIsolatedImpactsFast(StepContext& ctx, double threshold, Flown flown)
{
    StepScratch& s = ctx.scratch;
    const std::vector<Contact>& contacts = ctx.contacts;
    s.impacts.clear();
    s.isolated.clear();
    countContactsOf(ctx, &s.contactPairs);
    const size_t n = ctx.bodies.size();
    s.alone.resize(n);
    for (size_t i = 0; i < n; ++i)
        s.alone[i] = !ctx.bodies[i].isActive() || s.contactsOf[i] == 1;
    for (size_t k = 0; k < contacts.size(); ++k) {
        const auto [a, b] = s.contactPairs[k];
        if (!s.alone[static_cast<size_t>(a)] || !s.alone[static_cast<size_t>(b)])
            continue;
        IsolatedImpact impact;
        if (!isolatedImpact(ctx, contacts[k], threshold, flown, impact))
            continue;
        if (s.isolated.empty())
            s.isolated.assign(contacts.size(), 0);
        s.isolated[k] = 1;
        s.impacts.emplace_back(static_cast<int>(k), impact);
    }
    return !s.impacts.empty();
}

} // namespace rigidlab::physics
