// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow's actions, toolbars and menus: the menus are made in buildMenus() alone.
#include "window/main_window.h"

#include "common/modal_scope.h"
#include "editor/scene_document.h"
#include "lesson_player/lesson_player.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"
#include "window/about_dialog.h"
#include "window/language_switch.h"
#include "window/shortcuts.h"
#include "window/window_names.h"

#include "format/data_dirs.h"
#include "format/scene_catalog.h"
#include "format/scene_loader.h"

#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QSlider>
#include <QStyle>
#include <QToolBar>
#include <QUndoStack>

#include <cmath>
#include <utility>

namespace rigidlab::ui {

void MainWindow::buildActions()
{
    auto* toolbar = addToolBar(tr("Simulation"));
    toolbar->setObjectName(QStringLiteral("simulationToolbar"));
    toolbar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);

    m_playAction = new QAction(style()->standardIcon(QStyle::SP_MediaPlay), tr("Play"), this);
    m_playAction->setObjectName(QStringLiteral("play"));
    m_playAction->setShortcuts(controlKeys("play"));
    m_playAction->setToolTip(tr("Play or pause (%1)").arg(controlKeysText("play")));
    connect(m_playAction, &QAction::triggered, m_controller, &SimulationController::toggleRunning);

    m_stepAction =
        new QAction(style()->standardIcon(QStyle::SP_MediaSeekForward), tr("Step"), this);
    m_stepAction->setObjectName(QStringLiteral("step"));
    m_stepAction->setShortcuts(controlKeys("step"));
    m_stepAction->setToolTip(tr("One step forward (%1)").arg(controlKeysText("step")));
    connect(m_stepAction, &QAction::triggered, m_controller, &SimulationController::stepForward);

    m_backAction =
        new QAction(style()->standardIcon(QStyle::SP_MediaSeekBackward), tr("Back"), this);
    m_backAction->setObjectName(QStringLiteral("back"));
    m_backAction->setShortcuts(controlKeys("back"));
    m_backAction->setToolTip(tr("One step back in time (%1)").arg(controlKeysText("back")));
    connect(m_backAction, &QAction::triggered, m_controller, &SimulationController::stepBack);

    m_resetAction = new QAction(style()->standardIcon(QStyle::SP_BrowserReload), tr("Reset"), this);
    m_resetAction->setObjectName(QStringLiteral("reset"));
    m_resetAction->setShortcuts(controlKeys("reset"));
    m_resetAction->setToolTip(
        tr("Back to the start of the scene (%1)").arg(controlKeysText("reset")));
    connect(m_resetAction, &QAction::triggered, m_controller, &SimulationController::reset);

    m_fitAction = new QAction(tr("Fit scene"), this);
    m_fitAction->setObjectName(QStringLiteral("fit"));
    m_fitAction->setShortcuts(controlKeys("fit"));
    m_fitAction->setToolTip(tr("Zoom to show every body (%1)").arg(controlKeysText("fit")));
    connect(m_fitAction, &QAction::triggered, m_view, &WorldView::fitScene);

