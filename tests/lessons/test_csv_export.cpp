// SPDX-License-Identifier: GPL-3.0-or-later
// The command line's CSV files (rigidlab-cli run --trace/--diagnostics, runScene): times as a
// person writes them on every row, both dialects read back to the same numbers by a reader set
// to their conventions, heads with units, the BOM exactly in the spreadsheet dialect, and the
// shared pieces of lessons/export (the writer, the noise floor, the step's time).

#include "build_paths.h"
#include "csv_reader.h"

#include "export/csv_columns.h"
#include "export/csv_dialect.h"
#include "export/csv_writer.h"
#include "export/noise_floor.h"
#include "export/step_time.h"
#include "format/scene_loader.h"
#include "run/scene_run.h"
#include "test_files.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <cstring>

using namespace rigidlab;
using test::readAll;
using test::readCsv;
using test::readNumber;

namespace {

const QString kScenesDir = rigidlab::test::sourcePath(u"/lessons/scenes");

lessons::Scene loadScene(const char* name)
{
    const lessons::SceneLoadResult loaded = lessons::loadSceneFile(
        QDir(kScenesDir).filePath(QLatin1StringView(name) + QStringLiteral(".json")));
    if (!loaded.ok)
        qWarning("%s", qPrintable(loaded.error));
    return loaded.scene;
}

struct Written {
    QByteArray trace;
    QByteArray diagnostics;
};

/// Runs a shipped scene for `time` s at `dt` and returns both files in `csv`'s dialect.
Written run(const char* scene, double time, double dt, const lessons::CsvConventions& csv)
{
    QTemporaryDir dir;
    lessons::RunOptions options;
    options.time = time;
    options.dt = dt;
    options.csv = csv;
    options.tracePath = dir.filePath(QStringLiteral("t.csv"));
    options.diagnosticsPath = dir.filePath(QStringLiteral("d.csv"));
    const lessons::RunReport report =
        lessons::runScene(loadScene(scene), options, QLatin1StringView(scene));
    if (report.status != lessons::RunStatus::Ok)
        qWarning("%s", qPrintable(report.error));
    return {readAll(options.tracePath), readAll(options.diagnosticsPath)};
}

bool bitwiseEqual(double a, double b)
{
    return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b));
}

} // namespace

class TestCsvExport : public QObject {
    Q_OBJECT

private slots:
    void stepTimeRule();
    void timesAsWritten_data();
    void timesAsWritten();
    void dialectsReadBackAlike();
    void headsNameUnits();
    void noiseIsWrittenAsZero();
    void writerQuotesForItsSeparator();
    void cliSpreadsheetInCzech();
};

void TestCsvExport::stepTimeRule()
{
    QCOMPARE(lessons::stepTime(9, 0.001), 0.009);
    QCOMPARE(lessons::stepTime(9, 1.0 / 60.0), 0.15);
    QCOMPARE(lessons::stepTime(9, 0.003), 0.027);
    QCOMPARE(lessons::formatCsvNumber(lessons::stepTime(7, 1.0 / 60.0)),
             lessons::formatCsvNumber(7.0 / 60.0));
    // The summed clock is far from k dt after a dt changed mid-run: the sum is kept.
    QCOMPARE(lessons::stepTime(10, 0.001, 0.5), 0.5);
    double summed = 0;
    for (int k = 0; k < 9; ++k)
        summed += 0.001;
    QVERIFY(summed != 0.009); // what the issue was: the sum carries the binary rounding
    QCOMPARE(lessons::stepTime(9, 0.001, summed), 0.009);
}

void TestCsvExport::timesAsWritten_data()
{
    QTest::addColumn<double>("dt");
    QTest::addColumn<qlonglong>("m");      // dt = m / 10^places, or 0
    QTest::addColumn<int>("places");       //
    QTest::addColumn<qlonglong>("rate");   // 1/dt, or 0
    QTest::addColumn<QString>("language"); // of the spreadsheet dialect
    for (const QString& language : {QStringLiteral("cs"), QStringLiteral("en")}) {
        QTest::addRow("1 ms %s", qPrintable(language)) << 0.001 << 1LL << 3 << 0LL << language;
        QTest::addRow("1/60 s %s", qPrintable(language))
            << 1.0 / 60.0 << 0LL << 0 << 60LL << language;
        QTest::addRow("3 ms %s", qPrintable(language)) << 0.003 << 3LL << 3 << 0LL << language;
    }
}

