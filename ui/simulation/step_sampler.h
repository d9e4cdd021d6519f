// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The samples the plots read, made from a step's worlds: the main world's energies and
// momenta and, when worlds are compared side by side, the total energy and drift of each.
// The window's controller and the headless lesson export (lesson_export.h) sample the same
// way, so that an exported plot shows what the window showed.

#include "simulation/sample_buffer.h"

#include "export/quantity_scales.h"
#include "export/step_time.h"
#include "rigidlab/physics/world.h"

#include <vector>

namespace rigidlab::ui {

/// Samples are taken no closer than this in simulated time: plots need no more [s].
inline constexpr double kSampleInterval = 1.0 / 240.0;

/// What a world's energy drift is measured against. The drift is the numerical error alone:
/// what contacts, drag and dampers took (physics, not error) is added back to the total.
struct EnergyReference {
    double start = 0.0;      ///< total energy at the start [J]
    double dissipated = 0.0; ///< Diagnostics::dissipated at the start [J]
    /// |E0|, or the size of its parts (K + |P|) when E0 is near zero (lessons::energyScale) [J].
    double scale = 1.0;

    /// From the world's current diagnostics (call updateDiagnostics() first).
    static EnergyReference of(const physics::World& world);
    /// Energy taken since the start [J].
    double dissipatedSince(const physics::Diagnostics& d) const
    {
        return d.dissipated - dissipated;
    }
    /// (total + dissipated since the start - start) / scale * 100 [%].
    double driftPercent(const physics::Diagnostics& d) const
    {
        return (d.total + dissipatedSince(d) - start) / scale * 100.0;
    }
};

/// The time of step k of a run on a fixed dt [s], as a person writes it (lessons/export/
/// step_time.h has the rule): with dt = 0.01, step 35 is at 0.35.
using lessons::stepTime;
/// The time of the world's current step [s]: stepTime(steps, dt) when the world ran on one dt
/// since t = 0, so that the plots and their CSV say t = 0.35; after a change of dt mid-run,
/// the world's summed time.
double stepTime(const physics::World& world);

/// What momenta are worth in a scene (lessons/export/quantity_scales.h): the plots' noise
/// floor and the files' come from the same scales.
using lessons::kMinExtent;
using lessons::MomentumScales;
using lessons::momentumScales;

/// Takes a sample at most every kSampleInterval of simulated time: the first one always, then
/// the first step at least the interval after the last sample.
class SampleClock {
public:
    void reset() { m_last = -1.0; }
    /// True when a sample is due at time t [s] (and counts it as taken).
    bool due(double t);
    /// The run went back to t: sample again from there on.
    void rewound(double t) { m_last = t - kSampleInterval; }

private:
    double m_last = -1.0; ///< [s], < 0 before the first sample
};

/// One sample of the worlds as they are now. `main` is variant 0; `variants` are the others,
/// in order, each with its reference in `variantReferences`. With `compared` false (a step
/// that compares nothing) Sample::variants stays 0.
Sample makeSample(const physics::World& main, const EnergyReference& mainReference,
                  const std::vector<physics::World>& variants,
                  const std::vector<EnergyReference>& variantReferences, bool compared);

} // namespace rigidlab::ui
