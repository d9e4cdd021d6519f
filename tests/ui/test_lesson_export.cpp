// SPDX-License-Identifier: GPL-3.0-or-later
// A lesson step's plots and their export for handouts: the plots a step names, samples made
// exactly as the window makes them, captions, and the headless export of every shipped
// lesson through rigidlab-cli, each file checked for being what it says it is.

#include "build_paths.h"
#include "common/language.h"
#include "plots/lesson_export.h"
#include "plots/plot_widget.h"
#include "plots/sat_handout.h"
#include "simulation/step_sampler.h"

#include "format/lesson.h"

#include <qcustomplot.h>

#include <QDirIterator>
#include <QImage>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtTest>

#include "cli_run.h"
#include "near.h"
#include "step_walk.h"
#include "test_files.h"
#include "test_main.h"

#include <charconv>
#include <cmath>
#include <tuple>

using namespace rigidlab;

using rigidlab::test::readAll;

namespace {

const QString kLessonsDir = rigidlab::test::sourcePath(u"/lessons/lessons");

lessons::Lesson lesson(const char* name)
{
    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(
        QDir(kLessonsDir).filePath(QLatin1StringView(name) + QStringLiteral(".json")));
    if (!loaded.ok)
        qWarning("%s", qPrintable(loaded.error));
    return loaded.lesson;
}

/// The rows of a CSV file written by the export (numbers only after the header).
std::vector<std::vector<double>> csvRows(const QString& path, QByteArray* header = nullptr)
{
    const QList<QByteArray> lines = readAll(path).split('\n');
    std::vector<std::vector<double>> rows;
    for (qsizetype i = 1; i < lines.size(); ++i) {
        if (lines[i].isEmpty())
            continue;
        std::vector<double> row;
        for (const QByteArray& cell : lines[i].split(',')) {
            double v = std::nan("");
            std::from_chars(cell.constData(), cell.constData() + cell.size(), v);
            row.push_back(v);
        }
        rows.push_back(row);
    }
    if (header && !lines.isEmpty())
        *header = lines[0];
    return rows;
}

/// Checks an exported table, its cells separated by commas.
QString checkCsv(const QString& path, const QByteArray& bytes)
{
    if (path.endsWith(QStringLiteral("sat-projections.csv"))) {
        if (!bytes.startsWith("axis,body,edge,n_x,n_y,A_min [m],"))
            return QStringLiteral("SAT table without its header");
        if (bytes.count('\n') < 2)
            return QStringLiteral("SAT table without an axis");
    } else {
        if (!bytes.startsWith("t [s],"))
            return QStringLiteral("CSV without its header");
        if (bytes.count('\n') < 10)
            return QStringLiteral("CSV with almost no rows");
    }
    return {};
}

/// Checks one exported file by its suffix; an empty string when it is good.
QString checkFile(const QString& path, const QString& caption)
{
    const QByteArray bytes = readAll(path);
    if (bytes.isEmpty())
        return QStringLiteral("empty");
    if (path.endsWith(QStringLiteral(".png"))) {
        QImage image;
        if (!image.loadFromData(bytes, "PNG"))
            return QStringLiteral("does not decode as PNG");
        if (image.size() != QSize(1600, 1000))
            return QStringLiteral("PNG of %1 x %2").arg(image.width()).arg(image.height());
    } else if (path.endsWith(QStringLiteral(".pdf"))) {
        if (!bytes.startsWith("%PDF-") || !bytes.trimmed().endsWith("%%EOF"))
            return QStringLiteral("not a whole PDF");
    } else if (path.endsWith(QStringLiteral(".svg"))) {
        QXmlStreamReader xml(bytes);
        while (!xml.atEnd())
            xml.readNext();
        if (xml.hasError())
            return QStringLiteral("SVG does not parse: ") + xml.errorString();
        if (!QSvgRenderer(bytes).isValid())
            return QStringLiteral("SVG does not render");
        // The caption is drawn as text (its first line; the second may be laid out apart).
        const QString first = caption.section(u'\n', 0, 0).toHtmlEscaped();
        if (!caption.isEmpty() && !QString::fromUtf8(bytes).contains(first.left(20)))
            return QStringLiteral("SVG without its caption");
    } else if (path.endsWith(QStringLiteral(".csv"))) {
        // A Czech handout is in the Czech spreadsheet's form: a BOM, ';' between the cells.
        QByteArray text = bytes;
        if (text.startsWith("\xEF\xBB\xBF"))
            text.remove(0, 3).replace(';', ',');
        return checkCsv(path, text);
    } else {
        return QStringLiteral("unexpected file");
    }
    return {};
}

using rigidlab::test::CliRun;
using rigidlab::test::runCli;

} // namespace

