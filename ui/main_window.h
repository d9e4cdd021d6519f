#pragma once
// The lab window: the world view in the middle; controls, inspector and plots in docks;
// a timeline for time travel; menus, a toolbar and a status bar.

#include "overlays.h"

#include <QMainWindow>
#include <QMap>
#include <QString>

#include <array>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QSlider;

namespace rigidlab::lessons {
struct Lesson;
}

namespace rigidlab::ui {

class BouncePanel;
class CollisionPanel;
class ControlPanel;
class InspectorPanel;
class LessonPlayer;
class SatPanel;
class PlotWidget;
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
    /// The plot comparing worlds side by side in this lesson step, or nullptr.
    PlotWidget* comparePlot() const { return m_compare; }
    /// The dock holding a panel or plot, by its lesson name ("energy", "sat", ...).
    QDockWidget* dock(const QString& name) const;
    /// Writes the current step's plots (PNG, PDF, SVG, CSV) into a folder; returns errors.
    QStringList exportStepPlots(const QString& folder);

    SimulationController& controller() { return *m_controller; }
    WorldView& view() { return *m_view; }
    ControlPanel& controls() { return *m_controls; }
    InspectorPanel& inspector() { return *m_inspector; }
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

protected:
    void closeEvent(QCloseEvent* event) override;

private slots:
    void openDialog();
    void openLessonDialog();
    void applyLessonStep(const rigidlab::lessons::Lesson& lesson, int step);
    void leaveLesson();
    /// Hides what the lesson step's questions still hold back, shows what they released.
    void applyHeldBack(const QStringList& held);
    void updateStatus();
    void updateTimeline();

private:
    void buildActions();
    void buildMenus();
    void buildStatusBar();
    void buildDocks();
    void addRecent(const QString& path);
    void rebuildRecentMenu();
    void exportPlotDialog(PlotWidget* plot, const QString& format);
    void restoreSettings();

    SimulationController* m_controller;
    WorldView* m_view;
    ControlPanel* m_controls;
    InspectorPanel* m_inspector;
    LessonPlayer* m_player;
    SatPanel* m_sat;
    BouncePanel* m_bounces;
    CollisionPanel* m_collision;
    PlotWidget* m_compare = nullptr;
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
    QAction* m_playAction = nullptr;
    QAction* m_stepAction = nullptr;
    QAction* m_backAction = nullptr;
    QAction* m_resetAction = nullptr;
    QAction* m_fitAction = nullptr;
    std::array<QAction*, kOverlayCount> m_overlayActions{};
    QList<QAction*> m_rotateActions;
    QString m_lastError;
    QString m_lastFolder;
};

} // namespace rigidlab::ui
