// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow's scene editor (issue 15): Edit mode and its tools on a toolbar of their own,
// their messages in the status bar, the selection's properties in a dock. (The document, its
// files and its history: main_window.cpp, main_window_save.cpp.)
#include "window/main_window.h"

#include "editor/edit_tools.h"
#include "editor/scene_document.h"
#include "editor/scene_properties.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"

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
}

} // namespace rigidlab::ui
