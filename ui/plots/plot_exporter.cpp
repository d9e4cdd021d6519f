// SPDX-License-Identifier: GPL-3.0-or-later
#include "plots/plot_exporter.h"

#include "common/export_folder.h"
#include "common/language.h"
#include "common/modal_scope.h"
#include "plots/plot_widget.h"

#include "format/scene_schema.h"

#include <QClipboard>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QGuiApplication>
#include <QMessageBox>

namespace rigidlab::ui {

PlotExporter::PlotExporter(PlotWidget& plot) : QObject(&plot), m_plot(plot) {}

QString PlotExporter::proposedFileName(ExportFormat format) const
{
    // What it is of, which plot, in which language: "welcome_energie_cs.csv", not plot.csv
    // three times over; safe on a school's Windows share and a USB stick.
    const QString words = QStringList{m_context, m_plot.title(), currentLanguage()}.join(u' ');
    return lessons::schema::safeFileStem(words, QStringLiteral("plot")) + u'.' + suffixFor(format);
}

QString PlotExporter::exportInteractively(ExportFormat format)
{
    using lessons::CsvDialect;
    const ModalScope modal;
    const QString dir = exportFolder(); // the last one chosen, else the documents folder
    const QString suggested = QDir(dir).filePath(proposedFileName(format));
    QFileDialog dialog(&m_plot, tr("Export plot"), suggested);
    // A CSV's dialect is one of the filters, each saying what it writes; the one last chosen
    // comes first.
    const QString spreadsheet = csvFilterFor(CsvDialect::Spreadsheet);
    const QString plain = csvFilterFor(CsvDialect::Plain);
    if (format == ExportFormat::Csv) {
        dialog.setNameFilters({spreadsheet, plain});
        dialog.selectNameFilter(windowCsvDialect() == CsvDialect::Plain ? plain : spreadsheet);
    } else {
        dialog.setNameFilter(fileFilterFor(format));
    }
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    dialog.setDefaultSuffix(suffixFor(format)); // added before the overwrite question
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty())
        return {};
    const QString path = dialog.selectedFiles().constFirst();
    // What the user typed wins: "energy.pdf" typed in the PNG dialog is a PDF.
    if (const auto typed = formatFromSuffix(QFileInfo(path).suffix()))
        format = *typed;
    rememberExportFolder(path);

    // Exported from the window: the columns are named as the legend on screen names them.
    ExportOptions options = windowExportOptions();
    options.legendNames = true;
    if (dialog.selectedNameFilter() == plain || dialog.selectedNameFilter() == spreadsheet) {
        const CsvDialect chosen =
            dialog.selectedNameFilter() == plain ? CsvDialect::Plain : CsvDialect::Spreadsheet;
        rememberCsvDialect(chosen);
        options.csv = lessons::csvConventions(chosen, currentLanguage());
    }
    const ExportResult result = exportPlot(m_plot, path, format, options);
    if (!result.ok) {
        QMessageBox::warning(&m_plot, tr("Export failed"), result.error);
        return {};
    }
    emit exported(path);
    return path;
}

void PlotExporter::copyData()
{
    m_plot.drain();
    const QByteArray table =
        plotTable(m_plot.model(), lessons::clipboardConventions(currentLanguage()), true,
                  m_plot.shownTimes());
    QGuiApplication::clipboard()->setText(QString::fromUtf8(table));
}

} // namespace rigidlab::ui