class TestLessonExport : public QObject {
    Q_OBJECT

private slots:
    void stepPlotsAreTheNamedOnes();
    void folderNamesAndCaptions();
    void captionOnlyInExports();
    void headlessSamplesAreTheWorldsOwn();
    void headlessSamplingKeepsTheWindowsInterval();
    void exportStopsAtTheEndTime();
    void cliExportsEveryLesson_data();
    void cliExportsEveryLesson();
    void satHandoutIsTheProjections();
    void cliLessonErrors();
    void cliExportsInCzech();
};

void TestLessonExport::stepPlotsAreTheNamedOnes()
{
    QWidget parent;
    const lessons::Lesson drift = lesson("energy_drift");
    std::vector<ui::PlotWidget*> plots = ui::makeStepPlots(drift.steps[0], &parent);
    QCOMPARE(plots.size(), std::size_t{2});
    QCOMPARE(plots[0]->objectName(), QStringLiteral("compare-energy"));
    QCOMPARE(plots[1]->objectName(), QStringLiteral("compare-drift"));
    QCOMPARE(plots[0]->title(), QStringLiteral("Total energy by integrator"));
    QCOMPARE(plots[0]->model().seriesCount(), 4);
    const QStringList names = {QStringLiteral("euler"), QStringLiteral("symplectic-euler"),
                               QStringLiteral("verlet"), QStringLiteral("rk4")};
    for (int i = 0; i < 4; ++i) {
        QCOMPARE(plots[0]->model().seriesName(i), names[i]);
        QCOMPARE(plots[1]->model().seriesName(i), names[i]);
    }
    QCOMPARE(plots[0]->model().seriesUnit(0), QStringLiteral("J"));
    QCOMPARE(plots[1]->model().seriesUnit(0), QStringLiteral("%"));

    // One curve per variant, read from the samples' variant columns.
    ui::SampleBuffer buffer;
    ui::Sample s;
    s.t = 0.5;
    s.variants = 4;
    s.variantTotal = {1, 2, 3, 4, 0, 0};
    s.variantDriftPercent = {10, 20, 30, 40, 0, 0};
    buffer.push(s);
    for (ui::PlotWidget* p : plots) {
        p->model().setSource(&buffer);
        QCOMPARE(p->drain(), 1);
    }
    for (int i = 0; i < 4; ++i) {
        QCOMPARE(plots[0]->model().points(i).at(0).y(), 1.0 + i);
        QCOMPARE(plots[1]->model().points(i).at(0).y(), 10.0 * (i + 1));
    }

    const lessons::Lesson stacks = lesson("stacks");
    std::vector<ui::PlotWidget*> solvers = ui::makeStepPlots(stacks.steps[0], &parent);
    QCOMPARE(solvers.size(), std::size_t{1});
    QCOMPARE(solvers[0]->title(), QStringLiteral("Total energy by solver"));
    QCOMPARE(solvers[0]->model().seriesName(0), QStringLiteral("seed-impulse"));

    const lessons::Lesson bounces = lesson("restitution");
    std::vector<ui::PlotWidget*> plain = ui::makeStepPlots(bounces.steps[1], &parent);
    QCOMPARE(plain.size(), std::size_t{2});
    QCOMPARE(plain[0]->objectName(), QStringLiteral("momentum"));
    QCOMPARE(plain[0]->title(), QStringLiteral("Momentum"));
    QCOMPARE(plain[1]->objectName(), QStringLiteral("energy"));
    // A step without plots has none.
    QVERIFY(ui::makeStepPlots(lesson("separating_axis").steps[0], &parent).empty());
}

