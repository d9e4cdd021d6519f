// SPDX-License-Identifier: GPL-3.0-or-later
#include "run/scene_run.h"

#include "export/csv_columns.h"
#include "export/csv_writer.h"
#include "export/noise_floor.h"
#include "export/quantity_scales.h"
#include "export/step_time.h"
#include "format/atomic_file.h"
#include "format/divergence_message.h"
#include "format/scene_loader.h"

#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace rigidlab::lessons {

namespace {

/// A CSV output (atomic_file.h): a file appears, complete, only on commit(); dropped without
/// commit, it leaves nothing behind. A device or FIFO gets the rows as they come.
class CsvFile {
public:
    bool open(const QString& path, const CsvConventions& conventions, const QStringList& header,
              QString& error)
    {
        m_file = std::make_unique<OutputFile>(path);
        if (!m_file->open(error)) {
            m_file.reset();
            return false;
        }
        m_csv = CsvWriter(conventions);
        m_csv.row(header);
        return true;
    }
    bool isOpen() const { return m_file != nullptr; }
    /// True when commit() replaces a file whole (not a device): only then may it be undone.
    bool replacesWhole() const { return isOpen() && m_file->replacesWhole(); }
    CsvWriter& csv() { return m_csv; }

    /// Hands the buffer to the file once it is large.
    bool flushIfLarge(QString& error)
    {
        return m_csv.size() < (std::size_t{1} << 16) || flush(error);
    }
    /// Writes the rest and checks that all of it got there (a full disk shows here, before
    /// anything is put in place); true at once for a file never opened.
    bool finish(QString& error) { return !isOpen() || (flush(error) && m_file->flush(error)); }
    /// Puts the finished file in place; true at once for a file never opened.
    bool commit(QString& error) { return !isOpen() || m_file->commit(error); }

private:
    bool flush(QString& error)
    {
        const std::string rows = m_csv.take();
        return m_file->write(rows.data(), static_cast<qint64>(rows.size()), error);
    }

    std::unique_ptr<OutputFile> m_file;
    CsvWriter m_csv;
};

/// A second name for the file at `path` (a hard link, else a copy), so that it can be put
/// back after `path` was replaced.
bool keepUnderSecondName(const QString& path, const QString& second)
{
    QFile::remove(second); // left over from a run that was killed
    std::error_code error;
    std::filesystem::create_hard_link(QFile::encodeName(path).toStdString(),
                                      QFile::encodeName(second).toStdString(), error);
    return !error || QFile::copy(path, second);
}

/// The time of the world's step as a person writes it [s].
double honestTime(const physics::World& world)
{
    return stepTime(world.stepCount(), world.def().dt, world.time());
}

void writeTraceRows(CsvWriter& csv, const physics::World& world)
{
    const auto& bodies = world.bodies();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const physics::Body& body = bodies[i];
        if (!body.isDynamic()) {
            continue;
        }
        const physics::Vec2 origin = body.origin();
        const physics::Vec2 velocity = world.originVelocity(static_cast<physics::BodyId>(i));
        csv.integer(world.stepCount());
        csv.number(honestTime(world));
        csv.text(body.name);
        // No scale is known for a position or a speed: only what is noise in any unit goes.
        for (double v : {origin.x(), origin.y(), body.angle, velocity.x(), velocity.y(),
                         body.angularVelocity}) {
            csv.number(withoutNoise(v, 0.0));
        }
        csv.endRow();
    }
}

/// A row of the diagnostics; start: the world's at step 0, scale: energyScale(start).
void writeDiagnosticsRow(CsvWriter& csv, const physics::World& world,
                         const physics::Diagnostics& start, double scale)
{
    const physics::Diagnostics& d = world.diagnostics();
    csv.integer(world.stepCount());
    csv.number(honestTime(world));
    for (double v : {d.kinetic, d.potential, d.total}) {
        csv.number(withoutNoise(v, scale));
    }
    // The momenta's scales are the plots' (quantity_scales.h), taken of the bodies as they are.
    const MomentumScales momentum = momentumScales(world);
    csv.number(withoutNoise(d.momentum.x(), momentum.linear));
    csv.number(withoutNoise(d.momentum.y(), momentum.linear));
    csv.number(withoutNoise(d.angularMomentum, momentum.angular));
    csv.integer(d.contacts);
    const double dissipated = d.dissipated - start.dissipated;
    csv.number(withoutNoise(dissipated, scale));
    // The drift is relative: what it is worth is 1, all of the starting energy.
    csv.number(withoutNoise((d.total + dissipated - start.total) / scale, 1.0));
    csv.endRow();
}

