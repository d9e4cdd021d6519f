// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Samples for the plot tests (test_plots, test_plot_export): deterministic, every field
// different from the others.

#include "plots/plot_widget.h"
#include "simulation/sample_buffer.h"

#include <cmath>

namespace rigidlab::test {

/// A deterministic sample at time t [s]; every field differs from the others.
inline ui::Sample sampleAt(double t)
{
    ui::Sample s;
    s.t = t;
    s.kinetic = 1.5 + std::sin(t);
    s.potential = 2.25 - std::sin(t);
    s.total = s.kinetic + s.potential;
    s.px = 0.5 * t;
    s.py = -0.25 * t + 1.0 / 3.0;
    s.angularMomentum = 0.1 + t * t;
    s.driftPercent = 1e-7 * t;
    s.dissipated = 0.125 * t;
    return s;
}

/// Pushes samples t = first, first + dt, ... (count of them) and drains after each chunk.
inline void feed(ui::SampleBuffer& buffer, ui::PlotWidget& plot, double first, double dt, int count)
{
    const int chunk = static_cast<int>(buffer.capacity() / 2);
    for (int i = 0; i < count; ++i) {
        buffer.push(sampleAt(first + dt * i));
        if ((i + 1) % chunk == 0)
            plot.drain();
    }
    plot.drain();
}

} // namespace rigidlab::test
