// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Whether a contact is a touch, or only a look ahead. The narrow phase makes contacts between
// bodies closer than the margin, and with continuous collision between bodies whose motion in
// the step may close their gap (continuous.cpp): at dt = 0.2 s two balls falling side by side
// 1 m apart get one, with a gap of 0.8 m, though neither can reach the other. Whatever tells
// the user what touches (the diagnostics' count, the instruments, the scene's description,
// the drawn contact points) asks this.

#include "rigidlab/physics/contact.h"

#include <vector>

namespace rigidlab::physics {

/// Whether point i of the contact touches: its bodies meet or overlap there at the start of
/// the step, or it pushed them in the step (a bounce timed within the step leaves them apart
/// again by its end). A point with a gap that pushed nothing is speculative.
inline bool touches(const Contact& c, int i)
{
    const auto k = static_cast<size_t>(i);
    return c.manifold.points[k].separation <= 0.0 || c.normalImpulse[k] > 0.0;
}

/// How many points of the contacts touch (Diagnostics::contacts).
inline int touchingPoints(const std::vector<Contact>& contacts)
{
    int count = 0;
    for (const Contact& c : contacts)
        for (int i = 0; i < c.manifold.pointCount; ++i)
            count += touches(c, i) ? 1 : 0;
    return count;
}

/// Whether any point of the contact touches.
inline bool touches(const Contact& c)
{
    for (int i = 0; i < c.manifold.pointCount; ++i)
        if (touches(c, i))
            return true;
    return false;
}

} // namespace rigidlab::physics
