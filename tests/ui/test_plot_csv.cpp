// SPDX-License-Identifier: GPL-3.0-or-later
// The window's CSV: a plot's data exported (and a lesson's handouts, which go the same way)
// with times as a person writes them on every row of 10 s runs, in both dialects, read back
// alike; the dialog proposes a name, offers the dialect and remembers it; Ctrl+C copies the
// data shown as tab-separated text in the language's number format.

#include "build_paths.h"
#include "common/export_folder.h"
#include "common/language.h"
#include "panels/fitting_table.h"
#include "plots/plot_export.h"
#include "plots/plot_exporter.h"
#include "plots/plot_table.h"
#include "plots/plot_widget.h"
#include "simulation/step_sampler.h"

#include "format/scene_loader.h"
#include "run/scene_run.h"

#include <QApplication>
#include <QClipboard>
#include <QDir>
#include <QFileDialog>
#include <QLineEdit>
#include <QSettings>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

#include "csv_reader.h"
#include "sourced_plot.h"
#include "test_files.h"
#include "test_main.h"

#include <cmath>
#include <memory>

using namespace rigidlab;
using namespace rigidlab::ui;
using test::readAll;
using test::readCsv;
using test::readNumber;

namespace {

/// Runs a shipped scene for `seconds` at `dt`, sampled as the window samples it, into `plot`.
void runInto(test::SourcedPlot& sourced, const char* scene, double dt, double seconds)
{
    const lessons::SceneLoadResult loaded =
        lessons::loadSceneFile(rigidlab::test::sourcePath(u"/lessons/scenes/") +
                               QLatin1StringView(scene) + QStringLiteral(".json"));
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    lessons::Scene settings = loaded.scene;
    settings.world.dt = dt;
    physics::World world = lessons::buildWorld(settings);
    world.updateDiagnostics();
    const EnergyReference reference = EnergyReference::of(world);
    sourced.plot->model().setRangeMode(RangeMode::WholeRun);
    SampleClock clock;
    const long long steps = lessons::stepsForTime(seconds, dt);
    for (long long k = 0; k <= steps; ++k) {
        if (k > 0)
            world.step();
        if (clock.due(stepTime(world)))
            sourced.buffer.push(makeSample(world, reference, {}, {}, false));
        if (sourced.buffer.written() % 1000 == 0)
            sourced.plot->drain();
    }
    sourced.plot->drain();
}

/// Answers the next file dialog: notes the name it proposes and the filter it selected, picks
/// the filter `filter` (if not empty) and saves as `path`.
void answerDialog(QString* proposed, QString* selectedFilter, const QString& path,
                  const QString& filter = {})
{
    QTimer::singleShot(0, [=] {
        auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
        if (!dialog) {
            answerDialog(proposed, selectedFilter, path, filter);
            return;
        }
        auto* name = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"));
        *proposed = name ? name->text() : QString();
        *selectedFilter = dialog->selectedNameFilter();
        if (path.isEmpty()) {
            dialog->reject();
            return;
        }
        if (!filter.isEmpty())
            dialog->selectNameFilter(filter);
        if (name)
            name->setText(path);
        static_cast<QDialog*>(dialog)->accept();
    });
}

} // namespace

class TestPlotCsv : public QObject {
    Q_OBJECT
private slots:
    void timesAsWritten_data();
    void timesAsWritten();
    void dialogProposesAndRemembers();
    void copyIsTabSeparatedInTheLanguage();
    void tableReadoutInBothDialects();
};

void TestPlotCsv::timesAsWritten_data()
{
    QTest::addColumn<double>("dt");
    QTest::addColumn<qlonglong>("m");    // dt = m / 10^places, or 0
    QTest::addColumn<int>("places");     //
    QTest::addColumn<qlonglong>("rate"); // 1/dt, or 0
    QTest::newRow("1 ms") << 0.001 << 1LL << 3 << 0LL;
    QTest::newRow("1/60 s") << 1.0 / 60.0 << 0LL << 0 << 60LL;
    QTest::newRow("3 ms") << 0.003 << 3LL << 3 << 0LL;
}