// 10 s runs, every row of the trace and the diagnostics, in both dialects: step k's time is
// what a person writes (worked out here in whole numbers), with the dialect's decimal sign.
void TestCsvExport::timesAsWritten()
{
    QFETCH(double, dt);
    QFETCH(qlonglong, m);
    QFETCH(int, places);
    QFETCH(qlonglong, rate);
    QFETCH(QString, language);
    for (const auto dialect : {lessons::CsvDialect::Plain, lessons::CsvDialect::Spreadsheet}) {
        const lessons::CsvConventions csv = lessons::csvConventions(dialect, language);
        const Written files = run("ball_drop", 10.0, dt, csv);
        for (const QByteArray& file : {files.trace, files.diagnostics}) {
            const test::CsvTable table = readCsv(file, csv.separator);
            const long long steps = lessons::stepsForTime(10.0, dt);
            QVERIFY2(table.rows.size() >= steps + 2,
                     qPrintable(QString::number(table.rows.size())));
            QCOMPARE(table.rows.front().at(1), QStringLiteral("t [s]"));
            int checked = 0;
            for (qsizetype r = 1; r < table.rows.size(); ++r) {
                const long long k = table.rows[r].at(0).toLongLong();
                const QString t = table.rows[r].at(1);
                std::optional<QString> expected =
                    m > 0 ? std::optional(test::decimalStepTime(k, m, places))
                          : test::rateStepTime(k, rate);
                if (expected) {
                    expected->replace(u'.', QLatin1Char(csv.decimal));
                    if (t != *expected)
                        QFAIL(qPrintable(QStringLiteral("row %1, step %2: t = %3, expected %4")
                                             .arg(r)
                                             .arg(k)
                                             .arg(t, *expected)));
                } else {
                    // k / rate has no short decimal: the nearest double, in its shortest text.
                    const auto value = readNumber(t, csv.decimal);
                    QString digits = t;
                    digits.remove(QRegularExpression(QStringLiteral("[^0-9]")));
                    digits.remove(QRegularExpression(QStringLiteral("^0+")));
                    QVERIFY2(value && *value == double(k) / double(rate) && digits.size() <= 17,
                             qPrintable(QStringLiteral("step %1: t = %2").arg(k).arg(t)));
                }
                ++checked;
            }
            QCOMPARE(checked, table.rows.size() - 1);
        }
    }
}

// The same run in each dialect, each read by a reader set to that dialect's conventions
// (Czech: ';' and the decimal comma), gives the same numbers to the last bit; the BOM is
// there exactly in the spreadsheet dialect.
void TestCsvExport::dialectsReadBackAlike()
{
    struct Case {
        lessons::CsvDialect dialect;
        QString language;
        char separator;
        char decimal;
        bool bom;
    };
    const Case cases[] = {{lessons::CsvDialect::Plain, QStringLiteral("cs"), ',', '.', false},
                          {lessons::CsvDialect::Plain, QStringLiteral("en"), ',', '.', false},
                          {lessons::CsvDialect::Spreadsheet, QStringLiteral("cs"), ';', ',', true},
                          {lessons::CsvDialect::Spreadsheet, QStringLiteral("en"), ',', '.', true}};
    QList<QList<double>> reference;
    for (const Case& c : cases) {
        const lessons::CsvConventions csv = lessons::csvConventions(c.dialect, c.language);
        QCOMPARE(csv.separator, c.separator);
        QCOMPARE(csv.decimal, c.decimal);
        const Written files = run("welcome", 2.0, 0.001, csv);
        const test::CsvTable table = readCsv(files.diagnostics, c.separator);
        QCOMPARE(table.bom, c.bom);
        QCOMPARE(readCsv(files.trace, c.separator).bom, c.bom);
        QCOMPARE(table.rows.size(), 2002);
        QList<QList<double>> numbers;
        for (qsizetype r = 1; r < table.rows.size(); ++r) {
            QCOMPARE(table.rows[r].size(), table.rows.front().size());
            QList<double> row;
            for (const QString& field : table.rows[r]) {
                const auto value = readNumber(field, c.decimal);
                QVERIFY2(value && std::isfinite(*value),
                         qPrintable(QStringLiteral("row %1: \"%2\"").arg(r).arg(field)));
                row.append(*value);
            }
            numbers.append(row);
        }
        if (reference.isEmpty()) {
            reference = numbers;
            continue;
        }
        for (qsizetype r = 0; r < numbers.size(); ++r)
            for (qsizetype f = 0; f < numbers[r].size(); ++f)
                QVERIFY2(bitwiseEqual(numbers[r][f], reference[r][f]),
                         qPrintable(QStringLiteral("row %1 field %2: %3 against %4")
                                        .arg(r)
                                        .arg(f)
                                        .arg(numbers[r][f], 0, 'g', 17)
                                        .arg(reference[r][f], 0, 'g', 17)));
    }
}

void TestCsvExport::headsNameUnits()
{
    const QRegularExpression withUnit(QStringLiteral(R"(^\S.* \[[^\]]+\]$)"));
    const QStringList counts{lessons::csvColumnHead(lessons::CsvColumn::Step),
                             lessons::csvColumnHead(lessons::CsvColumn::Body),
                             lessons::csvColumnHead(lessons::CsvColumn::Contacts)};
    for (const QStringList& heads : {lessons::traceHeader(), lessons::diagnosticsHeader()})
        for (const QString& head : heads)
            QVERIFY2(counts.contains(head) || withUnit.match(head).hasMatch(), qPrintable(head));
    QVERIFY(lessons::diagnosticsHeader().contains(QStringLiteral("E_k [J]")));
    QCOMPARE(lessons::traceHeader().at(1), QStringLiteral("t [s]"));
}

