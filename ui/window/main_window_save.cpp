// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow's scene files of the editor: New, Save, Save As, the question about unsaved
// changes, and File › Your own scenes, where saved scenes appear.
#include "window/main_window.h"

#include "common/modal_scope.h"
#include "editor/edit_tools.h"
#include "editor/scene_document.h"
#include "lesson_player/lesson_player.h"
#include "simulation/simulation_controller.h"

#include "format/data_dirs.h"
#include "format/scene_catalog.h"
#include "format/scene_compare.h"
#include "format/scene_loader.h"
#include "format/scene_schema.h"
#include "format/scene_writer.h"

#include "rigidlab/physics/shape.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QStatusBar>

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

bool MainWindow::newScene()
{
    if (!confirmLeaveScene())
        return false;
    if (m_inLesson)
        m_player->closeLesson(); // a scene of one's own ends the lesson
    lessons::Scene scene;
    scene.title = tr("New scene");
    // The default world (physics::WorldDef: gravity, dt, integrator, solver...) and a ground
    // to put things on, its top at y = 0.
    physics::BodyDef ground;
    ground.name = "ground";
    ground.type = physics::BodyType::Static;
    ground.shape = physics::makePolygonShape(physics::makeBox(10.0, 0.5));
    ground.position = physics::Vec2(0.0, -0.25);
    scene.bodies.push_back(ground);
    scene.originalVertices.resize(scene.bodies.size());
    scene.colours.resize(scene.bodies.size());
    m_documentIsFile = false;
    m_document->reset(scene, QString()); // which loads the world
    m_lastError.clear();
    // A teacher starting a new scene wants to draw at once.
    m_editTools->setEditing(true);
    return true;
}

void MainWindow::adoptDocument(const lessons::Scene& edited, const QString& path, bool isFile,
                               bool modified)
{
    if (m_inLesson)
        m_player->closeLesson();
    m_documentIsFile = isFile;
    lessons::Scene base = edited;
    if (isFile && modified) {
        // The file as saved is where undoing leads (read in this window's language).
        if (const lessons::SceneLoadResult saved = lessons::loadSceneFile(path); saved.ok)
            base = saved.scene;
    }
    m_document->reset(base, path);
    if (modified)
        m_document->apply(tr("Edits made before the language changed"), edited);
}

bool MainWindow::saveScene()
{
    const QString path = m_document->path();
    if (!m_documentIsFile || path.isEmpty())
        return saveSceneAs();
    if (isShipped(path)) {
        statusBar()->showMessage(
            tr("%1 comes with RigidLab and is not overwritten: save your version under a name "
               "of its own.")
                .arg(QFileInfo(path).fileName()),
            8000);
        return saveSceneAs();
    }
    return writeDocument(path);
}

bool MainWindow::saveSceneAs()
{
    const QString folder = lessons::userScenesDir();
    QDir().mkpath(folder); // so that the dialog starts there
    const QString current = m_documentIsFile ? QFileInfo(m_document->path()).fileName() : QString();
    const QString suggested = QDir(folder).filePath(
        current.isEmpty() ? lessons::schema::safeFileName(m_document->scene().title) : current);
    QString path;
    if (m_savePathAsker) {
        path = m_savePathAsker(suggested);
    } else {
        const ModalScope modal;
        path = QFileDialog::getSaveFileName(this, tr("Save scene as"), suggested,
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
        auto* box = new QMessageBox(QMessageBox::Warning, tr("Scene not saved"), m_lastError,
                                    QMessageBox::Ok, this);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->setObjectName(QStringLiteral("saveErrorBox"));
        box->open();
        return false;
    }
    return writeDocument(path);
}

bool MainWindow::writeDocument(const QString& path)
{
    const QString error = lessons::saveScene(path, m_document->scene());
    if (!error.isEmpty()) {
        m_lastError = error;
        auto* box = new QMessageBox(QMessageBox::Warning, tr("Scene not saved"), error,
                                    QMessageBox::Ok, this);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->setObjectName(QStringLiteral("saveErrorBox"));
        box->open();
        return false;
    }
    m_lastError.clear();
    m_documentIsFile = true;
    m_document->markSaved(path);
    m_lastFolder = QFileInfo(path).absolutePath();
    addRecent(QFileInfo(path).absoluteFilePath());
    rebuildOwnScenesMenu();
    statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(path)), 5000);
    return true;
}

bool MainWindow::confirmLeaveScene()
{
    if (!m_document->isModified())
        return true;
    int answer = QMessageBox::Cancel;
    if (m_unsavedAsker) {
        answer = m_unsavedAsker();
    } else {
        const ModalScope modal;
        QMessageBox box(
            QMessageBox::Question, tr("Unsaved changes"),
            tr("The scene “%1” has changes that are not saved.").arg(m_document->scene().title),
            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, this);
        box.setObjectName(QStringLiteral("unsavedBox"));
        box.setInformativeText(tr("Save them before going on?"));
        box.setDefaultButton(QMessageBox::Save);
        answer = box.exec();
    }
    if (answer == QMessageBox::Save)
        return saveScene();
    return answer == QMessageBox::Discard;
}

void MainWindow::rebuildOwnScenesMenu()
{
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
        m_ownScenesMenu->addAction(scene.title, this, [this, p = scene.path] { openScene(p); });
}

} // namespace rigidlab::ui