// Every row of a 10 s run's energy CSV, in the plain dialect and Czech's spreadsheet one: t is
// step k's time as a person writes it; both read back, each by its conventions, to the same
// numbers; the heads name units; the BOM is there in the spreadsheet dialect alone.
void TestPlotCsv::timesAsWritten()
{
    QFETCH(double, dt);
    QFETCH(qlonglong, m);
    QFETCH(int, places);
    QFETCH(qlonglong, rate);
    test::SourcedPlot sourced(makeEnergyPlot(nullptr));
    runInto(sourced, "ball_drop", dt, 10.0);
    QTemporaryDir dir;
    QList<QList<double>> first;
    for (const auto dialect : {lessons::CsvDialect::Plain, lessons::CsvDialect::Spreadsheet}) {
        ExportOptions options;
        options.csv = lessons::csvConventions(dialect, QStringLiteral("cs"));
        const QString path = dir.filePath(lessons::csvDialectName(dialect) + ".csv");
        QVERIFY(exportPlot(*sourced.plot, path, ExportFormat::Csv, options).ok);
        const test::CsvTable table = readCsv(readAll(path), options.csv.separator);
        QCOMPARE(table.bom, dialect == lessons::CsvDialect::Spreadsheet);
        QCOMPARE(table.rows.front().join(u'|'),
                 QStringLiteral("t [s]|E_k [J]|E_p [J]|E [J]|E_diss [J]|E + E_diss [J]"));
        // A sample on the first step at least 1/240 s after the last one: 10 s of them.
        const double stride = std::max(1.0, std::ceil(kSampleInterval / dt - 1e-9));
        const double perSecond = 1.0 / (stride * dt);
        QVERIFY2(table.rows.size() > 10 * perSecond * 0.95,
                 qPrintable(QString::number(table.rows.size())));
        QList<QList<double>> numbers;
        for (qsizetype r = 1; r < table.rows.size(); ++r) {
            const QString t = table.rows[r].front();
            const auto value = readNumber(t, options.csv.decimal);
            QVERIFY2(value, qPrintable(t));
            const auto k = std::llround(*value / dt);
            std::optional<QString> expected =
                m > 0 ? std::optional(test::decimalStepTime(k, m, places))
                      : test::rateStepTime(k, rate);
            if (expected) {
                expected->replace(u'.', QLatin1Char(options.csv.decimal));
                if (t != *expected)
                    QFAIL(qPrintable(QStringLiteral("row %1: t = %2, step %3 is at %4")
                                         .arg(r)
                                         .arg(t)
                                         .arg(k)
                                         .arg(*expected)));
            } else {
                QVERIFY2(*value == double(k) / double(rate), qPrintable(t));
            }
            QList<double> row;
            for (const QString& field : table.rows[r]) {
                const auto number = readNumber(field, options.csv.decimal);
                QVERIFY2(number, qPrintable(field));
                row.append(*number);
            }
            numbers.append(row);
        }
        if (first.isEmpty())
            first = numbers;
        else
            QVERIFY(numbers == first); // the same doubles, whatever the dialect
    }
}

void TestPlotCsv::dialogProposesAndRemembers()
{
    QSettings().remove(QLatin1String(kCsvDialectKey));
    QCOMPARE(windowCsvDialect(), lessons::CsvDialect::Spreadsheet);
    test::SourcedPlot sourced(makeEnergyPlot(nullptr));
    runInto(sourced, "ball_drop", 0.001, 0.5);
    sourced.plot->exporter().setContext(QStringLiteral("Pád míče"));
    QCOMPARE(sourced.plot->exporter().proposedFileName(ExportFormat::Csv),
             QStringLiteral("pad_mice_energy_en.csv"));

    QTemporaryDir dir;
    QString proposed, selected;
    const QString spreadsheetFile = dir.filePath(QStringLiteral("a.csv"));
    answerDialog(&proposed, &selected, spreadsheetFile);
    QCOMPARE(sourced.plot->exporter().exportInteractively(ExportFormat::Csv), spreadsheetFile);
    QCOMPARE(proposed, QStringLiteral("pad_mice_energy_en.csv"));
    QCOMPARE(selected, csvFilterFor(lessons::CsvDialect::Spreadsheet)); // says which
    QVERIFY(readAll(spreadsheetFile).startsWith("\xEF\xBB\xBF"));

    // Plain chosen once is remembered: the next dialog starts with it.
    const QString plainFile = dir.filePath(QStringLiteral("b.csv"));
    answerDialog(&proposed, &selected, plainFile, csvFilterFor(lessons::CsvDialect::Plain));
    QCOMPARE(sourced.plot->exporter().exportInteractively(ExportFormat::Csv), plainFile);
    QVERIFY(readAll(plainFile).startsWith("t [s],"));
    QCOMPARE(windowCsvDialect(), lessons::CsvDialect::Plain);
    answerDialog(&proposed, &selected, QString());
    sourced.plot->exporter().exportInteractively(ExportFormat::Csv);
    QCOMPARE(selected, csvFilterFor(lessons::CsvDialect::Plain));
    QSettings().remove(QLatin1String(kCsvDialectKey));
    QSettings().remove(QLatin1String(kExportFolderKey));
}