void TestLessonExport::folderNamesAndCaptions()
{
    const lessons::Lesson drift = lesson("energy_drift");
    QCOMPARE(ui::stepFolderName(drift, 0), QStringLiteral("01-four-integrators-one-spring"));
    QCOMPARE(ui::stepFolderName(drift, 3),
             QStringLiteral("04-smaller-steps-less-drift-never-none"));
    const std::vector<physics::World> worlds = lessons::buildStepWorlds(drift.steps[0]);
    QCOMPARE(ui::stepCaption(drift, 0, worlds[0].def()),
             QStringLiteral("Energy drift: four ways to take a step, step 1: Four integrators, "
                            "one spring\nintegrators Explicit Euler, Symplectic Euler, "
                            "Velocity Verlet, Runge–Kutta 4 · dt = 0.01 s"));
    const lessons::Lesson stacks = lesson("stacks");
    QCOMPARE(ui::stepCaption(stacks, 1, lessons::buildStepWorlds(stacks.steps[1])[0].def()),
             QStringLiteral("Why stacks jitter, step 2: Sequential impulses and warm starting\n"
                            "integrator Symplectic Euler · dt = 0.001 s"));
    QCOMPARE(ui::stepCaption(stacks, 0, lessons::buildStepWorlds(stacks.steps[0])[0].def()),
             QStringLiteral("Why stacks jitter, step 1: Two stacks side by side\n"
                            "integrator Symplectic Euler · solvers The paper's impulse, "
                            "Sequential impulse · dt = 0.001 s"));
}

void TestLessonExport::captionOnlyInExports()
{
    ui::PlotWidget plot(QStringLiteral("Energy"));
    plot.resize(640, 400);
    const int rows = plot.plot()->plotLayout()->rowCount();
    plot.setCaption(QStringLiteral("A lesson, step 1: a step\nintegrator verlet · dt = 0.001 s"));
    QVERIFY(!plot.captionShown());
    QCOMPARE(plot.plot()->plotLayout()->rowCount(), rows); // the screen layout is unchanged

    QTemporaryDir dir;
    const QString svg = dir.filePath(QStringLiteral("p.svg"));
    QVERIFY(ui::exportPlot(plot, svg, ui::ExportFormat::Svg).ok);
    QVERIFY(QString::fromUtf8(readAll(svg)).contains(QStringLiteral("A lesson, step 1")));
    QCOMPARE(plot.plot()->plotLayout()->rowCount(), rows); // and back after the export

    plot.setCaptionShown(true);
    QCOMPARE(plot.plot()->plotLayout()->rowCount(), rows + 1);
    plot.setCaptionShown(false);
    QCOMPARE(plot.plot()->plotLayout()->rowCount(), rows);
    plot.setCaption({});
    const QString bare = dir.filePath(QStringLiteral("bare.svg"));
    QVERIFY(ui::exportPlot(plot, bare, ui::ExportFormat::Svg).ok);
    QVERIFY(!QString::fromUtf8(readAll(bare)).contains(QStringLiteral("A lesson")));
}

