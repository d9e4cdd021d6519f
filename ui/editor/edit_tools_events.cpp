// SPDX-License-Identifier: GPL-3.0-or-later
// EditTools' mouse and keys in Edit mode: each gesture goes to the tool in use
// (editor/tools/); the arrows, Q, E, Delete and Escape act on the selection and the gesture
// under way whatever the tool.

#include "editor/edit_tools.h"

#include "editor/tools/polygon_tool.h"

#include "view/world_view.h"

#include <QAction>
#include <QKeyEvent>
#include <QMouseEvent>

#include <numbers>

namespace rigidlab::ui {

using physics::Vec2;

namespace {

/// Q and E turn by this much, as they do outside Edit mode [rad].
constexpr double kTurnStep = 5.0 * std::numbers::pi / 180.0;

} // namespace

bool EditTools::eventFilter(QObject* watched, QEvent* event)
{
    if (!m_editing) {
        return false;
    }
    if (watched == m_view.viewport()) {
        return viewportEvent(event);
    }
    if (watched == &m_view) {
        if (event->type() == QEvent::ShortcutOverride && wantsKey(static_cast<QKeyEvent*>(event))) {
            event->accept(); // the key comes as a key press, not as the window's shortcut
            return true;
        }
        if (event->type() == QEvent::KeyPress) {
            return keyPress(static_cast<QKeyEvent*>(event));
        }
    }
    return false;
}

bool EditTools::viewportEvent(QEvent* event)
{
    switch (event->type()) {
    case QEvent::MouseButtonPress:
        return mousePress(static_cast<QMouseEvent*>(event));
    case QEvent::MouseButtonDblClick: {
        auto* mouse = static_cast<QMouseEvent*>(event);
        if (mouse->button() != Qt::LeftButton) {
            return false;
        }
        return current().doubleClick(pointerAt(mouse));
    }
    case QEvent::MouseMove:
        return mouseMove(static_cast<QMouseEvent*>(event));
    case QEvent::MouseButtonRelease:
        return mouseRelease(static_cast<QMouseEvent*>(event));
    default:
        return false;
    }
}

ToolPointer EditTools::pointerAt(const QMouseEvent* event) const
{
    const QPoint pixel = event->position().toPoint();
    return {m_view.worldAt(pixel), pixel};
}

bool EditTools::mousePress(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) {
        return false; // the middle button pans, as outside Edit mode
    }
    m_view.setFocus(Qt::MouseFocusReason);
    return current().press(pointerAt(event));
}

bool EditTools::mouseMove(QMouseEvent* event)
{
    const ToolPointer pointer = pointerAt(event);
    updateSnapText();
    Tool& tool = current();
    const bool hadMarker = m_bodySnap.has_value();
    if (tool.marksSnaps()) {
        m_bodySnap = featureSnap(pointer.raw);
    } else if (!tool.busy()) {
        m_bodySnap.reset(); // a moved body's drag sets it as the body moves
    }
    const bool taken = tool.move(pointer);
    // Repainted for a gesture under way, or for a snap marker that shows, moves or goes; a
    // pointer crossing empty space repaints nothing.
    if (tool.busy() || hadMarker || m_bodySnap) {
        refreshOverlay();
    }
    return taken;
}

bool EditTools::mouseRelease(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) {
        return false;
    }
    return current().release(pointerAt(event));
}

bool EditTools::wantsKey(const QKeyEvent* event) const
{
    if (isViewKey(*event)) {
        return true;
    }
    if (event->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier)) {
        return false;
    }
    const Tool& tool = *m_tools[static_cast<size_t>(m_tool)];
    switch (event->key()) {
    case Qt::Key_Left:
    case Qt::Key_Right:
    case Qt::Key_Up:
    case Qt::Key_Down:
    case Qt::Key_Q:
    case Qt::Key_E:
        return m_selected >= 0;
    case Qt::Key_Delete:
        return m_selected >= 0 || m_selectedSpring >= 0;
    case Qt::Key_Escape:
        return tool.busy();
    default:
        return tool.wantsKey(event->key());
    }
}

bool EditTools::keyPress(QKeyEvent* event)
{
    // A locked tool's key (its action is disabled, so no shortcut takes it): said, not ignored.
    const QKeySequence pressed(event->keyCombination());
    for (size_t i = 0; i < m_toolActions.size(); ++i) {
        if (locked(static_cast<EditTool>(i)) && m_toolActions[i]->shortcuts().contains(pressed)) {
            setTool(static_cast<EditTool>(i));
            return true;
        }
    }
    if (!wantsKey(event)) {
        return false;
    }
    if (!viewKey(*event) && !selectionKey(event)) {
        current().key(event->key());
    }
    return true;
}

bool EditTools::selectionKey(const QKeyEvent* event)
{
    // One grid step, or a tenth of one with Shift (or with the grid off).
    const double step =
        gridStep() *
        ((event->modifiers() & Qt::ShiftModifier) || !m_snapAction->isChecked() ? 0.1 : 1.0);
    switch (event->key()) {
    case Qt::Key_Left:
        nudgeSelected(Vec2(-step, 0.0));
        return true;
    case Qt::Key_Right:
        nudgeSelected(Vec2(step, 0.0));
        return true;
    case Qt::Key_Up:
        nudgeSelected(Vec2(0.0, step));
        return true;
    case Qt::Key_Down:
        nudgeSelected(Vec2(0.0, -step));
        return true;
    case Qt::Key_Q:
        rotateSelected(kTurnStep);
        return true;
    case Qt::Key_E:
        rotateSelected(-kTurnStep);
        return true;
    case Qt::Key_Delete:
        deleteSelected();
        return true;
    case Qt::Key_Escape:
        cancelGesture();
        say({});
        return true;
    default:
        return false;
    }
}

const std::vector<Vec2>& EditTools::polygonPoints() const
{
    return static_cast<const PolygonTool&>(*m_tools[static_cast<size_t>(EditTool::Polygon)])
        .points();
}

void EditTools::closePolygon()
{
    static_cast<PolygonTool&>(*m_tools[static_cast<size_t>(EditTool::Polygon)]).close();
}

} // namespace rigidlab::ui
