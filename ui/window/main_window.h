// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lab window: the world view in the middle; controls, inspector and plots in docks;
// a timeline for time travel; menus, a toolbar and a status bar.

#include "view/overlays.h"

#include <QFont>
#include <QMainWindow>
#include <QMap>
#include <QPalette>
#include <QPointer>
#include <QString>

#include <array>
#include <functional>
#include <utility>
#include <vector>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QSettings;
class QSlider;

namespace rigidlab::lessons {
struct Lesson;
struct LessonStep;
struct Scene;
} // namespace rigidlab::lessons

namespace rigidlab::ui {

class BouncePanel;
class CollisionPanel;
class ControlPanel;
class EditTools;
class InspectorPanel;
class LessonPlayer;
class SatPanel;
class PlotWidget;
class SceneDocument;
class SimulationController;
class WorldView;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Opens a scene file. On an error the current scene stays and the message is shown
    /// (in a dialog unless `quiet`); returns the error, empty on success.
    QString openScene(const QString& path, bool quiet = false);
    /// File › New scene: an empty scene with the default world and a ground. False when the
    /// question about unsaved changes was cancelled (nothing changes then).
    bool newScene();
    /// File › Save: writes the scene to its file; a scene with none (a new one, a lesson's) or
    /// a shipped one goes to Save As. True when written; on failure the writer's message is
    /// shown and lastError() holds it (main_window_save.cpp).
    bool saveScene();
    /// File › Save As: asks for a file (starting in the user's scenes folder) and writes there.
    /// A shipped scene is never overwritten. True when written.
    bool saveSceneAs();
    /// Where the scene has unsaved edits, asks whether to save them (Save / Discard / Cancel):
    /// true to go on (saved or discarded), false to stay (cancelled, or the save failed).
    bool confirmLeaveScene();
    /// The file Save As writes to, given the suggested path; empty to cancel. Unset: a file
    /// dialog. (Tests answer without a dialog.)
    using SavePathAsker = std::function<QString(const QString& suggested)>;
    void setSavePathAsker(SavePathAsker asker) { m_savePathAsker = std::move(asker); }
    /// The folder the Open dialog starts in (empty: the shipped scenes).
    const QString& lastFolder() const { return m_lastFolder; }
    /// The answer to the unsaved-changes question: QMessageBox::Save, Discard or Cancel.
    /// Unset: a message box.
    using UnsavedAsker = std::function<int()>;
    void setUnsavedAsker(UnsavedAsker asker) { m_unsavedAsker = std::move(asker); }
    /// Whether the document is a scene file of its own, which Save writes to (not a new scene
    /// nor a lesson's).
    bool documentIsFile() const { return m_documentIsFile; }
    /// Takes over the scene another window was editing (a language switch): `edited`, which
    /// belongs to the file at `path` when `isFile`, `modified` if it has unsaved edits (then
    /// undoing goes back to the file as saved, or to the scene as it was).
    void adoptDocument(const lessons::Scene& edited, const QString& path, bool isFile,
                       bool modified);
    /// Folder with the shipped scenes.
    static QString scenesFolder();
    /// Folder with the shipped lessons.
    static QString lessonsFolder();
    /// Opens a lesson at its first step; returns the error, empty on success.
    QString openLesson(const QString& path, bool quiet = false);
    LessonPlayer& lessonPlayer() { return *m_player; }
    SatPanel& satPanel() { return *m_sat; }
    BouncePanel& bouncePanel() { return *m_bounces; }
    CollisionPanel& collisionPanel() { return *m_collision; }
    /// The first plot comparing worlds side by side in this lesson step, or nullptr.
    PlotWidget* comparePlot() const
    {
        return m_comparePlots.empty() ? nullptr : m_comparePlots.front();
    }
    /// Every plot comparing worlds in this step (compare-energy, compare-drift), in the order
    /// the step names them.
    const std::vector<PlotWidget*>& comparePlots() const { return m_comparePlots; }
    /// The dock holding a panel or plot, by its lesson name ("energy", "sat", ...).
    QDockWidget* dock(const QString& name) const;
    /// Writes the current step's plots (PNG, PDF, SVG, CSV) into a folder; returns errors.
    QStringList exportStepPlots(const QString& folder);

