#include "cli_numerics.h"

#include "work_precision_plot.h"

#include "rigidlab/lessons/atomic_file.h"
#include "rigidlab/lessons/error_vs_time.h"
#include "rigidlab/lessons/stress.h"

#include <QApplication>
#include <QDir>
#include <QFileInfo>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <optional>

namespace rigidlab::cli {

namespace {

constexpr int kExitOk = 0;
constexpr int kExitOutputError = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitVerdict = 4;

void printErr(const QString& text)
{
    std::fputs(text.toLocal8Bit().constData(), stderr);
}

int usageError(const QString& what)
{
    printErr(QStringLiteral("rigidlab-cli: ") + what +
             QStringLiteral("\nTry 'rigidlab-cli --help'.\n"));
    return kExitBadInput;
}

/// `--name value` and `--name=value` options, each at most once; no positionals.
bool parseOptions(const QStringList& words, const QStringList& known,
                  std::map<QString, QString>& out, QString& error)
{
    for (qsizetype i = 0; i < words.size(); ++i) {
        QString name = words[i];
        std::optional<QString> value;
        if (!name.startsWith(QLatin1String("--"))) {
            error = QStringLiteral("unexpected argument \"%1\"").arg(name);
            return false;
        }
        if (const qsizetype eq = name.indexOf(u'='); eq > 0) {
            value = name.mid(eq + 1);
            name = name.left(eq);
        }
        if (!known.contains(name)) {
            error = QStringLiteral("unknown option %1").arg(name);
            return false;
        }
        if (!value) {
            if (i + 1 >= words.size()) {
                error = QStringLiteral("%1: needs a value").arg(name);
                return false;
            }
            value = words[++i];
        }
        if (out.count(name)) {
            error = QStringLiteral("%1: given twice").arg(name);
            return false;
        }
        out[name] = *value;
    }
    return true;
}

std::optional<double> number(const std::map<QString, QString>& o, const QString& name,
                             QString& error)
{
    const auto it = o.find(name);
    if (it == o.end())
        return std::nullopt;
    bool ok = false;
    const double v = it->second.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(v) || v <= 0) {
        error = QStringLiteral("%1: must be a positive number, got \"%2\"").arg(name, it->second);
        return std::nullopt;
    }
    return v;
}

bool writeFile(const QString& path, const QByteArray& bytes)
{
    const QString error = lessons::writeFileAtomically(path, bytes);
    if (!error.isEmpty()) {
        printErr(QStringLiteral("error: %1\n").arg(error));
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

} // namespace

std::unique_ptr<QCoreApplication> makeApplication(int& argc, char** argv)
{
    if (argc > 1 &&
        (std::strcmp(argv[1], "error-vs-time") == 0 || std::strcmp(argv[1], "lesson") == 0)) {
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
            qputenv("QT_QPA_PLATFORM", "offscreen");
        return std::make_unique<QApplication>(argc, argv);
    }
    return std::make_unique<QCoreApplication>(argc, argv);
}

int commandErrorVsTime(const QStringList& words)
{
    const QStringList known{"--problem",  "--integrators", "--dt-from", "--dt-to",
                            "--points",   "--t-end",       "--csv",     "--plot",
                            "--tol-from", "--tol-to",      "--min-cpu"};
    std::map<QString, QString> o;
    QString error;
    if (!parseOptions(words, known, o, error))
        return usageError(QStringLiteral("error-vs-time: ") + error);

    lessons::SweepOptions options;
    if (o.count("--problem") && o["--problem"] != u"all")
        options.problems = o["--problem"].split(u',', Qt::SkipEmptyParts);
    if (o.count("--integrators"))
        options.integrators = o["--integrators"].split(u',', Qt::SkipEmptyParts);
    options.dtFrom = number(o, "--dt-from", error);
    options.dtTo = number(o, "--dt-to", error);
    options.tEnd = number(o, "--t-end", error);
    if (const auto t = number(o, "--tol-from", error))
        options.tolFrom = *t;
    if (const auto t = number(o, "--tol-to", error))
        options.tolTo = *t;
    if (const auto t = number(o, "--min-cpu", error))
        options.minTimingSeconds = *t;
    if (o.count("--points")) {
        bool ok = false;
        options.points = o["--points"].toInt(&ok);
        if (!ok)
            error = QStringLiteral("--points: must be a whole number");
    }
    if (!error.isEmpty())
        return usageError(QStringLiteral("error-vs-time: ") + error);
    if (const QString bad = lessons::checkSweepOptions(options); !bad.isEmpty())
        return usageError(QStringLiteral("error-vs-time: ") + bad);
    const QString plotPath = o.count("--plot") ? o["--plot"] : QString();
    std::optional<ui::ExportFormat> format;
    if (!plotPath.isEmpty()) {
        format = ui::formatFromSuffix(QFileInfo(plotPath).suffix());
        if (!format || *format == ui::ExportFormat::Csv)
            return usageError(QStringLiteral("error-vs-time: --plot: a .png, .pdf or .svg file"));
    }

    std::printf("%-16s %-18s %12s %9s %11s %11s %11s %11s %11s\n", "problem", "integrator", "dt",
                "steps", "evaluations", "error", "max_error", "energy_err", "seconds");
    const std::vector<lessons::SweepRow> rows =
        lessons::runSweep(options, [](const lessons::SweepRow& r, int, int) {
            std::printf("%-16s %-18s %12.4g %9lld %11lld %11.3e %11.3e %11.3e %11.3e\n",
                        qPrintable(r.problem), qPrintable(r.integrator), r.dt, r.steps,
                        r.evaluations, r.error, r.maxError, r.energyError, r.seconds);
            std::fflush(stdout);
            return true;
        });

    // Observed orders, per problem and integrator.
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

    if (o.count("--csv") && !writeFile(o["--csv"], lessons::sweepCsv(rows)))
        return kExitOutputError;
    if (format) {
        ui::WorkPrecisionPlot plot;
        plot.resize(800, 500);
        plot.setRows(rows);
        for (const QString& p : problems) {
            plot.setProblem(p);
            const QString path = plotPathFor(plotPath, p, problems.size() > 1);
            const ui::ExportResult r = ui::exportPlot(plot, path, *format);
            if (!r.ok) {
                printErr(QStringLiteral("error: ") + r.error + u'\n');
                return kExitOutputError;
            }
            std::printf("wrote %s\n", qPrintable(path));
        }
    }
    return kExitOk;
}

int commandStress(const QStringList& words)
{
    std::map<QString, QString> o;
    QString error;
    if (!parseOptions(words, {"--case", "--json"}, o, error))
        return usageError(QStringLiteral("stress: ") + error);
    QString name;
    if (o.count("--case")) {
        name = o["--case"];
        if (name == u"list") {
            std::printf("%s\n", qPrintable(lessons::stressCaseNames().join(u'\n')));
            return kExitOk;
        }
        if (name == u"all")
            name.clear();
        else if (!lessons::stressCaseNames().contains(name))
            return usageError(QStringLiteral("stress: --case: unknown case \"%1\" (expected %2)")
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
    if (o.count("--json") && !writeFile(o["--json"], lessons::stressJson(rows)))
        return kExitOutputError;
    return unexpected == 0 ? kExitOk : kExitVerdict;
}

} // namespace rigidlab::cli