void TestPlotCsv::copyIsTabSeparatedInTheLanguage()
{
    test::SourcedPlot sourced(makeMomentumPlot(nullptr));
    runInto(sourced, "ball_drop", 0.001, 0.5);
    QVERIFY(applyLanguage(QStringLiteral("cs")));
    sourced.plot->exporter().copyData();
    QVERIFY(applyLanguage(QStringLiteral("en")));
    const test::CsvTable table = readCsv(QApplication::clipboard()->text().toUtf8(), '\t');
    QVERIFY(!table.bom);
    QCOMPARE(table.rows.front().join(u'|'),
             QStringLiteral("t [s]|p_x [kg m/s]|p_y [kg m/s]|L [kg m²/s]"));
    QVERIFY(table.rows.size() > 10);
    // Row 3 is step 10 (a sample every 1/240 s at 1 ms steps: 0, 5, 10 ms): 0,01 in Czech.
    QCOMPARE(table.rows.at(3).front(), QStringLiteral("0,01"));
    const auto py = readNumber(table.rows.at(3).at(2), ',');
    QVERIFY(py && *py < 0); // falling
}

// A lesson's readout table: its CSV in either dialect reads back to the same numbers, and
// Ctrl+C copies it tab-separated with the language's decimal sign.
void TestPlotCsv::tableReadoutInBothDialects()
{
    CsvTable csv;
    csv.headers = {QStringLiteral("bounce"), QStringLiteral("h [m]"), QStringLiteral("e; ratio")};
    csv.rows = {{QStringLiteral("1"), csvNumber(0.1 + 0.2), csvNumber(0.75)},
                {QStringLiteral("2"), csvNumber(-29.43), QString()}};
    const QByteArray plain = csvBytes(csv);
    const QByteArray czech =
        csvBytes(csv, lessons::csvConventions(lessons::CsvDialect::Spreadsheet, "cs"));
    QVERIFY(!plain.startsWith("\xEF\xBB\xBF"));
    QVERIFY(czech.startsWith("\xEF\xBB\xBF"));
    const test::CsvTable p = readCsv(plain, ',');
    const test::CsvTable c = readCsv(czech, ';');
    QCOMPARE(c.rows.front().at(2), QStringLiteral("e; ratio")); // quoted, read back whole
    QCOMPARE(c.rows.at(1).at(1), QStringLiteral("0,30000000000000004"));
    for (int r = 1; r < 3; ++r)
        for (int f = 0; f < 3; ++f) {
            const auto a = readNumber(p.rows[r][f], '.');
            const auto b = readNumber(c.rows[r][f], ',');
            QVERIFY(a && b);
            QVERIFY((std::isnan(*a) && std::isnan(*b)) || *a == *b);
        }

    FittingTable table;
    table.setCsv(csv, QStringLiteral("bounces"));
    QVERIFY(applyLanguage(QStringLiteral("cs")));
    table.copyData();
    QVERIFY(applyLanguage(QStringLiteral("en")));
    const test::CsvTable copied = readCsv(QApplication::clipboard()->text().toUtf8(), '\t');
    QCOMPARE(copied.rows.at(2).at(1), QStringLiteral("-29,43"));
}

RIGIDLAB_TEST_MAIN(TestPlotCsv)
#include "test_plot_csv.moc"
