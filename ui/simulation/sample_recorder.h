// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The run's samples for the plots, and the energy references the drift is measured against.
// The controller hands it its worlds after every step; it takes a sample when one is due
// (step_sampler.h: SampleClock), exactly as the headless lesson export does, so that an
// exported plot shows what the window showed.

#include "simulation/sample_buffer.h"
#include "simulation/step_sampler.h"

#include "rigidlab/physics/world.h"

#include <vector>

namespace rigidlab::ui {

class SampleRecorder {
public:
    /// The worlds as they are now are the start (call updateDiagnostics() on them first):
    /// their energies are the references, the samples so far are forgotten, and the next
    /// sample is due at once.
    void restart(const physics::World& main, const std::vector<physics::World>& variants);
    /// Samples the worlds when a sample is due at the main world's time. `main` is variant 0;
    /// with `compared` false (nothing compared side by side) a sample holds no variants.
    void record(const physics::World& main, const std::vector<physics::World>& variants,
                bool compared);
    /// The run went back to time t [s]: sample again from there on.
    void rewound(double t) { m_clock.rewound(t); }

    const SampleBuffer& samples() const { return m_samples; }
    /// The main world's energy drift since the start, the numerical error alone [%]
    /// (EnergyReference::driftPercent).
    double driftPercent(const physics::World& main) const;
    /// Energy `main` lost since the start to contacts, drag and dampers [J].
    double dissipated(const physics::World& main) const;
    /// The main world's energy scale at the start [J] (EnergyReference::scale).
    double energyScale() const { return m_reference.scale; }

private:
    SampleBuffer m_samples;
    SampleClock m_clock;
    EnergyReference m_reference;                      ///< the main world's
    std::vector<EnergyReference> m_variantReferences; ///< one per compared world
};

} // namespace rigidlab::ui
