// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A plot for a test that reads its own sample buffer, as the window's plots read the
// controller's:
//     auto [buffer, plot] = SourcedPlot(makeEnergyPlot(nullptr));
//     buffer.push(sample);
//     plot->drain();

#include "plots/plot_widget.h"
#include "simulation/sample_buffer.h"

#include <memory>

namespace rigidlab::test {

struct SourcedPlot {
    ui::SampleBuffer buffer; ///< declared first: it outlives the plot
    std::unique_ptr<ui::PlotWidget> plot;

    /// Takes `made` (a plot without a parent) and sets `buffer` as its source.
    explicit SourcedPlot(ui::PlotWidget* made) : plot(made) { plot->model().setSource(&buffer); }
    SourcedPlot(const SourcedPlot&) = delete;
    SourcedPlot& operator=(const SourcedPlot&) = delete;
};

} // namespace rigidlab::test
