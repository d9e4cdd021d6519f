// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The window's scene files: New, Open, Save, Save As, the question about unsaved changes, the
// recent files and File › Your own scenes (window_documents.cpp, window_documents_save.cpp).
// It works on the edited scene (editor/scene_document.h); the world follows the document.

#include <QObject>
#include <QString>

#include <functional>

class QAction;
class QMenu;
class QWidget;

namespace rigidlab::lessons {
struct Scene;
}

namespace rigidlab::ui {

class SceneDocument;

class WindowDocuments : public QObject {
    Q_OBJECT
public:
    /// `window` parents the dialogs and shows the messages in its status bar.
    WindowDocuments(QWidget& window, SceneDocument& document);

    /// Called before a scene of one's own replaces the lesson's (it ends the lesson).
    void setLeaveLesson(std::function<void()> leave) { m_leaveLesson = std::move(leave); }
    /// Where File › Open recent and File › Your own scenes go.
    void setMenus(QMenu* recent, QMenu* file, QAction* ownScenesBefore);

    QString openScene(const QString& path, bool quiet);
    void openDialog();
    /// An empty scene with the default world and a ground; false when the question about
    /// unsaved changes was cancelled.
    bool newScene();
    bool saveScene();
    bool saveSceneAs();
    bool confirmLeaveScene();
    void adoptDocument(const lessons::Scene& edited, const QString& path, bool isFile,
                       bool modified);
    /// A lesson step made the document: its path is the lesson's, Save asks where.
    void setDocumentIsFile(bool isFile) { m_documentIsFile = isFile; }
    bool documentIsFile() const { return m_documentIsFile; }

    using SavePathAsker = std::function<QString(const QString& suggested)>;
    void setSavePathAsker(SavePathAsker asker) { m_savePathAsker = std::move(asker); }
    using UnsavedAsker = std::function<int()>;
    void setUnsavedAsker(UnsavedAsker asker) { m_unsavedAsker = std::move(asker); }
    const QString& lastFolder() const { return m_lastFolder; }
    QString lastError() const { return m_lastError; }
    void setLastError(const QString& error) { m_lastError = error; }
    /// Reads the last folder from the settings and fills the recent files' menu.
    void restoreSettings();

signals:
    /// File › Open chose a lesson (a .rlesson, or a lesson's .json): the lesson opens.
    void lessonChosen(const QString& path);
    /// A new scene was made: the editor opens, so that the teacher can draw at once.
    void newSceneMade();
    /// A message for the status bar, shown for `ms` milliseconds.
    void message(const QString& text, int ms);

private:
    bool writeDocument(const QString& path);
    void showError(const QString& title, const QString& text, const char* name);
    void addRecent(const QString& path);
    void rebuildRecentMenu();
    void rebuildOwnScenesMenu();

    QWidget& m_window;
    SceneDocument& m_document;
    std::function<void()> m_leaveLesson;
    QMenu* m_recentMenu = nullptr;
    QMenu* m_fileMenu = nullptr;
    QMenu* m_ownScenesMenu = nullptr;     ///< File › Your own scenes, when there are any
    QAction* m_ownScenesBefore = nullptr; ///< the File menu entry it goes before
    /// The document is a scene file of its own (opened or saved): Save writes to its path.
    /// A new scene and a lesson's scene (its path is the lesson's) go to Save As.
    bool m_documentIsFile = false;
    SavePathAsker m_savePathAsker;
    UnsavedAsker m_unsavedAsker;
    QString m_lastError;
    QString m_lastFolder;
};

} // namespace rigidlab::ui
