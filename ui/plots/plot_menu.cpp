// SPDX-License-Identifier: GPL-3.0-or-later
// PlotWidget's context menu (export, follow, time range) and its export with a file dialog.

#include "plots/plot_widget.h"

#include "common/export_folder.h"
#include "common/modal_scope.h"

#include <qcustomplot.h>

#include <QActionGroup>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QRegularExpression>

#include <algorithm>
#include <utility>
#include <vector>

namespace rigidlab::ui {

namespace {

QString fileStem(const QString& title)
{
    QString stem = title.toLower();
    stem.replace(QRegularExpression(QStringLiteral("[^a-z0-9]+")), QStringLiteral("_"));
    stem.remove(QRegularExpression(QStringLiteral("^_+|_+$")));
    return stem.isEmpty() ? QStringLiteral("plot") : stem;
}

} // namespace

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
        connect(menu->addAction(entry.second), &QAction::triggered, this,
                [this, format] { exportInteractively(format); });
    }
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

    menu->popup(m_plot->mapToGlobal(pos));
}

void PlotWidget::exportInteractively(ExportFormat format)
{
    const ModalScope modal;
    const QString dir = exportFolder(); // the last one chosen, else the documents folder
    const QString suggested = QDir(dir).filePath(fileStem(title()) + '.' + suffixFor(format));
    QFileDialog dialog(this, tr("Export plot"), suggested, fileFilterFor(format));
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    dialog.setDefaultSuffix(suffixFor(format)); // added before the overwrite question
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty())
        return;
    const QString path = dialog.selectedFiles().constFirst();
    // What the user typed wins: "energy.pdf" typed in the PNG dialog is a PDF.
    if (const auto typed = formatFromSuffix(QFileInfo(path).suffix()))
        format = *typed;
    rememberExportFolder(path);

    // Exported from the window: the columns are named as the legend on screen names them.
    ExportOptions options;
    options.legendNames = true;
    const ExportResult result = exportPlot(*this, path, format, options);
    if (!result.ok) {
        QMessageBox::warning(this, tr("Export failed"), result.error);
        return;
    }
    emit exported(path);
}

} // namespace rigidlab::ui
