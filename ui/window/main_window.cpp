// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow's making and closing: the panels, the parts that each do one job, and how they
// are connected; its settings. The menus: main_window_menus.cpp; the editor's toolbar and
// docks: main_window_editor.cpp.
#include "window/main_window.h"

#include "common/modal_scope.h"
#include "editor/edit_tools.h"
#include "editor/scene_document.h"
#include "instruments/instruments.h"
#include "lesson_editor/lesson_editor.h"
#include "lesson_player/lesson_panels.h"
#include "lesson_player/lesson_player.h"
#include "measure/measurement_panel.h"
#include "measure/measurement_session.h"
#include "panels/control_panel.h"
#include "panels/divergence_banner.h"
#include "panels/error_panel.h"
#include "panels/inspector_panel.h"
#include "panels/sat_panel.h"
#include "plots/plot_table.h"
#include "plots/plot_turns.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"
#include "window/accessible_factories.h"
#include "window/lesson_session.h"
#include "window/settings_sync.h"
#include "window/status_line.h"
#include "window/window_actions.h"
#include "window/window_documents.h"
#include "window/window_drop.h"
#include "window/window_keyboard.h"
#include "window/window_layout.h"
#include "window/window_names.h"
#include "window/window_plots.h"

#include "format/data_dirs.h"
#include "format/lesson.h"
#include "format/lesson_pack.h"

#include <QAction>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileInfo>
#include <QSettings>
#include <QStatusBar>
#include <QToolBar>

#include <algorithm>
#include <array>

namespace rigidlab::ui {

namespace {

/// The window's controller, made before any of its widgets, and before them the factories of
/// the interfaces a screen reader is given: Qt makes a widget's interface at its first
/// accessibility event, often as it is built, and keeps it.
SimulationController* madeFirst(MainWindow* window)
{
    installAccessibleFactories();
    return new SimulationController(window);
}

} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), m_controller(madeFirst(this)), m_document(new SceneDocument(this)),
      m_view(new WorldView(*m_controller, this)), m_controls(new ControlPanel(*m_controller, this)),
      m_inspector(new InspectorPanel(*m_controller, this)),
      m_player(new LessonPlayer(*m_controller, this)), m_sat(new SatPanel(*m_controller, this)),
      m_bounces(new BouncePanel(*m_controller, this)),
      m_collision(new CollisionPanel(*m_controller, this)), m_plotTurns(new PlotTurns(this))
{
    m_view->scene()->addItem(m_sat->overlay());
    setWindowTitle(tr("RigidLab"));
    setCentralWidget(m_view);
    m_actions = new WindowActions(*this, *m_controller, *m_view);
    for (const PlotRow& row : kPlotRows)
        if (row.inWindow())
            m_plots << makeWorldPlot(row, this);
    WindowLayout::Panels panels;
    panels.lesson = m_player;
    panels.lessonNavigation = m_player->takeNavigation();
    panels.controls = m_controls;
    panels.inspector = m_inspector;
    panels.plots = m_plots;
    panels.sat = m_sat;
    panels.bounces = m_bounces;
    panels.collision = m_collision;
    panels.error = new ErrorPanel(this);
    m_measurement = new MeasurementSession(*this, *m_view, *m_document);
    panels.measurement = m_measurement->panel();
    m_layout = new WindowLayout(*this, panels);
    m_measurement->setDock(m_layout->dock(QStringLiteral("measurement")));
    connect(m_measurement->panel(), &MeasurementPanel::legendChanged, m_layout,
            &WindowLayout::fitPlotHeightSoon);
    m_status = new StatusLine(*this, *m_controller, *m_view);
    m_documents = new WindowDocuments(*this, *m_document);
    buildEditor();
    m_instruments = new Instruments(*this, *m_controller, *m_view, *m_plotTurns);
    m_instruments->setGraphPlacer([this](QDockWidget* graph) {
        // A tab beside the plots: the scene keeps its height on a small screen.
        addDockWidget(Qt::RightDockWidgetArea, graph);
        if (QDockWidget* plots = m_layout->dock(m_plots.front()->objectName());
            plots && !plots->isHidden())
            tabifyDockWidget(plots, graph);
    });
    m_session = new LessonSession({*this, *m_player, *m_controller, *m_document, *m_documents,
                                   *m_editTools, *m_layout, *m_actions, *m_view, *m_controls,
                                   *m_sat, *m_bounces, *m_collision, m_plots, *m_plotTurns});
    m_keyboard = new WindowKeyboard({*this, *m_view, *m_player, *m_inspector, *m_layout});
    buildMenus();
    new DivergenceBanner(*m_controller, m_view);
    wirePanels();
    wireDocument();
    // Every plot that follows the run drains after its frames, when its turn comes.
    connect(m_controller, &RunView::frameAdvanced, m_plotTurns, &PlotTurns::frameAdvanced);
    for (PlotWidget* plot : m_plots) {
        followController(*plot, *m_controller, *m_plotTurns);
        plot->addMenuAction(m_instruments->graphAction()); // graphs of chosen bodies
    }
    restoreSettings();
    followEventTables(); // after the docks the settings may have opened
    m_keyboard->applySavedChoice();
    updateStatus();
}

