// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/main_window.h"

#include "common/display_names.h"
#include "common/export_folder.h"
#include "common/modal_scope.h"
#include "common/status_text.h"
#include "lesson_player/lesson_panels.h"
#include "lesson_player/lesson_player.h"
#include "panels/control_panel.h"
#include "panels/divergence_banner.h"
#include "panels/error_panel.h"
#include "panels/inspector_panel.h"
#include "panels/sat_panel.h"
#include "plots/lesson_export.h"
#include "plots/plot_export.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"
#include "window/about_dialog.h"
#include "window/language_switch.h"
#include "window/shortcuts.h"

#include "format/data_dirs.h"
#include "format/lesson.h"
#include "format/lesson_catalog.h"
#include "format/scene_loader.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QScrollArea>
#include <QSettings>
#include <QSignalBlocker>
#include <QSlider>
#include <QStatusBar>
#include <QStyle>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace rigidlab::ui {

namespace {

constexpr int kMaxRecent = 8;

/// QSettings writes its file atomically (through QSaveFile): a write that fails leaves the
/// previous settings as they were. That it failed is said in the status bar, not lost.
void syncSettings(QSettings& settings, QMainWindow& window)
{
    settings.sync();
    if (settings.status() == QSettings::NoError)
        return;
    const QString why =
        QCoreApplication::translate("MainWindow", "Settings not saved: cannot write %1")
            .arg(QDir::toNativeSeparators(settings.fileName()));
    window.statusBar()->showMessage(why, 8000);
    qWarning("%s", qPrintable(why));
}

struct OverlayInfo {
    Overlay overlay;
    const char* text;
    const char* shortText; ///< on the toolbar
    const char* key;
    const char* shortcut;
};
constexpr std::array<OverlayInfo, kOverlayCount> kOverlays{{
    {Overlay::Velocities, QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "&Velocity vectors"),
     QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Velocities"), "velocities", "V"},
    {Overlay::Contacts,
     QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "&Contact points and normals"),
     QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Contacts"), "contacts", "C"},
    {Overlay::BoundingBoxes, QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "&Bounding boxes"),
     QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Boxes"), "boxes", "B"},
    {Overlay::CentresOfMass, QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Centres of &mass"),
     QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Centres"), "com", "M"},
    {Overlay::Trails, QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Motion &trails"),
     QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Trails"), "trails", "T"},
    {Overlay::SpringsJoints, QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "&Springs and joints"),
     QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Springs"), "springs", "J"},
}};

/// Raises the one of `docks` that the step cares most about, where they share tabs: its table
/// (its numbers are what the questions ask about), then the first plot it lists (its text
/// talks about it), then the controls, which the student finds by their tab.
void raiseFirst(const QMap<QString, QDockWidget*>& named, QList<QDockWidget*> docks)
{
    const auto rank = [&named](QDockWidget* d) {
        for (const char* table : {"sat", "bounces", "collision"})
            if (d == named.value(QLatin1String(table)))
                return 0;
        return d == named.value(QStringLiteral("controls")) ||
                       d == named.value(QStringLiteral("inspector"))
                   ? 2
                   : 1;
    };
    std::stable_sort(docks.begin(), docks.end(),
                     [&](QDockWidget* a, QDockWidget* b) { return rank(a) < rank(b); });
    if (!docks.isEmpty())
        docks.first()->raise();
}

} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), m_controller(new SimulationController(this)),
      m_view(new WorldView(*m_controller, this)), m_controls(new ControlPanel(*m_controller, this)),
      m_inspector(new InspectorPanel(*m_controller, this)),
      m_player(new LessonPlayer(*m_controller, this)), m_sat(new SatPanel(*m_controller, this)),
      m_bounces(new BouncePanel(*m_controller, this)),
      m_collision(new CollisionPanel(*m_controller, this))
{
    m_view->scene()->addItem(m_sat->overlay());
    m_player->scanFolder(lessonsFolder());
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
        const QString title = m_controller->scene().title;
        setWindowTitle(title.isEmpty() ? tr("RigidLab") : tr("%1 — RigidLab").arg(title));
    });
    for (PlotWidget* plot : m_plots)
        followController(plot);
    restoreSettings();
    updateStatus();
}

