// SPDX-License-Identifier: GPL-3.0-or-later
// WindowDocuments' saving: Save, Save As, the question about unsaved changes, and File › Your
// own scenes, where saved scenes appear.
#include "window/window_documents.h"

#include "common/display_names.h"
#include "common/modal_scope.h"
#include "editor/scene_document.h"

#include "format/data_dirs.h"
#include "format/scene_catalog.h"
#include "format/scene_schema.h"
#include "format/scene_writer.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>

namespace rigidlab::ui {

namespace {

/// Whether `path` is one of the scenes RigidLab comes with (in the shipped data folder, where
/// a package installs it read-only) or a file that cannot be written.
bool isShipped(const QString& path)
{
    const QFileInfo file(path);
    if (file.exists() && !file.isWritable())
        return true;
    const QString shipped = QFileInfo(lessons::shippedDataDir()).canonicalFilePath();
    if (shipped.isEmpty())
        return false;
    // The folder the file is (or would be) in, resolved: a link into the data folder counts.
    const QString folder = file.absoluteDir().canonicalPath();
    return !folder.isEmpty() &&
           (folder == shipped || folder.startsWith(shipped + QLatin1Char('/')));
}

} // namespace

bool WindowDocuments::saveScene()
{
    const QString path = m_document.path();
    if (!m_documentIsFile || path.isEmpty())
        return saveSceneAs();
    if (isShipped(path)) {
        emit message(tr("%1 comes with RigidLab and is not overwritten: save your version under "
                        "a name of its own.")
                         .arg(QFileInfo(path).fileName()),
                     8000);
        return saveSceneAs();
    }
    return writeDocument(path);
}

bool WindowDocuments::saveSceneAs()
{
    const QString folder = lessons::userScenesDir();
    QDir().mkpath(folder); // so that the dialog starts there
    const QString current = m_documentIsFile ? QFileInfo(m_document.path()).fileName() : QString();
    const QString suggested = QDir(folder).filePath(
        current.isEmpty() ? lessons::schema::safeFileName(m_document.scene().title) : current);
    QString path;
    if (m_savePathAsker) {
        path = m_savePathAsker(suggested);
    } else {
        const ModalScope modal;
        path = QFileDialog::getSaveFileName(&m_window, tr("Save scene as"), suggested,
                                            tr("RigidLab scenes (*.json)"));
    }
    if (path.isEmpty())
        return false;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".json");
    if (isShipped(path)) {
        m_lastError = tr("%1 comes with RigidLab and is not overwritten. Choose another name, "
                         "or a folder of your own (your scenes are in %2).")
                          .arg(QDir::toNativeSeparators(path), QDir::toNativeSeparators(folder));
        showError(tr("Scene not saved"), m_lastError, "saveErrorBox");
        return false;
    }
    return writeDocument(path);
}

bool WindowDocuments::writeDocument(const QString& path)
{
    const QString error = lessons::saveScene(path, m_document.scene());
    if (!error.isEmpty()) {
        m_lastError = error;
        showError(tr("Scene not saved"), error, "saveErrorBox");
        return false;
    }
    m_lastError.clear();
    m_documentIsFile = true;
    m_document.markSaved(path);
    m_lastFolder = QFileInfo(path).absolutePath();
    addRecent(QFileInfo(path).absoluteFilePath());
    rebuildOwnScenesMenu();
    emit message(tr("Saved %1").arg(QDir::toNativeSeparators(path)), 5000);
    return true;
}

bool WindowDocuments::confirmLeaveScene()
{
    if (!m_document.isModified())
        return true;
    int answer = QMessageBox::Cancel;
    if (m_unsavedAsker) {
        answer = m_unsavedAsker();
    } else {
        const ModalScope modal;
        QMessageBox box(
            QMessageBox::Question, tr("Unsaved changes"),
            tr("The scene “%1” has changes that are not saved.").arg(m_document.scene().title),
            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, &m_window);
        box.setObjectName(QStringLiteral("unsavedBox"));
        box.setInformativeText(tr("Save them before going on?"));
        box.setDefaultButton(QMessageBox::Save);
        answer = box.exec();
    }
    if (answer == QMessageBox::Save)
        return saveScene();
    return answer == QMessageBox::Discard;
}

void WindowDocuments::rebuildOwnScenesMenu()
{
    if (!m_fileMenu)
        return;
    const std::vector<lessons::SceneEntry> own = lessons::scenesIn(lessons::userScenesDir(), true);
    if (own.empty()) {
        delete m_ownScenesMenu;
        m_ownScenesMenu = nullptr;
        return;
    }
    if (!m_ownScenesMenu) {
        m_ownScenesMenu = new QMenu(tr("&Your own scenes"), m_fileMenu);
        m_ownScenesMenu->setObjectName(QStringLiteral("ownScenes"));
        m_fileMenu->insertMenu(m_ownScenesBefore, m_ownScenesMenu);
    }
    m_ownScenesMenu->clear();
    for (const lessons::SceneEntry& scene : own)
        m_ownScenesMenu->addAction(menuEntryText(scene.title), this,
                                   [this, p = scene.path] { openScene(p, false); });
}

} // namespace rigidlab::ui
