// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow's History dock (issue 15): the scene editor's undo stack as a list, one readable
// entry per edit ("Add circle circle1", "Move box2", "Set friction μ of box2"); clicking an
// entry undoes or redoes up to it. Shown in Edit mode, a tab beside the Properties.
#include "window/main_window.h"

#include "editor/edit_tools.h"
#include "editor/scene_document.h"
#include "window/dock_tabs.h"

#include <QDockWidget>
#include <QUndoView>

namespace rigidlab::ui {

void MainWindow::buildHistory(QDockWidget& properties)
{
    auto* view = new QUndoView(m_document->undoStack());
    view->setObjectName(QStringLiteral("historyView"));
    view->setEmptyLabel(tr("Scene as opened"));
    view->setToolTip(tr("Every edit since the scene was opened; click one to go back to it "
                        "(the later ones stay, to redo)"));
    // As narrow as the other panels: a long entry scrolls rather than widening the column.
    view->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    view->setTextElideMode(Qt::ElideRight);
    view->setMinimumWidth(0);

    auto* dock = new QDockWidget(tr("History"), this);
    dock->setObjectName(QStringLiteral("historyDock"));
    setFullTitle(*dock, tr("History of edits"));
    dock->setWidget(view);
    addDockWidget(Qt::LeftDockWidgetArea, dock);
    dock->hide();
    connect(m_editTools, &EditTools::editingChanged, dock, [this, dock, &properties](bool on) {
        // A tab beside the Properties, which the editor has put beside the inspector.
        if (on) {
            tabifyDockWidget(&properties, dock);
        }
        dock->setVisible(on);
        if (on) {
            properties.raise(); // the Properties stay in front, as before
        }
    });
}

} // namespace rigidlab::ui
