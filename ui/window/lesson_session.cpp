// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/lesson_session.h"

#include "common/announcer.h"
#include "common/display_names.h"
#include "common/export_folder.h"
#include "common/modal_scope.h"
#include "common/number_format.h"
#include "editor/edit_tools.h"
#include "editor/scene_document.h"
#include "lesson_player/lesson_panels.h"
#include "lesson_player/lesson_player.h"
#include "panels/control_panel.h"
#include "panels/sat_panel.h"
#include "plots/lesson_export.h"
#include "plots/plot_export.h"
#include "plots/plot_shelf.h"
#include "plots/plot_table.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"
#include "window/dock_tabs.h"
#include "window/empty_stage.h"
#include "window/window_actions.h"
#include "window/window_documents.h"
#include "window/window_layout.h"
#include "window/window_names.h"
#include "window/window_plots.h"

#include "format/data_dirs.h"
#include "format/lesson.h"
#include "format/lesson_catalog.h"
#include "run/featured_collision.h"
#include "run/swept_bounds.h"

#include <QAction>
#include <QDockWidget>
#include <QFileDialog>
#include <QMainWindow>
#include <QMessageBox>
#include <QStatusBar>

#include <algorithm>
#include <optional>
#include <utility>

namespace rigidlab::ui {

LessonSession::LessonSession(const Parts& parts) : QObject(&parts.window), m_parts(parts)
{
    LessonPlayer& player = parts.player;
    player.listLessons(lessons::allLessonsInOrder()); // shipped, then the user's own
    connect(&player, &LessonPlayer::stepActivated, this, &LessonSession::applyStep);
    connect(&player, &LessonPlayer::lessonClosed, this, &LessonSession::leave);
    connect(&player, &LessonPlayer::heldBackChanged, this, [this](const QStringList& held) {
        const bool wasHeld = m_runHeld;
        applyHeldBack(held);
        if (wasHeld && !m_runHeld)
            m_parts.controller.setRunning(true); // predicted: now see
    });
    connect(&player, &LessonPlayer::exportRequested, this, &LessonSession::exportDialog);
    // Why the run paused by itself: in the status bar, and told to a screen reader (which
    // reads no status bar; the scene only says where it paused).
    connect(&parts.controller, &SimulationController::leftStage, this,
            [this](physics::BodyId body, double t) {
                tellPause(
                    tr("%1 fell off the stage at t = %2 s: the run paused. Play runs on.")
                        .arg(m_parts.controller.scene().bodyLabel(body), formatReadable(t, 3)));
            });
    // Every moving body out of the view (two balls parting after their collision): nothing
    // left to watch, so the run pauses there once, as for a body off the stage.
    new EmptyStageWatch(
        parts.controller, parts.view, [this] { return m_inLesson && !m_loading; },
        [this](double t) {
            tellPause(tr("Every moving body has left the view at t = %1 s: the run paused. "
                         "Play runs on.")
                          .arg(formatReadable(t, 3)));
        },
        this);
    connect(&parts.controller, &SimulationController::endTimeReached, this, [this](double t) {
        tellPause(tr("This step's run ends at t = %1 s: the run paused. Play runs on.")
                      .arg(formatReadable(t, 3)));
    });
}

void LessonSession::tellPause(const QString& why)
{
    m_parts.window.statusBar()->showMessage(why, 20000);
    announce(m_parts.window, why);
}

QString LessonSession::openLesson(const QString& path, bool quiet)
{
    const QString error = m_parts.player.openLesson(path); // asks about unsaved edits first
    m_parts.documents.setLastError(error);
    if (!error.isEmpty() && !quiet && !m_parts.player.openCancelled()) {
        auto* box = new QMessageBox(QMessageBox::Warning, tr("Cannot open lesson"), error,
                                    QMessageBox::Ok, &m_parts.window);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->setObjectName(QStringLiteral("lessonErrorBox"));
        box->open();
    }
    if (error.isEmpty()) {
        m_parts.layout.dock(QStringLiteral("lesson"))->show();
        m_parts.layout.dock(QStringLiteral("lesson"))->raise();
    }
    return error;
}

void LessonSession::openLessonDialog()
{
    const ModalScope modal;
    const QString path = QFileDialog::getOpenFileName(&m_parts.window, tr("Open lesson"),
                                                      lessons::shippedLessonsDir(),
                                                      tr("RigidLab lessons (*.json *.rlesson)"));
    if (!path.isEmpty())
        openLesson(path, false);
}

void LessonSession::addLessonFolderDialog()
{
    const ModalScope modal;
    const QString folder = QFileDialog::getExistingDirectory(
        &m_parts.window, tr("Add a folder of lessons"), lessons::userLessonsDir());
    if (!folder.isEmpty())
        addLessonFolder(folder);
}

void LessonSession::addLessonFolder(const QString& folder)
{
    lessons::addLessonFolder(folder);
    m_parts.player.listLessons(lessons::allLessonsInOrder()); // shipped, own, added
}

void LessonSession::removeLessonFolder(const QString& folder)
{
    lessons::removeLessonFolder(folder);
    m_parts.player.listLessons(lessons::allLessonsInOrder());
}

const lessons::LessonStep* LessonSession::currentStep() const
{
    const lessons::Lesson* lesson = m_parts.player.lesson();
    if (!m_inLesson || !lesson)
        return nullptr;
    return &lesson->steps[static_cast<size_t>(m_parts.player.stepIndex())];
}

void LessonSession::applyStep(const lessons::Lesson& lesson, int index)
{
    const lessons::LessonStep& step = lesson.steps[static_cast<size_t>(index)];
    m_inLesson = true;
    m_parts.window.setWindowTitle(tr("%1 — step %2 — RigidLab").arg(lesson.title).arg(index + 1));

    const QString scenePath = step.scenePath.isEmpty() ? lesson.path : step.scenePath;
    // The step's scene is the document now; the step loads its worlds itself, just below.
    m_loading = true;
    m_parts.documents.setDocumentIsFile(false); // the lesson's or a shipped scene's: Save asks
    m_parts.document.reset(step.scene, scenePath);
    // A step may open the editor with some tools only (its "editor" key).
    m_parts.editTools.setAllowedTools(step.editor ? std::optional(step.editor->tools)
                                                  : std::nullopt);
    m_parts.editTools.setAllowedProperties(step.editor ? std::optional(step.editor->properties)
                                                       : std::nullopt);
    // A step with an editor opens in Edit mode, paused; any other step leaves it.
    m_parts.editTools.setEditing(step.editor.has_value());
    m_loading = false;
    const QStringList labels = loadStepWorlds(step, step.scene, scenePath);
    showStepDocks(step, labels);
    showStepOverlays(step);
    // What the questions hold back stays hidden until answered.
    applyHeldBack(m_parts.player.heldBack());
    m_parts.controls.setAllowed(step.allow);
    if (step.sat) {
        const auto a = step.scene.bodyIndex(step.sat->first);
        const auto b = step.scene.bodyIndex(step.sat->second);
        m_parts.sat.setBodies(a ? *a : -1, b ? *b : -1);
    } else {
        m_parts.sat.setBodies(-1, -1);
    }
    m_parts.collision.setNamedBodies(lessons::namedBodies(step, step.scene));
    frameStepAction(step);
    m_parts.controller.setEndTime(step.endTime);
    m_parts.controller.setStageWatched(true);
    if (!step.editor)
        m_parts.controller.setRunning(step.autoplay && !m_runHeld);
}

void LessonSession::frameStepAction(const lessons::LessonStep& step)
{
    // The class sees the step's whole event, not bodies that leave the view after the hit:
    // the view frames where the bodies will go until the step's export time. A step with the
    // editor holds still, the scene shown whole (what will happen depends on the edits).
    if (step.editor) {
        m_parts.view.setActionBounds({});
        return;
    }
    const SimulationController& c = m_parts.controller;
    // A step whose run ends earlier frames only what happens until then.
    const double until = std::min(step.exportTime, step.endTime.value_or(step.exportTime));
    QRectF action = lessons::sweptBounds(c.world(), until);
    for (int v = 0; v < c.variantCount(); ++v) {
        const physics::Vec2 shift = (v + 1) * c.variantOffset();
        action |= lessons::sweptBounds(c.variant(v), until).translated(shift.x(), shift.y());
    }
    m_parts.view.setActionBounds(action);
}

void LessonSession::showStepDocks(const lessons::LessonStep& step, const QStringList& labels)
{
    // Only what the step names: panels, plots. Those its questions hold back stay hidden
    // (shown and hidden again, a dock would leave the one it shares tabs with out of place).
    m_parts.layout.keepingSize([&] { showOnlyStepDocks(step, labels); });
    m_parts.layout.fitSideColumns();
}

void LessonSession::showOnlyStepDocks(const lessons::LessonStep& step, const QStringList& labels)
{
    const QStringList held = m_parts.player.heldBack();
    const QMap<QString, QDockWidget*>& docks = m_parts.layout.docks();
    for (auto it = docks.cbegin(); it != docks.cend(); ++it) {
        if (it.key() == QLatin1String("lesson"))
            continue;
        const bool panel = step.panels.contains(it.key());
        const bool plot = step.plots.contains(it.key());
        const bool heldBack = (panel && held.contains(QStringLiteral("panel:") + it.key())) ||
                              (plot && held.contains(QStringLiteral("plot:") + it.key()));
        it.value()->setVisible((panel || plot) && !heldBack);
    }
    QDockWidget* compareDock = m_parts.layout.compareDock();
    delete compareDock->widget();
    m_comparePlots.clear();
    if (!labels.isEmpty())
        makeComparePlots(step);
    compareDock->setVisible(!m_comparePlots.empty());
    // Room for the step's tables and plots beside the view, the ones it needs in front.
    QList<QDockWidget*> shown;
    for (const QString& name : step.panels + step.plots)
        if (QDockWidget* d = m_parts.layout.dock(name); d && !d->isHidden())
            shown << d;
    m_parts.layout.regroup();
    m_parts.layout.raiseFirst(shown);
}

void LessonSession::makeComparePlots(const lessons::LessonStep& step)
{
    // The step's compared worlds, one plot for each compare-… plot it names, made where the
    // headless export makes them (lesson_export.h), so the window shows and exports the same.
    QDockWidget* compareDock = m_parts.layout.compareDock();
    // Side by side, stacked or behind tabs, as the dock's room keeps each readable.
    auto* box = new PlotShelf(compareDock);
    QStringList titles;
    for (const QString& name : step.plots) {
        const PlotRow* row = findPlot(name);
        if (!row || row->inWindow())
            continue;
        PlotWidget* plot = makeStepPlot(step, name, box);
        if (!plot)
            continue;
        plot->setMinimumSize(180, 150);
        plot->setTitleShown(false);
        plot->setPresentation(m_parts.layout.presentation());
        followController(*plot, m_parts.controller, m_parts.plotTurns);
        // Its tab says what the plot's values are (the drift), its row's short title.
        box->addPlot(plot, plotTitle(*row, false));
        m_comparePlots.push_back(plot);
        titles << plot->title();
    }
    if (m_comparePlots.empty()) {
        delete box;
        return;
    }
    compareDock->setWidget(box);
    showContentIfInSight(*compareDock);
    // A short title on the narrow column's tab, the plots' titles in its tooltip.
    setFullTitle(*compareDock, titles.join(QStringLiteral(" · ")));
}

void LessonSession::showStepOverlays(const lessons::LessonStep& step)
{
    for (const OverlayNames& info : kOverlayNames)
        m_parts.actions.overlay(info.overlay)
            ->setChecked(step.overlays.contains(lessonOverlayName(info.overlay)));
    // Springs and joints are part of the scene, not a teaching aid: drawn whenever there are any.
    if (!step.scene.springs.empty() || !step.scene.joints.empty())
        m_parts.actions.overlay(Overlay::SpringsJoints)->setChecked(true);
}

QStringList LessonSession::loadStepWorlds(const lessons::LessonStep& step,
                                          const lessons::Scene& scene, const QString& path)
{
    // The step's worlds: the main one, then those compared beside it, built from `scene` (the
    // step's, or as edited) with the step's settings.
    lessons::LessonStep built = step;
    built.scene = scene;
    std::vector<physics::World> worlds = lessons::buildStepWorlds(built);
    QStringList labels;
    if (step.compare && step.compare->count() > 1)
        for (int i = 0; i < step.compare->count(); ++i)
            labels << methodDisplayName(step.compare->label(i));
    SimulationController& controller = m_parts.controller;
    controller.loadWorlds(scene, path, std::move(worlds), labels,
                          step.compare ? step.compare->offset : physics::Vec2::Zero());
    if (const auto scale = step.settings.get<double>("timeScale"))
        controller.setTimeScale(*scale);
    std::vector<lessons::Measure> measures;
    for (const lessons::Question& q : step.questions)
        if (const auto* measured = q.as<lessons::MeasuredQuestion>()) // the others measure nothing
            measures.push_back(measured->measure);
    controller.watch(measures);
    return labels;
}

void LessonSession::reloadStepWorlds()
{
    // The step's settings, compared worlds and measurements stay.
    if (const lessons::LessonStep* step = currentStep())
        loadStepWorlds(*step, m_parts.document.scene(), m_parts.document.path());
}

void LessonSession::followEditing(bool editing)
{
    // Entering or leaving Edit mode reloads the world from the document, which drops a
    // lesson step's measurements and compared worlds: the step's worlds come back, built
    // from the scene as edited, so its questions judge what the student built.
    if (m_loading || !currentStep())
        return;
    reloadStepWorlds();
    if (!editing && !m_runHeld)
        m_parts.controller.setRunning(true); // leaving Edit mode runs the scene as edited
}

void LessonSession::applyHeldBack(const QStringList& held)
{
    const bool runHeld = held.contains(QStringView(lessons::kHoldBackRun));
    m_runHeld = runHeld;
    if (m_runHeld)
        m_parts.controller.setRunning(false);
    emit runHeldChanged(m_runHeld);
    m_parts.collision.setAfterHeld(held.contains(QStringView(lessons::kHoldBackCollisionAfter)));
    m_parts.bounces.setHeightsHeld(held.contains(QStringView(lessons::kHoldBackBounceHeights)));
    const lessons::LessonStep* step = currentStep();
    if (!step)
        return;
    m_parts.layout.keepingSize([&] {
        QList<QDockWidget*> shown; // by an answer that released them: brought to the front
        for (const auto& [names, prefix] : {std::pair{&step->panels, QStringLiteral("panel:")},
                                            std::pair{&step->plots, QStringLiteral("plot:")}})
            for (const QString& name : *names)
                if (QDockWidget* d = m_parts.layout.dock(name)) {
                    const bool visible = !held.contains(prefix + name);
                    if (visible && d->isHidden())
                        shown << d;
                    d->setVisible(visible);
                }
        m_parts.layout.raiseFirst(shown);
    });
}

void LessonSession::leave()
{
    if (!m_inLesson)
        return;
    m_inLesson = false;
    m_parts.controller.setEndTime(std::nullopt);
    m_parts.controller.setStageWatched(false);
    m_parts.editTools.setAllowedTools(std::nullopt);
    m_parts.editTools.setAllowedProperties(std::nullopt);
    emit left();
    // Back to the plain lab: controls, inspector and the window's own plots.
    const QMap<QString, QDockWidget*>& docks = m_parts.layout.docks();
    for (auto it = docks.cbegin(); it != docks.cend(); ++it) {
        const PlotRow* plot = findPlot(it.key());
        const bool standard = it.key() == QLatin1String("lesson") ||
                              it.key() == QLatin1String("controls") ||
                              it.key() == QLatin1String("inspector") || (plot && plot->inWindow());
        it.value()->setVisible(standard);
    }
    delete m_parts.layout.compareDock()->widget();
    m_comparePlots.clear();
    m_parts.layout.compareDock()->hide();
    m_parts.controls.setAllowed(std::nullopt);
    m_parts.sat.setBodies(-1, -1);
    m_parts.collision.setNamedBodies({});
    applyHeldBack({});
    m_parts.layout.fitSideColumns();
    m_parts.view.setActionBounds({});
}

void LessonSession::exportDialog()
{
    const ModalScope modal;
    const QString folder = QFileDialog::getExistingDirectory(
        &m_parts.window, tr("Export the step's plots into"), exportFolder());
    if (folder.isEmpty())
        return;
    rememberExportFolder(folder);
    const QStringList errors = exportStepPlots(folder);
    if (!errors.isEmpty())
        QMessageBox::warning(&m_parts.window, tr("Export failed"), errors.join(QLatin1Char('\n')));
    else
        m_parts.window.statusBar()->showMessage(tr("Plots written to %1").arg(folder), 6000);
}

QStringList LessonSession::exportStepPlots(const QString& folder)
{
    // The plots as the student sees them, with a caption naming the lesson, step,
    // integrator and dt (or just the scene's title outside a lesson).
    std::vector<PlotWidget*> plots;
    const auto plotNamed = [&](const QString& name) -> PlotWidget* {
        for (PlotWidget* plot : m_parts.plots)
            if (plot->objectName() == name)
                return plot;
        for (PlotWidget* plot : m_comparePlots)
            if (plot->objectName() == name)
                return plot;
        return nullptr;
    };
    const lessons::Lesson* lesson = m_parts.player.lesson();
    if (lesson) {
        // In a lesson: the plots the step names, in its order, as rigidlab-cli lesson --export.
        for (const QString& name :
             lesson->steps.at(static_cast<size_t>(m_parts.player.stepIndex())).plots)
            if (PlotWidget* plot = plotNamed(name))
                plots.push_back(plot);
    } else {
        for (PlotWidget* plot : m_parts.plots)
            if (!m_parts.layout.dock(plot->objectName())->isHidden())
                plots.push_back(plot);
    }
    for (PlotWidget* plot : plots)
        plot->drain();
    const QString caption =
        lesson ? stepCaption(*lesson, m_parts.player.stepIndex(), m_parts.controller.world().def())
               : m_parts.controller.scene().title;
    const PlotFilesResult r = exportPlots(plots, folder, caption, windowExportOptions());
    return r.ok ? QStringList() : QStringList{r.error};
}

} // namespace rigidlab::ui