MainWindow::~MainWindow() = default;

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
    for (std::size_t i = 0; i < kOverlays.size(); ++i) {
        const OverlayInfo& info = kOverlays[i];
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

void MainWindow::buildDocks()
{
    setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks);
    auto addDock = [this](const QString& title, const QString& name, QWidget* w,
                          Qt::DockWidgetArea area) {
        auto* dock = new QDockWidget(title, this);
        dock->setObjectName(name + QStringLiteral("Dock"));
        if (qobject_cast<PlotWidget*>(w)) {
            dock->setWidget(w);
        } else {
            // Lists as narrow as a short name: a long entry ("Dormand-Prince 5(4), adaptive")
            // must not widen the side column on a small projector.
            for (QComboBox* box : w->findChildren<QComboBox*>()) {
                box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
                box->setMinimumContentsLength(8);
            }
            // A panel taller or wider than its dock scrolls instead of being cut.
            auto* scroll = new QScrollArea(dock);
            scroll->setWidgetResizable(true);
            scroll->setFrameShape(QFrame::NoFrame);
            scroll->setWidget(w);
            dock->setWidget(scroll);
        }
        addDockWidget(area, dock);
        m_docks.insert(name, dock);
        return dock;
    };
    QDockWidget* lessonDock =
        addDock(tr("Lesson"), QStringLiteral("lesson"), m_player, Qt::LeftDockWidgetArea);
    {
        // Back, Next, Restart and Export stay in sight below the lesson, which scrolls.
        auto* box = new QWidget(lessonDock);
        auto* column = new QVBoxLayout(box);
        column->setContentsMargins(0, 0, 0, 4);
        column->addWidget(lessonDock->widget(), 1);
        column->addWidget(m_player->takeNavigation());
        lessonDock->setWidget(box);
    }
    addDock(tr("Controls"), QStringLiteral("controls"), m_controls, Qt::LeftDockWidgetArea);
    addDock(tr("Inspector"), QStringLiteral("inspector"), m_inspector, Qt::LeftDockWidgetArea);
    tabifyDockWidget(m_docks.value(QStringLiteral("controls")),
                     m_docks.value(QStringLiteral("inspector")));
    m_docks.value(QStringLiteral("controls"))->raise();
    m_plots[0] = makeEnergyPlot(this);
    m_plots[1] = makeMomentumPlot(this);
    m_plots[2] = makeDriftPlot(this);
    const std::array<QString, kPlotCount> titles{tr("Energy"), tr("Momentum"), tr("Energy drift")};
    const std::array<QString, kPlotCount> names{
        QStringLiteral("energy"), QStringLiteral("momentum"), QStringLiteral("drift")};
    for (int i = 0; i < kPlotCount; ++i) {
        // Small enough that the plots fit beside the world on a 1024×768 projector.
        m_plots[static_cast<size_t>(i)]->setMinimumSize(180, 150);
        m_plots[static_cast<size_t>(i)]->setTitleShown(false); // the dock shows it
        addDock(titles[static_cast<size_t>(i)], names[static_cast<size_t>(i)],
                m_plots[static_cast<size_t>(i)], Qt::RightDockWidgetArea);
    }
    addDock(tr("Separating axis test"), QStringLiteral("sat"), m_sat, Qt::RightDockWidgetArea)
        ->hide();
    addDock(tr("Bounces"), QStringLiteral("bounces"), m_bounces, Qt::RightDockWidgetArea)->hide();
    addDock(tr("Collision"), QStringLiteral("collision"), m_collision, Qt::RightDockWidgetArea)
        ->hide();
    // The work-precision sweep, hidden until asked for (View menu).
    addDock(tr("Error vs run time"), QStringLiteral("errorDock"), new ErrorPanel(this),
            Qt::BottomDockWidgetArea)
        ->hide();
    m_compareDock = new QDockWidget(tr("Side by side"), this);
    m_compareDock->setObjectName(QStringLiteral("compareDock"));
    addDockWidget(Qt::RightDockWidgetArea, m_compareDock);
    m_compareDock->hide();
}

