// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lab window: the world view in the middle; controls, inspector and plots in docks;
// a timeline for time travel; menus, a toolbar and a status bar. MainWindow makes the panels
// and the parts that each do one job (window_documents.h, lesson_session.h, window_layout.h,
// status_line.h, window_actions.h) and connects them; its public functions are the parts'
// answers, for the program and the tests.

#include "view/overlays.h"

#include <QList>
#include <QMainWindow>
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
class QToolBar;

namespace rigidlab::lessons {
struct Lesson;
struct LessonStep;
struct Scene;
} // namespace rigidlab::lessons

namespace rigidlab::ui {

class BouncePanel;
class ClassResultsDialog;
class CollisionPanel;
class ControlPanel;
class EditTools;
class InspectorPanel;
class Instruments;
class LessonEditor;
class LessonPlayer;
class LessonSession;
class MeasurementSession;
class SatPanel;
class PlotTurns;
class PlotWidget;
class SceneDocument;
class SimulationController;
class StatusLine;
class WindowActions;
class WindowDocuments;
class WindowKeyboard;
class WindowLayout;
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
    /// shown and lastError() holds it.
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
    void setSavePathAsker(SavePathAsker asker);
    /// The folder the Open dialog starts in (empty: the shipped scenes).
    const QString& lastFolder() const;
    /// The answer to the unsaved-changes question: QMessageBox::Save, Discard or Cancel.
    /// Unset: a message box.
    using UnsavedAsker = std::function<int()>;
    void setUnsavedAsker(UnsavedAsker asker);
    /// Whether the document is a scene file of its own, which Save writes to (not a new scene
    /// nor a lesson's).
    bool documentIsFile() const;
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
    /// The lesson editor in a window of its own, on the lesson at `path` (a new lesson on the
    /// scene being edited when empty); Try as a student plays its lesson here. Returns it, or
    /// nullptr with `error` set when the lesson does not open.
    LessonEditor* editLesson(const QString& path, QString* error = nullptr);
    /// Before New lesson and Edit lesson: when an autosave a crash left is there (one no open
    /// editor holds, LessonEditor::keptLessons), asks whether to open it (as unsaved work),
    /// delete it, or cancel. Returns whether to go on with what was asked.
    bool offerKeptLesson();
    /// While a lesson tried from the lesson editor plays: raises the editor with the step the
    /// student is on selected (the bar above the docks, File › Back to the lesson editor).
    void backToLessonEditor();
    /// File › Class results…: the dialog that collects a class's answers files (one per
    /// window, raised again when open). Returns it.
    ClassResultsDialog* showClassResults();
    SatPanel& satPanel() { return *m_sat; }
    BouncePanel& bouncePanel() { return *m_bounces; }
    CollisionPanel& collisionPanel() { return *m_collision; }
    /// The first plot comparing worlds side by side in this lesson step, or nullptr.
    PlotWidget* comparePlot() const;
    /// Every plot comparing worlds in this step (compare-energy, compare-drift), in the order
    /// the step names them.
    const std::vector<PlotWidget*>& comparePlots() const;
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
    /// The scene editor: Edit mode and its tools.
    EditTools& editTools() { return *m_editTools; }
    /// An imported measurement, its comparison and fit (ui/measure).
    MeasurementSession& measurement() { return *m_measurement; }
    /// The instruments and graphs of chosen bodies (ui/instruments).
    Instruments& instruments() { return *m_instruments; }
    /// The window's own plot by its name in lessons (plot_table.h: "energy"), or nullptr.
    PlotWidget* plot(QStringView name) const;
    /// The window's own plots, one per row of the plots' table that is of the main world.
    const QList<PlotWidget*>& plots() const { return m_plots; }
    QString lastError() const;
    QAction* overlayAction(Overlay overlay) const;
    /// Help › Controls (rich text), from the table that registers the keys (shortcuts.h).
    QString controlsHelpText() const;
    /// What the status bar shows now, its visible parts joined.
    QString statusText() const;
    /// View › Status details: steps/s, frame and stage timings in the status bar.
    QAction* statusDetailsAction() const;

