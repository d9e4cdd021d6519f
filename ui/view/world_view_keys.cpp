// SPDX-License-Identifier: GPL-3.0-or-later
// WorldView's keyboard: what a mouse does in the scene, done with keys. A body is chosen with
// Select next/previous body; the arrows then move it and Shift+arrows change its velocity,
// through the controller (World's API), as dragging it would. Without a selected body the
// arrows go on to the window's shortcuts (step forward and back). Tab always leaves the view.
#include "view/world_view.h"

#include "simulation/simulation_controller.h"
#include "view/scene_narrator.h"
#include "view/world_view_accessible.h"

#include <QAccessible>
#include <QKeyEvent>

namespace rigidlab::ui {

namespace {

/// How far one arrow press moves the selected body [m], and with Ctrl.
constexpr double kMoveStep = 0.1;
constexpr double kFineMoveStep = 0.01;
/// How much one Shift+arrow press changes its velocity [m/s], and with Ctrl.
constexpr double kPushStep = 0.5;
constexpr double kFinePushStep = 0.1;

} // namespace

void WorldView::selectNextBody()
{
    selectBodyAfter(1);
}

void WorldView::selectPreviousBody()
{
    selectBodyAfter(-1);
}

void WorldView::selectBodyAfter(int step)
{
    const auto& bodies = m_controller.world().bodies();
    const int n = static_cast<int>(bodies.size());
    int id = m_selected < 0 ? (step > 0 ? -1 : n) : m_selected;
    for (int tries = 0; tries < n; ++tries) {
        id = ((id + step) % n + n) % n;
        if (bodies[static_cast<std::size_t>(id)].moves()) {
            selectBody(id);
            m_narrator->tellChosen(id);
            if (QAccessible::isActive())
                if (QAccessibleInterface* view = QAccessible::queryAccessibleInterface(this))
                    if (QAccessibleInterface* body =
                            view->child(WorldViewAccessible::FirstBody + id)) {
                        QAccessibleEvent event(body, QAccessible::Selection);
                        QAccessible::updateAccessibility(&event);
                    }
            return;
        }
    }
}

void WorldView::keyPressEvent(QKeyEvent* event)
{
    if (m_selected < 0) {
        QGraphicsView::keyPressEvent(event);
        return;
    }
    const bool fine = event->modifiers() & Qt::ControlModifier;
    const bool push = event->modifiers() & Qt::ShiftModifier;
    const double step =
        push ? (fine ? kFinePushStep : kPushStep) : (fine ? kFineMoveStep : kMoveStep);
    double dx = 0, dy = 0;
    switch (event->key()) {
    case Qt::Key_Left:
        dx = -step;
        break;
    case Qt::Key_Right:
        dx = step;
        break;
    case Qt::Key_Up:
        dy = step;
        break;
    case Qt::Key_Down:
        dy = -step;
        break;
    case Qt::Key_Return:
    case Qt::Key_Enter:
        emit numbersRequested(m_selected);
        return;
    case Qt::Key_Escape:
        selectBody(-1);
        return;
    default:
        QGraphicsView::keyPressEvent(event);
        return;
    }
    if (push)
        m_controller.pushBody(m_selected, dx, dy);
    else
        m_controller.moveBody(m_selected, dx, dy);
    m_narrator->tellMoved(m_selected);
}

bool WorldView::event(QEvent* event)
{
    // The arrows are also the window's Step and Back: with a body selected, the view takes
    // them (and Enter, Escape) before the shortcut does.
    if (event->type() == QEvent::ShortcutOverride && m_selected >= 0) {
        const auto* key = static_cast<QKeyEvent*>(event);
        const Qt::KeyboardModifiers mods =
            key->modifiers() & ~(Qt::ShiftModifier | Qt::ControlModifier | Qt::KeypadModifier);
        switch (key->key()) {
        case Qt::Key_Left:
        case Qt::Key_Right:
        case Qt::Key_Up:
        case Qt::Key_Down:
        case Qt::Key_Return:
        case Qt::Key_Enter:
        case Qt::Key_Escape:
            if (mods == Qt::NoModifier) {
                event->accept();
                return true;
            }
            break;
        default:
            break;
        }
    }
    return QGraphicsView::event(event);
}

} // namespace rigidlab::ui
