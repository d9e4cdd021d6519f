// SPDX-License-Identifier: GPL-3.0-or-later
// The plots' export: every export is either a valid file or nothing at all, the CSV keeps
// every digit, and what the window exports is named in the window's language.

#include "build_paths.h"
#include "common/display_names.h"
#include "plots/lesson_export.h"
#include "plots/plot_export.h"
#include "plots/plot_table.h"
#include "plots/plot_widget.h"
#include "simulation/sample_buffer.h"

#include <qcustomplot.h>

#include <QSignalSpy>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtTest>

#include "format/lesson.h"

#include "plot_test_samples.h"
#include "sourced_plot.h"
#include "test_files.h"
#include "test_main.h"

#include <cmath>

#ifdef Q_OS_UNIX
#include "file_size_limit.h"
#endif

using namespace rigidlab::ui;
using rigidlab::test::feed;
using rigidlab::test::readAll;
using rigidlab::test::sampleAt;
using rigidlab::test::SourcedPlot;

namespace {

/// Every export format, with the name its data rows go by.
constexpr std::pair<ExportFormat, const char*> kExportFormats[] = {{ExportFormat::Png, "png"},
                                                                   {ExportFormat::Pdf, "pdf"},
                                                                   {ExportFormat::Svg, "svg"},
                                                                   {ExportFormat::Csv, "csv"}};

QStringList entries(const QString& dir)
{
    return QDir(dir).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden, QDir::Name);
}

} // namespace

class TestPlotExport : public QObject {
    Q_OBJECT
private slots:
    void formatFromSuffix_data();
    void formatFromSuffix();
    void exportWritesValidFile_data();
    void exportWritesValidFile();
    void csvHasFullPrecisionAndUnits();
    void exportReplacesExistingFile();
    void failedExportLeavesNothing_data();
    void failedExportLeavesNothing();
    void failedExportKeepsExistingFile_data();
    void failedExportKeepsExistingFile();
    void windowExportNamesColumnsAsTheLegend();
    void presentationIsBlackOnWhite();
};

void TestPlotExport::formatFromSuffix_data()
{
    QTest::addColumn<QString>("suffix");
    QTest::addColumn<int>("format"); // -1: unknown
    QTest::newRow("png") << "png" << int(ExportFormat::Png);
    QTest::newRow("dot PDF") << ".PDF" << int(ExportFormat::Pdf);
    QTest::newRow("Svg") << "Svg" << int(ExportFormat::Svg);
    QTest::newRow("csv") << "csv" << int(ExportFormat::Csv);
    QTest::newRow("jpeg") << "jpeg" << -1;
    QTest::newRow("empty") << "" << -1;
}

void TestPlotExport::formatFromSuffix()
{
    QFETCH(QString, suffix);
    QFETCH(int, format);
    const std::optional<ExportFormat> found = rigidlab::ui::formatFromSuffix(suffix);
    QCOMPARE(found.has_value(), format >= 0);
    if (found) {
        QCOMPARE(int(*found), format);
        QCOMPARE(rigidlab::ui::formatFromSuffix(suffixFor(*found)), found);
    }
}

void TestPlotExport::exportWritesValidFile_data()
{
    QTest::addColumn<int>("format");
    QTest::newRow("png") << int(ExportFormat::Png);
    QTest::newRow("pdf") << int(ExportFormat::Pdf);
    QTest::newRow("svg") << int(ExportFormat::Svg);
    QTest::newRow("csv") << int(ExportFormat::Csv);
}

