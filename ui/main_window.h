#pragma once
// The lab window: the world view in the middle; controls, inspector and plots in docks;
// a timeline for time travel; menus, a toolbar and a status bar.

#include "overlays.h"

#include <QMainWindow>
#include <QString>

#include <array>

class QAction;
class QLabel;
class QMenu;
class QSlider;

namespace rigidlab::ui {

class ControlPanel;
class InspectorPanel;
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

protected:
    void closeEvent(QCloseEvent* event) override;

private slots:
    void openDialog();
    void updateStatus();
    void updateTimeline();

private:
    void buildActions();
    void buildMenus();
    void buildDocks();
    void addRecent(const QString& path);
    void rebuildRecentMenu();
    void exportPlotDialog(PlotWidget* plot, const QString& format);
    void restoreSettings();

    SimulationController* m_controller;
    WorldView* m_view;
    ControlPanel* m_controls;
    InspectorPanel* m_inspector;
    std::array<PlotWidget*, kPlotCount> m_plots{};
    QSlider* m_timeline = nullptr;
    QLabel* m_timeLabel = nullptr;
    QLabel* m_statusTime = nullptr;
    QLabel* m_statusRate = nullptr;
    QLabel* m_statusDrift = nullptr;
    QLabel* m_statusSlow = nullptr;
    QMenu* m_recentMenu = nullptr;
    QMenu* m_scenesMenu = nullptr;
    QMenu* m_viewMenu = nullptr;
    QAction* m_playAction = nullptr;
    QAction* m_stepAction = nullptr;
    QAction* m_backAction = nullptr;
    QAction* m_resetAction = nullptr;
    QAction* m_fitAction = nullptr;
    std::array<QAction*, kOverlayCount> m_overlayActions{};
    QString m_lastError;
    QString m_lastFolder;
};

} // namespace rigidlab::ui