    // Q and E turn the selected body (the SAT lesson turns its polygons this way).
    for (const auto& [name, degrees] : {std::pair{"turnLeft", 5.0}, std::pair{"turnRight", -5.0}}) {
        auto* turn = new QAction(
            degrees > 0 ? tr("Turn selected body left") : tr("Turn selected body right"), this);
        turn->setObjectName(QLatin1String(name));
        turn->setShortcuts(controlKeys(name));
        connect(turn, &QAction::triggered, this, [this, degrees] {
            if (m_view->selectedBody() >= 0)
                m_controller->rotateBody(m_view->selectedBody(), degrees * M_PI / 180.0);
        });
        addAction(turn);
        m_rotateActions << turn;
    }
    for (QAction* a : {m_backAction, m_playAction, m_stepAction, m_resetAction, m_fitAction})
        toolbar->addAction(a);
    toolbar->addSeparator();
    for (std::size_t i = 0; i < kOverlayNames.size(); ++i) {
        const OverlayNames& info = kOverlayNames[i];
        auto* a = new QAction(tr(info.text), this);
        a->setCheckable(true);
        a->setChecked(m_view->overlays().isEnabled(info.overlay));
        a->setShortcut(QKeySequence(QString::fromLatin1(info.shortcut)));
        connect(a, &QAction::toggled, this,
                [this, o = info.overlay](bool on) { m_view->overlays().setEnabled(o, on); });
        m_overlayActions[i] = a;
        // Short toolbar labels: the first word.
        auto* shortcutless = toolbar->addAction(tr(info.shortText));
        shortcutless->setCheckable(true);
        shortcutless->setChecked(a->isChecked());
        shortcutless->setToolTip(tr("%1 (%2)").arg(QString(tr(info.text)).remove(QLatin1Char('&')),
                                                   QLatin1String(info.shortcut)));
        connect(shortcutless, &QAction::toggled, a, &QAction::setChecked);
        connect(a, &QAction::toggled, shortcutless, &QAction::setChecked);
    }

    // The timeline: drag to any earlier moment of the run.
    auto* timebar = new QToolBar(tr("Timeline"), this);
    timebar->setObjectName(QStringLiteral("timelineToolbar"));
    addToolBar(Qt::BottomToolBarArea, timebar);
    m_timeline = new QSlider(Qt::Horizontal, timebar);
    m_timeline->setToolTip(tr("Time travel: drag to go back to any moment, then play to go on "
                              "(or change a setting to branch)"));
    m_timeline->setObjectName(QStringLiteral("timeline"));
    m_timeLabel = new QLabel(timebar);
    m_timeLabel->setObjectName(QStringLiteral("timelineLabel"));
    m_timeLabel->setMinimumWidth(180);
    timebar->addWidget(new QLabel(tr(" Timeline "), timebar));
    timebar->addWidget(m_timeline);
    timebar->addWidget(m_timeLabel);
    connect(m_timeline, &QSlider::valueChanged, this, [this](int value) {
        if (m_timeline->isSliderDown() || value != m_controller->currentStep())
            m_controller->seek(value);
    });
}

