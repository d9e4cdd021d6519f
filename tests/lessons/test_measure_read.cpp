// SPDX-License-Identifier: GPL-3.0-or-later
// Reading measurements: every layout the lab reads, and damaged files refused with the line
// and the column named.
#include "test_main.h"
#include "test_measure.h"

#include "measure/measurement.h"

#include <QDir>
#include <QTest>

#include <cmath>

using namespace rigidlab;
using measure::Layout;
using measure::Quantity;

void TestMeasure::readsLayouts_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("layout");
    QTest::addColumn<int>("quantity");
    QTest::addColumn<int>("points");
    QTest::addColumn<double>("firstT");
    QTest::addColumn<double>("firstValue");
    QTest::addColumn<double>("lastT");
    // Each sample: its layout, the quantity fitted, the number of its points, and its first
    // and last points in the lab's units (read by eye from the file).
    QTest::newRow("tracker-comma") << "ball_tracker.csv" << int(Layout::Tracker) << int(Quantity::Y)
                                   << 97 << 0.0 << 1.0474 << 1.6;
    QTest::newRow("tracker-tab-decimal-comma") << "box_tracker_cs.txt" << int(Layout::Tracker)
                                               << int(Quantity::X) << 61 << 0.0 << -1.0017 << 1.0;
    QTest::newRow("phyphox-comma") << "ball_phyphox.csv" << int(Layout::Phyphox) << int(Quantity::Y)
                                   << 97 << 0.0 << 1.0474 << 1.6;
    QTest::newRow("phyphox-semicolon-cm") << "box_phyphox_cs.csv" << int(Layout::Phyphox)
                                          << int(Quantity::X) << 61 << 0.0 << -1.0017 << 1.0;
    QTest::newRow("plain-two") << "ball_plain.csv" << int(Layout::Plain) << int(Quantity::Y) << 97
                               << 0.0 << 1.0474 << 1.6;
    QTest::newRow("plain-three") << "box_plain.csv" << int(Layout::Plain) << int(Quantity::X) << 61
                                 << 0.0 << -1.0017 << 1.0;
}

void TestMeasure::readsLayouts()
{
    QFETCH(QString, file);
    QFETCH(int, layout);
    QFETCH(int, quantity);
    QFETCH(int, points);
    QFETCH(double, firstT);
    QFETCH(double, firstValue);
    QFETCH(double, lastT);
    const auto r = measure::readMeasurementFile(QDir(test::kMeasureSamples).filePath(file));
    QVERIFY2(r.ok, qPrintable(r.error));
    QCOMPARE(int(r.measurement.layout), layout);
    const measure::Series* s = r.measurement.find(Quantity(quantity));
    QVERIFY(s);
    QCOMPARE(int(s->t.size()), points);
    QCOMPARE(s->t.front(), firstT);
    QVERIFY2(
        std::abs(s->value.front() - firstValue) < 1e-4,
        qPrintable(
            QStringLiteral("first value %1, expected %2").arg(s->value.front()).arg(firstValue)));
    QVERIFY2(std::abs(s->t.back() - lastT) < 1e-9,
             qPrintable(QStringLiteral("last time %1, expected %2").arg(s->t.back()).arg(lastT)));
    for (std::size_t i = 1; i < s->t.size(); ++i)
        QVERIFY(s->t[i] > s->t[i - 1]);
}

