// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow's files: opening scenes, the recent files, exporting a plot.
#include "window/main_window.h"

#include "common/export_folder.h"
#include "common/modal_scope.h"
#include "editor/scene_document.h"
#include "lesson_player/lesson_player.h"
#include "plots/plot_export.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "window/settings_sync.h"

#include "format/scene_loader.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>

namespace rigidlab::ui {

namespace {

constexpr int kMaxRecent = 8;

} // namespace

QString MainWindow::openScene(const QString& path, bool quiet)
{
    const lessons::SceneLoadResult r = lessons::loadSceneFile(path);
    if (!r.ok) {
        m_lastError = r.error;
        if (!quiet) {
            auto* box = new QMessageBox(QMessageBox::Warning, tr("Cannot open scene"), r.error,
                                        QMessageBox::Ok, this);
            box->setAttribute(Qt::WA_DeleteOnClose);
            box->setObjectName(QStringLiteral("sceneErrorBox"));
            box->open();
        }
        return r.error;
    }
    if (!confirmLeaveScene()) {
        m_lastError = tr("%1 was not opened: the edited scene stays.").arg(path);
        return m_lastError;
    }
    m_lastError.clear();
    if (m_inLesson)
        m_player->closeLesson(); // a scene of one's own ends the lesson
    m_documentIsFile = true;
    // Which loads the world (the document's sceneChanged, MainWindow::MainWindow).
    m_document->reset(r.scene, path);
    for (const QString& w : r.warnings)
        statusBar()->showMessage(w, 8000);
    // The Open dialog starts where a scene was last opened or saved; the shipped folder, where
    // the welcome scene is opened from at every start, does not replace a folder of one's own
    // (found by hand: saved, quit, started again, and Open showed the shipped scenes).
    const QString folder = QFileInfo(path).absolutePath();
    if (m_lastFolder.isEmpty() || QDir(folder) != QDir(scenesFolder()))
        m_lastFolder = folder;
    addRecent(QFileInfo(path).absoluteFilePath());
    return QString();
}

void MainWindow::openDialog()
{
    const ModalScope modal;
    const QString folder = m_lastFolder.isEmpty() ? scenesFolder() : m_lastFolder;
    const QString path = QFileDialog::getOpenFileName(this, tr("Open scene"), folder,
                                                      tr("RigidLab scenes (*.json)"));
    if (!path.isEmpty())
        openScene(path);
}

void MainWindow::addRecent(const QString& path)
{
    QSettings s;
    QStringList recent = s.value(QStringLiteral("recentFiles")).toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent)
        recent.removeLast();
    s.setValue(QStringLiteral("recentFiles"), recent);
    s.setValue(QStringLiteral("lastFolder"), m_lastFolder);
    syncSettings(s, *this);
    rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu()
{
    m_recentMenu->clear();
    const QStringList recent = QSettings().value(QStringLiteral("recentFiles")).toStringList();
    for (const QString& path : recent)
        m_recentMenu->addAction(QFileInfo(path).fileName(), this,
                                [this, path] { openScene(path); });
    m_recentMenu->setEnabled(!recent.isEmpty());
}

void MainWindow::exportPlotDialog(PlotWidget* plot, const QString& format)
{
    const ModalScope modal;
    const QString suffix = format.toLower();
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export plot"), QDir(exportFolder()).filePath(QStringLiteral("plot.") + suffix),
        tr("%1 files (*.%2)").arg(format, suffix));
    if (path.isEmpty())
        return;
    rememberExportFolder(path);
    const ExportResult r = exportPlot(*plot, path, *formatFromSuffix(suffix));
    if (!r.ok)
        QMessageBox::warning(this, tr("Export failed"), r.error);
    else
        statusBar()->showMessage(tr("Exported %1").arg(path), 5000);
}

} // namespace rigidlab::ui
