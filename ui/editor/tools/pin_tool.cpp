// SPDX-License-Identifier: GPL-3.0-or-later
#include "editor/tools/pin_tool.h"

#include "editor/edit_tools.h"
#include "editor/overlay_paint.h"

#include "edit/scene_edits.h"

#include <QPainter>

namespace rigidlab::ui {

using physics::Vec2;

QString PinTool::status() const
{
    return tr("Pin: click a point of a body, then a second body or empty space for the world; "
              "Enter pins the selected body to the world at its centre");
}

bool PinTool::press(const ToolPointer& pointer)
{
    const int body = m_tools.bodyAtOrSnapped(pointer.raw);
    if (m_start) {
        pinTo(body);
        return true;
    }
    if (body < 0) {
        m_tools.say(tr("Click a point of a body to pin it"));
        return true;
    }
    m_start = std::pair{body, m_tools.snapped(pointer.raw)};
    m_tools.selectBody(body);
    m_tools.say(tr("Now click a second body, or empty space to pin it to the world"));
    m_tools.refreshOverlay();
    return true;
}

void PinTool::pinTo(physics::BodyId body)
{
    const lessons::Scene& scene = m_tools.scene();
    const auto [first, point] = *m_start;
    m_start.reset();
    m_tools.apply(
        body < 0 ? tr("Pin %1 to the world").arg(EditTools::bodyName(scene, first))
                 : tr("Pin %1 to %2")
                       .arg(EditTools::bodyName(scene, first), EditTools::bodyName(scene, body)),
        lessons::edit::addPin(scene, first, body, point));
    m_tools.refreshOverlay();
}

bool PinTool::wantsKey(int key) const
{
    return key == Qt::Key_Return || key == Qt::Key_Enter;
}

void PinTool::key(int /*key*/)
{
    if (!m_start) {
        const int body = m_tools.selectedBody();
        if (body < 0) {
            m_tools.say(tr("Click a point of a body to pin it"));
            return;
        }
        m_start = std::pair{body, m_tools.scene().bodies[static_cast<size_t>(body)].position};
    }
    pinTo(physics::kWorld);
}

void PinTool::paint(QPainter& painter, double zoom) const
{
    if (!m_start) {
        return;
    }
    const double r = 5.0 / zoom;
    painter.drawEllipse(overlay::at(m_start->second), r, r);
}

} // namespace rigidlab::ui