void TestMeasure::refusesDamaged_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("message");
    QTest::newRow("empty") << "empty.csv"
                           << "empty.csv: the file is empty";
    QTest::newRow("no-numbers") << "no_numbers.csv"
                                << "no_numbers.csv: no row of numbers (a measurement has a number "
                                   "in every column of its rows)";
    QTest::newRow("one-column") << "one_column.csv"
                                << "one_column.csv: line 2: only one column; a time series needs "
                                   "the time and a measured value (or read it as bounce times)";
    QTest::newRow("time-backwards")
        << "time_backwards.csv"
        << "time_backwards.csv: line 5, column 1 (\"t\"): the time 0.15 is not after 0.2 on line 4 "
           "(time must rise from row to row)";
    QTest::newRow("nan") << "nan.csv"
                         << "nan.csv: line 3, column 2 (\"y\"): \"NaN\" is not a finite number";
    QTest::newRow("inf") << "inf.csv"
                         << "inf.csv: line 3, column 2 (\"y\"): \"inf\" is not a finite number";
    QTest::newRow("ragged") << "ragged.csv"
                            << "ragged.csv: line 3: 3 values where the header (or the first row) "
                               "has 2: a ragged row";
    QTest::newRow("not-a-number")
        << "not_a_number.csv"
        << "not_a_number.csv: line 3, column 2 (\"y\"): \"0.9x\" is not a number";
    QTest::newRow("binary") << "binary.csv"
                            << "binary.csv: line 3: binary data (byte 0), not text";
    QTest::newRow("time-missing")
        << "time_missing.csv"
        << "time_missing.csv: line 3, column 1 (\"t\"): the time is missing";
    QTest::newRow("unknown-unit") << "unknown_unit.csv"
                                  << "unknown_unit.csv: column 2 (\"Height\"): unknown unit \"px\" "
                                     "for y (expected m, cm, mm, "
                                     "or set the unit)";
    QTest::newRow("header-mismatch")
        << "header_mismatch.csv"
        << "header_mismatch.csv: line 2: the header names 3 columns, the rows below it have 2";
    QTest::newRow("two-heights")
        << "two_heights.csv"
        << "two_heights.csv: column 2 (\"y\") and column 3 (\"height\") both hold y: map one "
           "of them";
    QTest::newRow("open-quote") << "open_quote.csv"
                                << "open_quote.csv: line 1: a quote (\") is not closed";
}

void TestMeasure::refusesDamaged()
{
    QFETCH(QString, file);
    QFETCH(QString, message);
    const QString path = QDir(test::kMeasureDamaged).filePath(file);
    const auto r = measure::readMeasurementFile(path);
    QVERIFY(!r.ok);
    QCOMPARE(r.error, path.left(path.size() - file.size()) + message);
    QVERIFY(!r.error.contains(u'\n'));
}

void TestMeasure::refusesMillionRows()
{
    // 10⁶ rows: the reader stops at the limit, at the line past it.
    QByteArray bytes = "t,y\n";
    bytes.reserve(12'000'000);
    for (int i = 0; i < 1'000'000; ++i)
        bytes += QByteArray::number(i) + ",1\n";
    const auto r = measure::readTable(bytes, QStringLiteral("big.csv"));
    QVERIFY(!r.ok);
    QCOMPARE(r.error, QStringLiteral("big.csv: line %1: more than %2 rows of numbers (the limit)")
                          .arg(measure::kMaxRows + 2)
                          .arg(measure::kMaxRows));
    // At the limit itself it reads.
    QByteArray limit = "t,y\n";
    for (int i = 0; i < measure::kMaxRows; ++i)
        limit += QByteArray::number(i) + ",1\n";
    const auto ok = measure::readTable(limit, QStringLiteral("limit.csv"));
    QVERIFY2(ok.ok, qPrintable(ok.error));
    QCOMPARE(ok.table.rows(), measure::kMaxRows);
}

void TestMeasure::refusesTooLarge()
{
    const QByteArray bytes(measure::kMaxFileBytes + 1, '1');
    const auto r = measure::readTable(bytes, QStringLiteral("huge.csv"));
    QVERIFY(!r.ok);
    QCOMPARE(r.error, QStringLiteral("huge.csv: larger than 16 MB (the limit)"));
}

void TestMeasure::unitsAndOffsets()
{
    // Milliseconds and centimetres from the header; time zero and origin in lab units.
    const QByteArray bytes = "t (ms),x (cm),y [mm]\n0,10,500\n100,20,400\n200,30,300\n";
    const auto table = measure::readTable(bytes, QStringLiteral("u.csv"));
    QVERIFY2(table.ok, qPrintable(table.error));
    measure::MeasurementOptions options;
    options.timeZero = 0.1;
    options.originX = 0.05;
    options.originY = -1.0;
    const auto r = measure::toMeasurement(table.table, QStringLiteral("u.csv"), options);
    QVERIFY2(r.ok, qPrintable(r.error));
    QCOMPARE(r.measurement.rowsBeforeStart, 1);
    const measure::Series* x = r.measurement.find(Quantity::X);
    const measure::Series* y = r.measurement.find(Quantity::Y);
    QVERIFY(x && y);
    QCOMPARE(int(x->t.size()), 2);
    QVERIFY(std::abs(x->t[0]) < 1e-12 && std::abs(x->t[1] - 0.1) < 1e-12);
    QVERIFY(std::abs(x->value[0] - 0.15) < 1e-12 && std::abs(x->value[1] - 0.25) < 1e-12);
    QVERIFY(std::abs(y->value[0] - 1.4) < 1e-12 && std::abs(y->value[1] - 1.3) < 1e-12);
    QCOMPARE(x->lines, (std::vector<int>{3, 4}));
    // A unit set by hand wins over the header's.
    options = {};
    options.lengthScale = 1.0;
    const auto raw = measure::toMeasurement(table.table, QStringLiteral("u.csv"), options);
    QVERIFY(raw.ok);
    QCOMPARE(raw.measurement.find(Quantity::X)->value[0], 10.0);
}