std::array<QDockWidget*, 2> MainWindow::eventTables() const
{
    return {m_layout->dock(QStringLiteral("bounces")), m_layout->dock(QStringLiteral("collision"))};
}

void MainWindow::followEventTables()
{
    // The bounce and collision tables read the run's events: measured while one is open (a
    // lesson step measures them anyway). A table behind another's tab is open: it may be
    // brought forward at any time.
    const std::array<QDockWidget*, 2> tables = eventTables();
    const auto follow = [this, tables] {
        m_controller->setEventsShown(std::any_of(tables.begin(), tables.end(),
                                                 [](QDockWidget* d) { return !d->isHidden(); }));
    };
    for (QDockWidget* dock : tables) {
        // Ticked in the View menu (after the dock's own slot showed or hid it), and shown or
        // hidden otherwise (a lesson step's panels) while the window is on screen.
        connect(dock->toggleViewAction(), &QAction::triggered, this, follow);
        connect(dock, &QDockWidget::visibilityChanged, this, follow);
    }
    follow();
}

MainWindow::~MainWindow()
{
    // QWidget's destructor hides the docks after this window's members are gone: the tables'
    // follower must not hear of it.
    for (QDockWidget* dock : eventTables()) {
        disconnect(dock, nullptr, this, nullptr);
        disconnect(dock->toggleViewAction(), nullptr, this, nullptr);
    }
}

void MainWindow::wirePanels()
{
    connect(m_view, &WorldView::bodySelected, m_inspector, &InspectorPanel::setBody);
    // A typed value refused (out of range, not a number) is said in the status bar too.
    // (Received by the status bar itself: a field left while the window is being destroyed
    // commits, and may refuse, after MainWindow's own part is gone.)
    QStatusBar* bar = statusBar();
    const auto showRefusal = [bar](const QString& why) { bar->showMessage(why, 8000); };
    connect(m_controls, &ControlPanel::inputRefused, bar, showRefusal);
    connect(m_inspector, &InspectorPanel::inputRefused, bar, showRefusal);
    connect(m_inspector, &InspectorPanel::graphRequested, m_instruments,
            [this](int body) { m_instruments->askGraph({body}); });
    connect(m_documents, &WindowDocuments::message, bar, &QStatusBar::showMessage);
    connect(m_measurement, &MeasurementSession::message, bar, &QStatusBar::showMessage);
    // A measurement stays through the steps of its lesson, not into another scene or lesson.
    connect(m_player, &LessonPlayer::stepActivated, m_measurement,
            [this](const lessons::Lesson& lesson, int) { m_measurement->setLesson(lesson.path); });
    connect(m_player, &LessonPlayer::lessonClosed, m_measurement,
            [this] { m_measurement->setLesson(QString()); });
    connect(m_session, &LessonSession::runHeldChanged, this,
            [this](bool held) { m_actions->setRunState(m_editTools->editing(), held); });
    connect(m_session, &LessonSession::left, this, &MainWindow::showSceneTitle);
    connect(m_layout, &WindowLayout::presentationChanged, this, [this](bool on) {
        m_status->setPresentation(on);
        m_view->scene()->update();
        m_view->viewport()->update();
        if (m_presentAction)
            m_presentAction->setChecked(on);
    });
}