/// The first body whose state is not finite, or -1.
int firstNonFiniteBody(const physics::World& world)
{
    const auto& bodies = world.bodies();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const physics::Body& b = bodies[i];
        if (!physics::isFinite(b.position) || !physics::isFinite(b.velocity) ||
            !std::isfinite(b.angle) || !std::isfinite(b.angularVelocity)) {
            return static_cast<int>(i);
        }
    }
    return -1;
}

/// Adds a step's stage times into a running sum; the counts are the step's.
void addProfile(physics::StepProfile& sum, const physics::StepProfile& step)
{
    for (int k = 0; k < physics::kStageCount; ++k) {
        sum.ms[k] += step.ms[k];
        sum.ran[k] = sum.ran[k] || step.ran[k];
    }
    sum.total += step.total;
    sum.directIntegration = step.directIntegration;
    sum.pairs = step.pairs;
    sum.contacts = step.contacts;
    sum.reusedFaces = step.reusedFaces;
    sum.solved = step.solved;
    sum.positionPasses = step.positionPasses;
    sum.awake = step.awake;
    sum.asleep = step.asleep;
    sum.islands = step.islands;
}

QString formatEnergy(double joules)
{
    return QString::number(joules, 'g', 6) + QStringLiteral(" J");
}

/// The number of steps the options ask for, or why they cannot be run (`error`).
std::optional<long long> stepsToRun(const RunOptions& options, const physics::WorldDef& def,
                                    QString& error)
{
    if (options.time && options.steps) {
        error = QStringLiteral("give a time or a number of steps, not both");
        return std::nullopt;
    }
    if (!(std::isfinite(def.dt) && def.dt >= kMinDt && def.dt <= kMaxDt)) {
        error = QStringLiteral("the step must be from 1e-07 to 1 s");
        return std::nullopt;
    }
    if (options.every < 1) {
        error = QStringLiteral("rows must be written every 1 or more steps");
        return std::nullopt;
    }
    long long steps = 0;
    if (options.steps) {
        steps = *options.steps;
    } else {
        const double time = options.time.value_or(kDefaultRunTime);
        if (!(std::isfinite(time) && time >= 0)) {
            error = QStringLiteral("the time must be a number >= 0");
            return std::nullopt;
        }
        if (time / def.dt > static_cast<double>(kMaxRunSteps)) {
            error = QStringLiteral("%1 s at a step of %2 s is more than %3 steps")
                        .arg(QString::number(time), QString::number(def.dt))
                        .arg(kMaxRunSteps);
            return std::nullopt;
        }
        steps = stepsForTime(time, def.dt);
    }
    if (steps < 0 || steps > kMaxRunSteps) {
        error = QStringLiteral("the number of steps must be from 0 to %1").arg(kMaxRunSteps);
        return std::nullopt;
    }
    if (!options.tracePath.isEmpty() && !options.diagnosticsPath.isEmpty() &&
        QFileInfo(options.tracePath).absoluteFilePath() ==
            QFileInfo(options.diagnosticsPath).absoluteFilePath()) {
        error = QStringLiteral("the trace and the diagnostics name the same file");
        return std::nullopt;
    }
    return steps;
}

/// Why the run cannot go on after step `step`, or an empty string.
QString blowUp(const physics::World& world, long long step)
{
    // The world stops itself on a non-finite state or runaway energy, with a diagnosis.
    if (const auto& diverged = world.divergence()) {
        // Energy the contacts made is named as such: it is the solver's, not the integrator's.
        const double added = -world.diagnostics().collisionLoss;
        if (added > 0)
            return QStringLiteral("the simulation blew up at step %1: %2; contacts added %3 J: "
                                  "the run diverged; nothing was written. Look for bodies that "
                                  "start overlapping, or try a smaller --dt.")
                .arg(QString::number(diverged->step), divergenceMessage(*diverged),
                     QString::number(added, 'g', 6));
        return QStringLiteral("the simulation blew up at step %1: %2; nothing was "
                              "written. Try a smaller --dt or another --integrator.")
            .arg(QString::number(diverged->step), divergenceMessage(*diverged));
    }
    // Finite bodies can still give an infinite energy (a speed whose square overflows,
    // two attracting bodies at one point), so both are checked.
    const int bad = firstNonFiniteBody(world);
    if (bad >= 0 || !std::isfinite(world.diagnostics().total)) {
        const QString what =
            bad >= 0
                ? QStringLiteral("body \"%1\"").arg(QString::fromStdString(world.body(bad).name))
                : QStringLiteral("the total energy");
        return QStringLiteral("the simulation blew up at step %1 (t = %2 s): %3 is no "
                              "longer finite; nothing was written. Try a smaller --dt or "
                              "another --integrator.")
            .arg(step)
            .arg(world.time())
            .arg(what);
    }
    return QString();
}