void MainWindow::buildMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    m_fileMenu = file;
    QAction* newAction = file->addAction(tr("&New scene"), this, &MainWindow::newScene);
    newAction->setObjectName(QStringLiteral("newScene"));
    newAction->setShortcuts(controlKeys("newScene"));
    QAction* open = file->addAction(tr("&Open scene…"), this, &MainWindow::openDialog);
    open->setObjectName(QStringLiteral("openScene"));
    open->setShortcuts(controlKeys("openScene"));
    QAction* openLessonAction =
        file->addAction(tr("Open &lesson…"), this, &MainWindow::openLessonDialog);
    openLessonAction->setObjectName(QStringLiteral("openLesson"));
    openLessonAction->setShortcuts(controlKeys("openLesson"));
    QMenu* lessonsMenu = file->addMenu(tr("Le&ssons"));
    for (int i = 0; i < m_player->lessonPaths().size(); ++i) {
        const QString path = m_player->lessonPaths()[i];
        lessonsMenu->addAction(m_player->lessonMenuTexts()[i], this,
                               [this, path] { openLesson(path); });
    }
    lessonsMenu->setEnabled(!m_player->lessonPaths().isEmpty());
    m_recentMenu = file->addMenu(tr("Open &recent"));
    m_recentMenu->setObjectName(QStringLiteral("recentMenu")); // file names: no language
    m_scenesMenu = file->addMenu(tr("&Shipped scenes"));
    for (const lessons::SceneEntry& scene : lessons::scenesIn(scenesFolder(), false))
        m_scenesMenu->addAction(scene.title, this, [this, p = scene.path] { openScene(p); });
    // The user's own scenes (lessons::userScenesDir()) go here when there are any.
    m_ownScenesBefore = file->addSeparator();
    QAction* save = file->addAction(tr("&Save"), this, &MainWindow::saveScene);
    save->setObjectName(QStringLiteral("saveScene"));
    save->setShortcuts(controlKeys("saveScene"));
    QAction* saveAs = file->addAction(tr("Save &as…"), this, &MainWindow::saveSceneAs);
    saveAs->setObjectName(QStringLiteral("saveSceneAs"));
    saveAs->setShortcuts(controlKeys("saveSceneAs"));
    file->addSeparator();
    rebuildOwnScenesMenu();
    QMenu* exportMenu = file->addMenu(tr("&Export plot"));
    for (int i = 0; i < kPlotCount; ++i) {
        QMenu* sub = exportMenu->addMenu(tr(kPlotNames[static_cast<size_t>(i)].title));
        for (const char* fmt : {"PNG", "PDF", "SVG", "CSV"}) {
            sub->addAction(tr("As %1…").arg(QLatin1String(fmt)), this, [this, i, fmt] {
                exportPlotDialog(m_plots[static_cast<size_t>(i)], QString::fromLatin1(fmt));
            });
        }
    }
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setObjectName(QStringLiteral("quit"));
    quit->setShortcuts(controlKeys("quit"));

    // Edit: undo and redo of the scene's edits (the editor's tools add theirs here).
    m_editMenu = menuBar()->addMenu(tr("&Edit"));
    m_editMenu->setObjectName(QStringLiteral("editMenu"));
    m_undoAction = m_document->undoStack()->createUndoAction(this, tr("&Undo"));
    m_undoAction->setObjectName(QStringLiteral("undo"));
    m_undoAction->setShortcuts(controlKeys("undo"));
    m_redoAction = m_document->undoStack()->createRedoAction(this, tr("&Redo"));
    m_redoAction->setObjectName(QStringLiteral("redo"));
    m_redoAction->setShortcuts(controlKeys("redo"));
    m_editMenu->addAction(m_undoAction);
    m_editMenu->addAction(m_redoAction);

    QMenu* sim = menuBar()->addMenu(tr("&Simulation"));
    for (QAction* a : {m_playAction, m_stepAction, m_backAction, m_resetAction})
        sim->addAction(a);
    sim->addSeparator();
    for (QAction* a : m_rotateActions)
        sim->addAction(a);

    m_viewMenu = menuBar()->addMenu(tr("&View"));
    m_viewMenu->addAction(m_fitAction);
    m_presentAction = m_viewMenu->addAction(tr("&Presentation"));
    m_presentAction->setCheckable(true);
    m_presentAction->setObjectName(QStringLiteral("presentation"));
    m_presentAction->setShortcuts(controlKeys("presentation"));
    m_presentAction->setToolTip(
        tr("Full screen, larger text and thicker lines for a projector (F11)"));
    connect(m_presentAction, &QAction::toggled, this, &MainWindow::setPresentation);
    addAction(m_presentAction); // F11 works in full screen, where the menu bar may be hidden
    addLanguageMenu(m_viewMenu, *this);
    m_viewMenu->addSeparator();
    for (QAction* a : m_overlayActions)
        m_viewMenu->addAction(a);
    m_viewMenu->addSeparator();
    for (QDockWidget* dock : findChildren<QDockWidget*>())
        m_viewMenu->addAction(dock->toggleViewAction());

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&Controls"), this, [this] {
        const ModalScope modal;
        QMessageBox box(QMessageBox::NoIcon, tr("Controls"), controlsHelpText(), QMessageBox::Ok,
                        this);
        box.setTextFormat(Qt::RichText);
        box.exec();
    });
    help->addAction(tr("&About RigidLab"), this, [this] { showAbout(this); });
}

QString MainWindow::controlsHelpText() const
{
    // The overlays' keys from their own table, kOverlayNames.
    QList<ControlHelpRow> overlays;
    for (const OverlayNames& info : kOverlayNames)
        overlays.push_back(
            {{QKeySequence(QString::fromLatin1(info.shortcut))},
             tr("Show or hide: %1").arg(QString(tr(info.text)).remove(QLatin1Char('&')))});
    return controlsHelpHtml(overlays);
}

} // namespace rigidlab::ui