void TestLessonExport::headlessSamplesAreTheWorldsOwn()
{
    // The exported numbers are the worlds' own energies, step for step: the Euler world's
    // total at t = 5 s is E0 (1 + (wh)^2)^500, and every column matches an independent run.
    const lessons::Lesson drift = lesson("energy_drift");
    QTemporaryDir dir;
    const ui::PlotFilesResult written = ui::exportStepPlots(drift, 0, dir.path());
    QVERIFY2(written.ok, qPrintable(written.error));
    QCOMPARE(written.files.size(), 8);
    const QString folder = QDir(dir.path()).filePath(ui::stepFolderName(drift, 0));
    QByteArray header;
    const auto rows = csvRows(QDir(folder).filePath(QStringLiteral("compare-energy.csv")), &header);
    QCOMPARE(header, QByteArray("t [s],euler [J],symplectic-euler [J],verlet [J],rk4 [J]"));
    QCOMPARE(rows.size(), std::size_t{1001}); // dt = 0.01 s is more than the sample interval

    std::vector<physics::World> worlds = lessons::buildStepWorlds(drift.steps[0]);
    for (physics::World& w : worlds)
        w.updateDiagnostics();
    for (std::size_t n = 0; n < rows.size(); ++n) {
        if (n > 0)
            for (physics::World& w : worlds)
                w.step();
        QCOMPARE(rows[n][0], worlds[0].time());
        for (std::size_t i = 0; i < 4; ++i)
            QCOMPARE(rows[n][i + 1], worlds[i].diagnostics().total);
    }
    RL_VERIFY_NEAR(rows[500][1] / 0.45, std::pow(1.001, 500), 1e-9, 0);

    const auto driftRows = csvRows(QDir(folder).filePath(QStringLiteral("compare-drift.csv")));
    QCOMPARE(driftRows.size(), rows.size());
    for (std::size_t n = 0; n < rows.size(); n += 100)
        RL_VERIFY_NEAR(driftRows[n][1], (rows[n][1] - 0.45) / 0.45 * 100, 1e-9, 0);
}

void TestLessonExport::headlessSamplingKeepsTheWindowsInterval()
{
    // dt = 1 ms: samples every 5 steps (the first step at least 1/240 s after the last), as
    // the window's controller takes them; the main world's energy and momentum in each.
    const lessons::Lesson bounces = lesson("restitution");
    QTemporaryDir dir;
    const ui::PlotFilesResult written = ui::exportStepPlots(bounces, 1, dir.path());
    QVERIFY2(written.ok, qPrintable(written.error));
    const QString folder = QDir(dir.path()).filePath(ui::stepFolderName(bounces, 1));
    QByteArray header;
    const auto rows = csvRows(QDir(folder).filePath(QStringLiteral("momentum.csv")), &header);
    QCOMPARE(header, QByteArray("t [s],p_x [kg m/s],p_y [kg m/s],L [kg m²/s]"));

    physics::World world = lessons::buildStepWorlds(bounces.steps[1])[0];
    world.updateDiagnostics();
    ui::SampleClock clock;
    std::vector<ui::Sample> expected;
    const ui::EnergyReference reference = ui::EnergyReference::of(world);
    if (clock.due(world.time()))
        expected.push_back(ui::makeSample(world, reference, {}, {}, false));
    for (int i = 0; i < 2000; ++i) {
        world.step();
        if (clock.due(world.time()))
            expected.push_back(ui::makeSample(world, reference, {}, {}, false));
    }
    QCOMPARE(rows.size(), expected.size());
    QCOMPARE(rows.size(), std::size_t{401});
    for (std::size_t n = 0; n < rows.size(); ++n) {
        QCOMPARE(rows[n][0], expected[n].t);
        QCOMPARE(rows[n][1], expected[n].px);
        QCOMPARE(rows[n][2], expected[n].py);
        QCOMPARE(rows[n][3], expected[n].angularMomentum);
    }
    RL_VERIFY_NEAR(rows.back()[1], 3.0, 1e-9, 0); // 1 kg at 3 m/s, all the way through
}

void TestLessonExport::exportStopsAtTheEndTime()
{
    // The step runs 2 s for its export (samples every 5 ms); told to stop at 1.2 s, as the
    // window's run stops there, its plots end there too. An end after the export time
    // changes nothing.
    lessons::Lesson bounces = lesson("restitution");
    lessons::LessonStep& step = bounces.steps[1];
    QCOMPARE(step.exportTime, 2.0);
    for (const auto& [end, rowsWanted, lastWanted] :
         {std::tuple{1.2, std::size_t{241}, 1.2}, std::tuple{5.0, std::size_t{401}, 2.0}}) {
        step.endTime = end;
        QCOMPARE(lessons::exportRunTime(step), std::min(end, 2.0));
        QTemporaryDir dir;
        const ui::PlotFilesResult written = ui::exportStepPlots(bounces, 1, dir.path());
        QVERIFY2(written.ok, qPrintable(written.error));
        const QString folder = QDir(dir.path()).filePath(ui::stepFolderName(bounces, 1));
        const auto rows = csvRows(QDir(folder).filePath(QStringLiteral("momentum.csv")));
        QCOMPARE(rows.size(), rowsWanted);
        RL_VERIFY_NEAR(rows.back()[0], lastWanted, 1e-9, 0);
    }
}

