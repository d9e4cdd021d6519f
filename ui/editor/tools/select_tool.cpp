// SPDX-License-Identifier: GPL-3.0-or-later
#include "editor/tools/select_tool.h"

#include "editor/edit_tools.h"

#include "edit/scene_edits.h"

namespace rigidlab::ui {

using physics::Vec2;
namespace edit = lessons::edit;

QString SelectTool::status() const
{
    return tr("Select: click a body or a spring to select it, drag a body to move it, drag "
              "the arrow's handle to set its velocity; Enter selects the next body, the arrow "
              "keys nudge, Q and E turn");
}

bool SelectTool::wantsKey(int key) const
{
    return m_body < 0 && (key == Qt::Key_Return || key == Qt::Key_Enter);
}

void SelectTool::key(int /*key*/)
{
    m_tools.selectNextBody();
}

bool SelectTool::press(const ToolPointer& pointer)
{
    const Vec2& raw = pointer.raw;
    if (pressVelocityHandle(raw)) {
        return true;
    }
    const int body = m_tools.bodyAt(raw);
    if (body < 0) {
        m_tools.selectBody(-1);
        if (const int spring = m_tools.springAt(raw); spring >= 0) {
            m_tools.selectSpring(spring);
            return true;
        }
        m_tools.selectSpring(-1);
        return false; // empty space pans
    }
    m_tools.selectBody(body);
    m_body = body;
    m_velocity = false;
    m_press = raw;
    m_grabOffset = m_tools.scene().bodies[static_cast<size_t>(body)].position - raw;
    m_mergeId = m_tools.newMergeId();
    return true;
}

bool SelectTool::move(const ToolPointer& pointer)
{
    if (m_body < 0) {
        return false;
    }
    if (m_velocity) {
        dragVelocity(pointer.raw);
        return true;
    }
    const lessons::Scene& scene = m_tools.scene();
    const Vec2 target = m_tools.movedBodyTarget(m_body, m_grabOffset, pointer.raw);
    const QString name = EditTools::bodyName(scene, m_body);
    if (m_tools.apply(tr("Move %1").arg(name), edit::moveBody(scene, m_body, target), m_mergeId)) {
        m_tools.say(tr("%1 at (%2; %3) m")
                        .arg(name, m_tools.metres(target.x()), m_tools.metres(target.y())));
    }
    return true;
}

bool SelectTool::release(const ToolPointer& /*pointer*/)
{
    if (m_body < 0) {
        return false;
    }
    m_body = -1;
    m_tools.clearBodySnap(); // the body is set down
    m_tools.refreshOverlay();
    return true;
}

} // namespace rigidlab::ui
