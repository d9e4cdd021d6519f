// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulation/step_sampler.h"

#include "run/scene_run.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace rigidlab::ui {

EnergyReference EnergyReference::of(const physics::World& world)
{
    const physics::Diagnostics& d = world.diagnostics();
    return {d.total, d.dissipated, lessons::energyScale(d)};
}

double stepTime(const physics::World& world)
{
    return lessons::stepTime(world.stepCount(), world.def().dt, world.time());
}

bool SampleClock::due(double t)
{
    // The 1e-12 keeps a step that lands on the interval, up to rounding, from being skipped.
    if (m_last >= 0 && t < m_last + kSampleInterval - 1e-12)
        return false;
    m_last = t;
    return true;
}

Sample makeSample(const physics::World& main, const EnergyReference& mainReference,
                  const std::vector<physics::World>& variants,
                  const std::vector<EnergyReference>& variantReferences, bool compared)
{
    assert(variants.size() == variantReferences.size());
    const physics::Diagnostics& d = main.diagnostics();
    Sample s;
    s.t = stepTime(main);
    s.kinetic = d.kinetic;
    s.potential = d.potential;
    s.total = d.total;
    s.px = d.momentum.x();
    s.py = d.momentum.y();
    s.angularMomentum = d.angularMomentum;
    s.dissipated = mainReference.dissipatedSince(d);
    s.driftPercent = mainReference.driftPercent(d);
    s.energyScale = mainReference.scale;
    const MomentumScales scales = momentumScales(main);
    s.momentumScale = scales.linear;
    s.angularMomentumScale = scales.angular;
    if (compared) {
        s.variants = std::min<int>(Sample::kMaxVariants, 1 + static_cast<int>(variants.size()));
        s.variantTotal[0] = s.total;
        s.variantDriftPercent[0] = s.driftPercent;
        for (int i = 1; i < s.variants; ++i) {
            const auto k = static_cast<std::size_t>(i - 1);
            const physics::Diagnostics& dv = variants[k].diagnostics();
            s.variantTotal[static_cast<std::size_t>(i)] = dv.total;
            s.variantDriftPercent[static_cast<std::size_t>(i)] =
                variantReferences[k].driftPercent(dv);
        }
    }
    return s;
}

} // namespace rigidlab::ui
