// SPDX-License-Identifier: GPL-3.0-or-later
// Numbers for people (common/number_format.h): fixed notation in the range a lab shows,
// rounding noise as 0 against the quantity's scale, large values with scaled units or a power
// of ten, the locale's decimal separator; and every text reads back as the value it shows.
// The status bar's energy numbers likewise (common/status_text.h): what the contacts took
// against the scene's energy, and the integrator's error estimate as a power of ten.

#include "common/number_format.h"
#include "common/status_text.h"

#include <QLocale>
#include <QRandomGenerator>
#include <QtTest>

#include "test_main.h"

#include <cmath>
#include <limits>
#include <numbers>

using namespace rigidlab::ui;

namespace {

const QString kNbsp(QChar(0x00A0));

} // namespace

class TestNumberFormat : public QObject {
    Q_OBJECT
private slots:
    void readable_data();
    void readable();
    void quantity_data();
    void quantity();
    void readsBackAsShown();
    void powerOfTen_data();
    void powerOfTen();
    void dissipated_data();
    void dissipated();
    void estimate_data();
    void estimate();
};

void TestNumberFormat::readable_data()
{
    QTest::addColumn<QString>("locale");
    QTest::addColumn<double>("value");
    QTest::addColumn<int>("significant");
    QTest::addColumn<double>("scale");
    QTest::addColumn<QString>("shown");
    const double pi = std::numbers::pi;
    const QString en = QStringLiteral("en_US"), cs = QStringLiteral("cs_CZ");
    // Rounding noise against the quantity's scale reads 0, never "-0".
    QTest::newRow("box lying flat") << en << 4.146e-7 << 4 << pi << QStringLiteral("0");
    QTest::newRow("cart never turned") << en << -3.681e-19 << 4 << pi << QStringLiteral("0");
    QTest::newRow("noise, no scale") << cs << -1.18e-18 << 4 << 0.0 << QStringLiteral("0");
    QTest::newRow("below the last digit") << en << -0.0004 << 4 << 1.0 << QStringLiteral("0");
    QTest::newRow("at the last digit") << en << -0.0006 << 4 << 1.0 << QStringLiteral("-0.001");
    QTest::newRow("zero") << en << 0.0 << 4 << 0.0 << QStringLiteral("0");
    QTest::newRow("negative zero") << en << -0.0 << 4 << 1.0 << QStringLiteral("0");
    // Fixed notation, trailing zeros dropped, the locale's separator, no grouping.
    QTest::newRow("percent, Czech") << cs << 1040.0 << 3 << 0.0 << QStringLiteral("1040");
    QTest::newRow("half, Czech") << cs << 0.5 << 4 << 0.0 << QStringLiteral("0,5");
    QTest::newRow("four digits") << en << 12.3456 << 4 << 0.0 << QStringLiteral("12.35");
    QTest::newRow("small") << en << 0.0012345 << 3 << 0.0 << QStringLiteral("0.00123");
    QTest::newRow("tiny drift") << en << 2e-6 << 3 << 0.0 << QStringLiteral("0.000002");
    QTest::newRow("whole hundred") << en << 100.0 << 4 << 0.0 << QStringLiteral("100");
    QTest::newRow("rounds up a digit") << en << 9.99996 << 4 << 0.0 << QStringLiteral("10");
    QTest::newRow("against its scale") << cs << 1.23456 << 4 << 100.0 << QStringLiteral("1,2");
    // Beyond the plain range: a power of ten, not "1,04E+03".
    QTest::newRow("million") << en << 1234567.0 << 3 << 0.0 << QStringLiteral("1.23 × 10⁶");
    QTest::newRow("mantissa rounds up") << en << 9999999.0 << 3 << 0.0 << QStringLiteral("1 × 10⁷");
    QTest::newRow("billion, Czech") << cs << 1.5e9 << 3 << 0.0 << QStringLiteral("1,5 × 10⁹");
    QTest::newRow("not a number") << en << std::numeric_limits<double>::quiet_NaN() << 4 << 0.0
                                  << QStringLiteral("–");
    QTest::newRow("infinite") << en << std::numeric_limits<double>::infinity() << 4 << 0.0
                              << QStringLiteral("–");
}