void TestLessonExport::cliExportsEveryLesson_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("language");
    const QStringList files =
        QDir(kLessonsDir).entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    QVERIFY(files.size() >= 10);
    const QStringList languages{QStringLiteral("en"), QStringLiteral("cs")};
    for (int i = 0; i < files.size(); ++i)
        for (int l = 0; l < languages.size(); ++l)
            if (test::walksLanguage(i, l, static_cast<int>(languages.size())))
                QTest::newRow(qPrintable(files[i] + u' ' + languages[l]))
                    << QDir(kLessonsDir).filePath(files[i]) << languages[l];
}

void TestLessonExport::cliExportsEveryLesson()
{
    // Every shipped lesson gives a handout in each language: at least one picture and one
    // table, each file what it says it is.
    QFETCH(QString, path);
    QFETCH(QString, language);
    const lessons::LessonLoadResult loaded =
        lessons::loadLessonFile(path, lessons::LessonLoadOptions{language});
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    QTemporaryDir dir;
    const CliRun run = runCli({QStringLiteral("lesson"), path, QStringLiteral("--export"),
                               dir.path(), QStringLiteral("--lang"), language});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QVERIFY(ui::applyLanguage(language)); // the captions compared are the language's

    int plots = 0, satSteps = 0;
    for (int i = 0; i < static_cast<int>(loaded.lesson.steps.size()); ++i) {
        const lessons::LessonStep& step = loaded.lesson.steps[static_cast<std::size_t>(i)];
        const QDir folder(QDir(dir.path()).filePath(ui::stepFolderName(loaded.lesson, i)));
        QCOMPARE(folder.exists(), !step.plots.isEmpty() || step.sat.has_value());
        if (step.sat) {
            ++satSteps;
            for (const char* name : {"sat-projections.png", "sat-projections.csv"}) {
                const QString file = folder.filePath(QLatin1StringView(name));
                const QString problem = checkFile(file, {});
                QVERIFY2(problem.isEmpty(), qPrintable(file + QStringLiteral(": ") + problem));
                QVERIFY(run.out.contains(("wrote " + file).toUtf8()));
            }
        }
        // The caption names the lesson, the step, the integrators and dt.
        const std::vector<physics::World> worlds = lessons::buildStepWorlds(step);
        const QString caption = ui::stepCaption(loaded.lesson, i, worlds[0].def());
        for (const QString& name : step.plots) {
            ++plots;
            for (const char* suffix : {".png", ".pdf", ".svg", ".csv"}) {
                const QString file = folder.filePath(name + QLatin1StringView(suffix));
                const QString problem = checkFile(file, caption);
                QVERIFY2(problem.isEmpty(), qPrintable(file + QStringLiteral(": ") + problem));
                QVERIFY(run.out.contains(("wrote " + file).toUtf8()));
            }
        }
    }
    QVERIFY(ui::applyLanguage(QStringLiteral("en")));
    // Nothing else was written: four files per plot, two per SAT step, no temporary files.
    int files = 0, pngs = 0, csvs = 0;
    QDirIterator it(dir.path(), QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString file = it.next();
        ++files;
        pngs += file.endsWith(QStringLiteral(".png")) ? 1 : 0;
        csvs += file.endsWith(QStringLiteral(".csv")) ? 1 : 0;
    }
    QCOMPARE(files, 4 * plots + 2 * satSteps);
    QVERIFY2(pngs >= 1 && csvs >= 1,
             qPrintable(QStringLiteral("%1 PNG, %2 CSV").arg(pngs).arg(csvs)));
}

