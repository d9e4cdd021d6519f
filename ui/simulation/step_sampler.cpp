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

double stepTime(long long k, double dt)
{
    // Integers below 2^53 are exact doubles, and a division is correctly rounded: (k m) / 10^d
    // is the double nearest the decimal k dt.
    constexpr double kExactInteger = 9007199254740992.0; // 2^53
    double scale = 1.0;
    for (int places = 0; places <= 9; ++places, scale *= 10.0) {
        const double m = std::round(dt * scale);
        if (m > 0 && m / scale == dt && static_cast<double>(k) * m < kExactInteger)
            return static_cast<double>(k) * m / scale;
    }
    const double n = std::round(1.0 / dt);
    if (n > 0 && 1.0 / n == dt)
        return static_cast<double>(k) / n;
    return static_cast<double>(k) * dt;
}

double stepTime(const physics::World& world)
{
    const double exact = stepTime(world.stepCount(), world.def().dt);
    // The sum of k dts is within k rounding errors of k dt; a dt changed mid-run, or a world
    // that did not start at 0, is far from it.
    const double tolerance = 1e-9 * std::max(exact, world.def().dt);
    return std::abs(world.time() - exact) <= tolerance ? exact : world.time();
}

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
