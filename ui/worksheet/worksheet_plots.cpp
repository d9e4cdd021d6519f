// SPDX-License-Identifier: GPL-3.0-or-later
#include "worksheet/worksheet_plots.h"

#include "plots/lesson_export.h"
#include "plots/plot_widget.h"
#include "simulation/step_sampler.h"

#include "run/scene_run.h"

namespace rigidlab::ui {

lessons::LessonStep stepAsRun(const lessons::LessonStep& step, const lessons::StepAnswers& ran)
{
    lessons::LessonStep out = step;
    if (ran.integrator)
        out.settings.integrator = ran.integrator;
    if (ran.dt)
        out.settings.dt = ran.dt;
    if (ran.solver)
        out.settings.solver = ran.solver;
    return out;
}

StepPlots runStepPlots(const lessons::LessonStep& step, QWidget* holder)
{
    StepPlots out;
    std::vector<physics::World> worlds = lessons::buildStepWorlds(step);
    physics::World main = std::move(worlds.front());
    std::vector<physics::World> variants(std::make_move_iterator(worlds.begin() + 1),
                                         std::make_move_iterator(worlds.end()));
    out.settings = main.def();
    if (step.plots.isEmpty())
        return out;
    main.updateDiagnostics();
    const EnergyReference mainReference = EnergyReference::of(main);
    std::vector<EnergyReference> references;
    for (physics::World& w : variants) {
        w.updateDiagnostics();
        references.push_back(EnergyReference::of(w));
    }
    const bool compared = step.compare.has_value();

    out.plots = makeStepPlots(step, holder);
    SampleBuffer buffer;
    for (PlotWidget* plot : out.plots) {
        plot->setRangeMode(RangeMode::WholeRun);
        plot->setSource(&buffer);
    }
    // The plots read the buffer only when drained: drained well before its ring wraps round,
    // so that no sample of the run is lost, and once more at the end.
    const std::uint64_t drainEvery = buffer.capacity() / 2;
    std::uint64_t sinceDrain = 0;
    const auto drainAll = [&] {
        for (PlotWidget* plot : out.plots)
            plot->drain();
        sinceDrain = 0;
    };
    SampleClock clock;
    clock.due(main.time());
    buffer.push(makeSample(main, mainReference, variants, references, compared));
    const long long steps = lessons::stepsForTime(step.exportTime, main.def().dt);
    for (long long i = 0; i < steps && !main.divergence(); ++i) {
        main.step();
        for (physics::World& w : variants)
            w.step();
        if (clock.due(main.time())) {
            buffer.push(makeSample(main, mainReference, variants, references, compared));
            if (++sinceDrain >= drainEvery)
                drainAll();
        }
    }
    drainAll();
    for (PlotWidget* plot : out.plots)
        plot->setSource(nullptr); // the buffer goes out of scope here
    return out;
}

} // namespace rigidlab::ui
