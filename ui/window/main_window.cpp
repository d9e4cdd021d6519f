// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow's making and closing: the parts and how they are wired, its settings.
// Its other parts: main_window_menus.cpp (actions, toolbars, menus), main_window_docks.cpp,
// main_window_files.cpp (scenes, recent files, plot export), main_window_lesson.cpp,
// main_window_status.cpp (status bar, timeline), main_window_layout.cpp.
#include "window/main_window.h"

#include "common/export_folder.h"
#include "common/modal_scope.h"
#include "editor/edit_tools.h"
#include "editor/scene_document.h"
#include "lesson_player/lesson_panels.h"
#include "lesson_player/lesson_player.h"
#include "panels/control_panel.h"
#include "panels/divergence_banner.h"
#include "panels/inspector_panel.h"
#include "panels/sat_panel.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"
#include "window/settings_sync.h"
#include "window/window_names.h"

#include "format/data_dirs.h"
#include "format/lesson.h"
#include "format/lesson_catalog.h"

#include <QAction>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>

namespace rigidlab::ui {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), m_controller(new SimulationController(this)),
      m_document(new SceneDocument(this)), m_view(new WorldView(*m_controller, this)),
      m_controls(new ControlPanel(*m_controller, this)),
      m_inspector(new InspectorPanel(*m_controller, this)),
      m_player(new LessonPlayer(*m_controller, this)), m_sat(new SatPanel(*m_controller, this)),
      m_bounces(new BouncePanel(*m_controller, this)),
      m_collision(new CollisionPanel(*m_controller, this))
{
    m_view->scene()->addItem(m_sat->overlay());
    m_player->listLessons(lessons::allLessonsInOrder()); // shipped, then the user's own
    connect(m_player, &LessonPlayer::stepActivated, this, &MainWindow::applyLessonStep);
    connect(m_player, &LessonPlayer::lessonClosed, this, &MainWindow::leaveLesson);
    connect(m_player, &LessonPlayer::heldBackChanged, this, [this](const QStringList& held) {
        const bool wasHeld = m_runHeld;
        applyHeldBack(held);
        if (wasHeld && !m_runHeld)
            m_controller->setRunning(true); // predicted: now see
    });
    connect(m_player, &LessonPlayer::exportRequested, this, [this] {
        const ModalScope modal;
        const QString folder = QFileDialog::getExistingDirectory(
            this, tr("Export the step's plots into"), exportFolder());
        if (folder.isEmpty())
            return;
        rememberExportFolder(folder);
        const QStringList errors = exportStepPlots(folder);
        if (!errors.isEmpty())
            QMessageBox::warning(this, tr("Export failed"), errors.join(QLatin1Char('\n')));
        else
            statusBar()->showMessage(tr("Plots written to %1").arg(folder), 6000);
    });
    setWindowTitle(tr("RigidLab"));
    setCentralWidget(m_view);
    buildActions();
    buildDocks();
    buildEditor();
    buildMenus();

    new DivergenceBanner(*m_controller, m_view);
    buildStatusBar();

    connect(m_view, &WorldView::bodySelected, m_inspector, &InspectorPanel::setBody);
    // A typed value refused (out of range, not a number) is said in the status bar too.
    // (Received by the status bar itself: a field left while the window is being destroyed
    // commits, and may refuse, after MainWindow's own part is gone.)
    QStatusBar* bar = statusBar();
    const auto showRefusal = [bar](const QString& why) { bar->showMessage(why, 8000); };
    connect(m_controls, &ControlPanel::inputRefused, bar, showRefusal);
    connect(m_inspector, &InspectorPanel::inputRefused, bar, showRefusal);
    connect(m_controller, &SimulationController::runningChanged, this, [this](bool running) {
        m_playAction->setText(running ? tr("Pause") : tr("Play"));
        m_playAction->setIcon(
            style()->standardIcon(running ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    });
    connect(m_controller, &SimulationController::worldChanged, this, &MainWindow::updateTimeline);
    connect(m_controller, &SimulationController::sceneLoaded, this, [this] {
        if (!m_inLesson) // in a lesson, its title and step stay (applyLessonStep)
            showSceneTitle();
    });
    // Every change to the document (an edit, undo, redo, opening) rebuilds the world from it,
    // so Run starts from the scene as edited and Reset returns to it. A lesson step loads its
    // worlds itself (compared worlds too) when it starts the document over.
    connect(m_document, &SceneDocument::sceneChanged, this, [this] {
        if (m_lessonLoading)
            return;
        const lessons::Lesson* lesson = m_player->lesson();
        if (m_inLesson && lesson) // the step's settings, compared worlds and measurements stay
            loadStepWorlds(lesson->steps[static_cast<size_t>(m_player->stepIndex())],
                           m_document->scene(), m_document->path());
        else
            m_controller->loadScene(m_document->scene(), m_document->path());
    });
    connect(m_document, &SceneDocument::modifiedChanged, this, [this](bool modified) {
        if (windowTitle().contains(QLatin1String("[*]")))
            setWindowModified(modified);
    });
    connect(m_document, &SceneDocument::pathChanged, this, [this] {
        if (!m_inLesson)
            showSceneTitle();
    });
    m_player->setLeaveGuard([this] { return confirmLeaveScene(); });
    for (PlotWidget* plot : m_plots)
        followController(plot);
    restoreSettings();
    updateStatus();
}

MainWindow::~MainWindow() = default;

void MainWindow::showSceneTitle()
{
    // The scene's title and its file; "*" (the [*] placeholder) while it has unsaved edits.
    const QString title = m_controller->scene().title;
    const QString file = QFileInfo(m_document->path()).fileName();
    if (file.isEmpty())
        setWindowTitle(title.isEmpty() ? tr("RigidLab[*]") : tr("%1[*] — RigidLab").arg(title));
    else if (title.isEmpty())
        setWindowTitle(tr("%1[*] — RigidLab").arg(file));
    else
        setWindowTitle(tr("%1 (%2)[*] — RigidLab").arg(title, file));
    setWindowModified(m_document->isModified());
}

void MainWindow::followController(PlotWidget* plot)
{
    // The live samples, cleared with a new scene, cut back on a rewind, marked where a setting
    // changed, drained after each frame.
    plot->setSource(&m_controller->samples());
    connect(m_controller, &SimulationController::samplesCleared, plot, &PlotWidget::clear);
    connect(m_controller, &SimulationController::rewound, plot, &PlotWidget::rewind);
    connect(m_controller, &SimulationController::marked, plot, &PlotWidget::addMark);
    connect(m_controller, &SimulationController::frameAdvanced, plot, &PlotWidget::frameAdvanced);
    // The plot keeps its points as far back as the timeline goes (going back shows them).
    connect(m_controller, &SimulationController::worldChanged, plot,
            [plot, c = m_controller] { plot->setTimelineStart(c->earliestTime()); });
}

QString MainWindow::scenesFolder()
{
    return lessons::shippedScenesDir();
}

QString MainWindow::lessonsFolder()
{
    return lessons::shippedLessonsDir();
}

void MainWindow::restoreSettings()
{
    QSettings s;
    m_lastFolder = s.value(QStringLiteral("lastFolder")).toString();
    restoreLayout(s);
    // A layout saved in Edit mode would show the editor's tools and docks outside it.
    const bool editing = m_editTools && m_editTools->editing();
    if (auto* tools = findChild<QToolBar*>(QStringLiteral("editToolbar")))
        tools->setVisible(editing);
    for (const char* name : {"propertiesDock", "historyDock"})
        if (auto* dock = findChild<QDockWidget*>(QLatin1String(name)))
            dock->setVisible(editing);
    for (std::size_t i = 0; i < kOverlayNames.size(); ++i) {
        const QString key =
            QStringLiteral("overlays/") + QLatin1String(kOverlayNames[i].settingKey);
        if (s.contains(key))
            m_overlayActions[i]->setChecked(s.value(key).toBool());
    }
    rebuildRecentMenu();
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    // Asked to close while a dialog's answer is still to be acted upon (an export's folder):
    // close right after it, so that nothing the user chose is dropped (modal_scope.h).
    if (ModalScope::active()) {
        event->ignore();
        if (!m_closePending) {
            m_closePending = true;
            ModalScope::whenDone(this, [this] {
                m_closePending = false;
                close();
            });
        }
        return;
    }
    if (!confirmLeaveScene()) { // unsaved edits: Save, Discard or Cancel
        event->ignore();
        return;
    }
    m_controller->setRunning(false);
    QSettings s;
    saveLayout(s);
    for (std::size_t i = 0; i < kOverlayNames.size(); ++i)
        s.setValue(QStringLiteral("overlays/") + QLatin1String(kOverlayNames[i].settingKey),
                   m_overlayActions[i]->isChecked());
    syncSettings(s, *this);
    event->accept();
}

} // namespace rigidlab::ui
