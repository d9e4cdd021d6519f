// SPDX-License-Identifier: GPL-3.0-or-later
#include "plots/lesson_export.h"

#include "common/display_names.h"
#include "common/number_format.h"
#include "plots/plot_table.h"
#include "plots/plot_widget.h"
#include "plots/sat_handout.h"
#include "simulation/step_sampler.h"

#include "run/scene_run.h"

#include <QCoreApplication>
#include <QDir>
#include <QLocale>

#include <cmath>
#include <limits>
#include <memory>

namespace rigidlab::ui {

namespace {

/// The translation context of a lesson step's exported plots.
struct LessonExport {
    Q_DECLARE_TR_FUNCTIONS(LessonExport)
};

/// "by integrator" or "by solver".
QString comparedBy(const lessons::LessonStep& step)
{
    return step.compare && !step.compare->solvers.empty() ? LessonExport::tr("by solver")
                                                          : LessonExport::tr("by integrator");
}

/// One curve per compared world, reading `value(sample, i)`.
PlotWidget* makeComparePlot(const lessons::LessonStep& step, const QString& title,
                            const QString& quantity, const QString& unit,
                            double (*value)(const Sample&, std::size_t), QWidget* parent)
{
    auto* plot = new PlotWidget(title, parent);
    plot->setYAxisLabel(quantity, unit);
    if (unit == u"%")
        plot->model().setValueScale(YAxis::Left, kDriftScalePercent);
    else {
        plot->model().setValueScale(YAxis::Left, [](const Sample& s) { return s.energyScale; });
        // A run that blew up (1e10 J) goes off the top rather than flatten the others to 0.
        // (Drifts are not clipped: explicit Euler's +172 % beside Verlet's 0.01 % is the
        // lesson.)
        plot->setOffScaleClipping(true);
    }
    const int count = step.compare ? std::min(step.compare->count(), Sample::kMaxVariants) : 0;
    for (int i = 0; i < count; ++i) {
        const auto index = static_cast<std::size_t>(i);
        const int series =
            plot->addSeries(step.compare->label(i), plotColor(i), [index, value](const Sample& s) {
                // Samples taken before the worlds were compared leave a gap.
                return static_cast<int>(index) < s.variants
                           ? value(s, index)
                           : std::numeric_limits<double>::quiet_NaN();
            });
        // The legend in words; a handout's CSV keeps the lesson file's code names as column
        // heads (scripts read them), one exported from the window the legend's words.
        // Curves that coincide (Verlet under RK4) stay visible: each later one in its own dashes.
        plot->setSeriesLegend(series, methodDisplayName(step.compare->label(i)));
        plot->setSeriesPen(series, plotPenStyle(i), plotPenWidthFactor(i, count));
    }
    return plot;
}

} // namespace

PlotWidget* makeCompareEnergyPlot(const lessons::LessonStep& step, QWidget* parent)
{
    return makeComparePlot(
        step, LessonExport::tr("Total energy %1").arg(comparedBy(step)),
        LessonExport::tr("energy E"), QStringLiteral("J"),
        [](const Sample& s, std::size_t i) { return s.variantTotal[i]; }, parent);
}

PlotWidget* makeCompareDriftPlot(const lessons::LessonStep& step, QWidget* parent)
{
    return makeComparePlot(
        step, LessonExport::tr("Energy drift %1").arg(comparedBy(step)), LessonExport::tr("drift"),
        QStringLiteral("%"),
        [](const Sample& s, std::size_t i) { return s.variantDriftPercent[i]; }, parent);
}

PlotWidget* makeStepPlot(const lessons::LessonStep& step, const QString& name, QWidget* parent)
{
    const PlotRow* row = findPlot(name);
    if (row == nullptr)
        return nullptr; // the loader admits no other name
    if (row->inWindow())
        return makeWorldPlot(*row, parent);
    PlotWidget* plot = row->makeCompared(step, parent);
    plot->setObjectName(name);
    return plot;
}

std::vector<PlotWidget*> makeStepPlots(const lessons::LessonStep& step, QWidget* parent)
{
    std::vector<PlotWidget*> plots;
    for (const QString& name : step.plots) {
        PlotWidget* plot = makeStepPlot(step, name, parent);
        Q_ASSERT(plot);
        if (!plot)
            continue;
        plots.push_back(plot);
    }
    return plots;
}

QString stepFolderName(const lessons::Lesson& lesson, int step)
{
    // Letters without their accents ("Čtyři" → "ctyri"), so that a Czech title gives a folder
    // name any file system and any script takes.
    const QString title = lesson.steps.at(static_cast<std::size_t>(step))
                              .title.toLower()
                              .normalized(QString::NormalizationForm_D);
    QString slug;
    for (const QChar c : title) {
        if (c.category() == QChar::Mark_NonSpacing)
            continue;
        if (c.isLetterOrNumber() && c.unicode() < 128)
            slug += c;
        else if (!slug.isEmpty() && !slug.endsWith(u'-'))
            slug += u'-';
    }
    while (slug.endsWith(u'-'))
        slug.chop(1);
    slug = slug.left(48);
    while (slug.endsWith(u'-'))
        slug.chop(1);
    const QString number = QStringLiteral("%1").arg(step + 1, 2, 10, QLatin1Char('0'));
    return slug.isEmpty() ? number : number + u'-' + slug;
}

QString stepCaption(const lessons::Lesson& lesson, int step, const physics::WorldDef& settings)
{
    const lessons::LessonStep& s = lesson.steps.at(static_cast<std::size_t>(step));
    const QString first =
        LessonExport::tr("%1, step %2: %3").arg(lesson.title, QString::number(step + 1), s.title);
    QString how;
    if (s.compare && !s.compare->integrators.empty()) {
        QStringList names;
        for (int i = 0; i < s.compare->count(); ++i)
            names.append(methodDisplayName(s.compare->label(i)));
        how = LessonExport::tr("integrators %1").arg(names.join(QStringLiteral(", ")));
    } else {
        how = LessonExport::tr("integrator %1").arg(integratorDisplayName(settings.integrator));
    }
    if (s.compare && !s.compare->solvers.empty()) {
        QStringList names;
        for (int i = 0; i < s.compare->count(); ++i)
            names.append(methodDisplayName(s.compare->label(i)));
        how += LessonExport::tr(" · solvers %1").arg(names.join(QStringLiteral(", ")));
    }
    how += LessonExport::tr(" · dt = %1 s").arg(formatReadable(settings.dt, 6));
    return first + u'\n' + how;
}

PlotFilesResult exportPlots(const std::vector<PlotWidget*>& plots, const QString& dir,
                            const QString& caption, const ExportOptions& options)
{
    PlotFilesResult result;
    if (!QDir().mkpath(dir)) {
        result.error =
            LessonExport::tr("cannot make the folder %1").arg(QDir::toNativeSeparators(dir));
        return result;
    }
    for (PlotWidget* plot : plots) {
        const QString previous = plot->caption();
        plot->setCaption(caption);
        for (ExportFormat format :
             {ExportFormat::Png, ExportFormat::Pdf, ExportFormat::Svg, ExportFormat::Csv}) {
            if (!canExport(format))
                continue;
            const QString path = QDir(dir).filePath(plot->objectName() + u'.' + suffixFor(format));
            const ExportResult written = exportPlot(*plot, path, format, options);
            if (!written.ok) {
                plot->setCaption(previous);
                result.error = written.error;
                return result;
            }
            result.files.append(path);
        }
        plot->setCaption(previous);
    }
    result.ok = true;
    return result;
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
        plot->model().setRangeMode(RangeMode::WholeRun);
        plot->model().setSource(&buffer);
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
    const long long steps = lessons::stepsForTime(lessons::exportRunTime(step), main.def().dt);
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
        plot->model().setSource(nullptr); // the buffer goes out of scope here
    return out;
}

PlotFilesResult exportStepPlots(const lessons::Lesson& lesson, int step, const QString& dir,
                                const ExportOptions& options)
{
    const lessons::LessonStep& s = lesson.steps.at(static_cast<std::size_t>(step));
    const QString folder = QDir(dir).filePath(stepFolderName(lesson, step));
    PlotFilesResult result{true, {}, {}};
    if (!s.plots.isEmpty()) {
        // The plots are never shown; they only need a parent to be owned by.
        auto holder = std::make_unique<QWidget>();
        const StepPlots ran = runStepPlots(s, holder.get());
        result = exportPlots(ran.plots, folder, stepCaption(lesson, step, ran.settings), options);
        if (!result.ok)
            return result;
    }
    // A separating-axis step's handout: the projections on every tested axis.
    const PlotFilesResult sat = exportSatHandout(lesson, step, folder, options);
    result.files.append(sat.files);
    result.ok = sat.ok;
    result.error = sat.error;
    return result;
}

PlotFilesResult exportLessonPlots(const lessons::Lesson& lesson, const QString& dir,
                                  const ExportOptions& options)
{
    PlotFilesResult all;
    for (int i = 0; i < static_cast<int>(lesson.steps.size()); ++i) {
        PlotFilesResult step = exportStepPlots(lesson, i, dir, options);
        all.files.append(step.files);
        if (!step.ok) {
            all.error = step.error;
            return all;
        }
    }
    all.ok = true;
    return all;
}

} // namespace rigidlab::ui
