// SPDX-License-Identifier: GPL-3.0-or-later
#include "plots/plot_export.h"

#include "common/export_folder.h"
#include "common/language.h"
#include "plots/plot_widget.h"

#include "export/csv_columns.h"
#include "export/csv_writer.h"
#include "export/noise_floor.h"
#include "format/atomic_file.h"

#include <qcustomplot.h>

#include <QBuffer>
#include <QDir>
#include <QFileDialog>
#include <QImage>
#include <QImageWriter>
#include <QPageLayout>
#include <QPageSize>
#include <QPdfWriter>
#include <QSettings>
#if RIGIDLAB_HAVE_SVG
#include <QSvgGenerator>
#endif

#include <cmath>
#include <limits>
#include <vector>

namespace rigidlab::ui {

namespace {

/// Logical pixels per inch: fonts given in points come out the same size as on a plain
/// screen, whatever the screen of the machine that exports.
constexpr double kLogicalDpi = 96.0;
constexpr double kInchesPerMeter = 1.0 / 0.0254;

QString cannotWrite(const QString& path, const QString& why)
{
    return QCoreApplication::translate("rigidlab::ui::exportPlot", "cannot write %1: %2")
        .arg(QDir::toNativeSeparators(path), why);
}

bool encodePng(QCustomPlot& plot, const ExportOptions& options, QByteArray& bytes, QString& why)
{
    const QSize logical = options.logicalSize;
    const double ratio = options.pngPixelRatio;
    QImage image(qRound(logical.width() * ratio), qRound(logical.height() * ratio),
                 QImage::Format_ARGB32_Premultiplied);
    if (image.isNull()) {
        why = QCoreApplication::translate("rigidlab::ui::exportPlot",
                                          "not enough memory for a %1 x %2 px image")
                  .arg(qRound(logical.width() * ratio))
                  .arg(qRound(logical.height() * ratio));
        return false;
    }
    // Points resolve against the image's resolution: fix it at the logical one while drawing.
    const int logicalDpm = qRound(kLogicalDpi * kInchesPerMeter);
    image.setDotsPerMeterX(logicalDpm);
    image.setDotsPerMeterY(logicalDpm);
    image.fill(Qt::white);
    {
        QCPPainter painter(&image);
        // Lines scale with the picture, and tick labels are drawn at its resolution rather
        // than copied from the screen's cached pixmaps.
        painter.setMode(QCPPainter::pmNonCosmetic);
        painter.setMode(QCPPainter::pmNoCaching);
        painter.scale(ratio, ratio);
        plot.toPainter(&painter, logical.width(), logical.height());
    }
    // The file says its true resolution, so it prints at the size of the PDF.
    const int fileDpm = qRound(kLogicalDpi * ratio * kInchesPerMeter);
    image.setDotsPerMeterX(fileDpm);
    image.setDotsPerMeterY(fileDpm);

    QBuffer out(&bytes);
    out.open(QIODevice::WriteOnly);
    QImageWriter writer(&out, "png");
    if (!writer.write(image)) {
        why = writer.errorString();
        return false;
    }
    return true;
}

/// The plot drawn as vectors (PDF, SVG) at its logical size; false with `why` = `cannot`
/// when the device refuses a painter.
bool drawVectorized(QCustomPlot& plot, QPaintDevice& device, QSize logical, const QString& cannot,
                    QString& why)
{
    QCPPainter painter;
    if (!painter.begin(&device)) {
        why = cannot;
        return false;
    }
    painter.setMode(QCPPainter::pmVectorized);
    painter.setMode(QCPPainter::pmNonCosmetic);
    plot.toPainter(&painter, logical.width(), logical.height());
    painter.end();
    return true;
}

bool encodePdf(QCustomPlot& plot, const QString& title, const ExportOptions& options,
               QByteArray& bytes, QString& why)
{
    const QSize logical = options.logicalSize;
    QBuffer out(&bytes);
    out.open(QIODevice::WriteOnly);
    QPdfWriter pdf(&out);
    pdf.setCreator(QStringLiteral("RigidLab"));
    pdf.setTitle(title);
    // One device pixel per logical pixel, and a page exactly the plot's size.
    pdf.setResolution(static_cast<int>(kLogicalDpi));
    const QSizeF pagePoints = QSizeF(logical) * (72.0 / kLogicalDpi);
    pdf.setPageLayout(
        QPageLayout(QPageSize(pagePoints, QPageSize::Point, QString(), QPageSize::ExactMatch),
                    QPageLayout::Portrait, QMarginsF()));

    return drawVectorized(
        plot, pdf, logical,
        QCoreApplication::translate("rigidlab::ui::exportPlot", "could not start drawing the PDF"),
        why);
}

bool encodeSvg(QCustomPlot& plot, const QString& title, const ExportOptions& options,
               QByteArray& bytes, QString& why)
{
#if !RIGIDLAB_HAVE_SVG
    Q_UNUSED(plot)
    Q_UNUSED(title)
    Q_UNUSED(options)
    Q_UNUSED(bytes)
    why = QCoreApplication::translate("rigidlab::ui::exportPlot",
                                      "this build of RigidLab cannot write SVG");
    return false;
#else
    const QSize logical = options.logicalSize;
    QBuffer out(&bytes);
    out.open(QIODevice::WriteOnly);
    QSvgGenerator svg;
    svg.setOutputDevice(&out);
    svg.setSize(logical);
    svg.setViewBox(QRect(QPoint(0, 0), logical));
    svg.setResolution(static_cast<int>(kLogicalDpi));
    svg.setTitle(title);
    svg.setDescription(QStringLiteral("RigidLab plot"));

    return drawVectorized(
        plot, svg, logical,
        QCoreApplication::translate("rigidlab::ui::exportPlot", "could not start drawing the SVG"),
        why);
#endif
}

} // namespace

QByteArray plotTable(const PlotModel& model, const lessons::CsvConventions& conventions,
                     bool legendNames, std::optional<PlotRange> within)
{
    lessons::CsvWriter csv(conventions);
    QStringList heads{lessons::csvColumnHead(lessons::CsvColumn::Time)};
    std::vector<std::vector<QPointF>> columns;
    std::vector<double> scales;
    for (int i = 0; i < model.seriesCount(); ++i) {
        heads.append(model.csvHead(i, legendNames));
        columns.push_back(model.points(i, within));
        scales.push_back(model.seriesScale(i));
    }
    csv.row(heads);

    // One row per distinct time over all series (series fed point by point need not share
    // their times); a series with no point at that time leaves its cell empty. The times are
    // the samples' (step_sampler.h), written as a person writes them.
    std::vector<std::size_t> next(columns.size(), 0);
    for (;;) {
        double t = std::numeric_limits<double>::infinity();
        for (std::size_t c = 0; c < columns.size(); ++c)
            if (next[c] < columns[c].size())
                t = std::min(t, columns[c][next[c]].x());
        if (std::isinf(t))
            break;
        csv.number(t);
        for (std::size_t c = 0; c < columns.size(); ++c) {
            if (next[c] < columns[c].size() && columns[c][next[c]].x() == t)
                csv.number(lessons::withoutNoise(columns[c][next[c]++].y(), scales[c]));
            else
                csv.number(std::numeric_limits<double>::quiet_NaN()); // an empty cell
        }
        csv.endRow();
    }
    const std::string& data = csv.data();
    return QByteArray(data.data(), static_cast<qsizetype>(data.size()));
}

bool canExport(ExportFormat format)
{
    return format != ExportFormat::Svg || RIGIDLAB_HAVE_SVG;
}

std::optional<ExportFormat> formatFromSuffix(const QString& suffix)
{
    QString s = suffix.trimmed().toLower();
    if (s.startsWith('.'))
        s.remove(0, 1);
    if (s == QLatin1String("png"))
        return ExportFormat::Png;
    if (s == QLatin1String("pdf"))
        return ExportFormat::Pdf;
    if (s == QLatin1String("svg"))
        return ExportFormat::Svg;
    if (s == QLatin1String("csv"))
        return ExportFormat::Csv;
    return std::nullopt;
}

QString suffixFor(ExportFormat format)
{
    switch (format) {
    case ExportFormat::Png:
        return QStringLiteral("png");
    case ExportFormat::Pdf:
        return QStringLiteral("pdf");
    case ExportFormat::Svg:
        return QStringLiteral("svg");
    case ExportFormat::Csv:
        return QStringLiteral("csv");
    }
    Q_UNREACHABLE();
}

QString fileFilterFor(ExportFormat format)
{
    switch (format) {
    case ExportFormat::Png:
        return QCoreApplication::translate("rigidlab::ui::exportPlot", "PNG image (*.png)");
    case ExportFormat::Pdf:
        return QCoreApplication::translate("rigidlab::ui::exportPlot", "PDF document (*.pdf)");
    case ExportFormat::Svg:
        return QCoreApplication::translate("rigidlab::ui::exportPlot", "SVG drawing (*.svg)");
    case ExportFormat::Csv:
        return QCoreApplication::translate("rigidlab::ui::exportPlot", "CSV table (*.csv)");
    }
    Q_UNREACHABLE();
}

lessons::CsvDialect windowCsvDialect()
{
    const QString saved = QSettings().value(QLatin1String(kCsvDialectKey)).toString();
    return lessons::csvDialectFromName(saved).value_or(lessons::CsvDialect::Spreadsheet);
}

void rememberCsvDialect(lessons::CsvDialect dialect)
{
    QSettings().setValue(QLatin1String(kCsvDialectKey), lessons::csvDialectName(dialect));
}

ExportOptions windowExportOptions()
{
    ExportOptions options;
    options.csv = lessons::csvConventions(windowCsvDialect(), currentLanguage());
    return options;
}

QString csvFilterFor(lessons::CsvDialect dialect)
{
    const lessons::CsvConventions c = lessons::csvConventions(dialect, currentLanguage());
    const QString separator =
        c.separator == ';' ? QStringLiteral(";")
                           : QCoreApplication::translate("rigidlab::ui::exportPlot", "comma");
    const QString decimal =
        c.decimal == ',' ? QCoreApplication::translate("rigidlab::ui::exportPlot", "decimal comma")
                         : QCoreApplication::translate("rigidlab::ui::exportPlot", "decimal point");
    if (dialect == lessons::CsvDialect::Spreadsheet)
        return QCoreApplication::translate("rigidlab::ui::exportPlot",
                                           "CSV for a spreadsheet (%1, %2) (*.csv)")
            .arg(separator, decimal);
    return QCoreApplication::translate("rigidlab::ui::exportPlot",
                                       "CSV plain, for scripts (%1, %2) (*.csv)")
        .arg(separator, decimal);
}

std::optional<CsvChoice> askCsvFile(QWidget* parent, const QString& title, const QString& suggested)
{
    using lessons::CsvDialect;
    QFileDialog dialog(parent, title, QDir(exportFolder()).filePath(suggested));
    const QString spreadsheet = csvFilterFor(CsvDialect::Spreadsheet);
    const QString plain = csvFilterFor(CsvDialect::Plain);
    dialog.setNameFilters({spreadsheet, plain});
    dialog.selectNameFilter(windowCsvDialect() == CsvDialect::Plain ? plain : spreadsheet);
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    dialog.setDefaultSuffix(QStringLiteral("csv"));
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty())
        return std::nullopt;
    const CsvChoice chosen{dialog.selectedFiles().constFirst(), dialog.selectedNameFilter() == plain
                                                                    ? CsvDialect::Plain
                                                                    : CsvDialect::Spreadsheet};
    rememberExportFolder(chosen.path);
    rememberCsvDialect(chosen.dialect);
    return chosen;
}

