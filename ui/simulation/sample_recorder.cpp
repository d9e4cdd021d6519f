// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulation/sample_recorder.h"

namespace rigidlab::ui {

void SampleRecorder::restart(const physics::World& main,
                             const std::vector<physics::World>& variants)
{
    m_reference = EnergyReference::of(main);
    m_variantReferences.clear();
    for (const physics::World& w : variants)
        m_variantReferences.push_back(EnergyReference::of(w));
    m_clock.reset();
    m_samples.clear();
}

void SampleRecorder::record(const physics::World& main, const std::vector<physics::World>& variants,
                            bool compared)
{
    if (!m_clock.due(stepTime(main)))
        return;
    m_samples.push(makeSample(main, m_reference, variants, m_variantReferences, compared));
}

double SampleRecorder::driftPercent(const physics::World& main) const
{
    return m_reference.driftPercent(main.diagnostics());
}

double SampleRecorder::dissipated(const physics::World& main) const
{
    return m_reference.dissipatedSince(main.diagnostics());
}

} // namespace rigidlab::ui
