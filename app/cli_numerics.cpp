// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli_numerics.h"

#include "cli_common.h"

#include "plots/plot_export.h"
#include "plots/work_precision_plot.h"

#include "format/atomic_file.h"
#include "format/data_dirs.h"
#include "numerics/error_vs_time.h"
#include "numerics/stress.h"

#include <QApplication>
#include <QDir>
#include <QFileInfo>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <optional>

#ifdef Q_OS_WIN
#include <windows.h>
#endif

namespace rigidlab::cli {

namespace {

bool writeFile(const QString& path, const QByteArray& bytes)
{
    const QString error = lessons::writeFileAtomically(path, bytes);
    if (!error.isEmpty()) {
        outputError(error);
        return false;
    }
    return true;
}

/// FILE.png for one problem; FILE-PROBLEM.png for each of several.
QString plotPathFor(const QString& path, const QString& problem, bool several)
{
    if (!several)
        return path;
    const QFileInfo info(path);
    return info.dir().filePath(info.completeBaseName() + u'-' + problem + u'.' + info.suffix());
}

/// error-vs-time's options from its command line into `options`: an empty string, or what is
/// wrong with them.
QString readSweepOptions(const CommandLine& args, lessons::SweepOptions& options)
{
    QString error;
    // A positive number from an option, when given.
    const auto number = [&](const char* name) -> std::optional<double> {
        const auto text = args.value(QLatin1StringView(name));
        if (!text || !error.isEmpty())
            return std::nullopt;
        return positiveNumber(QStringLiteral("--") + QLatin1StringView(name), *text, error);
    };
    if (const auto problem = args.value(QStringLiteral("problem")); problem && *problem != u"all")
        options.problems = problem->split(u',', Qt::SkipEmptyParts);
    if (const auto integrators = args.value(QStringLiteral("integrators")))
        options.integrators = integrators->split(u',', Qt::SkipEmptyParts);
    options.dtFrom = number("dt-from");
    options.dtTo = number("dt-to");
    options.tEnd = number("t-end");
    if (const auto t = number("tol-from"))
        options.tolFrom = *t;
    if (const auto t = number("tol-to"))
        options.tolTo = *t;
    if (const auto t = number("min-cpu"))
        options.minTimingSeconds = *t;
    if (const auto points = args.value(QStringLiteral("points")); points && error.isEmpty()) {
        bool ok = false;
        options.points = points->toInt(&ok);
        if (!ok)
            error = QStringLiteral("--points: must be a whole number");
    }
    if (!error.isEmpty())
        return error;
    return lessons::checkSweepOptions(options);
}

/// Runs the sweep, printing each row as it is done.
std::vector<lessons::SweepRow> runAndPrintSweep(const lessons::SweepOptions& options)
{
    std::printf("%-16s %-18s %12s %9s %11s %11s %11s %11s %11s\n", "problem", "integrator", "dt",
                "steps", "evaluations", "error", "max_error", "energy_err", "seconds");
    return lessons::runSweep(options, [](const lessons::SweepRow& r, int, int) {
        std::printf("%-16s %-18s %12.4g %9lld %11lld %11.3e %11.3e %11.3e %11.3e\n",
                    qPrintable(r.problem), qPrintable(r.integrator), r.dt, r.steps, r.evaluations,
                    r.error, r.maxError, r.energyError, r.seconds);
        std::fflush(stdout);
        return true;
    });
}

/// Prints the observed order of each integrator on each problem; returns the problems of
/// `rows`, in their order.
QStringList printObservedOrders(const std::vector<lessons::SweepRow>& rows,
                                const lessons::SweepOptions& options)
{
    QStringList problems;
    for (const lessons::SweepRow& r : rows)
        if (!problems.contains(r.problem))
            problems.append(r.problem);
    std::printf("\nobserved order (slope of log error against log dt, rows with 1e-10 < error < "
                "1e-2):\n");
    for (const QString& p : problems) {
        std::printf("  %-16s", qPrintable(p));
        QStringList seen;
        for (const lessons::SweepRow& r : rows) {
            if (r.problem != p || seen.contains(r.integrator))
                continue;
            seen.append(r.integrator);
            const auto order = lessons::observedOrder(rows, p, r.integrator);
            std::printf(" %s %s", qPrintable(r.integrator),
                        order ? qPrintable(QString::number(*order, 'f', 2)) : "?");
        }
        std::printf("\n");
    }
    std::printf("seconds: CPU time of the integration alone, the smallest of repeated runs (at "
                "least %d, and until %g s of CPU time were spent on the row).\n",
                options.minRepeats, options.minTimingSeconds);
    return problems;
}

/// The work-precision diagram of each problem into `path` (FILE-PROBLEM.png for several).
int writeWorkPrecisionPlots(const std::vector<lessons::SweepRow>& rows, const QStringList& problems,
                            const QString& path, ui::ExportFormat format)
{
    ui::WorkPrecisionPlot plot;
    plot.resize(800, 500);
    plot.setRows(rows);
    for (const QString& p : problems) {
        plot.setProblem(p);
        const QString file = plotPathFor(path, p, problems.size() > 1);
        const ui::ExportResult r = ui::exportPlot(plot, file, format);
        if (!r.ok)
            return outputError(r.error);
        std::printf("wrote %s\n", qPrintable(file));
    }
    return kExitOk;
}

#ifdef Q_OS_WIN
/// The console's code page when the program started, put back when it ends.
UINT consoleCodePage = 0;
#endif

/// The program writes its texts in the system's 8-bit code page (QString::toLocal8Bit); a
/// Windows console shows another one (the OEM code page: 852 where the ANSI one is 1250), and
/// would garble the Czech letters. The console shows the ANSI code page while the program runs.
void matchConsoleCodePage()
{
#ifdef Q_OS_WIN
    consoleCodePage = GetConsoleOutputCP();
    if (consoleCodePage != 0 && SetConsoleOutputCP(GetACP()))
        std::atexit([] { SetConsoleOutputCP(consoleCodePage); });
#endif
}

} // namespace

std::unique_ptr<QCoreApplication> makeApplication(int& argc, char** argv)
{
    matchConsoleCodePage();
    lessons::useSettingsFiles();
    if (argc > 1 && (std::strcmp(argv[1], "error-vs-time") == 0 ||
                     std::strcmp(argv[1], "lesson") == 0 || std::strcmp(argv[1], "results") == 0)) {
        // The plots are drawn into files, never shown: no display is needed. On Windows the
        // Windows platform needs none either, and its fonts are the system's (Qt's offscreen
        // platform there would look for fonts in Qt's own folder, and find none).
#ifndef Q_OS_WIN
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
            qputenv("QT_QPA_PLATFORM", "offscreen");
#endif
        return std::make_unique<QApplication>(argc, argv);
    }
    return std::make_unique<QCoreApplication>(argc, argv);
}

int commandErrorVsTime(const QStringList& words)
{
    CommandLine args(QStringLiteral("error-vs-time"));
    for (const char* name : {"problem", "integrators", "dt-from", "dt-to", "points", "t-end", "csv",
                             "plot", "tol-from", "tol-to", "min-cpu", "csv-dialect", "lang"})
        args.addValue(QLatin1StringView(name));
    if (!args.parseOptionsOnly(words))
        return usageError(args.command(), args.error());
    QString csvError;
    const auto conventions = csvOption(args, csvError);
    if (!conventions)
        return usageError(args.command(), csvError);
    lessons::SweepOptions options;
    if (const QString bad = readSweepOptions(args, options); !bad.isEmpty())
        return usageError(args.command(), bad);
    const QString plotPath = args.value(QStringLiteral("plot")).value_or(QString());
    std::optional<ui::ExportFormat> format;
    if (!plotPath.isEmpty()) {
        format = ui::formatFromSuffix(QFileInfo(plotPath).suffix());
        if (!format || *format == ui::ExportFormat::Csv)
            return usageError(args.command(), QStringLiteral("--plot: a .png, .pdf or .svg file"));
    }

    const std::vector<lessons::SweepRow> rows = runAndPrintSweep(options);
    const QStringList problems = printObservedOrders(rows, options);
    if (const auto csv = args.value(QStringLiteral("csv"));
        csv && !writeFile(*csv, lessons::sweepCsv(rows, *conventions)))
        return kExitOutputError;
    if (format)
        return writeWorkPrecisionPlots(rows, problems, plotPath, *format);
    return kExitOk;
}

int commandStress(const QStringList& words)
{
    CommandLine args(QStringLiteral("stress"));
    args.addValue(QStringLiteral("case"));
    args.addValue(QStringLiteral("json"));
    if (!args.parseOptionsOnly(words))
        return usageError(args.command(), args.error());
    QString name;
    if (const auto chosen = args.value(QStringLiteral("case"))) {
        name = *chosen;
        if (name == u"list") {
            std::printf("%s\n", qPrintable(lessons::stressCaseNames().join(u'\n')));
            return kExitOk;
        }
        if (name == u"all")
            name.clear();
        else if (!lessons::stressCaseNames().contains(name))
            return usageError(args.command(),
                              QStringLiteral("--case: unknown case \"%1\" (expected %2)")
                                  .arg(name, lessons::stressCaseNames().join(u", ")));
    }
    const std::vector<lessons::StressRow> rows = lessons::runStress(name);
    std::fputs(qPrintable(lessons::stressTable(rows)), stdout);
    int unexpected = 0;
    for (const lessons::StressRow& r : rows) {
        if (!r.diagnosis.isEmpty())
            std::printf("%s, %s, %s: %s\n", qPrintable(r.caseName), qPrintable(r.setup),
                        qPrintable(r.integrator), qPrintable(r.diagnosis));
        unexpected += r.asDocumented() ? 0 : 1;
    }
    std::printf("%zu rows, %d not as documented.\n", rows.size(), unexpected);
    if (const auto json = args.value(QStringLiteral("json"));
        json && !writeFile(*json, lessons::stressJson(rows)))
        return kExitOutputError;
    return unexpected == 0 ? kExitOk : kExitVerdict;
}

} // namespace rigidlab::cli
