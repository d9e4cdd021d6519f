// SPDX-License-Identifier: GPL-3.0-or-later
#include "editor/tools/drag_tool.h"

#include "editor/edit_tools.h"

#include <QApplication>

namespace rigidlab::ui {

bool DragTool::dragged(const ToolPointer& pointer) const
{
    return (pointer.pixel - m_pressPixel).manhattanLength() >= QApplication::startDragDistance();
}

bool DragTool::press(const ToolPointer& pointer)
{
    m_start = m_tools.snapped(pointer.raw);
    m_current = m_start;
    m_pressPixel = pointer.pixel;
    m_active = true;
    m_dragged = false;
    m_tools.refreshOverlay();
    return true;
}

bool DragTool::move(const ToolPointer& pointer)
{
    if (!m_active) {
        return false;
    }
    m_current = m_tools.snapped(pointer.raw);
    m_dragged = m_dragged || dragged(pointer);
    m_tools.say(sizeText());
    return true;
}

bool DragTool::release(const ToolPointer& pointer)
{
    if (!m_active) {
        return false;
    }
    m_active = false;
    if (!m_dragged && !dragged(pointer)) {
        m_tools.say(status()); // a click: nothing drawn, and the status says how to draw
        m_tools.refreshOverlay();
        return true;
    }
    finish(m_tools.snapped(pointer.raw), pointer.raw);
    m_tools.refreshOverlay();
    return true;
}

bool DragTool::wantsKey(int key) const
{
    return !m_active && (key == Qt::Key_Return || key == Qt::Key_Enter);
}

void DragTool::key(int /*key*/)
{
    addByKey();
}

} // namespace rigidlab::ui