ExportResult exportPlot(PlotWidget& plot, const QString& path, ExportFormat format,
                        const ExportOptions& options)
{
    if (path.isEmpty())
        return {false, QCoreApplication::translate("rigidlab::ui::exportPlot",
                                                   "cannot export: no file name given")};
    if (format != ExportFormat::Csv &&
        (options.logicalSize.isEmpty() || !(options.pngPixelRatio > 0)))
        return {false, cannotWrite(path, QCoreApplication::translate("rigidlab::ui::exportPlot",
                                                                     "empty picture size"))};

    // The whole file is made in memory first, then written in one go: the encoders do not
    // all check their writes (QSvgGenerator and QTextStream take a short write silently),
    // and here every byte is checked.
    QByteArray bytes;
    QString why;
    bool encoded = true;
    if (format == ExportFormat::Csv) {
        bytes = plotTable(plot.model(), options.csv, options.legendNames);
    } else {
        QCustomPlot& qcp = *plot.plot();
        // Two points per pixel column: of the image for a PNG, of a fine print for the rest.
        const double density = format == ExportFormat::Png ? options.pngPixelRatio : 2.0;
        const ExportLayout layout(plot, options.logicalSize,
                                  qRound(options.logicalSize.width() * density));
        switch (format) {
        case ExportFormat::Png:
            encoded = encodePng(qcp, options, bytes, why);
            break;
        case ExportFormat::Pdf:
            encoded = encodePdf(qcp, plot.title(), options, bytes, why);
            break;
        case ExportFormat::Svg:
            encoded = encodeSvg(qcp, plot.title(), options, bytes, why);
            break;
        case ExportFormat::Csv:
            break;
        }
    }
    if (!encoded)
        return {false, cannotWrite(path, why)};
    // Made whole before the file is touched: a failed drawing leaves the previous file.
    if (const QString error = lessons::writeFileAtomically(path, bytes); !error.isEmpty())
        return {false, error};
    return {true, {}};
}

ExportLayout::ExportLayout(PlotWidget& plot, QSize size, int columns)
    : m_plot(plot), m_titleShown(plot.titleShown()), m_captionShown(plot.captionShown()),
      m_antialiased(plot.plot()->antialiasedElements())
{
    m_plot.setTitleShown(true); // a handout needs its title, and its caption if any
    m_plot.setCaptionShown(true);
    m_plot.fitLegend(size.width());
    m_plot.fitMarks(size.width());
    m_plot.prepareGraphs(columns);
    m_plot.plot()->setAntialiasedElements(m_antialiased | QCP::aePlottables | QCP::aeItems |
                                          QCP::aeLegendItems | QCP::aeScatters);
}

ExportLayout::~ExportLayout()
{
    m_plot.plot()->setAntialiasedElements(m_antialiased);
    m_plot.setTitleShown(m_titleShown);
    m_plot.setCaptionShown(m_captionShown);
    m_plot.fitLegend(m_plot.plot()->width());
    m_plot.fitMarks();
    m_plot.prepareGraphs();
    m_plot.plot()->replot(QCustomPlot::rpQueuedReplot);
}

} // namespace rigidlab::ui