void TestPlotExport::exportWritesValidFile()
{
    QFETCH(int, format);
    const auto fmt = ExportFormat(format);

    PlotWidget* plot = makeEnergyPlot(nullptr);
    std::unique_ptr<PlotWidget> owner(plot);
    SampleBuffer buffer;
    plot->model().setSource(&buffer);
    feed(buffer, *plot, 0.0, 0.05, 150);
    plot->model().addMark(3.0, QStringLiteral("RK4"));
    plot->drain();

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("energy." + suffixFor(fmt));
    const ExportResult result = exportPlot(*plot, path, fmt);
    QVERIFY2(result.ok, qPrintable(result.error));
    QVERIFY(result.error.isEmpty());
    QCOMPARE(entries(dir.path()), QStringList{QFileInfo(path).fileName()}); // no leftovers

    const QByteArray bytes = readAll(path);
    switch (fmt) {
    case ExportFormat::Png: {
        QImage image;
        QVERIFY(image.loadFromData(bytes, "PNG"));
        const ExportOptions defaults;
        QCOMPARE(image.size(), defaults.logicalSize * defaults.pngPixelRatio);
        QCOMPARE(image.size(), QSize(1600, 1000));
        QCOMPARE(image.pixelColor(0, 0), QColor(Qt::white));
        int inked = 0; // curves, text and axes: far from an empty white picture
        for (int y = 0; y < image.height(); y += 4)
            for (int x = 0; x < image.width(); x += 4)
                inked += image.pixelColor(x, y) != QColor(Qt::white) ? 1 : 0;
        QVERIFY2(inked > 2000, qPrintable(QString::number(inked)));
        break;
    }
    case ExportFormat::Pdf:
        QVERIFY(bytes.startsWith("%PDF-"));
        QVERIFY(bytes.trimmed().endsWith("%%EOF"));
        break;
    case ExportFormat::Svg: {
        QXmlStreamReader xml(bytes);
        QString root;
        while (!xml.atEnd()) {
            xml.readNext();
            if (xml.isStartElement() && root.isEmpty())
                root = xml.name().toString();
        }
        QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
        QCOMPARE(root, QStringLiteral("svg"));
        QSvgRenderer renderer(path);
        QVERIFY(renderer.isValid());
        break;
    }
    case ExportFormat::Csv: {
        const QList<QByteArray> lines = bytes.trimmed().split('\n');
        // The heads the command line's diagnostics give the same quantities.
        QCOMPARE(lines.first(),
                 QByteArray("t [s],E_k [J],E_p [J],E [J],E_diss [J],E + E_diss [J]"));
        QCOMPARE(lines.size(), 1 + 150);
        for (const QByteArray& line : lines)
            QCOMPARE(line.count(','), 5);
        break;
    }
    }
}

void TestPlotExport::csvHasFullPrecisionAndUnits()
{
    auto [buffer, plot] = SourcedPlot(makeMomentumPlot(nullptr));
    feed(buffer, *plot, 0.1, 0.1, 40); // 0.1 is not exact in binary: a good test of precision

    QTemporaryDir dir;
    const QString path = dir.filePath("momentum.csv");
    const ExportResult result = exportPlot(*plot, path, ExportFormat::Csv);
    QVERIFY2(result.ok, qPrintable(result.error));

    const QList<QByteArray> lines = readAll(path).trimmed().split('\n');
    QCOMPARE(QString::fromUtf8(lines.first()),
             QStringLiteral("t [s],p_x [kg m/s],p_y [kg m/s],L [kg m²/s]"));
    QCOMPARE(lines.size(), 41);
    for (int i = 0; i < 40; ++i) {
        const QList<QByteArray> cells = lines[i + 1].split(',');
        QCOMPARE(cells.size(), 4);
        const Sample s = sampleAt(0.1 + 0.1 * i);
        // Exact equality: the text reads back as the very same double.
        QVERIFY(cells[0].toDouble() == s.t);
        QVERIFY(cells[1].toDouble() == s.px);
        QVERIFY(cells[2].toDouble() == s.py);
        QVERIFY(cells[3].toDouble() == s.angularMomentum);
    }
}

void TestPlotExport::exportReplacesExistingFile()
{
    auto [buffer, plot] = SourcedPlot(makeDriftPlot(nullptr));
    feed(buffer, *plot, 0.0, 0.5, 4);

    QTemporaryDir dir;
    const QString path = dir.filePath("drift.csv");
    {
        QFile old(path);
        QVERIFY(old.open(QIODevice::WriteOnly));
        old.write("an older export, much longer than the new one\n");
    }
    const ExportResult result = exportPlot(*plot, path, ExportFormat::Csv);
    QVERIFY2(result.ok, qPrintable(result.error));
    QCOMPARE(readAll(path).trimmed().split('\n').size(), 5);
    QCOMPARE(entries(dir.path()), QStringList{"drift.csv"});
}