QDockWidget* MainWindow::dock(const QString& name) const
{
    if (name == QLatin1String("compare-energy") || name == QLatin1String("compare-drift"))
        return m_compareDock;
    return m_docks.value(name, nullptr);
}

void MainWindow::buildMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
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
    m_scenesMenu = file->addMenu(tr("&Shipped scenes"));
    const QDir scenes(scenesFolder());
    for (const QFileInfo& info :
         scenes.entryInfoList({QStringLiteral("*.json")}, QDir::Files, QDir::Name)) {
        const lessons::SceneLoadResult r = lessons::loadSceneFile(info.filePath());
        const QString title = r.ok && !r.scene.title.isEmpty() ? r.scene.title : info.baseName();
        m_scenesMenu->addAction(title, this, [this, path = info.filePath()] { openScene(path); });
    }
    QMenu* exportMenu = file->addMenu(tr("&Export plot"));
    const std::array<QString, kPlotCount> titles{tr("Energy"), tr("Momentum"), tr("Energy drift")};
    for (int i = 0; i < kPlotCount; ++i) {
        QMenu* sub = exportMenu->addMenu(titles[static_cast<size_t>(i)]);
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
    // The overlays' keys from their own table, kOverlays.
    QList<ControlHelpRow> overlays;
    for (std::size_t i = 0; i < kOverlays.size(); ++i)
        overlays.push_back(
            {{QKeySequence(QString::fromLatin1(kOverlays[i].shortcut))},
             tr("Show or hide: %1").arg(QString(tr(kOverlays[i].text)).remove(QLatin1Char('&')))});
    return controlsHelpHtml(overlays);
}

QString MainWindow::openScene(const QString& path, bool quiet)
{
    const lessons::SceneLoadResult r = lessons::loadSceneFile(path);
    if (!r.ok) {
        m_lastError = r.error;
        if (!quiet) {
            auto* box = new QMessageBox(QMessageBox::Warning, tr("Cannot open scene"), r.error,
                                        QMessageBox::Ok, this);
            box->setAttribute(Qt::WA_DeleteOnClose);
            box->setObjectName(QStringLiteral("sceneErrorBox"));
            box->open();
        }
        return r.error;
    }
    m_lastError.clear();
    if (m_inLesson)
        m_player->closeLesson(); // a scene of one's own ends the lesson
    m_controller->loadScene(r.scene, path);
    for (const QString& w : r.warnings)
        statusBar()->showMessage(w, 8000);
    m_lastFolder = QFileInfo(path).absolutePath();
    addRecent(QFileInfo(path).absoluteFilePath());
    return QString();
}

void MainWindow::openDialog()
{
    const ModalScope modal;
    const QString folder = m_lastFolder.isEmpty() ? scenesFolder() : m_lastFolder;
    const QString path = QFileDialog::getOpenFileName(this, tr("Open scene"), folder,
                                                      tr("RigidLab scenes (*.json)"));
    if (!path.isEmpty())
        openScene(path);
}

void MainWindow::addRecent(const QString& path)
{
    QSettings s;
    QStringList recent = s.value(QStringLiteral("recentFiles")).toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent)
        recent.removeLast();
    s.setValue(QStringLiteral("recentFiles"), recent);
    s.setValue(QStringLiteral("lastFolder"), m_lastFolder);
    syncSettings(s, *this);
    rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu()
{
    m_recentMenu->clear();
    const QStringList recent = QSettings().value(QStringLiteral("recentFiles")).toStringList();
    for (const QString& path : recent)
        m_recentMenu->addAction(QFileInfo(path).fileName(), this,
                                [this, path] { openScene(path); });
    m_recentMenu->setEnabled(!recent.isEmpty());
}