void MainWindow::wireDocument()
{
    m_documents->setLeaveLesson([this] {
        if (m_session->inLesson())
            m_player->closeLesson();
    });
    // A teacher starting a new scene wants to draw at once.
    // The view shows the middle of the new ground, at a zoom that draws on a 1 m grid.
    connect(m_documents, &WindowDocuments::newSceneMade, this, [this] {
        m_view->fitRect(SceneDocument::newSceneFrame(), 20);
        m_editTools->setEditing(true);
    });
    m_player->setLeaveGuard([this] { return confirmLeaveScene(); });
    // File › Open, and a file dropped on the window, open a lesson as a lesson.
    connect(m_documents, &WindowDocuments::lessonChosen, this,
            [this](const QString& path) { openLesson(path); });
    new WindowDrop(*this, [this](const QString& path) {
        if (lessons::isLessonDocument(path))
            openLesson(path);
        else
            openScene(path);
    });
    connect(m_controller, &SimulationController::sceneLoaded, this, [this] {
        if (!m_session->inLesson()) // in a lesson, its title and step stay
            showSceneTitle();
    });
    // Every change to the document (an edit, undo, redo, opening) rebuilds the world from it,
    // so Run starts from the scene as edited and Reset returns to it. A lesson step loads its
    // worlds itself (compared worlds too) when it starts the document over.
    connect(m_document, &SceneDocument::sceneChanged, this, [this] {
        if (m_session->loading())
            return;
        if (m_session->inLesson() && m_player->lesson())
            m_session->reloadStepWorlds();
        else
            m_controller->loadScene(m_document->scene(), m_document->path());
    });
    connect(m_document, &SceneDocument::modifiedChanged, this, [this](bool modified) {
        if (windowTitle().contains(QLatin1String("[*]")))
            setWindowModified(modified);
    });
    connect(m_document, &SceneDocument::pathChanged, this, [this] {
        if (!m_session->inLesson())
            showSceneTitle();
    });
}

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

QList<PlotWidget*> MainWindow::plotsOnScreen() const
{
    // The standard plots whose docks are shown, then the compared worlds' plots of a lesson
    // step: what the student sees, not the plots the step hides.
    QList<PlotWidget*> plots;
    for (PlotWidget* plot : m_plots)
        if (!m_layout->dock(plot->objectName())->isHidden())
            plots << plot;
    if (!m_layout->compareDock()->isHidden())
        for (PlotWidget* plot : m_session->comparePlots())
            plots << plot;
    plots << m_instruments->graphsShown(); // graphs of chosen bodies
    // An imported measurement's comparison and residuals, as its dock shows them.
    if (QDockWidget* dock = m_layout->dock(QStringLiteral("measurement"));
        dock && !dock->isHidden())
        for (PlotWidget* plot : m_measurement->panel()->plotsShown())
            plots << plot;
    return plots;
}