void TestPlotExport::failedExportLeavesNothing_data()
{
    QTest::addColumn<int>("format");
    QTest::addColumn<QString>("failure");
    for (const auto& [format, name] : kExportFormats)
        for (const char* failure :
             {"missing directory", "target is a directory", "read-only directory"})
            QTest::addRow("%s, %s", name, failure) << int(format) << QString(failure);
}

void TestPlotExport::failedExportLeavesNothing()
{
    QFETCH(int, format);
    QFETCH(QString, failure);
    const auto fmt = ExportFormat(format);

    auto [buffer, plot] = SourcedPlot(makeEnergyPlot(nullptr));
    feed(buffer, *plot, 0.0, 0.05, 100);

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString name = "energy." + suffixFor(fmt);
    QString path;
    QString watched = dir.path(); // nothing may appear or vanish in here
    if (failure == "missing directory") {
        path = dir.filePath("no/such/dir/" + name);
    } else if (failure == "target is a directory") {
        path = dir.filePath(name);
        QVERIFY(QDir(dir.path()).mkdir(name));
    } else {
        watched = dir.filePath("read-only");
        QVERIFY(QDir(dir.path()).mkdir("read-only"));
        QVERIFY(QFile::setPermissions(watched, QFile::ReadOwner | QFile::ExeOwner |
                                                   QFile::ReadGroup | QFile::ExeGroup |
                                                   QFile::ReadOther | QFile::ExeOther));
        QFile probe(watched + "/probe");
        if (probe.open(QIODevice::WriteOnly)) {
            probe.remove();
            QSKIP("permissions do not stop this user (root): covered by the other rows and "
                  "by failedExportKeepsExistingFile");
        }
        path = watched + '/' + name;
    }
    const QStringList before = entries(watched);

    const ExportResult result = exportPlot(*plot, path, fmt);
    QFile::setPermissions(watched, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);

    QVERIFY(!result.ok);
    QVERIFY2(result.error.startsWith("cannot write "), qPrintable(result.error));
    QVERIFY2(result.error.contains(QDir::toNativeSeparators(path)), qPrintable(result.error));
    QCOMPARE(entries(watched), before);
    if (failure == "target is a directory")
        QVERIFY(QFileInfo(path).isDir());
    else
        QVERIFY(!QFileInfo::exists(path));
}

void TestPlotExport::failedExportKeepsExistingFile_data()
{
    QTest::addColumn<int>("format");
    QTest::addColumn<QString>("failure");
    for (const auto& [format, name] : kExportFormats)
        for (const char* failure : {"file size limit", "read-only directory"})
            QTest::addRow("%s, %s", name, failure) << int(format) << QString(failure);
}

void TestPlotExport::failedExportKeepsExistingFile()
{
    QFETCH(int, format);
    QFETCH(QString, failure);
    const auto fmt = ExportFormat(format);

    auto [buffer, plot] = SourcedPlot(makeEnergyPlot(nullptr));
    feed(buffer, *plot, 0.0, 0.05, 200); // well over the size limit below, in every format

    QTemporaryDir dir;
    const QString path = dir.filePath("energy." + suffixFor(fmt));
    const QByteArray precious = "the export from last week's lecture\n";
    {
        QFile old(path);
        QVERIFY(old.open(QIODevice::WriteOnly));
        QCOMPARE(old.write(precious), precious.size());
    }

    ExportResult result;
    if (failure == "file size limit") {
#ifdef Q_OS_UNIX
        // Fails halfway through writing, for root too.
        rigidlab::test::FileSizeLimit limit(1024);
        QVERIFY(limit.isActive());
        result = exportPlot(*plot, path, fmt);
#else
        QSKIP("needs a POSIX file size limit");
#endif
    } else {
        const auto readOnly = QFile::ReadOwner | QFile::ExeOwner | QFile::ReadGroup |
                              QFile::ExeGroup | QFile::ReadOther | QFile::ExeOther;
        QVERIFY(QFile::setPermissions(dir.path(), readOnly));
        QFile probe(dir.filePath("probe"));
        const bool permissionsIgnored = probe.open(QIODevice::WriteOnly);
        if (!permissionsIgnored)
            result = exportPlot(*plot, path, fmt);
        probe.remove();
        QFile::setPermissions(dir.path(), readOnly | QFile::WriteOwner);
        if (permissionsIgnored)
            QSKIP("permissions do not stop this user (root): see the file size limit rows");
    }
    QVERIFY(!result.ok);
    // What and where: "cannot write /tmp/.../energy.png: File too large".
    const QString where = "cannot write " + QDir::toNativeSeparators(path) + ": ";
    QVERIFY2(result.error.startsWith(where), qPrintable(result.error));
    QVERIFY2(result.error.size() > where.size(), qPrintable(result.error));
    QCOMPARE(readAll(path), precious);
    QCOMPARE(entries(dir.path()), QStringList{QFileInfo(path).fileName()}); // no temporary left
}

