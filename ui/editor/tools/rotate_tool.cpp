// SPDX-License-Identifier: GPL-3.0-or-later
#include "editor/tools/rotate_tool.h"

#include "editor/edit_tools.h"

#include "edit/scene_edits.h"
#include "panels/number_field.h"

#include <cmath>
#include <numbers>

namespace rigidlab::ui {

using physics::Vec2;

namespace {

/// Dragging with the grid on turns in steps of this much [rad].
constexpr double kAngleSnap = 15.0 * std::numbers::pi / 180.0;

double angleAbout(const Vec2& origin, const Vec2& p)
{
    return std::atan2(p.y() - origin.y(), p.x() - origin.x());
}

} // namespace

QString RotateTool::status() const
{
    return tr("Rotate: drag a body, or anywhere for the selected one, to turn it about its "
              "origin; a click selects, and so does Enter, body after body; Q and E turn the "
              "selected body by 5°");
}

bool RotateTool::wantsKey(int key) const
{
    return m_body < 0 && (key == Qt::Key_Return || key == Qt::Key_Enter);
}

void RotateTool::key(int /*key*/)
{
    m_tools.selectNextBody();
}

bool RotateTool::press(const ToolPointer& pointer)
{
    const int under = m_tools.bodyAt(pointer.raw);
    const int body = under >= 0 ? under : m_tools.selectedBody();
    if (body < 0) {
        m_tools.selectBody(-1);
        m_tools.selectSpring(-1);
        return false; // empty space pans
    }
    m_tools.selectBody(body);
    const auto& def = m_tools.scene().bodies[static_cast<size_t>(body)];
    m_body = body;
    m_startAngle = def.angle;
    m_pointerAngle = angleAbout(def.position, pointer.raw);
    m_mergeId = m_tools.newMergeId();
    return true;
}

bool RotateTool::move(const ToolPointer& pointer)
{
    if (m_body < 0) {
        return false;
    }
    const lessons::Scene& scene = m_tools.scene();
    const auto& def = scene.bodies[static_cast<size_t>(m_body)];
    double angle = m_startAngle + (angleAbout(def.position, pointer.raw) - m_pointerAngle);
    if (m_tools.snapping()) {
        angle = std::round(angle / kAngleSnap) * kAngleSnap;
    }
    const QString name = EditTools::bodyName(scene, m_body);
    if (m_tools.apply(tr("Rotate %1").arg(name), lessons::edit::rotateBody(scene, m_body, angle),
                      m_mergeId)) {
        m_tools.say(tr("%1 at %2°").arg(name, formatNumber(angle * 180.0 / std::numbers::pi, 4)));
    }
    return true;
}

bool RotateTool::release(const ToolPointer& /*pointer*/)
{
    if (m_body < 0) {
        return false;
    }
    m_body = -1;
    m_tools.refreshOverlay();
    return true;
}

} // namespace rigidlab::ui