void TestLessonExport::satHandoutIsTheProjections()
{
    // The SAT lesson's first step: the table's intervals are the polygons' corners projected
    // here on each axis, and the test stops where the text says, at the sixth axis of seven,
    // on a gap of 0.14 m between [−0.71, 0.71] m and [−1.41, −0.85] m.
    const lessons::Lesson sat = lesson("separating_axis");
    const lessons::LessonStep& step = sat.steps.at(0);
    QTemporaryDir dir;
    const ui::PlotFilesResult written = ui::exportSatHandout(sat, 0, dir.path());
    QVERIFY2(written.ok, qPrintable(written.error));
    QCOMPARE(written.files.size(), 2);
    const std::vector<std::vector<double>> rows =
        csvRows(QDir(dir.path()).filePath(QStringLiteral("sat-projections.csv")));
    QCOMPARE(rows.size(), std::size_t{6});
    const physics::World world = lessons::buildStepWorlds(step).front();
    const auto corners = [&](const QString& id) {
        const physics::Body& b = world.body(*step.scene.bodyIndex(id));
        std::vector<physics::Vec2> out;
        for (const physics::Vec2& v : b.shape.asPolygon()->vertices)
            out.push_back(b.transform().apply(v));
        return out;
    };
    const std::vector<physics::Vec2> a = corners(step.sat->first), b = corners(step.sat->second);
    for (const std::vector<double>& row : rows) {
        const physics::Vec2 n(row[3], row[4]);
        for (const auto& [poly, column] : {std::pair{&a, 5}, std::pair{&b, 7}}) {
            double lo = 1e300, hi = -1e300;
            for (const physics::Vec2& v : *poly) {
                lo = std::min(lo, v.dot(n));
                hi = std::max(hi, v.dot(n));
            }
            RL_VERIFY_NEAR(row[static_cast<std::size_t>(column)], lo, 1e-12, 0);
            RL_VERIFY_NEAR(row[static_cast<std::size_t>(column) + 1], hi, 1e-12, 0);
        }
        const double overlap = std::min(row[6] - row[7], row[8] - row[5]);
        RL_VERIFY_NEAR(row[9], overlap, 1e-12, 0);
        QCOMPARE(row[10], overlap < 0 ? 1.0 : 0.0);
    }
    const std::vector<double>& last = rows.back();
    RL_VERIFY_NEAR(-last[9], 0.14, 0.005, 0);
    RL_VERIFY_NEAR(last[5], -0.71, 0.005, 0);
    RL_VERIFY_NEAR(last[8], -0.85, 0.005, 0);
    QImage image;
    QVERIFY(image.load(QDir(dir.path()).filePath(QStringLiteral("sat-projections.png"))));
    QCOMPARE(image.size(), QSize(1600, 1000));
    // A step without a pair writes nothing.
    const ui::PlotFilesResult none = ui::exportSatHandout(lesson("restitution"), 0, dir.path());
    QVERIFY(none.ok && none.files.isEmpty());
}