/// What the run ended with: its time and energies, the losses since `start`.
void recordEnd(RunReport& report, const physics::World& world, const physics::Diagnostics& start)
{
    report.simulatedTime = world.time();
    report.energyEnd = world.diagnostics().total;
    report.collisionLoss = world.diagnostics().collisionLoss - start.collisionLoss;
    report.dissipated = world.diagnostics().dissipated - start.dissipated;
}

/// Puts both finished outputs in place, or neither (`error` says why).
bool commitOutputs(CsvFile& trace, CsvFile& diagnostics, const RunOptions& options, QString& error)
{
    // Both files are complete in their temporary files before either is put in place, so a
    // full disk leaves both previous files as they were. Only a rename can still fail after
    // that; then the previous trace, kept under a second name meanwhile, is put back.
    if (!trace.finish(error) || !diagnostics.finish(error)) {
        return false;
    }
    const QString previousTrace = options.tracePath + QStringLiteral(".previous");
    // A device is neither kept nor taken away: what went into it is gone already.
    const bool keptTrace = trace.replacesWhole() && diagnostics.isOpen() &&
                           QFileInfo::exists(options.tracePath) &&
                           keepUnderSecondName(options.tracePath, previousTrace);
    if (!trace.commit(error)) {
        if (keptTrace) {
            QFile::remove(previousTrace);
        }
        return false;
    }
    if (!diagnostics.commit(error)) {
        // Take the new trace away again, so that a failed run changes nothing.
        if (trace.replacesWhole()) {
            QFile::remove(options.tracePath);
        }
        if (keptTrace) {
            QFile::rename(previousTrace, options.tracePath);
        }
        return false;
    }
    if (keptTrace) {
        QFile::remove(previousTrace);
    }
    return true;
}

} // namespace

QStringList traceHeader()
{
    QStringList heads;
    for (const CsvColumn c :
         {CsvColumn::Step, CsvColumn::Time, CsvColumn::Body, CsvColumn::X, CsvColumn::Y,
          CsvColumn::Angle, CsvColumn::Vx, CsvColumn::Vy, CsvColumn::Omega})
        heads.append(csvColumnHead(c));
    return heads;
}

QStringList diagnosticsHeader()
{
    QStringList heads;
    for (const CsvColumn c :
         {CsvColumn::Step, CsvColumn::Time, CsvColumn::Kinetic, CsvColumn::Potential,
          CsvColumn::Total, CsvColumn::Px, CsvColumn::Py, CsvColumn::AngularMomentum,
          CsvColumn::Contacts, CsvColumn::Dissipated, CsvColumn::Drift})
        heads.append(csvColumnHead(c));
    return heads;
}

QString RunReport::profileTable() const
{
    if (!profile) {
        return {};
    }
    const physics::StepProfile& p = *profile;
    const double n = std::max<double>(1.0, static_cast<double>(steps));
    QString out = QStringLiteral("stage            ms/step    share\n");
    for (int k = 0; k < physics::kStageCount; ++k) {
        const auto stage = static_cast<physics::Stage>(k);
        QString name = QString::fromLatin1(physics::stageName(stage));
        name = name.leftJustified(16);
        if (!p.ran[k]) {
            out += name + QStringLiteral(" left out\n");
            continue;
        }
        out += name + QStringLiteral(" %1 %2 %\n")
                          .arg(p.ms[k] / n, 8, 'f', 4)
                          .arg(p.total > 0 ? 100.0 * p.ms[k] / p.total : 0.0, 6, 'f', 1);
    }
    out += QStringLiteral("step             %1\n").arg(p.total / n, 8, 'f', 4);
    out += QStringLiteral("last step: %1 pairs, %2 contacts (%9 from kept faces, without the "
                          "SAT), %3 solved, %4 position passes, %5 awake, %6 asleep, %7 islands; "
                          "integration %8\n")
               .arg(p.pairs)
               .arg(p.contacts)
               .arg(p.solved)
               .arg(p.positionPasses)
               .arg(p.awake)
               .arg(p.asleep)
               .arg(p.islands)
               .arg(p.directIntegration ? QStringLiteral("direct")
                                        : QStringLiteral("by the ODE "
                                                         "system"))
               .arg(p.reusedFaces);
    return out;
}

double energyScale(const physics::Diagnostics& start)
{
    const double parts = start.kinetic + std::abs(start.potential);
    const double total = std::abs(start.total);
    if (total > 0 && total >= 1e-9 * parts) {
        return total;
    }
    return parts > 0 ? parts : 1.0;
}

double RunReport::drift() const
{
    return (energyEnd + dissipated - energyStart) / energyScale;
}

