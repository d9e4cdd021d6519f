// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Saving a plot for handouts: PNG, PDF and SVG pictures, and the numbers as CSV.
//
// Every export is made whole in memory, then written through lessons' OutputFile
// (format/atomic_file.h): a file appears, complete, only when everything was written, so a
// failed export never leaves a broken or half-written file and never destroys a file that was
// already at that path; a device (/dev/null) is written into, never replaced.

#include "export/csv_dialect.h"
#include "plots/plot_model.h"

#include <qcustomplot.h>

#include <QSize>
#include <QString>

#include <optional>

class QWidget;

namespace rigidlab::ui {

class PlotWidget;

enum class ExportFormat { Png, Pdf, Svg, Csv };

/// Whether this build writes `format`: all but SVG always; SVG where the program was built with
/// Qt SVG (not the Windows build, whose Qt has no SVG module). Menus and handouts offer only
/// what it writes.
bool canExport(ExportFormat format);

/// "png", ".PNG", "pdf"... (case-insensitive, with or without the dot); nullopt if unknown.
std::optional<ExportFormat> formatFromSuffix(const QString& suffix);
/// The usual suffix, without the dot: "png".
QString suffixFor(ExportFormat format);
/// A file dialog filter: "PNG image (*.png)".
QString fileFilterFor(ExportFormat format);

struct ExportOptions {
    /// Size the plot is laid out at, in device-independent pixels (1/96 in). It is also the
    /// PDF page (800 x 500 -> 212 x 132 mm, about A5 landscape) and the SVG canvas.
    QSize logicalSize{800, 500};
    /// PNG only: image pixels per logical pixel (2 -> 1600 x 1000 px, sharp when printed).
    double pngPixelRatio = 2.0;
    /// CSV only: column heads as the legend names the series, in the window's language
    /// ("Explicitní Euler [J]"), rather than the names they were added with (a lesson file's
    /// code names, "euler [J]", which the handouts keep for scripts that read them).
    bool legendNames = false;
    /// CSV only: the dialect (lessons/export/csv_dialect.h); plain unless asked.
    lessons::CsvConventions csv;
};

/// The dialect the window's CSV exports use: the one last chosen in an export dialog
/// (QSettings kCsvDialectKey), else the spreadsheet dialect.
lessons::CsvDialect windowCsvDialect();
/// Remembers the dialect chosen for the next export.
void rememberCsvDialect(lessons::CsvDialect dialect);
inline constexpr char kCsvDialectKey[] = "csvDialect";
/// The options the window exports with: its CSV dialect in the language in effect.
ExportOptions windowExportOptions();
/// A file dialog filter for a CSV dialect in the language in effect, saying what it is:
/// "CSV for a spreadsheet (;, decimal comma) (*.csv)".
QString csvFilterFor(lessons::CsvDialect dialect);

/// A CSV file chosen in a save dialog, in the dialect its filter named.
struct CsvChoice {
    QString path;
    lessons::CsvDialect dialect = lessons::CsvDialect::Spreadsheet;
};
/// Asks where to save a CSV table, starting at `suggested` (a file name, put in the folder
/// last exported into) with the dialect last chosen offered first, and remembers the folder and
/// the dialect chosen; nothing when cancelled.
std::optional<CsvChoice> askCsvFile(QWidget* parent, const QString& title,
                                    const QString& suggested);

/// The plot's data as a CSV table: a time column "t [s]" and a column per series (headed by
/// PlotModel::csvHead), a row per distinct time; with `within`, the points in that time
/// range alone (the time axis as shown).
QByteArray plotTable(const PlotModel& model, const lessons::CsvConventions& conventions,
                     bool legendNames, std::optional<PlotRange> within = std::nullopt);

struct ExportResult {
    bool ok = false;
    QString error; ///< what went wrong and where: "cannot write /ro/plot.png: Permission denied"
};

/// Writes `plot` to `path` as `format`, atomically. The plot is laid out at the export size
/// while it is drawn, then put back as it was on screen.
ExportResult exportPlot(PlotWidget& plot, const QString& path, ExportFormat format,
                        const ExportOptions& options = {});

/// Lays the plot out for an export `size` [logical pixels] while it is drawn, and back for the
/// screen after: title and caption shown, the legend and the marks fitted to the export's
/// width, the graphs decimated for its pixels (`columns`), and every curve, item and legend
/// line antialiased. The exports and the worksheet's figures draw within one.
class ExportLayout {
public:
    ExportLayout(PlotWidget& plot, QSize size, int columns);
    ~ExportLayout();
    ExportLayout(const ExportLayout&) = delete;
    ExportLayout& operator=(const ExportLayout&) = delete;

private:
    PlotWidget& m_plot;
    bool m_titleShown;
    bool m_captionShown;
    QCP::AntialiasedElements m_antialiased;
};

} // namespace rigidlab::ui