void TestLessonExport::cliLessonErrors()
{
    QTemporaryDir dir;
    const QString good = QDir(kLessonsDir).filePath(QStringLiteral("restitution.json"));

    CliRun run = runCli({QStringLiteral("lesson")});
    QCOMPARE(run.exitCode, 2);
    QVERIFY(run.err.contains("lesson: which lesson file?"));

    run = runCli({QStringLiteral("lesson"), good, QStringLiteral("--export")});
    QCOMPARE(run.exitCode, 2);
    QVERIFY(run.err.contains("--export: needs a folder"));

    run = runCli({QStringLiteral("lesson"), good, QStringLiteral("--exprt"), dir.path()});
    QCOMPARE(run.exitCode, 2);
    QVERIFY(run.err.contains("unknown option --exprt"));

    const QString broken = dir.filePath(QStringLiteral("broken.json"));
    {
        QFile file(broken);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(
            R"({"rigidlab-lesson": 1, "title": "t", "steps": [{"title": "s", "scene": "../x.json"}]})");
    }
    run = runCli({QStringLiteral("lesson"), broken, QStringLiteral("--export"), dir.path()});
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains(("error: " + broken +
                               R"(: steps[0].scene: must not leave the lesson's folder, )"
                               R"(got "../x.json")"
                               "\n")
                                  .toUtf8()),
             run.err.constData());
    run = runCli({QStringLiteral("validate"), broken});
    QCOMPARE(run.exitCode, 2);

    // Without --export: the outline.
    run = runCli({QStringLiteral("lesson"), good});
    QCOMPARE(run.exitCode, 0);
    QVERIFY(run.out.startsWith("Bounces and collisions: the coefficient of restitution (35 min"));
    QVERIFY(run.out.contains("1. Four balls, four coefficients (plots: energy; panels: bounces; "
                             "2 question(s))"));

    // A folder that cannot be made: exit 1, naming it.
    const QString blocker = dir.filePath(QStringLiteral("file"));
    {
        QFile file(blocker);
        QVERIFY(file.open(QIODevice::WriteOnly));
    }
    run = runCli({QStringLiteral("lesson"), good, QStringLiteral("--export"),
                  blocker + QStringLiteral("/out")});
    QCOMPARE(run.exitCode, 1);
    QVERIFY2(run.err.contains("cannot make the folder"), run.err.constData());
}

void TestLessonExport::cliExportsInCzech()
{
    // `--lang cs`: the handouts' captions are the Czech ones the window would write (read back
    // from the SVG), with the decimal comma, and the tables open in a Czech spreadsheet; the
    // English run's captions are not.
    const QString path = QDir(kLessonsDir).filePath(QStringLiteral("energy_drift.json"));
    QTemporaryDir dir;
    const CliRun run = runCli({QStringLiteral("lesson"), path, QStringLiteral("--export"),
                               dir.path(), QStringLiteral("--lang"), QStringLiteral("cs")});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QVERIFY(ui::applyLanguage(QStringLiteral("cs")));
    const lessons::LessonLoadResult cs =
        lessons::loadLessonFile(path, lessons::LessonLoadOptions{QStringLiteral("cs")});
    const lessons::LessonLoadResult en =
        lessons::loadLessonFile(path, lessons::LessonLoadOptions{QStringLiteral("en")});
    QVERIFY(cs.ok && en.ok);
    int checked = 0;
    for (int i = 0; i < static_cast<int>(cs.lesson.steps.size()); ++i) {
        const lessons::LessonStep& step = cs.lesson.steps[static_cast<std::size_t>(i)];
        if (step.plots.isEmpty())
            continue;
        const std::vector<physics::World> worlds = lessons::buildStepWorlds(step);
        const QString caption = ui::stepCaption(cs.lesson, i, worlds[0].def());
        QVERIFY2(caption.contains(cs.lesson.title), qPrintable(caption));
        QVERIFY(cs.lesson.title != en.lesson.title);
        QVERIFY2(caption.contains(QStringLiteral("dt = 0,")), qPrintable(caption));
        const QDir folder(QDir(dir.path()).filePath(ui::stepFolderName(cs.lesson, i)));
        for (const QString& name : step.plots) {
            const QString svg = folder.filePath(name + QStringLiteral(".svg"));
            const QString problem = checkFile(svg, caption);
            QVERIFY2(problem.isEmpty(), qPrintable(svg + QStringLiteral(": ") + problem));
            // The table is in the Czech spreadsheet's form: a BOM, ';' and decimal commas.
            const QByteArray table = readAll(folder.filePath(name + QStringLiteral(".csv")));
            QVERIFY2(table.startsWith("\xEF\xBB\xBFt [s];"), table.left(40).constData());
            ++checked;
        }
    }
    QVERIFY(ui::applyLanguage(QStringLiteral("en")));
    QVERIFY(checked > 0);
}

RIGIDLAB_TEST_MAIN(TestLessonExport)
#include "test_lesson_export.moc"
