// SPDX-License-Identifier: GPL-3.0-or-later
// rigidlab-cli: scenes without a window. Argument handling only; the work is done by
// rigidlab_lessons (scene_loader, scene_run, sat_report, document).

#include "bench.h"
#include "cli_common.h"
#include "cli_fit.h"
#include "cli_lesson.h"
#include "cli_numerics.h"
#include "cli_results.h"
#include "format/atomic_file.h"

#include "format/data_dirs.h"
#include "format/document.h"
#include "format/sat_report.h"
#include "format/scene_loader.h"
#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/integrator.h"
#include "rigidlab/physics/settings.h"
#include "rigidlab/version.h"
#include "run/scene_run.h"

#include <QCoreApplication>
#include <QDir>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace {

using namespace rigidlab;
using namespace rigidlab::cli;

constexpr const char* kUsage = R"(usage: rigidlab-cli COMMAND [ARGS]

Commands:
  run SCENE.json [OPTIONS]   run a scene without a window and print a summary
      --time T               simulated time [s] (default 5)
      --steps N              number of steps instead of a time
      --dt H                 time step [s], overrides the scene's (1e-07 to 1)
      --integrator NAME      @INTEGRATORS@
      --solver NAME          @SOLVERS@
      --trace FILE.csv       step, t [s], body, x [m], y [m], angle [rad], v_x [m/s],
                             v_y [m/s], ω [rad/s] per dynamic body
      --diagnostics FILE.csv step, t [s], E_k [J], E_p [J], E [J], p_x [kg m/s],
                             p_y [kg m/s], L [kg m²/s], contacts, E_diss [J], drift [1];
                             E_diss: energy taken by contacts, drag and dampers;
                             drift: the numerical error, (E + E_diss - E0)/|E0|
      --csv-dialect D        plain (comma, decimal point, no BOM) or spreadsheet (the
                             --lang language's: Czech ';' and decimal comma; with a UTF-8
                             BOM); the default is plain, or spreadsheet with a --lang that
                             writes a decimal comma (cs); times as a person writes them,
                             noise as 0
      --lang en|cs           the language of the files' column heads (default en)
      --every K              write rows every K steps (default 1; step 0 and the last
                             step are always written)
      --profile              print each stage's time per step (broad phase, narrow phase,
                             islands, forces, integration, contact solve, sleep, diagnostics)
  validate FILE.json...      check documents (scenes, lessons) and say what is wrong; a
                             translated lesson is warned of for each text without a
                             shipped language
      --lang en|cs           the language a lesson's title is printed in (default en)
  bench [OPTIONS]            RigidLab's side of the benchmarks (./lab bench adds the peers)
      --scene NAME           one scene: pyramid-20, pyramid-40, pyramid-100, rain-1000,
                             stack-12, mass-ratio (default: all)
      --steps N              steps per run (default 600: 10 s at 1/60 s)
      --runs K               runs; the table gives the median (default 3)
      --export FILE.json     write the scene as a scene file instead of running it
      --solver NAME          @SOLVERS@:
                             the runs' (default sequential-impulse, the table's RigidLab
                             row) or the one --export's file names (default soft-step,
                             the lab's own, which the window runs)
  sat PAIR.json              the separating axis test on polygon pairs, as JSON
  lesson LESSON.json         a lesson's steps, with their plots, panels and questions
                             (LESSON.json or a lesson in one file, FILE.rlesson)
      --validate             only check it: "ok: ..." or what is wrong and where
      --export DIR           run every step that has plots for its exportTime and write
                             them as PNG, PDF, SVG and CSV into DIR/NN-step-title/
      --csv-dialect D        the handouts' CSV: plain or spreadsheet (default as for run)
      --lang en|cs           the language of the lesson's texts: outline, step titles,
                             plot titles, axes, legends and captions of --export (default en;
                             English where a text has none)
      --worksheet OUT.pdf    write the lesson's worksheet (A4 PDF): empty, to print before
                             class; with --answers FILE the student's, from the answers
                             file the window saves beside a handed-in sheet
                             (lessons/ANSWERS_FORMAT.md); with --key the teacher's key
      --student NAME         the name on the worksheet (instead of the answers file's)
      --answers FILE         the answers the sheet shows (its language is the default)
      --key                  the measured answers, for the teacher
  lesson pack LESSON.json -o FILE.rlesson
                             the lesson and every scene it uses in one file, to share
      --author NAME          who made it, shown in the lesson lists
      --date YYYY-MM-DD      when it was made (default: none)
  lesson unpack FILE.rlesson -o DIR
                             the reverse: DIR/FILE.json and its scenes in DIR/scenes/
  lessons                    the shipped lessons: each file's path and title (the data
                             folder: RIGIDLAB_DATA_DIR, else beside the installed program),
                             then the user's own (@USER_LESSONS@), marked
                             "your own" in a third column
  results FOLDER             a class's hand-ins in one table: every answers file of FOLDER
                             (*.answers.json, as Hand in saves them) judged again; a row
                             per student (name, class, date), per question the first
                             answer, its verdict, the tries and whether the hint or Show me
                             was used, and a last row with the share right at the first
                             answer. Damaged files and another lesson's are left out, one
                             line each on standard error
      --lesson FILE          the lesson to judge by (default: the one most files answer,
                             found among the shipped lessons and your own)
      --all-lessons          a table for every lesson the folder answers, instead of
                             leaving the other lessons' files out
      -o OUT.csv|OUT.pdf     write the table as CSV or PDF (default: text on stdout)
      --csv-dialect D        the CSV's dialect (default as for run: the Czech spreadsheet's
                             with --lang cs)
      --lang en|cs           the language of the heads, the verdicts and the lesson
  error-vs-time [OPTIONS]    work against precision of every integrator on reference problems
      --problem NAME|all     oscillator, pendulum, kepler, spinning-body, double-pendulum
      --integrators LIST     comma-separated (default: all, Boost.Odeint's odeint-rk4 and
                             odeint-dopri5 included)
      --dt-from A --dt-to B  the steps swept [s] (default: each problem's own)
      --points N             steps per integrator (default 6)
      --tol-from A --tol-to B  the tolerances swept by the adaptive ones (1e-3 to 1e-11)
      --t-end T              end time [s] (default: each problem's own)
      --min-cpu S            CPU time spent timing each row (default 0.05 s)
      --csv FILE.csv         problem,integrator,dt [s],steps,evaluations,error,max_error,
                             energy_error,seconds [s]
      --csv-dialect D        plain or spreadsheet in --lang's conventions (default as for run)
      --plot FILE.png|.pdf|.svg  the work-precision diagram (FILE-PROBLEM.png for several)
  stress [OPTIONS]           stiff and extreme cases, each with its verdict
      --case NAME            one case (default: all; --case list names them)
      --json FILE.json       the table as JSON
  conserve [OPTIONS]         kinetic energy of an elastic gas and a cradle row, per solver
      --balls N              balls in the gas (default 300)
      --time T               simulated time [s] (default 60)
      --dt DT                time step [s] (default 0.001)
  fit SCENE.json MEASUREMENT.csv [OPTIONS]
                             fit the scene's parameters to a measured time series by least
                             squares over runs of the scene; prints each value with its
                             95 % interval and standard uncertainty, and the residual RMS
                             (file layouts: lessons/measure/MEASUREMENT_FORMAT.md)
      --param P              a parameter, once per parameter (one to three): restitution,
                             friction (every body), restitution:BODY, friction:BODY,
                             restitution:A,B, friction:A,B (a pair), vx:BODY, vy:BODY
      --quantity Q:BODY      what the measurement holds: x, y, vx, vy or v of a body
      --bounce-times         fit restitution from the times of the bounces alone
                             (successive flights shrink by e); no --quantity
      --time-zero T          the file's time at which the scene starts [s] (default 0)
      --origin X,Y           where the scene's origin is in the file's frame [m]
      --time-unit U          the file's time unit: s, ms, min (default: from the header)
      --length-unit U        the file's length unit: m, cm, mm (default: from the header)
  --help                     this text
  --version                  the version of rigidlab-cli

Exit status: 0 done, 1 an output file could not be written, 2 bad input or usage,
3 the simulation diverged (nothing written), 4 a stress case ended with another verdict
than documented.
rigidlab-cli's own messages are in English, whatever --lang says: scripts read them.
Scene format: lessons/SCENE_FORMAT.md.
)";

/// The names --integrator and --solver take, from the engine's own tables: a new integrator
/// or solver is listed here without a change to this file.
QString integratorNames()
{
    QStringList names;
    for (const physics::IntegratorInfo& info : physics::kIntegrators)
        names << QString::fromUtf8(info.name.data(), qsizetype(info.name.size()));
    return names.join(QStringLiteral(", "));
}

QString solverNames()
{
    QStringList names;
    for (const physics::SolverKind kind : physics::kAllSolvers) {
        const std::string_view name = physics::solverName(kind);
        names << QString::fromUtf8(name.data(), qsizetype(name.size()));
    }
    return names.join(QStringLiteral(", "));
}

/// kUsage with the names filled in.
QByteArray usage()
{
    return QString::fromUtf8(kUsage)
        .replace(QStringLiteral("@INTEGRATORS@"), integratorNames())
        .replace(QStringLiteral("@SOLVERS@"), solverNames())
        .replace(QStringLiteral("@USER_LESSONS@"),
                 QDir::toNativeSeparators(lessons::userLessonsDir()))
        .toUtf8();
}

/// Reads the run options; false with `error` set when one is wrong.
bool readRunOptions(const CommandLine& args, lessons::RunOptions& options, QString& error)
{
    const auto time = args.value(QStringLiteral("time"));
    const auto steps = args.value(QStringLiteral("steps"));
    if (time && steps) {
        error = QStringLiteral("--time and --steps: give one or the other");
        return false;
    }
    if (time) {
        options.time = finiteNumber(QStringLiteral("--time"), *time, error);
        if (!options.time) {
            return false;
        }
        if (*options.time < 0) {
            error = QStringLiteral("--time: must be >= 0, got \"%1\"").arg(*time);
            return false;
        }
    }
    if (steps) {
        options.steps =
            wholeNumber(QStringLiteral("--steps"), *steps, 0, lessons::kMaxRunSteps, error);
        if (!options.steps) {
            return false;
        }
    }
    if (const auto dt = args.value(QStringLiteral("dt"))) {
        options.dt = finiteNumber(QStringLiteral("--dt"), *dt, error);
        if (!options.dt) {
            return false;
        }
        if (*options.dt < lessons::kMinDt || *options.dt > lessons::kMaxDt) {
            error = QStringLiteral("--dt: must be from 1e-07 to 1 s, got \"%1\"").arg(*dt);
            return false;
        }
    }
    if (const auto every = args.value(QStringLiteral("every"))) {
        const auto k =
            wholeNumber(QStringLiteral("--every"), *every, 1, lessons::kMaxRunSteps, error);
        if (!k) {
            return false;
        }
        options.every = *k;
    }
    if (const auto name = args.value(QStringLiteral("integrator"))) {
        options.integrator = physics::integratorFromName(name->toStdString());
        if (!options.integrator) {
            error = QStringLiteral("--integrator: unknown integrator \"%1\" (expected %2)")
                        .arg(*name, integratorNames());
            return false;
        }
    }
    if (const auto name = args.value(QStringLiteral("solver"))) {
        options.solver = physics::solverFromName(name->toStdString());
        if (!options.solver) {
            error = QStringLiteral("--solver: unknown solver \"%1\" (expected %2)")
                        .arg(*name, solverNames());
            return false;
        }
    }
    for (const auto& [flag, path] :
         {std::pair{QStringLiteral("trace"), &options.tracePath},
          std::pair{QStringLiteral("diagnostics"), &options.diagnosticsPath}}) {
        if (const auto value = args.value(flag)) {
            if (value->isEmpty()) {
                error = QStringLiteral("--%1: needs a file name").arg(flag);
                return false;
            }
            *path = *value;
        }
    }
    return true;
}

int commandRun(const QStringList& words)
{
    CommandLine args(QStringLiteral("run"));
    for (const char* name : {"time", "steps", "dt", "integrator", "solver", "trace", "diagnostics",
                             "every", "csv-dialect", "lang"})
        args.addValue(QLatin1StringView(name));
    args.addSwitch(QStringLiteral("profile"));
    QString error;
    lessons::RunOptions options;
    if (!args.parse(words))
        return usageError(args.command(), args.error());
    if (!readRunOptions(args, options, error))
        return usageError(args.command(), error);
    const auto csv = csvOption(args, error);
    if (!csv)
        return usageError(args.command(), error);
    options.csv = *csv;
    options.profile = args.isSet(QStringLiteral("profile"));
    const auto path = args.onlyFile();
    if (!path)
        return usageError(args.command(), args.error());
    const lessons::SceneLoadResult loaded = lessons::loadSceneFile(*path);
    printWarnings(loaded.warnings);
    if (!loaded.ok) {
        return inputError(loaded.error);
    }
    // The files' heads in --lang's language; checked above, so this cannot fail.
    applyOutputLanguage(args, error);
    const lessons::RunReport report = lessons::runScene(loaded.scene, options, *path);
    switch (report.status) {
    case lessons::RunStatus::Ok:
        printOut(report.summary(*path) + u'\n');
        printOut(report.profileTable());
        return kExitOk;
    case lessons::RunStatus::BadOptions:
        return inputError(report.error);
    case lessons::RunStatus::OutputError:
        return outputError(report.error);
    case lessons::RunStatus::NonFinite:
        inputError(report.error);
        return kExitNonFinite;
    }
    return kExitBadInput;
}

int commandValidate(const QStringList& words)
{
    CommandLine args(QStringLiteral("validate"));
    addLanguageOption(args);
    if (!args.parse(words))
        return usageError(args.command(), args.error());
    QString languageError;
    if (!applyLanguageOption(args, languageError))
        return usageError(args.command(), languageError);
    if (args.positionals().isEmpty())
        return usageError(args.command(), QStringLiteral("which file?"));
    int status = kExitOk;
    for (const QString& path : args.positionals()) {
        const lessons::DocumentCheck check = lessons::checkDocumentFile(path);
        printWarnings(check.warnings);
        if (check.ok) {
            printOut(QStringLiteral("ok: %1: %2\n").arg(path, check.summary));
        } else {
            status = inputError(check.error);
        }
    }
    return status;
}

int commandSat(const QStringList& words)
{
    CommandLine args(QStringLiteral("sat"));
    if (!args.parse(words))
        return usageError(args.command(), args.error());
    const auto path = args.onlyFile();
    if (!path)
        return usageError(args.command(), args.error());
    const lessons::SatReport report = lessons::satReportFile(*path);
    printWarnings(report.warnings);
    if (!report.ok) {
        return inputError(report.error);
    }
    std::fwrite(report.json.constData(), 1, static_cast<size_t>(report.json.size()), stdout);
    return kExitOk;
}

int commandBench(const QStringList& words)
{
    CommandLine args(QStringLiteral("bench"));
    for (const char* name : {"scene", "steps", "runs", "export", "solver"})
        args.addValue(QLatin1StringView(name));
    QString error;
    if (!args.parse(words))
        return usageError(args.command(), args.error());
    if (!args.positionals().isEmpty())
        return usageError(args.command(), QStringLiteral("no files, only options"));
    bench::BenchOptions options;
    if (const auto steps = args.value(QStringLiteral("steps"))) {
        const auto n = wholeNumber(QStringLiteral("--steps"), *steps, 2, 1'000'000, error);
        if (!n) {
            return usageError(args.command(), error);
        }
        options.steps = static_cast<int>(*n);
    }
    if (const auto runs = args.value(QStringLiteral("runs"))) {
        const auto n = wholeNumber(QStringLiteral("--runs"), *runs, 1, 1000, error);
        if (!n) {
            return usageError(args.command(), error);
        }
        options.runs = static_cast<int>(*n);
    }
    std::vector<std::string> names = bench::benchSceneNames();
    if (const auto scene = args.value(QStringLiteral("scene"))) {
        if (!bench::makeBenchScene(scene->toStdString())) {
            return usageError(args.command(),
                              QStringLiteral("--scene: unknown scene \"%1\" (expected %2)")
                                  .arg(*scene, QString::fromStdString([&] {
                                      std::string all;
                                      for (const auto& n : names)
                                          all += (all.empty() ? "" : ", ") + n;
                                      return all;
                                  }())));
        }
        names = {scene->toStdString()};
    }
    std::optional<physics::SolverKind> solver;
    if (const auto name = args.value(QStringLiteral("solver"))) {
        solver = physics::solverFromName(name->toStdString());
        if (!solver)
            return usageError(args.command(),
                              QStringLiteral("--solver: unknown solver \"%1\" (expected %2)")
                                  .arg(*name, solverNames()));
    }
    bench::RigidLabBenchSettings settings;
    if (const auto path = args.value(QStringLiteral("export"))) {
        if (names.size() != 1) {
            return usageError(args.command(), QStringLiteral("--export: name one --scene"));
        }
        // The file is for the window, which runs a scene with the solver it names: by default
        // the one the lab runs a scene in, not the table's sequential impulses.
        settings.solver = solver.value_or(physics::WorldDef{}.solver);
        const std::string json =
            bench::benchSceneJson(*bench::makeBenchScene(names.front()), settings);
        const QString error = lessons::writeFileAtomically(
            *path, QByteArray(json.data(), static_cast<qsizetype>(json.size())));
        if (!error.isEmpty())
            return outputError(error);
        return kExitOk;
    }
    if (solver)
        settings.solver = *solver;
    const auto engine = bench::makeRigidLabBenchEngine(settings);
    std::vector<bench::BenchResult> results;
    for (const std::string& name : names) {
        results.push_back(bench::runBench(*engine, *bench::makeBenchScene(name), options));
    }
    std::fputs(bench::benchTable(results).c_str(), stdout);
    std::printf("RigidLab: %s; %d steps per run (the first not timed), median of %d runs.\n",
                engine->settings().c_str(), options.steps, options.runs);
    return kExitOk;
}

/// The commands; a new one is a function and a row here (and a paragraph of kUsage).
struct Command {
    QLatin1StringView name;
    int (*run)(const QStringList& words);
};
constexpr Command kCommands[] = {
    {QLatin1StringView("run"), &commandRun},
    {QLatin1StringView("validate"), &commandValidate},
    {QLatin1StringView("sat"), &commandSat},
    {QLatin1StringView("error-vs-time"), &cli::commandErrorVsTime},
    {QLatin1StringView("stress"), &cli::commandStress},
    {QLatin1StringView("conserve"), &cli::commandConserve},
    {QLatin1StringView("bench"), &commandBench},
    {QLatin1StringView("lesson"), &cli::commandLesson},
    {QLatin1StringView("lessons"), &cli::commandLessons},
    {QLatin1StringView("results"), &cli::commandResults},
    {QLatin1StringView("fit"), &cli::commandFit},
};

} // namespace

int main(int argc, char* argv[])
{
    const auto app = cli::makeApplication(argc, argv);
    QStringList words = QCoreApplication::arguments();
    words.removeFirst();
    if (words.isEmpty()) {
        std::fputs(usage().constData(), stderr);
        return kExitBadInput;
    }
    const auto isHelp = [](const QString& word) { return word == u"--help" || word == u"-h"; };
    if (words.front() == u"help" || std::any_of(words.cbegin(), words.cend(), isHelp)) {
        std::fputs(usage().constData(), stdout);
        return kExitOk;
    }
    if (words.size() == 1 && words.front() == u"--version") {
        std::fputs("rigidlab-cli " RIGIDLAB_VERSION "\n", stdout);
        return kExitOk;
    }
    const QString name = words.takeFirst();
    for (const Command& command : kCommands) {
        if (name == command.name) {
            return command.run(words);
        }
    }
    std::fputs(usage().constData(), stderr);
    return usageError(QString(), QStringLiteral("unknown command \"%1\"").arg(name));
}