// The parts' answers.
QString MainWindow::openScene(const QString& path, bool quiet)
{
    return m_documents->openScene(path, quiet);
}
bool MainWindow::newScene()
{
    return m_documents->newScene();
}
bool MainWindow::saveScene()
{
    return m_documents->saveScene();
}
bool MainWindow::saveSceneAs()
{
    return m_documents->saveSceneAs();
}
bool MainWindow::confirmLeaveScene()
{
    return m_documents->confirmLeaveScene();
}
void MainWindow::setSavePathAsker(SavePathAsker asker)
{
    m_documents->setSavePathAsker(std::move(asker));
}
void MainWindow::setUnsavedAsker(UnsavedAsker asker)
{
    m_documents->setUnsavedAsker(std::move(asker));
}
const QString& MainWindow::lastFolder() const
{
    return m_documents->lastFolder();
}
bool MainWindow::documentIsFile() const
{
    return m_documents->documentIsFile();
}
void MainWindow::adoptDocument(const lessons::Scene& edited, const QString& path, bool isFile,
                               bool modified)
{
    m_documents->adoptDocument(edited, path, isFile, modified);
}
QString MainWindow::lastError() const
{
    return m_documents->lastError();
}
QString MainWindow::scenesFolder()
{
    return lessons::shippedScenesDir();
}
QString MainWindow::lessonsFolder()
{
    return lessons::shippedLessonsDir();
}
QString MainWindow::openLesson(const QString& path, bool quiet)
{
    return m_session->openLesson(path, quiet);
}
PlotWidget* MainWindow::plot(QStringView name) const
{
    for (PlotWidget* plot : m_plots)
        if (plot->objectName() == name)
            return plot;
    return nullptr;
}

PlotWidget* MainWindow::comparePlot() const
{
    return m_session->comparePlots().empty() ? nullptr : m_session->comparePlots().front();
}
const std::vector<PlotWidget*>& MainWindow::comparePlots() const
{
    return m_session->comparePlots();
}
QDockWidget* MainWindow::dock(const QString& name) const
{
    return m_layout->dock(name);
}
QStringList MainWindow::exportStepPlots(const QString& folder)
{
    return m_session->exportStepPlots(folder);
}
QAction* MainWindow::overlayAction(Overlay overlay) const
{
    return m_actions->overlay(overlay);
}
QString MainWindow::statusText() const
{
    return m_status->text();
}
QAction* MainWindow::statusDetailsAction() const
{
    return m_status->detailsAction();
}
void MainWindow::setDetailsShown(bool shown)
{
    m_status->setDetailsShown(shown);
}
void MainWindow::updateStatus()
{
    m_status->update();
}
void MainWindow::fitToScreen(const QRect& available)
{
    m_layout->fitToScreen(available);
}
bool MainWindow::compactLayout() const
{
    return m_layout->compact();
}
void MainWindow::setPresentation(bool on)
{
    m_layout->setPresentation(on);
}
bool MainWindow::presentation() const
{
    return m_layout->presentation();
}

void MainWindow::restoreSettings()
{
    QSettings s;
    m_documents->restoreSettings();
    m_layout->restore(s);
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
            m_actions->overlays()[i]->setChecked(s.value(key).toBool());
    }
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
    // A lesson being written with unsaved edits asks first (Save, Discard or Cancel).
    for (LessonEditor* editor : findChildren<LessonEditor*>())
        if (editor->isVisible() && !editor->close()) {
            event->ignore();
            return;
        }
    if (!confirmLeaveScene()) { // unsaved edits: Save, Discard or Cancel
        event->ignore();
        return;
    }
    m_controller->setRunning(false);
    QSettings s;
    m_layout->save(s);
    for (std::size_t i = 0; i < kOverlayNames.size(); ++i)
        s.setValue(QStringLiteral("overlays/") + QLatin1String(kOverlayNames[i].settingKey),
                   m_actions->overlays()[i]->isChecked());
    syncSettings(s, *this);
    event->accept();
}

void MainWindow::showEvent(QShowEvent* event)
{
    QMainWindow::showEvent(event);
    m_layout->windowShown();
}

void MainWindow::resizeEvent(QResizeEvent* event)
{
    QMainWindow::resizeEvent(event);
    m_layout->windowResized();
}

void MainWindow::moveEvent(QMoveEvent* event)
{
    QMainWindow::moveEvent(event);
    m_layout->windowMoved();
}

} // namespace rigidlab::ui
