// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow's scene editor: Edit mode and its tools on a toolbar of their own, their messages
// in the status bar, the selection's properties and the history of edits in docks. The tools
// are the editor's (ui/editor); here they are given their places in the window.
#include "window/main_window.h"

#include "common/accessible_names.h"
#include "common/current_with_focus.h"
#include "common/dock_names.h"
#include "editor/edit_tools.h"
#include "editor/scene_document.h"
#include "editor/scene_properties.h"
#include "window/dock_tabs.h"
#include "window/lesson_session.h"
#include "window/window_actions.h"
#include "window/window_layout.h"

#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QScrollArea>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoView>

namespace rigidlab::ui {

void MainWindow::buildEditor()
{
    m_editTools = new EditTools(*m_view, *m_controller, *m_document, this);
    m_editTools->setReloadsWorld(false); // the window reloads it after every change already
    connect(m_editTools, &EditTools::message, this, [this](const QString& text) {
        if (text.isEmpty())
            statusBar()->clearMessage();
        else
            statusBar()->showMessage(text, 10000);
    });
    connect(m_editTools, &EditTools::editingChanged, this, [this](bool on) {
        // Q and E turn the body in the scene while editing (EditTools), not in the world.
        for (QAction* a : m_actions->rotate())
            a->setEnabled(!on);
        m_actions->setRunState(on, m_session && m_session->runHeld());
        if (m_session)
            m_session->followEditing(on);
    });

    // Edit on or off sits on the simulation toolbar, beside Play. The tools get a row of their
    // own below it, shown in Edit mode only: on a 1024-pixel projector one row cannot hold the
    // simulation's actions and ten tools, and the tools would hide behind "»".
    const QList<QAction*> actions = m_editTools->actions();
    m_actions->toolbar()->addSeparator();
    m_actions->toolbar()->addAction(actions.front());
    addToolBarBreak();
    auto* toolbar = addToolBar(tr("Scene editor"));
    toolbar->setObjectName(QStringLiteral("editToolbar"));
    toolbar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    for (qsizetype i = 1; i < actions.size(); ++i)
        toolbar->addAction(actions[i]);
    toolbar->hide();
    connect(m_editTools, &EditTools::editingChanged, toolbar, &QToolBar::setVisible);
    addAction(m_editTools->deleteSelectionAction());
    buildHistoryDock(*buildPropertiesDock());
    m_actions->setRunState(false, false);
}

QDockWidget* MainWindow::buildPropertiesDock()
{
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
    auto* dock = new QDockWidget(this);
    nameDock(*dock, QStringLiteral("propertiesDock"));
    nameScrollArea(*scroll, dock->windowTitle());
    dock->setWidget(scroll);
    addDockWidget(Qt::LeftDockWidgetArea, dock);
    keepFocusInSight(*dock);
    dock->hide();
    connect(m_editTools, &EditTools::editingChanged, dock, [this, dock](bool on) {
        // A tab beside the inspector, wherever the layout has put the inspector since.
        if (QDockWidget* inspector = m_layout->dock(QStringLiteral("inspector")); on && inspector)
            tabifyDockWidget(inspector, dock);
        dock->setVisible(on);
        if (on)
            dock->raise();
    });
    return dock;
}

void MainWindow::buildHistoryDock(QDockWidget& properties)
{
    // The undo stack as a list, one readable entry per edit ("Add circle circle1", "Move
    // box2"); clicking an entry undoes or redoes up to it.
    auto* view = new QUndoView(m_document->undoStack());
    view->setObjectName(QStringLiteral("historyView"));
    view->setEmptyLabel(tr("Scene as opened"));
    view->setToolTip(tr("Every edit since the scene was opened; click one to go back to it "
                        "(the later ones stay, to redo)"));
    view->setAccessibleName(tr("History of edits"));
    keepCurrentOnlyWhileFocused(*view);
    // As narrow as the other panels: a long entry scrolls rather than widening the column.
    view->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    view->setTextElideMode(Qt::ElideRight);
    view->setMinimumWidth(0);

    auto* dock = new QDockWidget(this);
    nameDock(*dock, QStringLiteral("historyDock"));
    setFullTitle(*dock, tr("History of edits"));
    dock->setWidget(view);
    addDockWidget(Qt::LeftDockWidgetArea, dock);
    keepFocusInSight(*dock);
    dock->hide();
    connect(m_editTools, &EditTools::editingChanged, dock, [this, dock, &properties](bool on) {
        // A tab beside the Properties, which the editor has put beside the inspector.
        if (on)
            tabifyDockWidget(&properties, dock);
        dock->setVisible(on);
        if (on)
            properties.raise(); // the Properties stay in front, as before
    });
}

} // namespace rigidlab::ui