void MainWindow::exportPlotDialog(PlotWidget* plot, const QString& format)
{
    const ModalScope modal;
    const QString suffix = format.toLower();
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export plot"), QDir(exportFolder()).filePath(QStringLiteral("plot.") + suffix),
        tr("%1 files (*.%2)").arg(format, suffix));
    if (path.isEmpty())
        return;
    rememberExportFolder(path);
    const ExportResult r = exportPlot(*plot, path, *formatFromSuffix(suffix));
    if (!r.ok)
        QMessageBox::warning(this, tr("Export failed"), r.error);
    else
        statusBar()->showMessage(tr("Exported %1").arg(path), 5000);
}

void MainWindow::buildStatusBar()
{
    m_statusTime = new QLabel(this);
    m_statusRate = new QLabel(this);
    m_statusDrift = new QLabel(this);
    m_statusDetails = new QLabel(this);
    m_statusSlow = new QLabel(tr("slower than real time"), this);
    m_statusSlow->setStyleSheet(
        QStringLiteral("color: white; background: #c0392b; padding: 1px 6px;"));
    m_statusSlow->setVisible(false);
    statusBar()->addWidget(m_statusTime);
    statusBar()->addWidget(m_statusRate);
    statusBar()->addWidget(m_statusDrift);
    statusBar()->addWidget(m_statusDetails);
    statusBar()->addPermanentWidget(m_statusSlow);

    // The timings are for whoever tunes the engine, not for the class: off unless asked for.
    const QString key = QStringLiteral("status/details");
    m_detailsAction = new QAction(tr("Status &details (steps/s, stage timings)"), this);
    m_detailsAction->setObjectName(QStringLiteral("statusDetails"));
    m_detailsAction->setCheckable(true);
    m_detailsAction->setChecked(QSettings().value(key, false).toBool());
    setDetailsShown(true);
    connect(m_detailsAction, &QAction::toggled, this, [this, key](bool on) {
        setDetailsShown(on);
        QSettings s;
        s.setValue(key, on);
        syncSettings(s, *this);
        updateStatus();
    });
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(m_detailsAction);

    auto* statusTimer = new QTimer(this);
    connect(statusTimer, &QTimer::timeout, this, &MainWindow::updateStatus);
    statusTimer->start(250);
}

void MainWindow::updateStatus()
{
    const QLocale locale;
    const physics::World& w = m_controller->world();
    const bool running = m_controller->isRunning();
    m_statusTime->setText(tr("t = %1 s").arg(locale.toString(w.time(), 'f', 3)));
    // Simulated seconds per wall second; while paused there is no rate to show.
    if (!running)
        m_statusRate->setText(tr("paused"));
    else if (const std::optional<double> factor = m_controller->realTimeFactor())
        m_statusRate->setText(tr("%1 × real time").arg(locale.toString(*factor, 'f', 2)));
    else
        m_statusRate->setText(tr("running"));
    // Drift is the numerical error alone: what contacts, friction, drag and dampers took is
    // physics, said apart.
    // On a projector, in short: the line must fit 1024 pixels at one and a half times the size.
    QString drift =
        (m_presentation ? tr("energy drift %1 %") : tr("energy drift (numerical error) %1 %"))
            .arg(driftPercentText(m_controller->driftPercent(), locale));
    const double lost = m_controller->dissipated();
    if (std::abs(lost) > 1e-9)
        drift += (m_presentation ? tr(" · dissipated %1 J")
                                 : tr(" · dissipated by contacts, friction, drag and dampers %1 J"))
                     .arg(locale.toString(lost, 'g', 3));
    // The adaptive integrator's own estimate of its local error, live (a developer's detail,
    // not shown on a projector).
    if (const auto estimate = w.integrator().errorEstimate(); estimate && !m_presentation)
        drift += tr(" · %1 error estimate %2 (%Ln substep(s))", nullptr, w.integrator().substeps())
                     .arg(integratorDisplayName(w.def().integrator))
                     .arg(locale.toString(*estimate, 'g', 2));
    m_statusDrift->setText(drift);
    if (m_detailsAction->isChecked()) {
        // The last step's stages that ran, with their times (physics/profile.h).
        QStringList stages;
        const physics::StepProfile& profile = w.profile();
        for (int k = 0; k < physics::kStageCount; ++k)
            if (profile.ran[k])
                stages << tr("%1 %2").arg(stageDisplayName(static_cast<physics::Stage>(k)),
                                          locale.toString(profile.ms[k], 'f', 2));
        const QString step =
            tr("last step %1 ms: %2")
                .arg(locale.toString(profile.total, 'f', 2), stages.join(QStringLiteral(", ")));
        // Rates only while the clock runs: a paused world has none, and an old one is stale.
        m_statusDetails->setText(
            running ? tr("%1 steps/s · frame %2 ms (physics %3 ms) · %4")
                          .arg(locale.toString(m_controller->stepsPerSecond(), 'f', 0),
                               locale.toString(m_controller->frameMilliseconds(), 'f', 1),
                               locale.toString(m_controller->physicsMilliseconds(), 'f', 1), step)
                    : step);
    } else {
        m_statusDetails->clear();
    }
    // Over the world, a banner when it diverged.
    if (auto* banner = findChild<DivergenceBanner*>()) {
        banner->refresh();
        banner->setGeometry(0, 0, m_view->width(), banner->sizeHint().height());
        banner->raise();
    }
    m_statusSlow->setVisible(running && m_controller->slowerThanRealTime());
}

