// SPDX-License-Identifier: GPL-3.0-or-later
// WindowDocuments: opening scenes, new scenes, the recent files.
#include "window/window_documents.h"

#include "common/display_names.h"
#include "common/modal_scope.h"
#include "editor/scene_document.h"
#include "window/settings_sync.h"

#include "format/data_dirs.h"
#include "format/lesson_pack.h"
#include "format/scene_loader.h"

#include "rigidlab/physics/shape.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>

namespace rigidlab::ui {

namespace {

constexpr int kMaxRecent = 8;

} // namespace

WindowDocuments::WindowDocuments(QWidget& window, SceneDocument& document)
    : QObject(&window), m_window(window), m_document(document)
{
}

void WindowDocuments::setMenus(QMenu* recent, QMenu* file, QAction* ownScenesBefore)
{
    m_recentMenu = recent;
    m_fileMenu = file;
    m_ownScenesBefore = ownScenesBefore;
    rebuildOwnScenesMenu();
}

void WindowDocuments::showError(const QString& title, const QString& text, const char* name)
{
    auto* box = new QMessageBox(QMessageBox::Warning, title, text, QMessageBox::Ok, &m_window);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setObjectName(QLatin1String(name));
    box->open();
}

QString WindowDocuments::openScene(const QString& path, bool quiet)
{
    const lessons::SceneLoadResult r = lessons::loadSceneFile(path);
    if (!r.ok) {
        m_lastError = r.error;
        if (!quiet)
            showError(tr("Cannot open scene"), r.error, "sceneErrorBox");
        return r.error;
    }
    if (!confirmLeaveScene()) {
        m_lastError = tr("%1 was not opened: the edited scene stays.").arg(path);
        return m_lastError;
    }
    m_lastError.clear();
    if (m_leaveLesson)
        m_leaveLesson(); // a scene of one's own ends the lesson
    m_documentIsFile = true;
    // Which loads the world (the document's sceneChanged, MainWindow::MainWindow).
    m_document.reset(r.scene, path);
    for (const QString& w : r.warnings)
        emit message(w, 8000);
    // The Open dialog starts where a scene was last opened or saved; the shipped folder, where
    // the welcome scene is opened from at every start, does not replace a folder of one's own
    // (found by hand: saved, quit, started again, and Open showed the shipped scenes).
    const QString folder = QFileInfo(path).absolutePath();
    if (m_lastFolder.isEmpty() || QDir(folder) != QDir(lessons::shippedScenesDir()))
        m_lastFolder = folder;
    addRecent(QFileInfo(path).absoluteFilePath());
    return QString();
}

void WindowDocuments::openDialog()
{
    const ModalScope modal;
    const QString folder = m_lastFolder.isEmpty() ? lessons::shippedScenesDir() : m_lastFolder;
    const QString path = QFileDialog::getOpenFileName(
        &m_window, tr("Open scene or lesson"), folder,
        tr("RigidLab scenes and lessons (*.json *.rlesson);;Lessons in one file (*.rlesson)"));
    if (path.isEmpty())
        return;
    if (lessons::isLessonDocument(path))
        emit lessonChosen(path);
    else
        openScene(path, false);
}

bool WindowDocuments::newScene()
{
    if (!confirmLeaveScene())
        return false;
    if (m_leaveLesson)
        m_leaveLesson(); // a scene of one's own ends the lesson
    // The default world and a long ground to put things on, its top at y = 0 (SceneDocument).
    const lessons::Scene scene = SceneDocument::newScene(tr("New scene"));
    m_documentIsFile = false;
    m_document.reset(scene, QString()); // which loads the world
    m_lastError.clear();
    emit newSceneMade();
    return true;
}

void WindowDocuments::adoptDocument(const lessons::Scene& edited, const QString& path, bool isFile,
                                    bool modified)
{
    if (m_leaveLesson)
        m_leaveLesson();
    m_documentIsFile = isFile;
    lessons::Scene base = edited;
    if (isFile && modified) {
        // The file as saved is where undoing leads (read in this window's language).
        if (const lessons::SceneLoadResult saved = lessons::loadSceneFile(path); saved.ok)
            base = saved.scene;
    }
    m_document.reset(base, path);
    if (modified)
        m_document.apply(tr("Edits made before the language changed"), edited);
}

void WindowDocuments::restoreSettings()
{
    m_lastFolder = QSettings().value(QStringLiteral("lastFolder")).toString();
    rebuildRecentMenu();
}

void WindowDocuments::addRecent(const QString& path)
{
    QSettings s;
    QStringList recent = s.value(QStringLiteral("recentFiles")).toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent)
        recent.removeLast();
    s.setValue(QStringLiteral("recentFiles"), recent);
    s.setValue(QStringLiteral("lastFolder"), m_lastFolder);
    if (auto* main = qobject_cast<QMainWindow*>(&m_window))
        syncSettings(s, *main);
    rebuildRecentMenu();
}

void WindowDocuments::rebuildRecentMenu()
{
    if (!m_recentMenu)
        return;
    m_recentMenu->clear();
    const QStringList recent = QSettings().value(QStringLiteral("recentFiles")).toStringList();
    for (const QString& path : recent)
        m_recentMenu->addAction(menuEntryText(QFileInfo(path).fileName()), this,
                                [this, path] { openScene(path, false); });
    m_recentMenu->setEnabled(!recent.isEmpty());
}

} // namespace rigidlab::ui
