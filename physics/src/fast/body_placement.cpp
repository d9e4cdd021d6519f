// SPDX-License-Identifier: GPL-3.0-or-later
// The acceleration of the bodies' placement (placeBodies, step_plan.cpp): a body's transform
// is recomputed only when its pose changed since the last step, which saves a sine and a
// cosine per body at rest. The same transform either way, bit for bit.

#include "stages.h"

#include <limits>

namespace rigidlab::physics {

void placeMovedBodies(StepContext& ctx)
{
    StepScratch& s = ctx.scratch;
    const size_t n = ctx.bodies.size();
    if (s.xf.size() != n) {
        s.xf.resize(n);
        // NaN never equals itself: every new entry is computed below.
        s.xfPosition.resize(n, Vec2::Constant(std::numeric_limits<double>::quiet_NaN()));
        s.xfAngle.resize(n, std::numeric_limits<double>::quiet_NaN());
    }
    for (size_t i = 0; i < n; ++i) {
        const Body& b = ctx.bodies[i];
        if (b.angle == s.xfAngle[i] && b.position == s.xfPosition[i])
            continue; // has not moved: the same transform, without a sine and a cosine
        s.xf[i] = b.transform();
        s.xfAngle[i] = b.angle;
        s.xfPosition[i] = b.position;
    }
}

} // namespace rigidlab::physics