long long stepsForTime(double time, double dt)
{
    const double exact = time / dt;
    const double nearest = std::round(exact);
    if (std::abs(exact - nearest) <= 1e-9 * std::max(1.0, nearest)) {
        return static_cast<long long>(nearest);
    }
    return static_cast<long long>(std::ceil(exact));
}

QString RunReport::summary(const QString& sourceName) const
{
    const auto name = [](std::string_view s) {
        return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
    };
    // The drift is the numerical error alone: what contacts, drag and dampers took is
    // physics, and is added back first.
    const QString drift = QStringLiteral("a drift of %1 % of the starting energy")
                              .arg(QString::number(100.0 * this->drift(), 'g', 4));
    // Each part in one multi-argument arg(), so that a '%' in a file name is never taken for
    // a placeholder.
    const QString run =
        QStringLiteral("%1: %2 steps of %3 s (%4 s simulated) in %5 s of wall time, with the %6 "
                       "integrator and the %7 solver.")
            .arg(sourceName, QString::number(steps), QString::number(dt, 'g', 6),
                 QString::number(simulatedTime, 'g', 8), QString::number(wallSeconds, 'f', 3),
                 name(physics::integratorName(integrator)), name(physics::solverName(solver)));
    // Contacts that gave energy back are said to have added it, never booked as a negative
    // loss (a kinematic body pushing, or a run that diverged for it).
    const QString contacts =
        collisionLoss < 0 ? QStringLiteral("contacts added %1").arg(formatEnergy(-collisionLoss))
                          : QStringLiteral("contacts took %1").arg(formatEnergy(collisionLoss));
    const QString energy = QStringLiteral(" Total energy went from %1 to %2; %3, drag and dampers "
                                          "%4; the rest, %5, is the numerical error.")
                               .arg(formatEnergy(energyStart), formatEnergy(energyEnd), contacts,
                                    formatEnergy(dissipated - collisionLoss), drift);
    return run + energy;
}

RunReport runScene(const Scene& scene, const RunOptions& options, const QString& sourceName)
{
    RunReport report;
    const auto fail = [&](RunStatus status, const QString& what) {
        report.status = status;
        report.error = sourceName + QStringLiteral(": ") + what;
        return report;
    };

    // Settings: the scene's, overridden by the options.
    physics::WorldDef def = scene.world;
    def.dt = options.dt.value_or(def.dt);
    def.integrator = options.integrator.value_or(def.integrator);
    def.solver = options.solver.value_or(def.solver);
    QString error;
    const std::optional<long long> toRun = stepsToRun(options, def, error);
    if (!toRun)
        return fail(RunStatus::BadOptions, error);
    const long long steps = *toRun;
    report.dt = def.dt;
    report.integrator = def.integrator;
    report.solver = def.solver;

    // Open the outputs first, so that a bad path fails before the run rather than after it.
    CsvFile trace;
    CsvFile diagnostics;
    if ((!options.tracePath.isEmpty() &&
         !trace.open(options.tracePath, options.csv, traceHeader(), error)) ||
        (!options.diagnosticsPath.isEmpty() &&
         !diagnostics.open(options.diagnosticsPath, options.csv, diagnosticsHeader(), error))) {
        return fail(RunStatus::OutputError, error);
    }

    Scene settings = scene;
    settings.world = def;
    physics::World world = buildWorld(settings);
    world.updateDiagnostics();
    const physics::Diagnostics start = world.diagnostics();
    report.energyStart = start.total;
    report.energyScale = energyScale(start);

    QElapsedTimer clock;
    if (options.profile) {
        report.profile.emplace();
    }
    clock.start();
    for (long long step = 0; step <= steps; ++step) {
        if (step > 0) {
            world.step();
            if (options.profile) {
                addProfile(*report.profile, world.profile());
            }
        }
        if (const QString why = blowUp(world, step); !why.isEmpty()) {
            return fail(RunStatus::NonFinite, why);
        }
        if (step % options.every == 0 || step == steps) {
            if (trace.isOpen()) {
                writeTraceRows(trace.csv(), world);
            }
            if (diagnostics.isOpen()) {
                writeDiagnosticsRow(diagnostics.csv(), world, start, report.energyScale);
            }
            if ((trace.isOpen() && !trace.flushIfLarge(error)) ||
                (diagnostics.isOpen() && !diagnostics.flushIfLarge(error))) {
                return fail(RunStatus::OutputError, error);
            }
        }
    }
    report.wallSeconds = static_cast<double>(clock.nsecsElapsed()) * 1e-9;

    if (!commitOutputs(trace, diagnostics, options, error)) {
        return fail(RunStatus::OutputError, error);
    }
    report.status = RunStatus::Ok;
    report.steps = steps;
    recordEnd(report, world, start);
    return report;
}

} // namespace rigidlab::lessons