QString MainWindow::statusText() const
{
    QStringList parts;
    for (const QLabel* label :
         {m_statusTime, m_statusRate, m_statusDrift, m_statusDetails, m_statusSlow})
        if (!label->isHidden() && !label->text().isEmpty())
            parts << label->text();
    return parts.join(QStringLiteral(" | "));
}

void MainWindow::updateTimeline()
{
    // The label follows the drag too; the slider itself is left to the hand that holds it.
    const long long lo = m_controller->earliestStep(), hi = m_controller->latestStep();
    m_timeLabel->setText(tr(" step %1 of %2 · t = %3 s")
                             .arg(m_controller->currentStep())
                             .arg(hi)
                             .arg(QLocale().toString(m_controller->world().time(), 'f', 3)));
    if (m_timeline->isSliderDown())
        return;
    const QSignalBlocker block(m_timeline);
    m_timeline->setRange(static_cast<int>(lo), static_cast<int>(hi));
    m_timeline->setValue(static_cast<int>(m_controller->currentStep()));
}

void MainWindow::restoreSettings()
{
    QSettings s;
    m_lastFolder = s.value(QStringLiteral("lastFolder")).toString();
    restoreLayout(s);
    for (std::size_t i = 0; i < kOverlays.size(); ++i) {
        const QString key = QStringLiteral("overlays/") + QLatin1String(kOverlays[i].key);
        if (s.contains(key))
            m_overlayActions[i]->setChecked(s.value(key).toBool());
    }
    rebuildRecentMenu();
}

QString MainWindow::openLesson(const QString& path, bool quiet)
{
    const QString error = m_player->openLesson(path);
    m_lastError = error;
    if (!error.isEmpty() && !quiet) {
        auto* box = new QMessageBox(QMessageBox::Warning, tr("Cannot open lesson"), error,
                                    QMessageBox::Ok, this);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->setObjectName(QStringLiteral("lessonErrorBox"));
        box->open();
    }
    if (error.isEmpty()) {
        m_docks.value(QStringLiteral("lesson"))->show();
        m_docks.value(QStringLiteral("lesson"))->raise();
    }
    return error;
}

void MainWindow::openLessonDialog()
{
    const ModalScope modal;
    const QString path = QFileDialog::getOpenFileName(this, tr("Open lesson"), lessonsFolder(),
                                                      tr("RigidLab lessons (*.json)"));
    if (!path.isEmpty())
        openLesson(path);
}