void TestPlotExport::windowExportNamesColumnsAsTheLegend()
{
    // The side-by-side comparison: a handout keeps the lesson file's code names ("euler [J]")
    // for scripts; exported from the window, the columns are named as its legend is, in the
    // window's language.
    const rigidlab::lessons::LessonLoadResult loaded = rigidlab::lessons::loadLessonFile(
        rigidlab::test::sourcePath(u"/lessons/lessons/energy_drift.json"));
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    QWidget parent;
    PlotWidget* plot =
        makeStepPlot(loaded.lesson.steps[0], QStringLiteral("compare-energy"), &parent);
    QVERIFY(plot);
    QVERIFY(plot->model().seriesCount() >= 2);
    QCOMPARE(plot->model().seriesName(0), QStringLiteral("euler"));
    QCOMPARE(plot->model().seriesLegend(0), methodDisplayName(QStringLiteral("euler")));
    QVERIFY(plot->model().seriesLegend(0) != plot->model().seriesName(0));
    QTemporaryDir dir;
    const auto header = [&](bool legendNames) {
        ExportOptions options;
        options.legendNames = legendNames;
        const QString path = dir.filePath(legendNames ? "window.csv" : "handout.csv");
        const ExportResult written = exportPlot(*plot, path, ExportFormat::Csv, options);
        return written.ok ? QString::fromUtf8(readAll(path).split('\n').value(0)) : written.error;
    };
    const QString handout = header(false), window = header(true);
    QVERIFY2(handout.startsWith(QStringLiteral("t [s],euler [J],")), qPrintable(handout));
    QStringList expected{QStringLiteral("t [s]")};
    for (int i = 0; i < plot->model().seriesCount(); ++i)
        expected << plot->model().seriesLegend(i) + " [" + plot->model().seriesUnit(i) + "]";
    QCOMPARE(window.split(u','), expected);
}

void TestPlotExport::presentationIsBlackOnWhite()
{
    // What the README promises for a washed-out projector: black text, axes and a grid that
    // shows on white; the curves keep their colours, which tell compared runs apart.
    PlotWidget plot(QStringLiteral("energy"));
    plot.setCaption(QStringLiteral("a caption"));
    plot.setCaptionShown(true);
    const QCustomPlot& qcp = *plot.plot();
    const auto darkest = [](const QColor& c) { return std::max({c.red(), c.green(), c.blue()}); };
    const int windowGrid = darkest(qcp.xAxis->grid()->pen().color());
    plot.setPresentation(true);
    for (const QCPAxis* axis : {qcp.xAxis, qcp.yAxis}) {
        QCOMPARE(axis->labelColor(), QColor(Qt::black));
        QCOMPARE(axis->tickLabelColor(), QColor(Qt::black));
        QCOMPARE(axis->basePen().color(), QColor(Qt::black));
        QVERIFY2(darkest(axis->grid()->pen().color()) <= 0x80,
                 qPrintable(axis->grid()->pen().color().name()));
    }
    QCOMPARE(plot.captionColour(), QColor(Qt::black));
    plot.setPresentation(false);
    QCOMPARE(darkest(qcp.xAxis->grid()->pen().color()), windowGrid);
    QVERIFY(plot.captionColour() != QColor(Qt::black));
}

RIGIDLAB_TEST_MAIN(TestPlotExport)
#include "test_plot_export.moc"