    SimulationController& controller() { return *m_controller; }
    /// The scene as edited (ui/editor): opening a scene or a lesson step starts it over; every
    /// change to it reloads the world, so Run and Reset start from the scene as edited.
    SceneDocument* document() const { return m_document; }
    WorldView& view() { return *m_view; }
    ControlPanel& controls() { return *m_controls; }
    InspectorPanel& inspector() { return *m_inspector; }
    /// The scene editor: Edit mode and its tools (main_window_editor.cpp).
    EditTools& editTools() { return *m_editTools; }
    PlotWidget* plot(int index) const { return m_plots[static_cast<size_t>(index)]; }
    static constexpr int kPlotCount = 3;
    QString lastError() const { return m_lastError; }
    QAction* overlayAction(Overlay overlay) const
    {
        return m_overlayActions[static_cast<size_t>(overlay)];
    }
    /// Help › Controls (rich text), from the table that registers the keys (shortcuts.h).
    QString controlsHelpText() const;
    /// What the status bar shows now, its visible parts joined.
    QString statusText() const;
    /// View › Status details: steps/s, frame and stage timings in the status bar.
    QAction* statusDetailsAction() const { return m_detailsAction; }

    /// Sizes the window for a screen's available area (never larger) and arranges the docks
    /// for it: on a small screen the plots share a tabbed dock (main_window_layout.cpp).
    void fitToScreen(const QRect& available);
    /// Whether the docks are arranged for a small screen.
    bool compactLayout() const { return m_compact; }
    /// Presentation mode (View › Presentation, F11, rigidlab --present): full screen, larger
    /// text, thicker lines, a high-contrast palette, no developer details. Leaving it
    /// restores the layout.
    void setPresentation(bool on);
    bool presentation() const { return m_presentation; }
    /// Stage timings and steps per second in the status bar, where View › Status details asks
    /// for them and presentation mode does not hide them.
    void setDetailsShown(bool shown);

signals:
    /// View › Language chose another language (saved already): the owner of the window
    /// replaces it with one in that language (window/language_switch.h).
    void languageChosen(const QString& code);

protected:
    void closeEvent(QCloseEvent* event) override;
    void showEvent(QShowEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private slots:
    void openDialog();
    void openLessonDialog();
    void applyLessonStep(const rigidlab::lessons::Lesson& lesson, int step);
    void leaveLesson();
    /// The window's title outside a lesson: the scene's.
    void showSceneTitle();
    /// Hides what the lesson step's questions still hold back, shows what they released.
    void applyHeldBack(const QStringList& held);
    void updateStatus();
    void updateTimeline();

private:
    /// Loads a lesson step's worlds (compared ones too) from `scene`, with the step's settings
    /// and measurements; returns the compared worlds' labels, empty when none.
    QStringList loadStepWorlds(const lessons::LessonStep& step, const lessons::Scene& scene,
                               const QString& path);
    void buildActions();
    void buildMenus();
    void buildStatusBar();
    void buildDocks();
    /// The scene editor's document, tools and toolbar (main_window_editor.cpp).
    void buildEditor();
    /// The editor's History dock, a tab beside its Properties (main_window_history.cpp).
    void buildHistory(QDockWidget& properties);
    /// What Edit mode changes in the rest of the window: Step and Back off while editing, a
    /// lesson step's measurements kept on the world as edited (main_window_editor.cpp).
    void followEditMode();
    /// Step and Back: disabled while editing (the world does not step) or while a question
    /// holds the run back, with a tooltip saying why.
    void updateStepActions();
    void addRecent(const QString& path);
    /// File › Your own scenes, made when the user's scenes folder holds any, remade after a
    /// save (main_window_save.cpp).
    void rebuildOwnScenesMenu();
    /// Writes the document to `path`: true when written, else the reason is shown.
    bool writeDocument(const QString& path);
    void rebuildRecentMenu();
    void exportPlotDialog(PlotWidget* plot, const QString& format);
    void restoreSettings();
    /// Connects a plot to the controller's samples and clock.
    void followController(PlotWidget* plot);
    QRect availableScreenArea() const;
    /// Stacked plots on a roomy `screen`, tabbed on a small one; side columns for the window.
    void arrangeDocks(const QSize& screen, int windowWidth);
    /// Side columns no wider than their share of `windowWidth`: the world keeps half.
    void fitSideColumns(int windowWidth);
    void saveLayout(QSettings& settings) const;
    void restoreLayout(const QSettings& settings);

    SimulationController* m_controller;
    SceneDocument* m_document;
    /// A lesson step is starting the document over: it loads its own worlds (compared ones too).
    bool m_lessonLoading = false;
    WorldView* m_view;
    ControlPanel* m_controls;
    InspectorPanel* m_inspector;
    LessonPlayer* m_player;
    SatPanel* m_sat;
    BouncePanel* m_bounces;
    CollisionPanel* m_collision;
    std::vector<PlotWidget*> m_comparePlots; ///< in m_compareDock
    QDockWidget* m_compareDock = nullptr;
    QMap<QString, QDockWidget*> m_docks;
    bool m_inLesson = false;
    bool m_closePending = false; ///< asked to close while a dialog's answer was pending
    bool m_runHeld = false;      ///< a question keeps the scene from running until it is answered
    std::array<PlotWidget*, kPlotCount> m_plots{};
    QSlider* m_timeline = nullptr;
    QLabel* m_timeLabel = nullptr;
    QLabel* m_statusTime = nullptr;
    QLabel* m_statusRate = nullptr;
    QLabel* m_statusDrift = nullptr;
    QLabel* m_statusSlow = nullptr;
    QLabel* m_statusDetails = nullptr;
    QAction* m_detailsAction = nullptr;
    QMenu* m_recentMenu = nullptr;
    QMenu* m_scenesMenu = nullptr;
    QMenu* m_viewMenu = nullptr;
    QMenu* m_editMenu = nullptr;
    QMenu* m_fileMenu = nullptr;
    QMenu* m_ownScenesMenu = nullptr;     ///< File › Your own scenes, when there are any
    QAction* m_ownScenesBefore = nullptr; ///< the File menu entry it goes before
    /// The document is a scene file of its own (opened or saved): Save writes to its path.
    /// A new scene and a lesson's scene (its path is the lesson's) go to Save As.
    bool m_documentIsFile = false;
    SavePathAsker m_savePathAsker;
    UnsavedAsker m_unsavedAsker;
    QAction* m_undoAction = nullptr;
    QAction* m_redoAction = nullptr;
    QAction* m_playAction = nullptr;
    QAction* m_stepAction = nullptr;
    QAction* m_backAction = nullptr;
    QAction* m_resetAction = nullptr;
    QAction* m_fitAction = nullptr;
    std::array<QAction*, kOverlayCount> m_overlayActions{};
    QList<QAction*> m_rotateActions;
    QString m_lastError;
    QString m_lastFolder;

    // Layout and presentation mode (main_window_layout.cpp).
    QRect m_screenArea;     ///< the available area the layout was made for
    bool m_compact = false; ///< plots tabbed for a small screen
    bool m_presentation = false;
    bool m_restoreStatePending = false; ///< docks to put back once full screen has ended
    bool m_normalWasMaximized = false;
    QByteArray m_normalGeometry; ///< before presentation mode
    QByteArray m_normalState;
    QFont m_normalFont;
    std::vector<std::pair<QPointer<QWidget>, QFont>> m_explicitFonts; ///< before presentation
    QPalette m_normalPalette;
    QAction* m_presentAction = nullptr;

    // The scene editor's tools (main_window_editor.cpp).
    EditTools* m_editTools = nullptr;
};

} // namespace rigidlab::ui