void TestMeasure::explicitMapping()
{
    const QByteArray bytes = "a;b;c\n0;1,5;2\n1;2,5;3\n";
    const auto table = measure::readTable(bytes, QStringLiteral("m.csv"));
    QVERIFY2(table.ok, qPrintable(table.error));
    QVERIFY(table.table.decimalComma);
    QCOMPARE(table.table.separator, QChar(u';'));
    // Unknown names: nothing guessed, so no time column.
    const auto guessed = measure::toMeasurement(table.table, QStringLiteral("m.csv"));
    QVERIFY(!guessed.ok);
    QCOMPARE(guessed.error,
             QStringLiteral("m.csv: no column holds the time (name it t or Time (s), "
                            "or map a column to it)"));
    measure::MeasurementOptions options;
    options.mapping = {Quantity::Time, Quantity::Speed, Quantity::Ignored};
    const auto r = measure::toMeasurement(table.table, QStringLiteral("m.csv"), options);
    QVERIFY2(r.ok, qPrintable(r.error));
    QCOMPARE(r.measurement.find(Quantity::Speed)->value, (std::vector<double>{1.5, 2.5}));
    options.mapping = {Quantity::Time, Quantity::Y, Quantity::Y};
    const auto twice = measure::toMeasurement(table.table, QStringLiteral("m.csv"), options);
    QCOMPARE(twice.error,
             QStringLiteral(
                 "m.csv: column 2 (\"b\") and column 3 (\"c\") both hold y: map one of them"));
    options.mapping = {Quantity::Time};
    const auto shortMap = measure::toMeasurement(table.table, QStringLiteral("m.csv"), options);
    QCOMPARE(shortMap.error, QStringLiteral("m.csv: the mapping names 1 columns, the file has 3"));
}

void TestMeasure::bounceTimesOnly()
{
    measure::MeasurementOptions options;
    options.bounceTimesOnly = true;
    const auto r = measure::readMeasurementFile(
        QDir(test::kMeasureSamples).filePath(QStringLiteral("ball_bounces_phyphox.csv")), options);
    QVERIFY2(r.ok, qPrintable(r.error));
    QCOMPARE(int(r.measurement.bounces.size()), 8);
    QCOMPARE(r.measurement.bounces.front(), 0.4518);
    // Empty cells in a bounce column are left out; a time column is still read.
    const QByteArray bytes = "t,bounce\n0,0.45\n0.5,\n1.0,1.18\n";
    const auto table = measure::readTable(bytes, QStringLiteral("b.csv"));
    QVERIFY(table.ok);
    const auto b = measure::toMeasurement(table.table, QStringLiteral("b.csv"), options);
    QVERIFY2(b.ok, qPrintable(b.error));
    QCOMPARE(b.measurement.bounces, (std::vector<double>{0.45, 1.18}));
    // A file of positions holds the time of every frame, not bounce times: refused, where a
    // time column alone is still read as bounce times.
    const auto positions = measure::readMeasurementFile(
        QDir(test::kMeasureSamples).filePath(QStringLiteral("ball_tracker.csv")), options);
    QVERIFY(!positions.ok);
    QVERIFY2(positions.error.contains(QStringLiteral("holds the time of every frame, not "
                                                     "bounce times")),
             qPrintable(positions.error));
    const auto alone = measure::readTable("t\n0.45\n1.18\n1.7\n", QStringLiteral("t.csv"));
    QVERIFY(alone.ok);
    QVERIFY(measure::toMeasurement(alone.table, QStringLiteral("t.csv"), options).ok);
    // Time zero so far off that the times round together: said, not taken for time going back.
    measure::MeasurementOptions far;
    far.timeZero = -1e300;
    const auto rounded = measure::readMeasurementFile(
        QDir(test::kMeasureSamples).filePath(QStringLiteral("ball_tracker.csv")), far);
    QVERIFY(!rounded.ok);
    QVERIFY2(rounded.error.contains(QStringLiteral("time zero (-1e+300 s) is so far from the "
                                                   "file's times that they cannot be told "
                                                   "apart")),
             qPrintable(rounded.error));
}