void TestNumberFormat::readable()
{
    QFETCH(QString, locale);
    QFETCH(double, value);
    QFETCH(int, significant);
    QFETCH(double, scale);
    QFETCH(QString, shown);
    QCOMPARE(formatReadable(value, significant, scale, QLocale(locale)), shown);
}

void TestNumberFormat::quantity_data()
{
    QTest::addColumn<QString>("locale");
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("unit");
    QTest::addColumn<QString>("shown");
    const QString en = QStringLiteral("en_US"), cs = QStringLiteral("cs_CZ");
    QTest::newRow("kilojoules") << en << 12346.0 << QStringLiteral("J") << "12.35" + kNbsp + "kJ";
    QTest::newRow("megajoules, Czech")
        << cs << 2.5e6 << QStringLiteral("J") << "2,5" + kNbsp + "MJ";
    QTest::newRow("kilometres") << en << 20000.0 << QStringLiteral("m") << "20" + kNbsp + "km";
    QTest::newRow("below 10 000: as it is")
        << en << 9876.0 << QStringLiteral("J") << "9876" + kNbsp + "J";
    QTest::newRow("percent: no prefix")
        << cs << 1040.0 << QStringLiteral("%") << "1040" + kNbsp + "%";
    QTest::newRow("large percent")
        << en << 1234567.0 << QStringLiteral("%") << "1.235 × 10⁶" + kNbsp + "%";
    QTest::newRow("speed: no prefix")
        << en << 12345.0 << QStringLiteral("m/s") << "12345" + kNbsp + "m/s";
    QTest::newRow("tiny energy") << en << 5e-7 << QStringLiteral("J") << "0.0000005" + kNbsp + "J";
    QTest::newRow("no unit") << en << 0.25 << QString() << QStringLiteral("0.25");
}

void TestNumberFormat::quantity()
{
    QFETCH(QString, locale);
    QFETCH(double, value);
    QFETCH(QString, unit);
    QFETCH(QString, shown);
    QCOMPARE(formatQuantity(value, unit, 4, 0, QLocale(locale)), shown);
}

void TestNumberFormat::readsBackAsShown()
{
    // Any value of the plain range, in either language, reads back (as the number fields
    // read it) within half of its last digit, and is never written with an exponent.
    QRandomGenerator random(27);
    for (const QString& name : {QStringLiteral("en_US"), QStringLiteral("cs_CZ")}) {
        const QLocale locale(name);
        for (int i = 0; i < 2000; ++i) {
            const double magnitude = std::pow(10.0, -5.0 + random.bounded(11.0));
            const double v =
                (random.bounded(2) ? -1 : 1) * magnitude * (1.0 + random.bounded(8.99));
            if (std::abs(v) >= kPlainUpTo)
                continue;
            const QString text = formatReadable(v, 4, 0, locale);
            QVERIFY2(!text.contains(u'e', Qt::CaseInsensitive), qPrintable(text));
            bool ok = false;
            const double back = locale.toDouble(text, &ok);
            QVERIFY2(ok, qPrintable(text));
            const int decimals = std::clamp(
                4 - 1 - static_cast<int>(std::floor(std::log10(std::abs(v)))), 0, kMostDecimals);
            const double halfDigit = 0.5 * std::pow(10.0, -decimals) * (1 + 1e-9);
            QVERIFY2(std::abs(back - v) <= halfDigit,
                     qPrintable(QStringLiteral("%1 shown as %2, read back as %3 (tolerance %4)")
                                    .arg(v, 0, 'g', 17)
                                    .arg(text)
                                    .arg(back, 0, 'g', 17)
                                    .arg(halfDigit)));
        }
    }
}

