// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow's scene editor (issue 15): Edit mode and its tools on a toolbar of their own,
// their messages in the status bar, the selection's properties in a dock. (The document, its
// files and its history: main_window.cpp, main_window_save.cpp.)
#include "window/main_window.h"

#include "editor/edit_tools.h"
#include "editor/scene_document.h"
#include "editor/scene_properties.h"
#include "lesson_player/lesson_player.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"
#include "window/shortcuts.h"

#include <QComboBox>
#include <QDockWidget>
#include <QScrollArea>
#include <QStatusBar>
#include <QToolBar>

namespace rigidlab::ui {

void MainWindow::buildEditor()
{
    m_editTools = new EditTools(*m_view, *m_controller, *m_document, this);
    m_editTools->setReloadsWorld(false); // the window reloads it after every change already
    connect(m_editTools, &EditTools::message, this, [this](const QString& text) {
        if (text.isEmpty()) {
            statusBar()->clearMessage();
        } else {
            statusBar()->showMessage(text, 10000);
        }
    });
    // Q and E turn the body in the scene while editing (EditTools), not in the world.
    connect(m_editTools, &EditTools::editingChanged, this, [this](bool on) {
        for (QAction* a : m_rotateActions) {
            a->setEnabled(!on);
        }
    });

    // Edit on or off sits on the simulation toolbar, beside Play. The tools get a row of their
    // own below it, shown in Edit mode only: on a 1024-pixel projector one row cannot hold the
    // simulation's actions and ten tools, and the tools would hide behind "»".
    const QList<QAction*> actions = m_editTools->actions();
    if (auto* simulation = findChild<QToolBar*>(QStringLiteral("simulationToolbar"))) {
        simulation->addSeparator();
        simulation->addAction(actions.front());
    }
    addToolBarBreak();
    auto* toolbar = addToolBar(tr("Scene editor"));
    toolbar->setObjectName(QStringLiteral("editToolbar"));
    toolbar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    for (qsizetype i = 1; i < actions.size(); ++i) {
        toolbar->addAction(actions[i]);
    }
    toolbar->hide();
    connect(m_editTools, &EditTools::editingChanged, toolbar, &QToolBar::setVisible);
    addAction(m_editTools->deleteSelectionAction());

    // The selection's properties, beside the inspector, shown in Edit mode.
    auto* properties = new SceneProperties(*m_editTools, *m_document, this);
    connect(properties, &SceneProperties::refused, this,
            [this](const QString& why) { statusBar()->showMessage(why, 10000); });
    // As the other panels: lists as narrow as a short name, so that a long integrator's name
    // does not widen the side column on a projector, and a panel that scrolls, not cut.
    for (QComboBox* box : properties->findChildren<QComboBox*>()) {
        box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        box->setMinimumContentsLength(8);
    }
    auto* scroll = new QScrollArea(this);
    scroll->setWidget(properties);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto* dock = new QDockWidget(tr("Properties"), this);
    dock->setObjectName(QStringLiteral("propertiesDock"));
    dock->setWidget(scroll);
    addDockWidget(Qt::LeftDockWidgetArea, dock);
    dock->hide();
    connect(m_editTools, &EditTools::editingChanged, dock, [this, dock](bool on) {
        // A tab beside the inspector, wherever the layout has put the inspector since.
        if (QDockWidget* inspector = m_docks.value(QStringLiteral("inspector")); on && inspector) {
            tabifyDockWidget(inspector, dock);
        }
        dock->setVisible(on);
        if (on) {
            dock->raise();
        }
    });
    buildHistory(*dock);
    followEditMode();
}

void MainWindow::followEditMode()
{
    m_stepAction->setProperty("runToolTip", m_stepAction->toolTip());
    m_backAction->setProperty("runToolTip", m_backAction->toolTip());
    connect(m_editTools, &EditTools::editingChanged, this, [this](bool on) {
        updateStepActions();
        // Entering or leaving Edit mode reloads the world from the document, which drops a
        // lesson step's measurements and compared worlds: the step's worlds come back, built
        // from the scene as edited, so its questions judge what the student built.
        const lessons::Lesson* lesson = m_player->lesson();
        if (m_lessonLoading || !m_inLesson || !lesson)
            return;
        loadStepWorlds(lesson->steps[static_cast<size_t>(m_player->stepIndex())],
                       m_document->scene(), m_document->path());
        if (!on && !m_runHeld)
            m_controller->setRunning(true); // leaving Edit mode runs the scene as edited
    });
    updateStepActions();
}

void MainWindow::updateStepActions()
{
    const bool editing = m_editTools && m_editTools->editing();
    m_stepAction->setEnabled(!editing && !m_runHeld);
    m_backAction->setEnabled(!editing);
    const QString editingTip = tr("The world does not step in Edit mode: leave it (%1) or press "
                                  "Play to run the scene as edited")
                                   .arg(controlKeysText("editMode"));
    for (QAction* a : {m_stepAction, m_backAction})
        a->setToolTip(editing ? editingTip : a->property("runToolTip").toString());
}

} // namespace rigidlab::ui
