// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow in a lesson: opening one, showing what each step names, holding back what its
// questions hide, leaving it, exporting the step's plots.
#include "window/main_window.h"

#include "common/display_names.h"
#include "common/modal_scope.h"
#include "editor/edit_tools.h"
#include "editor/scene_document.h"
#include "lesson_player/lesson_panels.h"
#include "lesson_player/lesson_player.h"
#include "panels/control_panel.h"
#include "panels/sat_panel.h"
#include "plots/lesson_export.h"
#include "plots/plot_export.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"
#include "window/dock_tabs.h"
#include "window/window_names.h"

#include "format/lesson.h"
#include "format/lesson_catalog.h"

#include <QAction>
#include <QDockWidget>
#include <QFileDialog>
#include <QMessageBox>
#include <QVBoxLayout>

#include <algorithm>

namespace rigidlab::ui {

namespace {

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

QString MainWindow::openLesson(const QString& path, bool quiet)
{
    const QString error = m_player->openLesson(path); // asks about unsaved edits first
    m_lastError = error;
    if (!error.isEmpty() && !quiet && !m_player->openCancelled()) {
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

    const QString scenePath = step.scenePath.isEmpty() ? lesson.path : step.scenePath;
    // The step's scene is the document now; the step loads its worlds itself, just below.
    m_lessonLoading = true;
    m_documentIsFile = false; // its path is the lesson's or a shipped scene's: Save asks where
    m_document->reset(step.scene, scenePath);
    m_lessonLoading = false;
    // A step may open the editor with some tools only (its "editor" key).
    m_editTools->setAllowedTools(step.editor ? std::optional(step.editor->tools) : std::nullopt);
    m_editTools->setAllowedProperties(step.editor ? std::optional(step.editor->properties)
                                                  : std::nullopt);
    // A step with an editor opens in Edit mode, paused; any other step leaves it.
    m_lessonLoading = true;
    m_editTools->setEditing(step.editor.has_value());
    m_lessonLoading = false;
    const QStringList labels = loadStepWorlds(step, step.scene, scenePath);

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
            // A short title on the narrow column's tab, the plots' titles in its tooltip.
            setFullTitle(*m_compareDock, titles.join(QStringLiteral(" · ")));
        }
    }
    m_compareDock->setVisible(!m_comparePlots.empty());
    for (const OverlayNames& info : kOverlayNames)
        overlayAction(info.overlay)
            ->setChecked(step.overlays.contains(lessonOverlayName(info.overlay)));
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
    if (!step.editor) {
        m_controller->setRunning(step.autoplay && !m_runHeld);
    } else {
        // The view holds still while editing: the step's scene is shown whole once.
        m_view->fitScene();
    }
}

QStringList MainWindow::loadStepWorlds(const lessons::LessonStep& step, const lessons::Scene& scene,
                                       const QString& path)
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
    m_controller->loadWorlds(scene, path, std::move(worlds), labels,
                             step.compare ? step.compare->offset : physics::Vec2::Zero());
    if (step.settings.timeScale)
        m_controller->setTimeScale(*step.settings.timeScale);
    std::vector<lessons::Measure> measures;
    for (const lessons::Question& q : step.questions)
        measures.push_back(q.measure);
    m_controller->watch(measures);
    return labels;
}

void MainWindow::applyHeldBack(const QStringList& held)
{
    m_runHeld = held.contains(QStringView(lessons::kHoldBackRun));
    m_playAction->setEnabled(!m_runHeld);
    updateStepActions();
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
    m_editTools->setAllowedTools(std::nullopt);
    m_editTools->setAllowedProperties(std::nullopt);
    showSceneTitle();
    // Back to the plain lab: controls, inspector and the three plots.
    for (auto it = m_docks.cbegin(); it != m_docks.cend(); ++it) {
        const bool standard =
            it.key() == QLatin1String("lesson") || it.key() == QLatin1String("controls") ||
            it.key() == QLatin1String("inspector") ||
            std::any_of(kPlotNames.begin(), kPlotNames.end(),
                        [&](const PlotNames& p) { return it.key() == QLatin1String(p.name); });
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
    const auto nameOf = [](int i) {
        return QLatin1String(kPlotNames[static_cast<size_t>(i)].name);
    };
    const auto plotNamed = [&](const QString& name) -> PlotWidget* {
        for (int i = 0; i < kPlotCount; ++i)
            if (nameOf(i) == name)
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
            if (!m_docks.value(nameOf(i))->isHidden())
                plots.push_back(m_plots[static_cast<size_t>(i)]);
    }
    for (int i = 0; i < kPlotCount; ++i)
        m_plots[static_cast<size_t>(i)]->setObjectName(nameOf(i));
    for (PlotWidget* plot : plots)
        plot->drain();
    const lessons::Lesson* lesson = m_player->lesson();
    const QString caption =
        lesson ? stepCaption(*lesson, m_player->stepIndex(), m_controller->world().def())
               : m_controller->scene().title;
    const PlotFilesResult r = exportPlots(plots, folder, caption);
    return r.ok ? QStringList() : QStringList{r.error};
}

} // namespace rigidlab::ui