void TestNumberFormat::powerOfTen_data()
{
    QTest::addColumn<QString>("locale");
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("shown");
    const QString en = QStringLiteral("en_US"), cs = QStringLiteral("cs_CZ");
    QTest::newRow("small, Czech") << cs << 1.234e-7 << QStringLiteral("1,23 × 10⁻⁷");
    QTest::newRow("small") << en << 1.234e-7 << QStringLiteral("1.23 × 10⁻⁷");
    QTest::newRow("negative") << en << -5e-12 << QStringLiteral("-5 × 10⁻¹²");
    QTest::newRow("mantissa rounds up") << cs << 9.999e-5 << QStringLiteral("1 × 10⁻⁴");
    QTest::newRow("no power for 1 to 10") << cs << 2.5 << QStringLiteral("2,5");
    QTest::newRow("large") << en << 3.0e9 << QStringLiteral("3 × 10⁹");
    QTest::newRow("zero") << en << 0.0 << QStringLiteral("0");
    QTest::newRow("not a number") << en << std::numeric_limits<double>::quiet_NaN()
                                  << QStringLiteral("–");
}

void TestNumberFormat::powerOfTen()
{
    QFETCH(QString, locale);
    QFETCH(double, value);
    QFETCH(QString, shown);
    QCOMPARE(formatPowerOfTen(value, 3, QLocale(locale)), shown);
}

void TestNumberFormat::dissipated_data()
{
    QTest::addColumn<QString>("locale");
    QTest::addColumn<double>("joules");
    QTest::addColumn<double>("scale");
    QTest::addColumn<QString>("shown");
    const QString en = QStringLiteral("en_US"), cs = QStringLiteral("cs_CZ");
    // The two carts' elastic hit (tests/lessons/data/two_carts): the soft contact took a
    // millionth of the scene's 11.92 J. Nothing a student should read as lost.
    QTest::newRow("elastic hit, Czech") << cs << 1.06e-5 << 11.92 << QStringLiteral("0");
    QTest::newRow("elastic hit") << en << 1.06e-5 << 11.92 << QStringLiteral("0");
    QTest::newRow("a millionth of a joule") << en << 1.2e-6 << 1.0 << QStringLiteral("0");
    // What an inelastic hit takes, in the locale's notation.
    QTest::newRow("inelastic, Czech") << cs << 2.6667 << 11.92 << QStringLiteral("2,67");
    QTest::newRow("inelastic") << en << 2.6667 << 11.92 << QStringLiteral("2.67");
    QTest::newRow("a small scene, Czech") << cs << 0.00123 << 0.05 << QStringLiteral("0,00123");
    QTest::newRow("a large scene") << en << 12345.6 << 50000.0 << QStringLiteral("12346");
}

void TestNumberFormat::dissipated()
{
    QFETCH(QString, locale);
    QFETCH(double, joules);
    QFETCH(double, scale);
    QFETCH(QString, shown);
    const QString text = dissipatedText(joules, scale, QLocale(locale));
    QVERIFY2(text == shown, qPrintable(text + QStringLiteral(" | expected ") + shown));
}

void TestNumberFormat::estimate_data()
{
    QTest::addColumn<QString>("locale");
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("shown");
    const QString en = QStringLiteral("en_US"), cs = QStringLiteral("cs_CZ");
    QTest::newRow("tiny, Czech") << cs << 3.14e-9 << QStringLiteral("3,1 × 10⁻⁹");
    QTest::newRow("tiny") << en << 3.14e-9 << QStringLiteral("3.1 × 10⁻⁹");
    QTest::newRow("plain, Czech") << cs << 0.0126 << QStringLiteral("0,013");
    QTest::newRow("zero") << en << 0.0 << QStringLiteral("0");
    QTest::newRow("huge") << en << 2.5e7 << QStringLiteral("2.5 × 10⁷");
}

void TestNumberFormat::estimate()
{
    QFETCH(QString, locale);
    QFETCH(double, value);
    QFETCH(QString, shown);
    QCOMPARE(estimateText(value, 2, QLocale(locale)), shown);
}

RIGIDLAB_TEST_MAIN(TestNumberFormat)
#include "test_number_format.moc"
