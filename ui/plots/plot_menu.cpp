// SPDX-License-Identifier: GPL-3.0-or-later
// PlotWidget's context menu (export, follow, time range) and its export with a file dialog.

#include "plots/plot_widget.h"

#include "common/export_folder.h"
#include "common/language.h"
#include "common/modal_scope.h"
#include "plots/plot_accessible.h"

#include "format/scene_schema.h"

#include <qcustomplot.h>

#include <QActionGroup>
#include <QClipboard>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QGuiApplication>
#include <QMenu>
#include <QMessageBox>
#include <QShortcut>

#include <algorithm>
#include <utility>
#include <vector>

namespace rigidlab::ui {

void PlotWidget::showContextMenu(const QPoint& pos)
{
    auto* menu = new QMenu(this);
    menu->setAttribute(Qt::WA_DeleteOnClose);

    const std::pair<ExportFormat, QString> exports[] = {
        {ExportFormat::Png, tr("Export as PNG…")},
        {ExportFormat::Pdf, tr("Export as PDF…")},
        {ExportFormat::Svg, tr("Export as SVG…")},
        {ExportFormat::Csv, tr("Export data as CSV…")},
    };
    for (const auto& entry : exports) {
        const ExportFormat format = entry.first;
        if (!canExport(format))
            continue;
        connect(menu->addAction(entry.second), &QAction::triggered, this,
                [this, format] { exportInteractively(format); });
    }
    QAction* copy = menu->addAction(tr("Copy data shown"), this, &PlotWidget::copyData);
    copy->setShortcut(QKeySequence::Copy); // shown in the menu; the plot's own shortcut acts
    menu->addAction(tr("Describe this plot…"), this, [this] {
        drain();
        QMessageBox box(QMessageBox::Information, title(), describePlot(*this), QMessageBox::Ok,
                        this);
        box.setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
        const ModalScope modal;
        box.exec();
    });
    menu->addSeparator();

    QAction* followAction = menu->addAction(tr("Follow"));
    followAction->setCheckable(true);
    followAction->setChecked(m_following);
    connect(followAction, &QAction::toggled, this, &PlotWidget::setFollowing);
    menu->addSeparator();

    // Last N s (a few usual lengths, and the current one) or the whole run.
    auto* modes = new QActionGroup(menu);
    std::vector<double> lengths{5, 10, 30, 60}; // [s]
    if (std::find(lengths.begin(), lengths.end(), m_windowSeconds) == lengths.end())
        lengths.insert(std::upper_bound(lengths.begin(), lengths.end(), m_windowSeconds),
                       m_windowSeconds);
    for (const double seconds : lengths) {
        QAction* action = modes->addAction(tr("Last %1 s").arg(seconds));
        action->setCheckable(true);
        action->setChecked(m_rangeMode == RangeMode::Window && seconds == m_windowSeconds);
        connect(action, &QAction::triggered, this, [this, seconds] {
            setWindowSeconds(seconds);
            setRangeMode(RangeMode::Window);
        });
    }
    QAction* wholeRun = modes->addAction(tr("Whole run"));
    wholeRun->setCheckable(true);
    wholeRun->setChecked(m_rangeMode == RangeMode::WholeRun);
    connect(wholeRun, &QAction::triggered, this, [this] { setRangeMode(RangeMode::WholeRun); });
    menu->addActions(modes->actions());
    for (QAction* action : std::as_const(m_menuActions))
        if (action) {
            menu->addSeparator();
            menu->addAction(action);
        }

    menu->popup(m_plot->mapToGlobal(pos));
}

QString PlotWidget::proposedFileName(ExportFormat format) const
{
    // What it is of, which plot, in which language: "welcome_energie_cs.csv", not plot.csv
    // three times over; safe on a school's Windows share and a USB stick.
    const QString words = QStringList{m_exportContext, title(), currentLanguage()}.join(u' ');
    return lessons::schema::safeFileStem(words, QStringLiteral("plot")) + u'.' + suffixFor(format);
}

QString PlotWidget::exportInteractively(ExportFormat format)
{
    using lessons::CsvDialect;
    const ModalScope modal;
    const QString dir = exportFolder(); // the last one chosen, else the documents folder
    const QString suggested = QDir(dir).filePath(proposedFileName(format));
    QFileDialog dialog(this, tr("Export plot"), suggested);
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
    const ExportResult result = exportPlot(*this, path, format, options);
    if (!result.ok) {
        QMessageBox::warning(this, tr("Export failed"), result.error);
        return {};
    }
    emit exported(path);
    return path;
}

void PlotWidget::installMenuAndCopy()
{
    m_plot->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(m_plot, &QWidget::customContextMenuRequested, this, &PlotWidget::showContextMenu);
    // Ctrl+C while the plot has the focus (a click or Tab gives it) copies the data shown;
    // the menu key or Shift+F10 opens the menu from the keyboard.
    setFocusPolicy(Qt::StrongFocus);
    setContextMenuPolicy(Qt::CustomContextMenu);
    connect(this, &QWidget::customContextMenuRequested, this,
            [this](const QPoint& pos) { showContextMenu(m_plot->mapFrom(this, pos)); });
    installPlotAccessible();
    auto* copy = new QShortcut(QKeySequence::Copy, this, this, &PlotWidget::copyData);
    copy->setContext(Qt::WidgetWithChildrenShortcut);
}

void PlotWidget::copyData()
{
    drain();
    const QByteArray table =
        plotTable(*this, lessons::clipboardConventions(currentLanguage()), true, true);
    QGuiApplication::clipboard()->setText(QString::fromUtf8(table));
}

} // namespace rigidlab::ui