void MainWindow::applyLessonStep(const lessons::Lesson& lesson, int index)
{
    const lessons::LessonStep& step = lesson.steps[static_cast<size_t>(index)];
    m_inLesson = true;
    setWindowTitle(tr("%1 — step %2 — RigidLab").arg(lesson.title).arg(index + 1));

    // The step's worlds: the main one, then those compared beside it.
    std::vector<physics::World> worlds = lessons::buildStepWorlds(step);
    QStringList labels;
    if (step.compare && step.compare->count() > 1)
        for (int i = 0; i < step.compare->count(); ++i)
            labels << methodDisplayName(step.compare->label(i));
    m_controller->loadWorlds(step.scene, step.scenePath.isEmpty() ? lesson.path : step.scenePath,
                             std::move(worlds), labels,
                             step.compare ? step.compare->offset : physics::Vec2::Zero());
    if (step.settings.timeScale)
        m_controller->setTimeScale(*step.settings.timeScale);
    std::vector<lessons::Measure> measures;
    for (const lessons::Question& q : step.questions)
        measures.push_back(q.measure);
    m_controller->watch(measures);

    // Only what the step names: panels, plots, overlays.
    for (auto it = m_docks.cbegin(); it != m_docks.cend(); ++it) {
        if (it.key() == QLatin1String("lesson"))
            continue;
        it.value()->setVisible(step.panels.contains(it.key()) || step.plots.contains(it.key()));
    }
    // The step's compared worlds, one plot for each compare-… plot it names, made where the
    // headless export makes them (lesson_export.h), so the window shows and exports the same.
    delete m_compareDock->widget();
    m_comparePlots.clear();
    if (!labels.isEmpty()) {
        auto* box = new QWidget(m_compareDock);
        auto* layout = new QVBoxLayout(box);
        layout->setContentsMargins(0, 0, 0, 0);
        QStringList titles;
        for (const QString& name : step.plots) {
            if (!name.startsWith(QLatin1String("compare-")))
                continue;
            PlotWidget* plot = makeStepPlot(step, name, box);
            if (!plot)
                continue;
            plot->setObjectName(name);
            plot->setMinimumSize(180, 150);
            plot->setTitleShown(false);
            plot->setPresentation(m_presentation);
            followController(plot);
            layout->addWidget(plot);
            m_comparePlots.push_back(plot);
            titles << plot->title();
        }
        if (m_comparePlots.empty()) {
            delete box;
        } else {
            m_compareDock->setWidget(box);
            m_compareDock->setWindowTitle(titles.join(QStringLiteral(" · ")));
        }
    }
    m_compareDock->setVisible(!m_comparePlots.empty());
    static const std::array<const char*, kOverlayCount> kNames{"velocities", "contacts", "boxes",
                                                               "centres",    "trails",   "springs"};
    for (int i = 0; i < kOverlayCount; ++i)
        m_overlayActions[static_cast<size_t>(i)]->setChecked(
            step.overlays.contains(QLatin1String(kNames[static_cast<size_t>(i)])));
    // Springs and joints are part of the scene, not a teaching aid: drawn whenever there are any.
    if (!step.scene.springs.empty() || !step.scene.joints.empty())
        overlayAction(Overlay::SpringsJoints)->setChecked(true);
    // What the questions hold back stays hidden until answered.
    applyHeldBack(m_player->heldBack());
    // Room for the step's tables and plots beside the view.
    QList<QDockWidget*> right;
    for (const QString& name : step.panels + step.plots)
        if (QDockWidget* d = dock(name);
            d && !d->isHidden() && dockWidgetArea(d) == Qt::RightDockWidgetArea)
            right << d;
    raiseFirst(m_docks, right);
    fitSideColumns(width());
    m_controls->setAllowed(step.allow);
    if (step.sat) {
        const auto a = step.scene.bodyIndex(step.sat->first);
        const auto b = step.scene.bodyIndex(step.sat->second);
        m_sat->setBodies(a ? *a : -1, b ? *b : -1);
    } else {
        m_sat->setBodies(-1, -1);
    }
    m_controller->setRunning(step.autoplay && !m_runHeld);
}