    /// Sizes the window for a screen's available area (never larger) and arranges the docks
    /// for it: on a small screen the plots share a tabbed dock (window_layout.cpp).
    void fitToScreen(const QRect& available);
    /// Whether the docks are arranged for a small screen.
    bool compactLayout() const;
    /// Presentation mode (View › Presentation, F11, rigidlab --present): full screen, larger
    /// text, thicker lines, a high-contrast palette, no developer details. Leaving it
    /// restores the layout.
    void setPresentation(bool on);
    bool presentation() const;
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
    void moveEvent(QMoveEvent* event) override;

private slots:
    void updateStatus();

private:
    void wireDocument();
    void wirePanels();
    /// Tells the controller whether the bounce or collision table is open
    /// (SimulationController::setEventsShown), now and whenever one opens or closes.
    /// The docks that show the run's events (bounces, collision), which measure while open.
    std::array<QDockWidget*, 2> eventTables() const;
    void followEventTables();
    void buildMenus();
    void buildFileMenu();
    /// File › New lesson and Edit lesson…: the lesson editor (window_lesson_editor.cpp).
    void addLessonEditorEntries(QMenu& file);
    /// The way back to `editor` shown while the lesson tried from it plays; hidden again when
    /// another lesson or a scene opens, or the editor closes (window_lesson_editor.cpp).
    void showWayBack(LessonEditor* editor);
    void hideWayBack();
    void buildEditMenu();
    void buildViewMenu();
    void buildHelpMenu();
    /// The scene editor's tools, toolbar and docks (main_window_editor.cpp).
    void buildEditor();
    QDockWidget* buildPropertiesDock();
    void buildHistoryDock(QDockWidget& properties);
    /// The plots on screen now: File › Export plot offers these.
    QList<PlotWidget*> plotsOnScreen() const;
    void showControlsHelp();
    /// The window's title outside a lesson: the scene's.
    void showSceneTitle();
    void restoreSettings();

    SimulationController* m_controller;
    SceneDocument* m_document;
    WorldView* m_view;
    ControlPanel* m_controls;
    InspectorPanel* m_inspector;
    LessonPlayer* m_player;
    SatPanel* m_sat;
    BouncePanel* m_bounces;
    CollisionPanel* m_collision;
    PlotTurns* m_plotTurns;      ///< the plots' drains spread over the frames
    QList<PlotWidget*> m_plots;  ///< each named by its row (plot_table.h)
    bool m_closePending = false; ///< asked to close while a dialog's answer was pending

    // The parts the window wires together, each with one job.
    WindowActions* m_actions = nullptr;          ///< run actions, overlays, simulation toolbar
    WindowLayout* m_layout = nullptr;            ///< docks, their places, presentation mode
    WindowKeyboard* m_keyboard = nullptr;        ///< step, focus and body keys; focus ring
    StatusLine* m_status = nullptr;              ///< status bar and timeline
    WindowDocuments* m_documents = nullptr;      ///< scene files and recent files
    EditTools* m_editTools = nullptr;            ///< the scene editor (ui/editor)
    LessonSession* m_session = nullptr;          ///< a lesson's steps in the window
    MeasurementSession* m_measurement = nullptr; ///< an imported measurement (ui/measure)
    Instruments* m_instruments = nullptr;        ///< ruler, protractor, stopwatch, probe
    QMenu* m_viewMenu = nullptr;
    QAction* m_presentAction = nullptr;
    // Try as a student: the editor the lesson playing was tried from, the lesson's file, and
    // the way back (the bar is made at the first try, so that no saved layout shows it).
    // Held as a widget: its end is heard from QWidget's destructor, when it is no longer
    // a LessonEditor.
    QPointer<QWidget> m_triedFrom;
    QString m_triedPath;
    QAction* m_backToEditor = nullptr;
    QToolBar* m_backBar = nullptr;
};

} // namespace rigidlab::ui