void TestCsvExport::noiseIsWrittenAsZero()
{
    // The floor the plots draw flat below: a billionth of what the quantity is worth.
    QCOMPARE(lessons::withoutNoise(2.439454888092385e-19, 30.0), 0.0);
    QCOMPARE(lessons::withoutNoise(-5e-16, 0.0), 0.0);
    QCOMPARE(lessons::withoutNoise(1e-7, 30.0), 1e-7);
    QCOMPARE(lessons::withoutNoise(-29.430000000000003, 30.0), -29.430000000000003);
    QVERIFY(std::isnan(lessons::withoutNoise(std::nan(""), 1.0)));
    QVERIFY(!std::signbit(lessons::withoutNoise(-1e-20, 1.0))); // no "-0" in a file

    // A ball falling for 0.2 s dissipates nothing: the column says 0 on every row.
    const Written files = run("ball_drop", 0.2, 0.001, {});
    const test::CsvTable table = readCsv(files.diagnostics, ',');
    const qsizetype column = table.rows.front().indexOf(QStringLiteral("E_diss [J]"));
    QVERIFY(column > 0);
    for (qsizetype r = 1; r < table.rows.size(); ++r)
        QCOMPARE(table.rows[r].at(column), QStringLiteral("0"));
}

void TestCsvExport::writerQuotesForItsSeparator()
{
    lessons::CsvWriter czech(lessons::csvConventions(lessons::CsvDialect::Spreadsheet, "cs"));
    czech.text(QStringLiteral("a,b"));
    czech.text(QStringLiteral("c;d"));
    czech.text(QStringLiteral("\"e\""));
    czech.number(-29.43);
    czech.number(std::nan(""));
    czech.integer(-7);
    czech.endRow();
    QCOMPARE(QByteArray::fromStdString(czech.data()),
             QByteArray("\xEF\xBB\xBF"
                        "a,b;\"c;d\";\"\"\"e\"\"\";-29,43;;-7\n"));
    lessons::CsvWriter plain;
    plain.text(QStringLiteral("a,b"));
    plain.number(0.1 + 0.2);
    plain.endRow();
    QCOMPARE(QByteArray::fromStdString(plain.take()), QByteArray("\"a,b\",0.30000000000000004\n"));
    plain.number(1e-5);
    plain.endRow();
    QCOMPARE(QByteArray::fromStdString(plain.data()), QByteArray("1e-05\n")); // no second BOM
    QVERIFY(!lessons::csvDialectFromName(QStringLiteral("excel")));
    QCOMPARE(*lessons::csvDialectFromName(QStringLiteral("spreadsheet")),
             lessons::CsvDialect::Spreadsheet);
}

// The program itself: --lang cs alone writes what Czech Excel opens, headed in Czech (as
// --csv-dialect spreadsheet does); --csv-dialect plain keeps the plain form with Czech heads;
// without the flags, plain English.
void TestCsvExport::cliSpreadsheetInCzech()
{
    QTemporaryDir dir;
    const QString scene = QDir(kScenesDir).filePath(QStringLiteral("ball_drop.json"));
    const auto run = [&](const QString& name, const QStringList& flags) {
        const QString path = dir.filePath(name);
        QProcess process;
        process.start(rigidlab::test::cliPath(),
                      QStringList{"run", scene, "--time", "0.01", "--diagnostics", path} + flags);
        const bool finished = process.waitForFinished(60'000);
        return finished && process.exitCode() == 0 ? readAll(path) : QByteArray();
    };
    const QByteArray czech = run("cs.csv", {"--lang", "cs"});
    const QByteArray asked = run("asked.csv", {"--csv-dialect", "spreadsheet", "--lang", "cs"});
    const QByteArray czechPlain = run("cs-plain.csv", {"--lang", "cs", "--csv-dialect", "plain"});
    const QByteArray plain = run("plain.csv", {});
    QVERIFY(!czech.isEmpty() && !plain.isEmpty() && !czechPlain.isEmpty());
    QCOMPARE(czech, asked);

    const test::CsvTable cs = readCsv(czech, ';');
    QVERIFY(cs.bom);
    QCOMPARE(cs.rows.front().join(u'|'),
             QStringLiteral("krok|t [s]|E_k [J]|E_p [J]|E [J]|p_x [kg m/s]|p_y [kg m/s]|"
                            "L [kg m²/s]|kontakty|E_diss [J]|drift [1]"));
    QCOMPARE(cs.rows.at(10).at(1), QStringLiteral("0,009"));
    const test::CsvTable csPlain = readCsv(czechPlain, ',');
    QVERIFY(!csPlain.bom);
    QCOMPARE(csPlain.rows.front().at(0), QStringLiteral("krok"));
    QCOMPARE(csPlain.rows.at(10).at(1), QStringLiteral("0.009"));
    const test::CsvTable en = readCsv(plain, ',');
    QVERIFY(!en.bom);
    QCOMPARE(en.rows.front().at(0), QStringLiteral("step"));
    QCOMPARE(en.rows.at(10).at(1), QStringLiteral("0.009"));
    QCOMPARE(cs.rows.size(), en.rows.size());
}

QTEST_GUILESS_MAIN(TestCsvExport)
#include "test_csv_export.moc"