void MainWindow::applyHeldBack(const QStringList& held)
{
    m_runHeld = held.contains(QStringView(lessons::kHoldBackRun));
    m_playAction->setEnabled(!m_runHeld);
    m_stepAction->setEnabled(!m_runHeld);
    if (m_runHeld)
        m_controller->setRunning(false);
    m_collision->setAfterHeld(held.contains(QStringView(lessons::kHoldBackCollisionAfter)));
    m_bounces->setHeightsHeld(held.contains(QStringView(lessons::kHoldBackBounceHeights)));
    const lessons::Lesson* lesson = m_player->lesson();
    if (!m_inLesson || !lesson)
        return;
    const lessons::LessonStep& step = lesson->steps[static_cast<size_t>(m_player->stepIndex())];
    QList<QDockWidget*> shown; // by an answer that released them: brought to the front
    for (const auto& [names, prefix] : {std::pair{&step.panels, QStringLiteral("panel:")},
                                        std::pair{&step.plots, QStringLiteral("plot:")}})
        for (const QString& name : *names)
            if (QDockWidget* d = dock(name)) {
                const bool visible = !held.contains(prefix + name);
                if (visible && d->isHidden())
                    shown << d;
                d->setVisible(visible);
            }
    raiseFirst(m_docks, shown);
}

void MainWindow::leaveLesson()
{
    if (!m_inLesson)
        return;
    m_inLesson = false;
    // Back to the plain lab: controls, inspector and the three plots.
    for (auto it = m_docks.cbegin(); it != m_docks.cend(); ++it) {
        const bool standard =
            it.key() == QLatin1String("lesson") || it.key() == QLatin1String("controls") ||
            it.key() == QLatin1String("inspector") || it.key() == QLatin1String("energy") ||
            it.key() == QLatin1String("momentum") || it.key() == QLatin1String("drift");
        it.value()->setVisible(standard);
    }
    delete m_compareDock->widget();
    m_comparePlots.clear();
    m_compareDock->hide();
    m_controls->setAllowed(std::nullopt);
    m_sat->setBodies(-1, -1);
    applyHeldBack({});
}

QStringList MainWindow::exportStepPlots(const QString& folder)
{
    // The plots as the student sees them, with a caption naming the lesson, step,
    // integrator and dt (or just the scene's title outside a lesson).
    std::vector<PlotWidget*> plots;
    const std::array<QString, kPlotCount> names{
        QStringLiteral("energy"), QStringLiteral("momentum"), QStringLiteral("drift")};
    const auto plotNamed = [&](const QString& name) -> PlotWidget* {
        for (int i = 0; i < kPlotCount; ++i)
            if (names[static_cast<size_t>(i)] == name)
                return m_plots[static_cast<size_t>(i)];
        for (PlotWidget* plot : m_comparePlots)
            if (plot->objectName() == name)
                return plot;
        return nullptr;
    };
    if (const lessons::Lesson* lesson = m_player->lesson()) {
        // In a lesson: the plots the step names, in its order, as rigidlab-cli lesson --export.
        for (const QString& name :
             lesson->steps.at(static_cast<size_t>(m_player->stepIndex())).plots)
            if (PlotWidget* plot = plotNamed(name))
                plots.push_back(plot);
    } else {
        for (int i = 0; i < kPlotCount; ++i)
            if (!m_docks.value(names[static_cast<size_t>(i)])->isHidden())
                plots.push_back(m_plots[static_cast<size_t>(i)]);
    }
    for (int i = 0; i < kPlotCount; ++i)
        m_plots[static_cast<size_t>(i)]->setObjectName(names[static_cast<size_t>(i)]);
    for (PlotWidget* plot : plots)
        plot->drain();
    const lessons::Lesson* lesson = m_player->lesson();
    const QString caption =
        lesson ? stepCaption(*lesson, m_player->stepIndex(), m_controller->world().def())
               : m_controller->scene().title;
    const PlotFilesResult r = exportPlots(plots, folder, caption);
    return r.ok ? QStringList() : QStringList{r.error};
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
    m_controller->setRunning(false);
    QSettings s;
    saveLayout(s);
    for (std::size_t i = 0; i < kOverlays.size(); ++i)
        s.setValue(QStringLiteral("overlays/") + QLatin1String(kOverlays[i].key),
                   m_overlayActions[i]->isChecked());
    syncSettings(s, *this);
    event->accept();
}

void MainWindow::setDetailsShown(bool shown)
{
    // Presentation mode hides them whatever View › Status details says.
    m_statusDetails->setVisible(shown && m_detailsAction->isChecked() && !m_presentation);
}

} // namespace rigidlab::ui
