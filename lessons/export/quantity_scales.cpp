// SPDX-License-Identifier: GPL-3.0-or-later
#include "export/quantity_scales.h"

#include <algorithm>
#include <cmath>

namespace rigidlab::lessons {

MomentumScales momentumScales(const physics::World& world)
{
    double extent = kMinExtent;
    for (const physics::Body& b : world.bodies())
        if (b.isDynamic())
            extent = std::max(extent, b.position.norm());
    const double fall = std::sqrt(2.0 * world.def().gravity.norm() * extent);
    MomentumScales s;
    for (const physics::Body& b : world.bodies()) {
        if (!b.isDynamic())
            continue;
        const double p = b.mass * (b.velocity.norm() + fall);
        s.linear += p;
        s.angular += p * extent + b.inertia * std::abs(b.angularVelocity);
    }
    return s;
}

} // namespace rigidlab::lessons
